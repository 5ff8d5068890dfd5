#pragma once
// Bilinear interpolation (4.8) and its inversion (practical 4.3).
//
// Vertex order as in the course: A = P(0,0), B = P(1,0), C = P(1,1), D = P(0,1):
//   P(α, β) = (1−α)(1−β)A + α(1−β)B + αβC + (1−α)βD.
//
// Inversion solves Aq·β² + Bq·β + Cq = 0 (4.9) with the course's coefficients, oriented
// by the diagonals' cross product n = (C−A)×(D−B) so that either vertex order works,
// and takes the course's root (4.10) through the cancellation-free branch (4.11):
//   Bq > 0: β = (−Bq − √disc)/(2Aq);  Bq ≤ 0: β = 2Cq/(−Bq + √disc).
// The second form is also the one that stays finite for parallelograms (Aq = 0): for a
// convex quad oriented by n, Bq < 0 there, and it gives β = −Cq/Bq exactly.
// α is then the position of P on the segment s1(β)s2(β), by projection.
#include <glm/glm.hpp>

#include <optional>

namespace wb {

glm::dvec2 bilinear(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                    const glm::dvec2& d, double alpha, double beta);
glm::dvec3 bilinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                    const glm::dvec3& d, double alpha, double beta);
// The same weights applied to values f(A), f(B), f(C), f(D).
double bilinear(double fa, double fb, double fc, double fd, double alpha, double beta);

// (α, β) with bilinear(a, b, c, d, α, β) = p. Returns nothing when there is no real
// solution (discriminant clearly negative: p outside the region the map covers), when
// the quad is degenerate (all coefficients vanish, e.g. collinear vertices), or on
// non-finite input. A discriminant negative only by rounding (|disc| ≤ 8 ulp of
// Bq² + 4|Aq·Cq|, points on a fold or an edge) is taken as 0. Where s1(β) = s2(β) (a quad
// with two coincident vertices, at that vertex) every α fits; α = 0.5 is returned.
// Points outside [0,1]² are not rejected: callers check the range they need.
std::optional<glm::dvec2> invertBilinear(const glm::dvec2& p, const glm::dvec2& a,
                                         const glm::dvec2& b, const glm::dvec2& c,
                                         const glm::dvec2& d);
// 3D form (the course's pseudocode): coefficients dotted with n = (C−A)×(D−B). Exact for
// points on the bilinear surface, planar or twisted (tested); a point off the surface gets
// the course's approximate answer (β from the n-projected equation, α by projection).
std::optional<glm::dvec2> invertBilinear(const glm::dvec3& p, const glm::dvec3& a,
                                         const glm::dvec3& b, const glm::dvec3& c,
                                         const glm::dvec3& d);

// The quadratic's root as chosen above, exposed for tests of the branch: returns
// nothing when no real root can be taken.
std::optional<double> bilinearBeta(double aq, double bq, double cq);

} // namespace wb
