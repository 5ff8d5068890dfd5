#include "core/raytrace/primitive.h"

#include "core/raytrace/quadratic.h"

#include <cmath>

namespace wb::rt {

QuadraticRoots solveQuadratic(double a, double h, double c, double disc) {
    QuadraticRoots r;
    if (!(disc >= 0) || !std::isfinite(a) || !std::isfinite(h) || !std::isfinite(c)) return r;
    if (a == 0) { // linear: 2h·t + c = 0
        if (h == 0) return r;
        r.count = 1;
        r.t0 = r.t1 = -c / (2 * h);
        return r;
    }
    const double q = -(h + std::copysign(std::sqrt(disc), h));
    if (q == 0) { // h == 0 and disc == 0, so c == 0: double root at 0
        r.count = 1;
        r.t0 = r.t1 = 0;
        return r;
    }
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    r.count = (disc == 0) ? 1 : 2;
    r.t0 = t0;
    r.t1 = t1;
    return r;
}

QuadraticRoots solveQuadratic(double a, double h, double c) {
    return solveQuadratic(a, h, c, h * h - a * c);
}

} // namespace wb::rt
