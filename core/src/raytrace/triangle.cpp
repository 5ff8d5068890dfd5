#include "core/raytrace/triangle.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace wb::rt {

Triangle::Triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool closedMesh)
    : v0(a), v1(b), v2(c), closed_(closedMesh) {
    glm::dvec3 n = glm::cross(v1 - v0, v2 - v0);
    double len = glm::length(n);
    if (std::isinf(len) && std::isfinite(n.x + n.y + n.z)) {
        // |n|² overflowed (vertices beyond ~1e77 apart, issue 12 point 5): scale n by a
        // power of two first (exact), so the direction is kept. Inputs where len is
        // finite take the unscaled path and keep their bits.
        const double m = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
        n *= std::ldexp(1.0, -std::ilogb(m));
        len = glm::length(n);
    }
    normal_ = (len > 0 && std::isfinite(len)) ? n / len : glm::dvec3(0.0);
}

bool Triangle::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    if (normal_ == glm::dvec3(0.0)) return false; // zero-area triangle
    return intersectSheared(ray, triangleShear(ray.direction), tMin, tMax, hit);
}

bool Triangle::intersectSheared(const Ray& ray, const TriangleShear& shear, double tMin,
                                double tMax, Hit& hit) const {
    if (normal_ == glm::dvec3(0.0)) return false; // zero-area triangle
    const int kx = shear.kx, ky = shear.ky, kz = shear.kz;
    const double sx = shear.sx, sy = shear.sy, sz = shear.sz;

    // The same differences and products as with glm vectors (bit for bit), read through
    // plain arrays: glm's operator[] with a run-time index is a switch (issue 21).
    const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double a[3] = {v0.x - o[0], v0.y - o[1], v0.z - o[2]};
    const double b[3] = {v1.x - o[0], v1.y - o[1], v1.z - o[2]};
    const double c[3] = {v2.x - o[0], v2.y - o[1], v2.z - o[2]};
    const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
    const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
    const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
    double u = cx * by - cy * bx;
    double v = ax * cy - ay * cx;
    double w = bx * ay - by * ax;
    if (u == 0 || v == 0 || w == 0) { // on an edge in double: decide in long double
        using LD = long double;
        u = double(LD(cx) * LD(by) - LD(cy) * LD(bx));
        v = double(LD(ax) * LD(cy) - LD(ay) * LD(cx));
        w = double(LD(bx) * LD(ay) - LD(by) * LD(ax));
    }
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
    const double det = u + v + w;
    if (det == 0) return false; // ray in the triangle's plane, or degenerate projection
    const double az = sz * a[kz], bz = sz * b[kz], cz = sz * c[kz];
    double t = (u * az + v * bz + w * cz) / det;
    if (!std::isfinite(t)) {
        // u·az is a product of three coordinate differences: it overflows beyond ~1e100
        // (issue 12 point 5). The same formula with u, v, w, det scaled by one power of
        // two (exact) rounds exactly as the unscaled one would without the overflow;
        // dividing first instead lost enough accuracy to shadow the triangle by itself.
        // Taken only here, so every hit that was finite keeps its bits.
        const double m = std::max({std::abs(u), std::abs(v), std::abs(w)});
        const double k = std::ldexp(1.0, -std::ilogb(m));
        t = ((u * k) * az + (v * k) * bz + (w * k) * cz) / (det * k);
    }
    if (!(t > tMin && t <= tMax)) return false;
    const double b0 = u / det, b1 = v / det, b2 = w / det;
    hit.t = t;
    hit.point = b0 * v0 + b1 * v1 + b2 * v2; // on the triangle, error relative to the vertices
    hit.outwardNormal = normal_;
    hit.uv = {b1, b2};
    hit.hasUv = true;
    finishHit(ray, hit);
    return true;
}

Aabb Triangle::bounds() const {
    Aabb b;
    b.extend(v0);
    b.extend(v1);
    b.extend(v2);
    return b;
}

} // namespace wb::rt
