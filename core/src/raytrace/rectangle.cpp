#include "core/raytrace/rectangle.h"

#include <cmath>
#include <stdexcept>

namespace wb::rt {

Rectangle::Rectangle(const glm::dvec3& q1, const glm::dvec3& q2, const glm::dvec3& q3) {
    loc = q1;
    e1 = q2 - loc;
    e2 = q3 - loc;
    const glm::dvec3 n = glm::cross(e1, e2);
    const double len = glm::length(n);
    const double s11 = glm::dot(e1, e1), s12 = glm::dot(e1, e2), s22 = glm::dot(e2, e2);
    const double det = s11 * s22 - s12 * s12;
    if (!(len > 0) || !std::isfinite(len) || !(det > 0))
        throw std::invalid_argument("Rectangle: Q1, Q2, Q3 must be finite and not collinear");
    normal = n / len;
    ku = (e1 * s22 - e2 * s12) / det;
    kv = (e2 * s11 - e1 * s12) / det;
    u0 = glm::dot(loc, ku);
    v0 = glm::dot(loc, kv);
}

glm::dvec2 Rectangle::uvOf(const glm::dvec3& p) const {
    return {glm::dot(p - loc, ku), glm::dot(p - loc, kv)};
}

bool Rectangle::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    const double vd = glm::dot(normal, ray.direction);
    if (vd == 0) return false; // seed 000 rejects |VD| <= 0.01; only exact parallels here
    const double t = glm::dot(loc - ray.origin, normal) / vd;
    if (!(t > tMin && t <= tMax)) return false;
    glm::dvec3 p = ray.at(t);
    p -= glm::dot(p - loc, normal) * normal; // project back onto the plane
    const glm::dvec2 uv = uvOf(p);
    // Points on the border count as inside. A relative slack of 8 ULPs of 1 covers the
    // rounding of P and of the dot products, so the exact border points of seed 000
    // (e.g. u = 1 at (20,0,40)) are inside even when P comes out a few ULPs off.
    constexpr double kSlack = 8 * 2.220446049250313e-16;
    if (!(uv.x >= -kSlack && uv.y >= -kSlack && uv.x <= 1 + kSlack && uv.y <= 1 + kSlack))
        return false;
    hit.t = t;
    hit.point = p;
    hit.outwardNormal = normal;
    hit.uv = uv;
    hit.hasUv = true;
    finishHit(ray, hit);
    return true;
}

Aabb Rectangle::bounds() const {
    Aabb b;
    b.extend(loc);
    b.extend(loc + e1);
    b.extend(loc + e2);
    b.extend(loc + e1 + e2);
    return b;
}

} // namespace wb::rt
