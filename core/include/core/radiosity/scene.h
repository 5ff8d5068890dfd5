#pragma once
// The input of the radiosity method (§1.13–1.14): planar convex polygons (triangles and
// quads) with an RGB reflectivity R (0 <= R < 1, formula 14.16) and an RGB emission E
// (light energy per unit area and time, W/m², any consistent unit). Lengths are metres.
// A surface is one-sided: it emits and receives on the side its normal points to, the
// normal being (v1 − v0) × (v2 − v0) (counter-clockwise seen from the front).
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace wb::rad {

struct Surface {
    std::vector<glm::dvec3> vertices; // 3 or 4 corners, coplanar, convex, counter-clockwise
    glm::dvec3 reflectivity{0.5};     // R per channel, 0 <= R < 1
    glm::dvec3 emission{0.0};         // E per channel, >= 0 (W/m²)
    std::string name;                 // for messages and the panel ("left wall", "light")
};

struct Scene {
    std::string name;              // shown by the lab ("Cornell box")
    std::vector<Surface> surfaces; // every polygon of the scene
    bool closed = false; // the surfaces enclose space: every row of F sums to 1
    // Where to look from (the lab's default camera), metres.
    glm::dvec3 eye{0.0, 0.0, 3.0}, target{0.0}, up{0.0, 1.0, 0.0};
};

// Throws std::invalid_argument naming the surface (index and name) and the problem when
// the scene cannot be solved: fewer than 3 or more than 4 vertices, a non-finite
// coordinate, zero area, non-planar or non-convex polygon, R outside [0, 1), negative or
// non-finite E, or no surface emitting at all (B would be 0 everywhere: silent nonsense).
void validate(const Scene& scene);

// Area and unit normal of a planar polygon (Newell's method, robust for slivers);
// area 0 and normal 0 when degenerate.
double polygonArea(const std::vector<glm::dvec3>& poly);
glm::dvec3 polygonNormal(const std::vector<glm::dvec3>& poly);
// Area-weighted centroid of a planar polygon by its fan of triangles from poly[0] (the
// polygon is assumed star-shaped from poly[0], as the mesh's convex cells and exposed slivers
// are); false, centroid untouched, when the fan has no area.
bool polygonCentroid(const std::vector<glm::dvec3>& poly, glm::dvec3& centroid);

} // namespace wb::rad
