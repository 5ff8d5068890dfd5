#include "core/raytrace/triangle.h"

#include <glm/gtc/type_ptr.hpp>

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
    degenerate_ = !(len > 0 && std::isfinite(len));
    normal_ = degenerate_ ? glm::dvec3(0.0) : n / len;
}

bool Triangle::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    if (degenerate_) return false; // zero-area triangle
    return intersectSheared(ray, triangleShear(ray.direction), tMin, tMax, hit);
}

namespace {
// An edge function recomputed in long double (the rare exact 0 in double). Out of line and
// with its operands by value: inline, GCC loaded the operands onto the x87 stack on every
// test, not only on the rare path (issue 21, ninth session; taken by reference, as the
// eighth session tried, they lived in memory instead).
__attribute__((noinline, cold)) double edgeLong(double p, double q, double r, double s) {
    using LD = long double;
    return double(LD(p) * LD(q) - LD(r) * LD(s));
}

// t when (u·az + v·bz + w·cz) / det overflowed: u·az is a product of three coordinate
// differences, which overflows beyond ~1e100 (issue 12 point 5). The same formula with u, v,
// w, det scaled by one power of two (exact) rounds exactly as the unscaled one would without
// the overflow; dividing first instead lost enough accuracy to shadow the triangle by itself.
// Out of line: taken only after an overflow, so every hit that was finite keeps its bits.
__attribute__((noinline, cold)) double scaledT(double u, double v, double w, double det, double az,
                                               double bz, double cz) {
    const double m = std::max({std::abs(u), std::abs(v), std::abs(w)});
    const double k = std::ldexp(1.0, -std::ilogb(m));
    return ((u * k) * az + (v * k) * bz + (w * k) * cz) / (det * k);
}
} // namespace

bool Triangle::intersectSheared(const Ray& ray, const TriangleShear& shear, double tMin,
                                double tMax, Hit& hit) const {
    if (degenerate_) return false; // zero-area triangle
    const int kx = shear.kx, ky = shear.ky, kz = shear.kz;
    const double sx = shear.sx, sy = shear.sy, sz = shear.sz;

    // The same differences and products as with glm vectors (bit for bit): each vertex
    // coordinate minus the origin's, read at the shear's axes straight from the vertices and
    // the ray (glm's operator[] with a run-time index is a switch; copies into local arrays,
    // as before the ninth session, went through the stack: ~30 instructions a test).
    const double* o = glm::value_ptr(ray.origin);
    const double* p0 = glm::value_ptr(v0);
    const double* p1 = glm::value_ptr(v1);
    const double* p2 = glm::value_ptr(v2);
    const double oz = o[kz];
    const double a_z = p0[kz] - oz, b_z = p1[kz] - oz, c_z = p2[kz] - oz;
    const double ax = (p0[kx] - o[kx]) - sx * a_z, ay = (p0[ky] - o[ky]) - sy * a_z;
    const double bx = (p1[kx] - o[kx]) - sx * b_z, by = (p1[ky] - o[ky]) - sy * b_z;
    const double cx = (p2[kx] - o[kx]) - sx * c_z, cy = (p2[ky] - o[ky]) - sy * c_z;
    double u = cx * by - cy * bx;
    double v = ax * cy - ay * cx;
    double w = bx * ay - by * ax;
    if (u == 0 || v == 0 || w == 0) { // on an edge in double: decide in long double
        u = edgeLong(cx, by, cy, bx);
        v = edgeLong(ax, cy, ay, cx);
        w = edgeLong(bx, ay, by, ax);
    }
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
    const double det = u + v + w;
    if (det == 0) return false; // ray in the triangle's plane, or degenerate projection
    const double az = sz * a_z, bz = sz * b_z, cz = sz * c_z;
    double t = (u * az + v * bz + w * cz) / det;
    if (!std::isfinite(t)) t = scaledT(u, v, w, det, az, bz, cz);
    if (!(t > tMin && t <= tMax)) return false;
    const double b0 = u / det, b1 = v / det, b2 = w / det;
    hit.t = t;
    hit.point = b0 * v0 + b1 * v1 + b2 * v2; // on the triangle, error relative to the vertices
    hit.outwardNormal = normal_;
    hit.uv = {b1, b2};
    hit.hasUv = true;
    finishHit(ray, hit, closed_); // solid() is closed_ (final)
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
