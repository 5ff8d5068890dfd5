// Lab 07 - ray tracing versus rasterization: one scene drawn with OpenGL Phong (g) and
// ray-traced in the background (G), both timed, their difference as a heat map, the
// lab's timing experiment (one sphere vs two, SPD balls) and a ray inspector.
// Keys:
//   g         OpenGL Phong rasterization
//   G         ray traced (background, tile by tile, progress and time left)
//   arrows    rotate the scene (the traced view follows the same camera)
//   f         fixed function / per-fragment GLSL Phong (shaders/phong.*)
//   d         difference heat map |raster - trace| with mean and max
//   m         tracer shading model course / phong
//   b         BVH on/off
//   x         cancel the trace (or the timing experiment)
//   n N       next / previous scene
//   [ ]       tracer depth limit down / up
//   r         trace resolution 1, 1/2, 1/4
//   c         clear the ray inspector
//   t         run the timing experiment (every scene with and without the BVH)
//   click     inspect the ray tree of a pixel
#include "common/shell.h"
#include "raytrace_lab.h"

int main(int argc, char** argv) { return wb::runLab(argc, argv, wb::makeRaytraceLab); }
