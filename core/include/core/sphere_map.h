#pragma once
// The sphere-map formula of section 1.5.3, as OpenGL's GL_SPHERE_MAP texgen applies it
// per vertex, and its inverse (used to build a sphere-map environment texture).
#include <glm/glm.hpp>

namespace wb {

// Texture coordinates (s, t) of a vertex with eye-space position `eyePos` and eye-space
// normal `eyeNormal`: u = eyePos/|eyePos|, f = u - 2n(n·u), m = 2√(fx²+fy²+(fz+1)²),
// s = fx/m + ½, t = fy/m + ½. Like GL, u is normalised; n is normalised here too (GL does
// that only with GL_NORMALIZE, so callers that compare with GL must pass unit normals).
// Degenerate input gives a defined answer instead of NaN: a zero position or normal gives
// the disc centre (½, ½); f = (0, 0, -1) (looking straight through the map's blind spot,
// where the whole rim of the disc is the answer) gives the rim point (1, ½).
glm::dvec2 sphereMapCoord(const glm::dvec3& eyePos, const glm::dvec3& eyeNormal);

// The eye-space reflection direction f (unit length) that sphereMapCoord maps to (s, t).
// Returns false, leaving `f` alone, when (s, t) lies outside the disc (2s-1)²+(2t-1)² ≤ 1.
bool sphereMapDirection(double s, double t, glm::dvec3& f);

} // namespace wb
