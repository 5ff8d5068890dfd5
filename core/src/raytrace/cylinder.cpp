#include "core/raytrace/cylinder.h"

#include "core/raytrace/quadratic.h"

#include <cmath>
#include <stdexcept>

namespace wb::rt {

Cone::Cone(const glm::dvec3& a, double ra, const glm::dvec3& b, double rb)
    : c0(a), c1(b), r0(ra), r1(rb) {
    const glm::dvec3 ax = c1 - c0;
    h_ = glm::length(ax);
    if (!(h_ > 0) || !std::isfinite(h_) || !(r0 >= 0) || !(r1 >= 0) || !std::isfinite(r0) ||
        !std::isfinite(r1) || (r0 == 0 && r1 == 0))
        throw std::invalid_argument("Cone: need c0 != c1, radii finite, >= 0 and not both 0");
    axis_ = ax / h_;
    // Any unit vector perpendicular to the axis: cross with the least aligned world axis.
    const glm::dvec3 aa = glm::abs(axis_);
    const glm::dvec3 other = (aa.x <= aa.y && aa.x <= aa.z) ? glm::dvec3(1, 0, 0)
                             : (aa.y <= aa.z)               ? glm::dvec3(0, 1, 0)
                                                            : glm::dvec3(0, 0, 1);
    ex_ = glm::normalize(glm::cross(axis_, other));
    ey_ = glm::cross(axis_, ex_);
    k_ = (r1 - r0) / h_;
}

bool Cone::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    const glm::dvec3 o = ray.origin - c0;
    const double ox = glm::dot(o, ex_), oy = glm::dot(o, ey_), oz = glm::dot(o, axis_);
    const double dx = glm::dot(ray.direction, ex_), dy = glm::dot(ray.direction, ey_),
                 dz = glm::dot(ray.direction, axis_);
    double bestT = tMax;
    bool found = false;
    glm::dvec3 bestN{0.0};
    glm::dvec2 bestUv{0.0};
    constexpr double kTwoPi = 6.283185307179586;

    // Lateral surface x² + y² = (r0 + k z)².
    QuadraticRoots roots;
    if (k_ == 0) {
        // Cylinder: the 2D analogue of the sphere's distance-to-line discriminant.
        const double a = dx * dx + dy * dy;
        if (a > 0) {
            const double hh = ox * dx + oy * dy;
            const double lx = ox - hh / a * dx, ly = oy - hh / a * dy;
            const double l = std::hypot(lx, ly);
            const double ol = std::hypot(ox, oy);
            roots = solveQuadratic(a, hh, (ol - r0) * (ol + r0), a * (r0 - l) * (r0 + l));
        }
    } else {
        const double rz = r0 + k_ * oz;
        const double a = dx * dx + dy * dy - k_ * k_ * dz * dz;
        const double hh = ox * dx + oy * dy - k_ * rz * dz;
        const double c = ox * ox + oy * oy - rz * rz;
        roots = solveQuadratic(a, hh, c);
    }
    for (int i = 0; i < roots.count; ++i) {
        const double t = i == 0 ? roots.t0 : roots.t1;
        if (!(t > tMin && t <= bestT)) continue;
        const double z = oz + t * dz;
        if (!(z >= 0 && z <= h_)) continue;
        const double x = ox + t * dx, y = oy + t * dy;
        glm::dvec3 nl = x * ex_ + y * ey_ - k_ * (r0 + k_ * z) * axis_;
        const double len = glm::length(nl);
        if (!(len > 0)) continue; // the apex: the cap test below decides
        bestT = t;
        bestN = nl / len;
        bestUv = {std::atan2(y, x) / kTwoPi + 0.5, z / h_}; // around the axis, up the side
        found = true;
    }
    // Caps z = 0 (outward −axis) and z = h (outward +axis).
    if (dz != 0) {
        const double capZ[2] = {0.0, h_};
        const double capR[2] = {r0, r1};
        for (int i = 0; i < 2; ++i) {
            if (capR[i] == 0) continue;
            const double t = (capZ[i] - oz) / dz;
            if (!(t > tMin && t <= bestT)) continue;
            const double x = ox + t * dx, y = oy + t * dy;
            if (x * x + y * y > capR[i] * capR[i]) continue;
            bestT = t;
            bestN = i == 0 ? -axis_ : axis_;
            bestUv = {0.5 + 0.5 * x / capR[i], 0.5 + 0.5 * y / capR[i]}; // across the disc
            found = true;
        }
    }
    if (!found) return false;
    hit.t = bestT;
    hit.point = ray.at(bestT);
    hit.outwardNormal = bestN;
    hit.uv = bestUv;
    hit.hasUv = true;
    finishHit(ray, hit);
    return true;
}

Aabb Cone::bounds() const {
    Aabb b;
    for (int c = 0; c < 2; ++c) {
        const glm::dvec3 p = c == 0 ? c0 : c1;
        const double r = c == 0 ? r0 : r1;
        // A disc of radius r perpendicular to the axis extends r·sqrt(1 − a_i²) along axis i.
        const glm::dvec3 e = r * glm::sqrt(glm::max(glm::dvec3(0.0), 1.0 - axis_ * axis_));
        b.extend(p - e);
        b.extend(p + e);
    }
    return b;
}

} // namespace wb::rt
