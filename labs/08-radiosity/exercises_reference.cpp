// Lab 08 - the reference answers and, behind WB_MUTANT(n), the typical mistakes CI checks
// the grading against (listed with their ids in exercise_checks.cpp).
#include "exercises.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace wb::lab08 {
namespace {
constexpr double kPi = 3.14159265358979323846;
glm::dvec3 centre(const Quad& q) {
    return 0.25 * (q.p[0] + q.p[1] + q.p[2] + q.p[3]);
}
glm::dvec3 areaVector(const Quad& q) { // n·A
    return 0.5 * glm::cross(q.p[2] - q.p[0], q.p[3] - q.p[1]);
}

// (15.20); `mistakes` lets the mutants of ③ in without touching ⑤, which uses it too.
double formula1520(const Quad& i, const Quad& j, bool mistakes) {
    const glm::dvec3 ci = centre(i), cj = centre(j);
    const glm::dvec3 ai = areaVector(i), aj = areaVector(j);
    const double areaI = glm::length(ai), areaJ = glm::length(aj);
    const glm::dvec3 v = cj - ci;
    const double d = glm::length(v);
    if (!(d > 0) || !(areaI > 0) || !(areaJ > 0)) return 0;
    const double cosI = glm::dot(ai / areaI, v) / d, cosJ = -glm::dot(aj / areaJ, v) / d;
    if ((cosI <= 0 || cosJ <= 0) && !(mistakes && WB_MUTANT(3)))
        return 0;                                              // 3: back sides not tested
    const double a = mistakes && WB_MUTANT(2) ? areaI : areaJ; // 2: A_i for A_j
    const double dd = mistakes && WB_MUTANT(4) ? d : d * d;    // 4: d for d²
    const double pi = mistakes && WB_MUTANT(1) ? 1.0 : kPi;    // 1: π forgotten
    return cosI * cosJ * a / (pi * dd);
}

} // namespace

double formFactor(const Quad& i, const Quad& j) {
    return formula1520(i, j, true);
}

std::vector<double> jacobiSweep(const std::vector<double>& B, const std::vector<double>& E,
                                const std::vector<double>& R, const std::vector<double>& F) {
    const size_t n = B.size();
    std::vector<double> out(n);
    std::vector<double> work = B; // 12: Gauss-Seidel updates this in place
    for (size_t i = 0; i < n; ++i) {
        double in = 0;
        for (size_t j = 0; j < n; ++j)
            in += (WB_MUTANT(11) ? F[j * n + i] : F[i * n + j]) * work[j]; // 11: F transposed
        const double r = WB_MUTANT(14) ? 1.0 : R[i];                       // 14: R forgotten
        out[i] = (WB_MUTANT(13) ? 0.0 : E[i]) + r * in;                    // 13: E forgotten
        if (WB_MUTANT(12)) work[i] = out[i];
    }
    return out;
}

double formFactorRays(const Quad& i, const Quad& j, int k, unsigned seed, const Visible& visible) {
    const double g = formula1520(i, j, false);
    if (!(g > 0) || k < 1) return 0;
    const int m = std::max(1, int(std::lround(std::sqrt(double(k)))));
    auto points = [m](const Quad& q) {
        std::vector<glm::dvec3> pts;
        for (int b = 0; b < m; ++b)
            for (int a = 0; a < m; ++a) {
                const double s = (a + 0.5) / m, t = (b + 0.5) / m;
                pts.push_back((1 - s) * (1 - t) * q.p[0] + s * (1 - t) * q.p[1] + s * t * q.p[2] +
                              (1 - s) * t * q.p[3]);
            }
        return pts;
    };
    std::vector<glm::dvec3> pi = points(i), pj = points(j);
    if (WB_MUTANT(24)) // 24: every ray between the centres (no spread of points)
        pi.assign(pi.size(), centre(i)), pj.assign(pj.size(), centre(j));
    std::vector<size_t> perm(pj.size());
    std::iota(perm.begin(), perm.end(), size_t(0));
    std::mt19937 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    int seen = 0;
    for (size_t s = 0; s < pi.size(); ++s)
        if (WB_MUTANT(21) || visible(pi[s], pj[perm[s]]) != WB_MUTANT(22))
            ++seen; // 21: ignored, 22: inverted
    const double v = double(seen) / double(WB_MUTANT(23) ? pi.size() + 1 : pi.size()); // 23: k + 1
    return v * g;
}

} // namespace wb::lab08

WB_EXERCISE_TABLE(wb::lab08::Table, lab08,
                  {&wb::lab08::formFactor, &wb::lab08::jacobiSweep, &wb::lab08::formFactorRays})
