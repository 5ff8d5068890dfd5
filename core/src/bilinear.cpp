#include "core/bilinear.h"

#include <cmath>
#include <limits>

namespace wb {
namespace {

double cross2(const glm::dvec2& u, const glm::dvec2& v) {
    return u.x * v.y - u.y * v.x;
}

template <typename Vec> bool finite(const Vec& v) {
    for (int i = 0; i < Vec::length(); ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

// α from β: P is a weighted sum of s1(β) = (1−β)A + βD and s2(β) = (1−β)B + βC.
template <typename Vec>
std::optional<glm::dvec2> finish(const Vec& p, const Vec& a, const Vec& b, const Vec& c,
                                 const Vec& d, std::optional<double> beta) {
    if (!beta) return std::nullopt;
    const double bt = *beta;
    const Vec s1 = (1.0 - bt) * a + bt * d;
    const Vec s2 = (1.0 - bt) * b + bt * c;
    const Vec e = s2 - s1;
    const double ee = glm::dot(e, e);
    const double alpha = ee > 0.0 ? glm::dot(p - s1, e) / ee : 0.5;
    if (!std::isfinite(alpha)) return std::nullopt;
    return glm::dvec2(alpha, bt);
}

} // namespace

glm::dvec2 bilinear(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                    const glm::dvec2& d, double alpha, double beta) {
    return (1 - alpha) * (1 - beta) * a + alpha * (1 - beta) * b + alpha * beta * c +
           (1 - alpha) * beta * d;
}

glm::dvec3 bilinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                    const glm::dvec3& d, double alpha, double beta) {
    return (1 - alpha) * (1 - beta) * a + alpha * (1 - beta) * b + alpha * beta * c +
           (1 - alpha) * beta * d;
}

double bilinear(double fa, double fb, double fc, double fd, double alpha, double beta) {
    return (1 - alpha) * (1 - beta) * fa + alpha * (1 - beta) * fb + alpha * beta * fc +
           (1 - alpha) * beta * fd;
}

std::optional<double> bilinearBeta(double aq, double bq, double cq) {
    if (!std::isfinite(aq) || !std::isfinite(bq) || !std::isfinite(cq)) return std::nullopt;
    double disc = bq * bq - 4.0 * aq * cq;
    if (disc < 0.0) {
        // Each of the two terms carries a few roundings; more than that is a real miss.
        const double slack =
            8.0 * std::numeric_limits<double>::epsilon() * (bq * bq + 4.0 * std::abs(aq * cq));
        if (-disc > slack) return std::nullopt;
        disc = 0.0;
    }
    const double root = std::sqrt(disc);
    double beta;
    if (bq > 0.0) {
        // (4.10) has no cancellation here (−Bq and −√disc have the same sign).
        // With Aq = 0 the course's root is at infinity: take the linear equation's root.
        beta = aq != 0.0 ? (-bq - root) / (2.0 * aq) : -cq / bq;
    } else if (bq < 0.0 || root > 0.0) {
        beta = 2.0 * cq / (-bq + root); // (4.11): −Bq ≥ 0 and √disc ≥ 0 add, no cancellation
    } else {
        // Bq = 0 and disc = 0, so Aq·Cq = 0: a double root at 0 if Aq ≠ 0, else no equation.
        if (aq == 0.0) return std::nullopt;
        beta = 0.0;
    }
    if (!std::isfinite(beta)) return std::nullopt;
    return beta;
}

std::optional<glm::dvec2> invertBilinear(const glm::dvec2& p, const glm::dvec2& a,
                                         const glm::dvec2& b, const glm::dvec2& c,
                                         const glm::dvec2& d) {
    if (!finite(p) || !finite(a) || !finite(b) || !finite(c) || !finite(d)) return std::nullopt;
    // Course names: x = A, y = B, z = C, w = D, u = p.
    const double k = cross2(c - a, d - b);
    const double sign = k < 0.0 ? -1.0 : 1.0;
    const double aq = sign * cross2(d - a, c - b);
    const double bq = sign * (cross2(c - b, p - a) - cross2(d - a, p - b));
    const double cq = sign * cross2(p - a, p - b);
    return finish(p, a, b, c, d, bilinearBeta(aq, bq, cq));
}

std::optional<glm::dvec2> invertBilinear(const glm::dvec3& p, const glm::dvec3& a,
                                         const glm::dvec3& b, const glm::dvec3& c,
                                         const glm::dvec3& d) {
    if (!finite(p) || !finite(a) || !finite(b) || !finite(c) || !finite(d)) return std::nullopt;
    const glm::dvec3 n = glm::cross(c - a, d - b);
    const double aq = glm::dot(n, glm::cross(d - a, c - b));
    const double bq = glm::dot(n, glm::cross(c - b, p - a) - glm::cross(d - a, p - b));
    const double cq = glm::dot(n, glm::cross(p - a, p - b));
    return finish(p, a, b, c, d, bilinearBeta(aq, bq, cq));
}

} // namespace wb
