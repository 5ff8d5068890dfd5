#include "core/raytrace/plane.h"

#include <cmath>
#include <stdexcept>

namespace wb::rt {

Plane::Plane(const glm::dvec3& point, const glm::dvec3& nrm) {
    const double len = glm::length(nrm);
    if (!(len > 0) || !std::isfinite(len))
        throw std::invalid_argument("Plane: normal must be non-zero and finite");
    normal = nrm / len;
    d = glm::dot(normal, point);
    if (!std::isfinite(d)) throw std::invalid_argument("Plane: point must be finite");
}

void Plane::bindTexture(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
    // The dual basis of seed 000's rectangle: uv = ((p−p0)·ku, (p−p0)·kv).
    const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
    const double s11 = glm::dot(e1, e1), s12 = glm::dot(e1, e2), s22 = glm::dot(e2, e2);
    const double det = s11 * s22 - s12 * s12;
    if (!(det > 1e-24 * s11 * s22))
        throw std::invalid_argument("Plane::bindTexture: the three points are collinear");
    texOrigin_ = p0;
    ku_ = (e1 * s22 - e2 * s12) / det;
    kv_ = (e2 * s11 - e1 * s12) / det;
    textured_ = true;
}

bool Plane::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    const double vd = glm::dot(normal, ray.direction);
    if (vd == 0) return false; // parallel (a ray inside the plane is no hit, practical 11.2)
    const double t = (d - glm::dot(normal, ray.origin)) / vd;
    if (!(t > tMin && t <= tMax)) return false; // also rejects Inf/NaN of nearly parallel rays
    glm::dvec3 p = ray.at(t);
    p -= (glm::dot(normal, p) - d) * normal; // project back onto the plane
    hit.t = t;
    hit.point = p;
    hit.outwardNormal = normal;
    hit.hasUv = textured_;
    if (textured_) hit.uv = {glm::dot(p - texOrigin_, ku_), glm::dot(p - texOrigin_, kv_)};
    finishHit(ray, hit);
    return true;
}

} // namespace wb::rt
