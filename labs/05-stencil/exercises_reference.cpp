// Lab 05 - the reference answers and, behind WB_MUTANT(n), the typical mistakes CI checks
// the grading against (listed with their ids in exercise_checks.cpp).
#include "exercises.h"

#include <cmath>

namespace wb::lab05 {

glm::dmat4 reflectionMatrix(const glm::dvec4& plane) {
    const glm::dvec3 abc(plane);
    const double len = WB_MUTANT(2) ? 1.0 : glm::length(abc); // 2: normal not normalised
    const glm::dvec3 n = abc / len;
    const double d = (WB_MUTANT(3) ? -plane.w : plane.w) / len; // 3: sign of D
    const double k = WB_MUTANT(4) ? 1.0 : 2.0;                  // 4: onto the plane, not across
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            m[c][r] -= k * n[r] * n[c];
    for (int r = 0; r < 3; ++r)
        m[3][r] = -k * d * n[r];
    return WB_MUTANT(1) ? glm::transpose(m) : m; // 1: transposed (row-major)
}

glm::dmat4 shadowMatrix(const glm::dvec4& plane, const glm::dvec4& light) {
    const glm::dvec4 pi = WB_MUTANT(13) ? glm::dvec4(glm::dvec3(plane), 0) : plane; // 13: D dropped
    const double dot = glm::dot(pi, light);
    const double sign = dot < 0 ? -1.0 : 1.0; // π·L > 0 for OpenGL's clipping
    glm::dmat4 m(0.0);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            m[c][r] =
                sign * ((r == c && !WB_MUTANT(12) ? dot : 0.0) - light[r] * pi[c]); // 12: no (π·L)I
    return WB_MUTANT(11) ? glm::transpose(m) : m; // 11: transposed
}

std::vector<glm::dvec3> ellipseOutline(const glm::dvec2& centre, double a, double b, double z,
                                       int n) {
    constexpr double kPi = 3.14159265358979323846;
    std::vector<glm::dvec3> p;
    const double step = WB_MUTANT(23) ? 2 * kPi / (n - 1) : 2 * kPi / n; // 23: last = first
    const double ax = WB_MUTANT(21) ? b : a, by = WB_MUTANT(21) ? a : b; // 21: a and b swapped
    for (int k = 0; k < n; ++k) {
        double t = WB_MUTANT(22) ? -k * step : k * step; // 22: clockwise
        if (WB_MUTANT(24)) t = 360.0 * k / n;            // 24: degrees into sin/cos
        p.push_back({centre.x + ax * std::cos(t), centre.y + by * std::sin(t), z});
    }
    return p;
}

} // namespace wb::lab05

WB_EXERCISE_TABLE(wb::lab05::Table, lab05,
                  {&wb::lab05::reflectionMatrix, &wb::lab05::shadowMatrix,
                   &wb::lab05::ellipseOutline})
