#include "core/radiosity/closed_forms.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace wb::rad {

double pointToPolygon(const glm::dvec3& point, const glm::dvec3& normal,
                      const std::vector<glm::dvec3>& polygon) {
    // 1. Clip away the part behind the point's tangent plane (Sutherland–Hodgman, one plane):
    //    it cannot receive light from the front side and would be counted with the wrong sign.
    //    Clipping one plane adds at most one vertex per edge crossing (two in all for a convex
    //    polygon, m in the worst case): the clipped polygon lives on the stack up to
    //    kOnStack vertices (the near field calls this ~10⁷ times per solve at lab 08's
    //    defaults, and a heap vector per call cost ~5% of it: docs/bench/radiosity.md).
    constexpr std::size_t kOnStack = 32;
    const std::size_t m = polygon.size();
    glm::dvec3 stackPoly[kOnStack];
    std::vector<glm::dvec3> heapPoly;
    glm::dvec3* poly = stackPoly;
    if (2 * m > kOnStack) {
        heapPoly.resize(2 * m);
        poly = heapPoly.data();
    }
    std::size_t count = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const glm::dvec3 a = polygon[k] - point;
        const glm::dvec3 b = polygon[(k + 1) % m] - point;
        const double da = glm::dot(a, normal);
        const double db = glm::dot(b, normal);
        if (da > 0.0) poly[count++] = a;
        if ((da > 0.0) != (db > 0.0) && da != db) {
            const double t = da / (da - db);
            poly[count++] = a + t * (b - a);
        }
    }
    if (count < 3) return 0.0;
    // 2. Lambert's contour integral: each edge contributes the angle it subtends times the
    //    cosine between the normal and the normal of the plane through the edge and the point.
    double sum = 0.0;
    const std::size_t q = count;
    for (std::size_t k = 0; k < q; ++k) {
        const glm::dvec3& a = poly[k];
        const glm::dvec3& b = poly[(k + 1) % q];
        const glm::dvec3 c = glm::cross(a, b);
        const double cl = glm::length(c);
        if (!(cl > 0.0)) continue; // edge through the point's line of sight: no contribution
        // atan2, accurate for small angles too (edgeAngle: within 2 ulp of std::atan2, 15× faster)
        const double gamma = edgeAngle(cl, glm::dot(a, b));
        sum += gamma * glm::dot(normal, c) / cl;
    }
    const double f = std::abs(sum) / (2.0 * glm::pi<double>());
    if (!std::isfinite(f)) return 0.0;
    return std::min(f, 1.0);
}

double parallelRectangles(double a, double b, double c) {
    const double X = a / c, Y = b / c;
    const double x2 = X * X, y2 = Y * Y;
    const double sx = std::sqrt(1 + x2), sy = std::sqrt(1 + y2);
    const double t = 0.5 * std::log((1 + x2) * (1 + y2) / (1 + x2 + y2)) +
                     X * sy * std::atan(X / sy) + Y * sx * std::atan(Y / sx) - X * std::atan(X) -
                     Y * std::atan(Y);
    return 2.0 * t / (glm::pi<double>() * X * Y);
}

double perpendicularRectangles(double l, double w1, double w2) {
    const double W = w1 / l, H = w2 / l;
    const double w2_ = W * W, h2 = H * H, s = w2_ + h2;
    const double rs = std::sqrt(s);
    // ln of the product of the three factors, taken term by term to avoid pow overflow.
    const double lnTerm = std::log((1 + w2_) * (1 + h2) / (1 + s)) +
                          w2_ * std::log(w2_ * (1 + s) / ((1 + w2_) * s)) +
                          h2 * std::log(h2 * (1 + s) / ((1 + h2) * s));
    const double t = W * std::atan(1 / W) + H * std::atan(1 / H) - rs * std::atan(1 / rs) +
                     0.25 * lnTerm;
    return t / (glm::pi<double>() * W);
}

double pointToCoaxialDisc(double h, double r) { return r * r / (h * h + r * r); }

} // namespace wb::rad
