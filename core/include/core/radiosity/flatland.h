#pragma once
// The course's 2D example (§1.15.3, formula 15.22): two segments P_i = q1q2 and P_j = q3q4 in
// the plane, optionally with occluding segments between them.
//
// The course's formula F_ij = 1/(π|P_i|) ∫_{P_i} γ(q) |dq| (the printed 15.22 divides by
// |q3q4| and integrates over q3q4: an index slip, the angle γ(q) is seen from q ∈ P_i) counts
// the fraction of DIRECTIONS from q that reach P_j, i.e. it assumes light leaves q uniformly in
// angle. A Lambertian (diffuse) surface emits with the cosine weight instead, and then the
// fraction of the light from q reaching P_j is (sin φ2 − sin φ1)/2 (φ the angles to the ends of
// P_j from the normal), whose integral is Hottel's crossed-strings rule. Both are computed here
// so the tests can show that the exact rule agrees with the cosine-weighted integral and how
// far the course's uniform-angle γ/π is from it.
#include <glm/glm.hpp>

#include <vector>

namespace wb::rad {

struct Segment2 {
    glm::dvec2 a, b;
};

// Hottel's crossed strings, unoccluded: F_ij = ((|q1q4| + |q2q3|) − (|q1q3| + |q2q4|)) / (2|q1q2|)
// with P_i = q1q2, P_j = q3q4 seen from each other (their facing sides); exact.
double crossedStrings(const Segment2& pi, const Segment2& pj);

// Crossed strings with one occluding segment between P_i and P_j (the course's figure 15.50):
// the light passes through two channels, beside each end of the occluder; in each, the strings
// are taut (wrapped around that end where a straight string would pass on the wrong side) and
// Hottel's rule gives that channel's part; the sum is the exact F. Throws for more than one
// occluder. P_i and P_j must see each other whole (each wholly in front of the other).
double crossedStringsOccluded(const Segment2& pi, const Segment2& pj,
                              const std::vector<Segment2>& occluders);

// The course's (15.22): 1/(π|P_i|) ∫ γ(q) dq, γ(q) the angle P_j subtends at q minus the parts
// hidden by occluders (γ1 + γ2 + … for the visible pieces), by Gauss–Legendre on `samples`
// subintervals. `lambertian` = true replaces γ/π by the cosine-weighted (sin φ2 − sin φ1)/2,
// which converges to crossedStrings().
// The side of P_i that emits is the one its left normal (rotate a→b by +90°) points to.
double course2D(const Segment2& pi, const Segment2& pj, const std::vector<Segment2>& occluders,
                int samples, bool lambertian);

} // namespace wb::rad
