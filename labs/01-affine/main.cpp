// Lab 01 - affine maps: mirror image and shadows (light at infinity, point light) of a
// polygon in a random line as ONE 3x3 homogeneous matrix each; in 3D, in a plane, as 4x4
// matrices given to glMultMatrixd; exercise 1.1 solved both ways.
// Keys:
//   1         mirror image in the line / plane
//   2         shadow from a light at infinity along l
//   3         shadow from a point light S
//   v         2D view / 3D view
//   r         new random line through K, L (next seed)
//   Left Right  turn l (mode 2) / move S left, right (mode 3)
//   Up Down     move S up, down (mode 3) / tilt l (3D view, mode 2)
#include "affine_lab.h"
#include "common/shell.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeAffineLab);
}
