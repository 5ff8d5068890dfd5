// Lab 03 - transforms and projections: a table, book, pen and teapot built with
// glTranslate/glRotate/glScale/glPushMatrix; a classroom of 3 x 4 tables with seeded
// random objects; glOrtho / gluPerspective / glFrustum with near/far clipping; the
// camera moved through gluLookAt; the classroom mirrored in the blackboard wall.
// Keys:
//   1 2 3     glOrtho / gluPerspective / glFrustum
//   z x       camera in / out (gluLookAt)
//   n N       near plane -/+ one step (0.1, 0.25, then 0.5 ... 30 in steps of 0.5)
//   b B       far plane -/+ 2 (2 ... 200)
//   r         new random placement (reseed)
//   c         classroom / single table
//   m         mirror image in the blackboard wall on/off
//   w         glFrontFace(GL_CW) for the mirror image on/off (off shows the wrong faces)
//   l         mirrored light position on/off (off lights the mirror image wrongly)
//   t         top view onto the wall
#include "common/shell.h"
#include "transforms_lab.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeTransformsLab);
}
