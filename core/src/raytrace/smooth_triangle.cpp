#include "core/raytrace/smooth_triangle.h"

#include <cmath>

namespace wb::rt {

namespace {
glm::dvec3 unitOr(const glm::dvec3& n, const glm::dvec3& fallback) {
    const double l = glm::length(n);
    return (l > 0 && std::isfinite(l)) ? n / l : fallback;
}
} // namespace

SmoothTriangle::SmoothTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                               const glm::dvec3& na, const glm::dvec3& nb, const glm::dvec3& nc,
                               bool closedMesh)
    : Triangle(a, b, c, closedMesh) {
    const glm::dvec3 g = unitOr(glm::cross(b - a, c - a), glm::dvec3(0, 0, 1));
    n0 = unitOr(na, g);
    n1 = unitOr(nb, g);
    n2 = unitOr(nc, g);
}

bool SmoothTriangle::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    Hit h;
    if (!Triangle::intersect(ray, tMin, tMax, h)) return false;
    const double b1 = h.uv.x, b2 = h.uv.y, b0 = 1 - b1 - b2;
    glm::dvec3 n = b0 * n0 + b1 * n1 + b2 * n2;
    const double l = glm::length(n);
    n = l > 0 ? n / l : h.outwardNormal; // opposite vertex normals can cancel
    if (glm::dot(n, h.outwardNormal) < 0) n = -n;
    h.outwardNormal = n;
    finishHit(ray, h);
    hit = h;
    return true;
}

} // namespace wb::rt
