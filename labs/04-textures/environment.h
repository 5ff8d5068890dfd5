#pragma once
// The surroundings that lab 4's mirror object reflects: a procedural room at infinity
// (checkered floor, sky, four coloured pillars marking ±x and ±z), and the two textures
// made from it: the sphere map that GL_SPHERE_MAP texgen samples and the
// latitude-longitude map drawn on the background sphere.
#include "core/image.h"

#include <glm/glm.hpp>

namespace wb {

// RGB in [0,1] seen along the unit world direction `dir`. Pillars: +x red, -x green,
// -z blue, +z yellow (the viewer's side at yaw 0, like the "VIEWER" wall of fig. 5.22).
glm::dvec3 environmentColour(const glm::dvec3& dir);

// The sphere map for a viewer whose world-to-eye rotation is `worldToEye` (mouse orbit):
// texel (s, t) shows the environment along worldToEyeᵀ·f(s, t), f from sphereMapDirection.
// Texels outside the disc repeat the rim. Top row of the image is t = 1 (upload flipped).
Image makeSphereMapImage(const glm::dmat3& worldToEye, int size);

// Latitude-longitude map with the parametrisation of makeSphere (s longitude from +z towards
// +x, t latitude from the south pole); top row is t = 1.
Image makeLatLongImage(int width, int height);

} // namespace wb
