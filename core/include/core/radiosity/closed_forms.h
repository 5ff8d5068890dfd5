#pragma once
// Exact form factors: the references the numerical methods are checked against, and the
// point-to-polygon term used for near patch pairs, where (15.20)'s centre-to-centre
// cos·cos·A/(π d²) is far off (it assumes d much larger than the patches).
// All functions are in double, return values in [0, 1], and take lengths in any unit.
#include <glm/glm.hpp>

#include <vector>

namespace wb::rad {

// Differential area at `point` with unit normal `normal` to a convex or concave planar polygon
// (vertices in order, either orientation), the polygon fully visible and in front:
// Lambert's contour integral (Nusselt / Hottel): F = 1/(2π) Σ_edges γ_k (n · (R_k × R_k+1)/|..|),
// γ_k the angle an edge subtends at the point. Parts of the polygon behind the point's
// plane are clipped away first, so any position is allowed; 0 for degenerate input.
double pointToPolygon(const glm::dvec3& point, const glm::dvec3& normal,
                      const std::vector<glm::dvec3>& polygon);

// Two directly opposed parallel rectangles a × b, distance c apart (Howell's catalogue C-11,
// Hottel): F from one to the other.
double parallelRectangles(double a, double b, double c);

// Two perpendicular rectangles sharing an edge of length l, widths w1 (emitter) and w2
// (receiver) (Howell C-14): F from the w1 × l rectangle to the w2 × l rectangle.
double perpendicularRectangles(double l, double w1, double w2);

// Differential area on the axis of a parallel disc of radius r at distance h, facing it
// (Howell B-13): r² / (h² + r²).
double pointToCoaxialDisc(double h, double r);

} // namespace wb::rad
