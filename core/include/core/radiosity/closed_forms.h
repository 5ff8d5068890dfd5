#pragma once
// Exact form factors: the references the numerical methods are checked against, and the
// point-to-polygon term used for near patch pairs, where (15.20)'s centre-to-centre
// cos·cos·A/(π d²) is far off (it assumes d much larger than the patches).
// All functions are in double, return values in [0, 1], and take lengths in any unit.
#include <glm/glm.hpp>

#include <vector>

namespace wb::rad {

// atan2(y, x) for y >= 0 (an angle in [0, π]: the angle an edge subtends, from |a × b| and
// a · b), to within 2 ulp of std::atan2 (tested against it: closed_forms_test.cpp). Cephes'
// atan (S. Moshier, atan.c: range reduced to |t| <= 0.66, a rational P(t²)/Q(t²) of degree
// 4/5, documented relative error 2.2e-16 in IEEE double) without libm's rounding-mode save
// and restore: ~5 ns against ~75 ns for glibc 2.36's atan2 here, which was 19% of lab 08's
// default run (the near field's contour terms: docs/bench/radiosity.md, "Lab 08 defaults").
// NaN in, NaN out.
inline double edgeAngle(double y, double x) {
    constexpr double kP[5] = {-8.750608600031904122785e-1, -1.615753718733365076637e1,
                              -7.500855792314704667340e1, -1.228866684490136173410e2,
                              -6.485021904942025371773e1};
    constexpr double kQ[5] = {2.485846490142306297962e1, 1.650270098316988542046e2,
                              4.328810604912902668951e2, 4.853903996359136964868e2,
                              1.945506571482613964425e2};
    constexpr double kMoreBits = 6.123233995736765886130e-17; // π/2 − double(π/2)
    constexpr double kPi = 3.14159265358979323846, kHalfPi = 1.57079632679489661923;
    auto atanOfNonNegative = [&](double t) {
        double base = 0.0, more = 0.0;
        if (t > 2.41421356237309504880) { // tan(3π/8): atan t = π/2 − atan(1/t)
            base = kHalfPi;
            more = kMoreBits;
            t = -1.0 / t;
        } else if (t > 0.66) { // atan t = π/4 + atan((t − 1)/(t + 1))
            base = 0.5 * kHalfPi;
            more = 0.5 * kMoreBits;
            t = (t - 1.0) / (t + 1.0);
        }
        const double z = t * t;
        const double p = (((kP[0] * z + kP[1]) * z + kP[2]) * z + kP[3]) * z + kP[4];
        const double q = ((((z + kQ[0]) * z + kQ[1]) * z + kQ[2]) * z + kQ[3]) * z + kQ[4];
        return base + ((t * (z * p / q) + t) + more);
    };
    if (x > 0.0) return atanOfNonNegative(y / x);
    if (x < 0.0) return kPi - atanOfNonNegative(y / -x);
    if (x == 0.0) return y > 0.0 ? kHalfPi : y; // π/2, or y = 0 (NaN stays NaN)
    return x + y;                               // x is NaN
}

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
