// Lab 01's reference answers (not shipped in a handout). The same functions as
// exercises.cpp, written independently of core/affine (glm only), and the typical mistakes
// CI plants one at a time behind WB_MUTANT(n) (listed in exercise_checks.cpp).
#include "exercises.h"

#include <cmath>

namespace wb::lab01 {
namespace {

glm::dvec3 lineThroughPoints(glm::dvec2 k, glm::dvec2 l) {
    const double a = k.y - l.y, b = l.x - k.x;
    return {a, b, -(a * k.x + b * k.y)};
}

} // namespace

glm::dmat3 mirrorMatrix(glm::dvec2 k, glm::dvec2 l) {
    const glm::dvec3 pi = lineThroughPoints(k, l);
    const glm::dvec3 n(pi.x, pi.y, 0.0);
    double nn = pi.x * pi.x + pi.y * pi.y;
    if (WB_MUTANT(4)) nn = std::sqrt(nn);        // divided by |n|, not (n, n): n not normalised
    const double two = WB_MUTANT(2) ? 1.0 : 2.0; // projection onto Λ instead of the mirror
    // P' = P - 2 n (pi·P)/(n·n): M = I - 2 n piᵀ/(n·n).
    glm::dmat3 m = glm::dmat3(1.0) - (two / nn) * glm::outerProduct(n, pi);
    if (WB_MUTANT(3)) m[2][0] = -m[2][0], m[2][1] = -m[2][1]; // translation's sign
    if (WB_MUTANT(1)) m = glm::transpose(m);
    return m;
}

glm::dmat3 shadowDirectionalMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 dir) {
    const glm::dvec3 pi = lineThroughPoints(k, l);
    const glm::dvec3 d(dir, WB_MUTANT(13) ? 1.0 : 0.0); // direction taken as a point
    const double nl = pi.x * d.x + pi.y * d.y;
    if (WB_MUTANT(14)) return glm::dmat3(1.0) - glm::outerProduct(d, pi) / nl; // divides by n·l
    glm::dmat3 m = nl * glm::dmat3(1.0) - glm::outerProduct(d, pi);
    if (WB_MUTANT(12)) m = nl * glm::dmat3(1.0) + glm::outerProduct(d, pi); // sign
    if (WB_MUTANT(11)) m = glm::transpose(m);
    return m;
}

glm::dmat3 shadowPointMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 s) {
    const glm::dvec3 pi = lineThroughPoints(k, l);
    const glm::dvec3 sh(s, WB_MUTANT(23) ? 0.0 : 1.0); // S taken as a direction (w = 0)
    const double ps = glm::dot(pi, sh);
    glm::dmat3 m = ps * glm::dmat3(1.0) - glm::outerProduct(sh, pi);
    if (WB_MUTANT(22)) m = ps * glm::dmat3(1.0) + glm::outerProduct(sh, pi); // sign
    if (WB_MUTANT(24)) m = m / ps; // normalised by pi·S: NaN when S is on Λ
    if (WB_MUTANT(21)) m = glm::transpose(m);
    return m;
}

} // namespace wb::lab01

WB_EXERCISE_TABLE(wb::lab01::Table, lab01,
                  {&wb::lab01::mirrorMatrix, &wb::lab01::shadowDirectionalMatrix,
                   &wb::lab01::shadowPointMatrix})
