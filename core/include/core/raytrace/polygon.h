#pragma once
// Triangles of a planar polygon given by its vertices in order (NFF `p`/`pp`, which may
// be concave: SPD gears' faces are 144-gons with a notch between every two teeth).
// A fan from vertex 0 is exact only for convex polygons; for a concave one it covers
// parts outside the polygon (the gaps between teeth next to vertex 0) and some inside
// twice. Concave polygons are cut by ear clipping instead.
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace wb::rt {

// Triangles as vertex indices, each in the polygon's winding order, covering the polygon
// exactly once. Convex polygons (collinear vertices allowed) give the fan
// (0, i, i+1), bit for bit what a fan always gave. Concave simple polygons are
// ear-clipped in the plane of their Newell normal (O(n·r) for r reflex vertices).
// Self-intersecting input has no such triangulation: ears are cut while any exist and
// the rest is fanned; so is the rest of a huge concave polygon once ear clipping has
// visited 2·10^8 vertices (hostile input: a 10^5-gon with half its corners reflex).
// Fewer than 3 vertices give no triangles.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<glm::dvec3>& vertices);

// The same, with the ear-clipping work (vertex visits) taken from `budget`, shared by
// every polygon of one file (issue 20 point 3: 40 random 10^5-gons took more than 60 s,
// each within its own cap). Returns false, with `out` empty, when the budget runs out
// before this polygon is cut: the caller refuses the file instead of drawing a fan
// that covers the wrong area.
bool triangulatePolygon(const std::vector<glm::dvec3>& vertices, long long& budget,
                        std::vector<std::array<int, 3>>& out);

} // namespace wb::rt
