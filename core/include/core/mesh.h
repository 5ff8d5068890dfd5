#pragma once
// Triangle meshes of a sphere and a torus with the project's own vertices, normals and
// texture coordinates (lab 4 forbids gluQuadric/glutSolid*). Both are parametric
// surfaces p(s, t) over [0,1]² sampled on a grid.
//
// The seam: the column s = 0 and the column s = 1 (and for the torus also the rows t = 0
// and t = 1) are separate vertices at the same positions, so no triangle interpolates
// from s ≈ 1 back to s ≈ 0 (which would smear the whole texture into one column).
//
// The poles of the sphere: the rows t = 0 and t = 1 are one point each; their grid
// vertices keep one copy per slice with s at the middle of the slice, (i + ½)/slices, and
// each pole quad becomes one triangle. The texture is squeezed to a point there
// (unavoidable for a latitude-longitude map) but every triangle stays non-degenerate.
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace wb {

struct Mesh {
    std::vector<glm::dvec3> positions; // object space
    std::vector<glm::dvec3> normals;   // unit, outward
    std::vector<glm::dvec3> tangents; // unit, along ∂p/∂s (texture s direction); for bump mapping
    std::vector<glm::dvec2> texCoords; // (s, t) in [0,1]²
    std::vector<uint32_t> indices;     // triangles, counter-clockwise seen from outside
};

// Sphere of `radius` centred at the origin, poles on the y axis: s is longitude (s = 0 on
// +z, growing towards +x), t is latitude from the south pole (t = 0) to the north pole.
// Needs slices ≥ 3, stacks ≥ 2 and a finite radius > 0; throws std::invalid_argument otherwise.
Mesh makeSphere(double radius, int slices, int stacks);

// Ring torus around the y axis: tube centre circle of radius `majorRadius` in the xz plane,
// tube radius `minorRadius`; s goes around the y axis (like the sphere's longitude), t around
// the tube (t = 0 on the outer equator, growing upwards). Needs rings ≥ 3, sides ≥ 3 and
// 0 < minorRadius < majorRadius; throws std::invalid_argument otherwise.
Mesh makeTorus(double majorRadius, double minorRadius, int rings, int sides);

} // namespace wb
