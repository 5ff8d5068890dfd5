// Lab 06 - Bezier curves and patches (practical 10, lab 6): a circle from two cubic
// Bezier curves (glMap1f + glMapGrid1f/glEvalMesh1) and a sphere from two bicubic
// patches on the course's control net (glMap2f + glMapGrid2f/glEvalMesh2,
// GL_AUTO_NORMAL); the panel shows radial error and time per mesh against the grid.
// Keys:
//   1         circle from two Bezier curves
//   2         sphere from two Bezier patches
//   c         control polygon / control net
//   [ ]       grid resolution halve / double (2..256)
//   a         next approximation: more arcs, fitted handles, fitted net
//   w         sphere wireframe / filled
//   t         true circle / sphere in grey
//   n         sphere / teapot normals: GL_AUTO_NORMAL / core evalPatch (limits at corners, poles)
//   3         the Utah teapot from Newell's 32 Bezier patches (glMap2f / core de Casteljau)
//   z         inset magnifying the spot GL_AUTO_NORMAL leaves unlit, on/off
#include "bezier_lab.h"
#include "common/shell.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeBezierLab);
}
