#pragma once
// Real roots of a·t² + 2·h·t + c = 0 (h = half the usual b) without cancellation:
// q = −(h + sign(h)·√disc), t0 = q/a, t1 = c/q (practical 4, formula 4.11; DESIGN.md).
// The caller may pass a discriminant computed more accurately than h² − a·c
// (the sphere's distance-to-line form).

namespace wb::rt {

struct QuadraticRoots {
    int count = 0;   // 0, 1 (linear or double root) or 2
    double t0 = 0.0; // smaller root
    double t1 = 0.0; // larger root (== t0 when count == 1)
};

// disc = h² − a·c (or an equivalent, better-conditioned value).
QuadraticRoots solveQuadratic(double a, double h, double c, double disc);
// Same with disc computed as h² − a·c.
QuadraticRoots solveQuadratic(double a, double h, double c);

} // namespace wb::rt
