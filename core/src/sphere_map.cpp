#include "core/sphere_map.h"

#include <cmath>

namespace wb {

glm::dvec2 sphereMapCoord(const glm::dvec3& eyePos, const glm::dvec3& eyeNormal) {
    const double pl = glm::length(eyePos), nl = glm::length(eyeNormal);
    if (!(pl > 0.0) || !(nl > 0.0) || !std::isfinite(pl) || !std::isfinite(nl)) return {0.5, 0.5};
    const glm::dvec3 u = eyePos / pl, n = eyeNormal / nl;
    const glm::dvec3 f = u - 2.0 * n * glm::dot(n, u);
    const double m = 2.0 * std::sqrt(f.x * f.x + f.y * f.y + (f.z + 1.0) * (f.z + 1.0));
    if (!(m > 0.0)) return {1.0, 0.5};
    return {f.x / m + 0.5, f.y / m + 0.5};
}

bool sphereMapDirection(double s, double t, glm::dvec3& f) {
    // (x, y) is the point of the unit disc; the mirror sphere's normal there faces the
    // viewer, N = (x, y, √(1-x²-y²)); reflecting the view ray (0, 0, -1) about N gives f.
    const double x = 2.0 * s - 1.0, y = 2.0 * t - 1.0, r2 = x * x + y * y;
    if (!(r2 <= 1.0)) return false;
    const double nz = std::sqrt(1.0 - r2);
    f = glm::dvec3(2.0 * nz * x, 2.0 * nz * y, 2.0 * nz * nz - 1.0);
    return true;
}

} // namespace wb
