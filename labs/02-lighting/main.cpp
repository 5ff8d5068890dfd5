// Lab 02 - Phong lighting: two cubes (face normals, centre normals), the 2x2 table of
// material and light, global ambient, local viewer, emission, flat/smooth, attenuation,
// spot, subdivided faces and per-fragment GLSL Phong.
// Keys:
//   1 2 3 4   specular/diffuse material x specular/diffuse light
//   5         all four combinations side by side (2x2)
//   a         global ambient (GL_LIGHT_MODEL_AMBIENT) on/off
//   v         local / infinite viewer (GL_LIGHT_MODEL_LOCAL_VIEWER)
//   e         emission (GL_EMISSION) on/off
//   s         glShadeModel smooth / flat
//   g         vertex (Gouraud) / per-fragment GLSL Phong
//   [ ]       face grid N down / up
//   w         positional / directional light
//   t         spot on/off
//   k         attenuation on/off
//   m         light marker on/off
//   b         blocker between light and cube on/off
//   arrows, PgUp/PgDn   move the light (x, y, z)
//   , .       spin the cubes
#include "common/shell.h"
#include "lighting_lab.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeLightingLab);
}
