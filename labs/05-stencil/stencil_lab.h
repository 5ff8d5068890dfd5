#pragma once
// Lab 5 - stencil buffer: the shadow of an object on a staircase, clipped to each step by
// the stencil and blended once; reflections in a rectangular and an elliptical mirror,
// confined to the mirror by the stencil; the raw stencil buffer on a key.
#include "common/lab.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace wb {

// The stencil's bits: 0-4 the receiver a pixel shows (shadow passes), 5-6 the mirror it lies
// in, 7 set where a shadow was blended. A pixel of a reflection keeps its mirror's bit and
// gets the receiver bits of the reflected receiver it shows.
constexpr uint8_t kReceiverMask = 0x1F;
constexpr uint8_t kMirrorMask = 0x60;
constexpr uint8_t kStencilRectMirror = 0x20;
constexpr uint8_t kStencilEllipseMirror = 0x40;
constexpr uint8_t kStencilFloor = 3;
constexpr uint8_t kStencilBackWall = 4;
constexpr uint8_t kStencilStairFront = 5; // the stairs' front side (z = +1.2)
constexpr uint8_t kStencilFirstStep = 6;  // tread i: 6 + 2i, riser i: 7 + 2i (at most 6 steps: 17)
constexpr uint8_t kShadowBit = 0x80;

// Scene geometry in world units (y up), shared with the tests' independent references.
constexpr double kStepWidth = 0.8, kStepHeight = 0.4;      // stairs climb towards +x from x = -1.6
constexpr double kStairX0 = -1.6, kStairHalfDepth = 1.2;   // stairs span z in [-1.2, 1.2]
constexpr double kWallZ = -3.0, kMirrorZ = -2.98;          // mirrors hang 2 cm in front of the wall
constexpr double kRectMirror[4] = {-3.1, 0.4, -0.7, 3.3};  // x0, y0, x1, y1
constexpr double kEllipseMirror[4] = {2.0, 2.1, 1.2, 1.4}; // centre x, y; semi-axes along x, y
constexpr double kTorusMajor = 0.5, kTorusMinor = 0.2;     // the object, axis tilted (objectModel)
inline const glm::dvec3 kStencilLight{-3.5, 5.0, 2.0};     // the point light
constexpr float kShadowAlpha = 0.5f;                       // shadow keeps 1 - 0.5 of the colour

struct StencilLabState {
    bool shadow = true; // s: shadows: the object's on everything, the stairs' on floor and wall
    bool naiveShadow = false;  // n: shadow without the stencil, to see leaks and double blending
    bool rectMirror = true;    // r: the rectangular mirror on the back wall
    bool ellipseMirror = true; // e: the elliptical mirror on the back wall
    bool showMask = false;     // m: show the raw stencil buffer instead of the scene
    glm::dvec3 object{-0.5, 2.4, 0.2}; // the torus' centre; arrows move x/z, PageUp/PageDown y
    int steps = 4;                     // stairs; each 0.8 wide, 0.4 high

    // Written by draw() for tests and the panel:
    std::vector<uint8_t> stencil; // last frame's stencil, width*height, top row first
    int width = 0, height = 0;    // of `stencil`
    // The mirrors' outlines projected to window pixels (x right, y DOWN, like the image).
    std::vector<glm::dvec2> rectOutline, ellipseOutline;
    glm::dmat4 objectModel{1.0};                // torus object space -> world
    glm::dmat4 modelview{1.0}, projection{1.0}; // the camera of the last frame (no mirror)
    int shadowTriangles = 0; // clipped caster triangles drawn as shadow in the last frame
};

std::unique_ptr<Lab> makeStencilLab();
// The lab working on `observe` (tests read and set the state).
std::unique_ptr<Lab> makeStencilLab(StencilLabState* observe);

} // namespace wb
