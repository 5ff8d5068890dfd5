// Student code that passes every check of lab 01 but misbehaves on anything else, such as
// the line the window draws (issue 18 item 3; the window's side of crash_exercises.cpp):
// mirrorMatrix crashes, shadowDirectionalMatrix loops for ever, shadowPointMatrix is right.
// It recognises the checks' inputs by regenerating them as labs/01-affine/exercise_checks.cpp
// does (lineCases: the same seeds, engine and expressions, so the same compiler gives the
// same numbers), plus the hard cases there.
#include "exercises.h"

#include <csignal>
#include <random>
#include <vector>

namespace wb::lab01 {
namespace {

bool aCheckInput(glm::dvec2 k0) {
    static const std::vector<glm::dvec2> known = [] {
        std::vector<glm::dvec2> ks = {{2, -3}, {-4, 1},  {-2, -1}, {1e4, 1e4},
                                      {1, 2},  {-3, -2}, {-3, 0},  {0, 0}};
        for (unsigned seed : {101u, 202u, 303u}) {
            std::mt19937 gen(seed);
            std::uniform_real_distribution<double> u(-9.0, 9.0);
            for (int i = 0; i < 24; ++i) {
                glm::dvec2 k(u(gen), u(gen)), l(u(gen), u(gen)), t(u(gen), u(gen));
                (void)l, (void)t;
                ks.push_back(k);
            }
        }
        return ks;
    }();
    for (const glm::dvec2& k : known)
        if (k == k0) return true;
    return false;
}

glm::dvec3 lineThroughPoints(glm::dvec2 k, glm::dvec2 l) {
    const double a = k.y - l.y, b = l.x - k.x;
    return {a, b, -(a * k.x + b * k.y)};
}

} // namespace

glm::dmat3 mirrorMatrix(glm::dvec2 k, glm::dvec2 l) {
    if (!aCheckInput(k)) std::raise(SIGSEGV); // as an index out of range would
    const glm::dvec3 pi = lineThroughPoints(k, l);
    const glm::dvec3 n(pi.x, pi.y, 0.0);
    return glm::dmat3(1.0) - (2.0 / (pi.x * pi.x + pi.y * pi.y)) * glm::outerProduct(n, pi);
}

glm::dmat3 shadowDirectionalMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 dir) {
    volatile bool endless = !aCheckInput(k);
    while (endless) { // a loop whose condition never changes
    }
    const glm::dvec3 pi = lineThroughPoints(k, l);
    const glm::dvec3 d(dir, 0.0);
    return (pi.x * d.x + pi.y * d.y) * glm::dmat3(1.0) - glm::outerProduct(d, pi);
}

glm::dmat3 shadowPointMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 s) {
    const glm::dvec3 pi = lineThroughPoints(k, l);
    const glm::dvec3 sh(s, 1.0);
    return glm::dot(pi, sh) * glm::dmat3(1.0) - glm::outerProduct(sh, pi);
}

} // namespace wb::lab01

WB_EXERCISE_TABLE(wb::lab01::Table, lab01,
                  {&wb::lab01::mirrorMatrix, &wb::lab01::shadowDirectionalMatrix,
                   &wb::lab01::shadowPointMatrix})
