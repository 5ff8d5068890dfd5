// Lab 08 - radiosity (§1.13-1.15): the scene cut into patches, form factors by rays
// (§1.15.1), by the hemicube on the CPU and drawn by OpenGL (§1.15.2), B = E + R·F·B
// solved by progressive refinement in the background, flat or smoothed (figures 13.42
// and 13.43), the Cornell box, the course's classroom and its floor lamp. In a window the
// scene starts solving at once (as after n); headless, only the keys given solve.
// Keys:
//   1 2 3     form factors by rays / CPU hemicube / GL hemicube
//   s         smooth (vertex values, Gouraud) / flat patches
//   p         patch outlines
//   space     one progressive step (shoot the patch with the most unshot power)
//   r         run to convergence in the background (any key cancels)
//   a         adaptive subdivision where the solution changes fast
//   [ ]       patch size down / up (remesh)
//   n         next scene
//   click     a patch: its form-factor row over the scene and its hemicube
#include "common/shell.h"
#include "radiosity_lab.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeRadiosityLab);
}
