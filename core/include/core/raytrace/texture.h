#pragma once
// Colour of a texture at texture coordinates (u, v), repeated outside [0, 1):
// nearest texel, u to the right, v upwards (row 0 of wb::Image is the top row).
// Planes bind (u, v) by three points, ellipsoids by longitude/latitude (seed 001).
#include "core/image.h"

#include <glm/glm.hpp>

namespace wb::rt {

// RGB in 0..1. An empty image gives white, so an unset texture changes nothing.
glm::dvec3 sampleTexture(const Image& image, const glm::dvec2& uv);

} // namespace wb::rt
