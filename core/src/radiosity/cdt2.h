#pragma once
// A constrained Delaunay mesh of a plane region (internal to meshing; CGAL's
// Constrained_Delaunay_triangulation_2 refined by Delaunay_mesher_2, Ruppert/Shewchuk style):
// every triangle has its smallest angle at least kMinAngleDeg and no edge longer than maxEdge,
// the input segments are edges of the mesh (split where the mesher needs it, at midpoints).
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace wb::rad::detail {

// sin²(20.7°) = 0.125 is the largest bound for which the mesher is proven to terminate (CGAL's
// Delaunay_mesh_criteria_2 documentation); with it a triangle's longest edge over its height
// onto that edge (patchAspect) is at most 2 / tan(20.7°) = 5.29.
constexpr double kMinAngleSin2 = 0.125;

struct Cdt2 {
    std::vector<glm::dvec2> points; // the input points first, in their order, then Steiner points
    std::vector<std::array<int, 3>> triangles; // counter-clockwise, inside the region
    // Per triangle: is its edge opposite corner k part of an input segment (or of a piece of one)
    std::vector<std::array<bool, 3>> constrained;
};

// `segments` (indices into `points`) must enclose the region to mesh (closed loops); points
// and segments inside it are kept as vertices and edges.
Cdt2 meshRegion(const std::vector<glm::dvec2>& points, const std::vector<std::array<int, 2>>& segments,
                double maxEdge);

} // namespace wb::rad::detail
