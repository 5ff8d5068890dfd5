// Lab 04 - textures: a texture on a flat object (wrap, filters, mipmaps), on a hand-made
// sphere and torus, a mirror object with GL_SPHERE_MAP texgen (section 1.5.3, lab 4), and
// Blinn bump mapping on the torus (section 1.5.2).
// Keys:
//   0  overview (first frame)   1  flat textured object     2  sphere     3  torus     4  mirror object (sphere map)
//   5  bump-mapped torus (GLSL) k  bump mapping on/off
//   w  GL_REPEAT / GL_CLAMP     f  filter: nearest / linear / mipmaps
//   t  texture: bricks / uv grid     o  mirror object sphere / torus     b  background room
//   arrows  spin the object (mouse drag orbits the viewer)
#include "textures_lab.h"

#include "common/shell.h"

int main(int argc, char** argv) {
    return wb::runLab(argc, argv, wb::makeTexturesLab);
}
