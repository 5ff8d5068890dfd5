// Lab 05 - stencil buffer: the shadow of a torus on a staircase, clipped to each step by
// the stencil and blended once, and reflections in a rectangular and an elliptical mirror
// confined by the stencil (lab 5).
// Keys:
//   s  shadow on/off              n  naive shadow without stencil (leaks, double blending)
//   r  rectangular mirror on/off  e  elliptical mirror on/off
//   m  show the raw stencil buffer
//   Left/Right, Up/Down  move the object in x / z      PageUp/PageDown  up / down
#include "stencil_lab.h"

#include "common/shell.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeStencilLab);
}
