#pragma once
// Lab 4 - textures (section 1.5.3, lab 4): a texture on a flat object with the wrap and
// filter modes, on a hand-made sphere and torus, a mirror object by GL_SPHERE_MAP, and
// Blinn bump mapping on the torus (section 1.5.2) in GLSL.
#include "common/lab.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>

namespace wb {

// Overview (key 0, the first frame): the sphere-mapped mirror object between the textured
// sphere and torus, in the room; 1-5 show one subject each.
enum class TextureScene { Overview = 0, Flat = 1, Sphere = 2, Torus = 3, Mirror = 4, Bump = 5 };
enum class TextureFilter { Nearest = 0, Linear = 1, Mipmap = 2 };

// Scene 5 (bump mapping), shared with the test's independent reference.
constexpr double kBumpTorusMajor = 1.1, kBumpTorusMinor = 0.45; // the torus of scenes 3-5
constexpr double kBumpRepeatS = 10, kBumpRepeatT = 3; // height-map tiles around the ring / the tube
// Point lights of scene 5 in eye coordinates (four white lights, fig. 5.20).
constexpr double kBumpLights[4][3] = {{4, 3, -1}, {-4, 3, -1}, {0, -3, -1}, {0, 4, -9}};

struct TexturesLabState {
    TextureScene scene = TextureScene::Overview;  // keys 0-5
    bool repeat = true;                           // w: GL_REPEAT, else GL_CLAMP
    TextureFilter filter = TextureFilter::Mipmap; // f cycles nearest / linear / mipmaps
    int texture = 0;          // t: 0 = bricks.png, 1 = uvgrid.png (1-3 pick the natural one)
    bool mirrorTorus = false; // o: the mirror object of scene 4 is a torus, else a sphere
    bool background = true;   // b: draw the room the mirror reflects
    bool bump = true;         // k: scene 5 with the height map, else the smooth torus (same shader)
    double bumpDepth = 0.04;  // scene 5: displacement of the height map's white, object units
    double spinX = 0, spinY = 0; // arrow keys: object rotation in degrees (not the viewer)
    std::string textureFiles[3] = {"assets/textures/bricks.png", "assets/textures/uvgrid.png",
                                   "assets/textures/bumps.png"}; // the last is the height map
    std::string message;     // texture load problems, shown in the panel and on stderr
    int sphereMapBuilds = 0; // how often the sphere map was rebuilt for a new view
    glm::dmat4 bumpModelview{1.0}, bumpProjection{1.0}; // scene 5: the torus's matrices (tests)
};

std::unique_ptr<Lab> makeTexturesLab();
// The lab working on `observe` (tests read and set the state).
std::unique_ptr<Lab> makeTexturesLab(TexturesLabState* observe);

} // namespace wb
