#include "core/raytrace/quadric.h"

#include "core/raytrace/quadratic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wb::rt {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Quadric::Quadric(Kind k, const glm::dvec3& c, const glm::dvec3& ax, double lo, double hi)
    : kind(k), centre(c), axes(ax), zLow(lo), zHigh(hi) {
    for (int i = 0; i < 3; ++i)
        if (!(axes[i] > 0) || !std::isfinite(axes[i]) || !std::isfinite(centre[i]))
            throw std::invalid_argument("Quadric: axes must be finite and > 0, centre finite");
    if (!(zLow < zHigh)) throw std::invalid_argument("Quadric: need zLow < zHigh");
}

bool Quadric::solid() const {
    return kind == Kind::Ellipsoid && zLow <= centre.z - axes.z && zHigh >= centre.z + axes.z;
}

bool Quadric::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    const glm::dvec3 o = ray.origin - centre;
    const glm::dvec3& d = ray.direction;
    QuadraticRoots roots;
    // F(x) = a x² + b y² + cz z² + e z + f, gradient (2a x, 2b y, 2cz z + e).
    const double a = 1 / (axes.x * axes.x), b = 1 / (axes.y * axes.y);
    double cz = 0, e = 0;
    if (kind == Kind::Ellipsoid) {
        // In the frame where the ellipsoid is the unit sphere: the sphere's
        // distance-to-line discriminant, for a direction of length |ds|.
        const glm::dvec3 os = o / axes, ds = d / axes;
        const double qa = glm::dot(ds, ds), qh = glm::dot(os, ds);
        const double l = glm::length(os - (qh / qa) * ds);
        const double ol = glm::length(os);
        roots = solveQuadratic(qa, qh, (ol - 1) * (ol + 1), qa * (1 - l) * (1 + l));
        cz = 1 / (axes.z * axes.z);
    } else {
        double f;
        if (kind == Kind::Paraboloid) {
            e = -1 / axes.z;
            f = 0;
        } else {
            cz = -1 / (axes.z * axes.z);
            f = -1;
        }
        const double qa = a * d.x * d.x + b * d.y * d.y + cz * d.z * d.z;
        const double qh = a * o.x * d.x + b * o.y * d.y + cz * o.z * d.z + 0.5 * e * d.z;
        const double qc = a * o.x * o.x + b * o.y * o.y + cz * o.z * o.z + e * o.z + f;
        roots = solveQuadratic(qa, qh, qc);
    }
    for (int i = 0; i < roots.count; ++i) {
        const double t = i == 0 ? roots.t0 : roots.t1;
        if (!(t > tMin && t <= tMax)) continue;
        const glm::dvec3 p = ray.at(t);
        if (!(p.z >= zLow && p.z <= zHigh)) continue; // cut away (seed 001)
        const glm::dvec3 l = p - centre;
        glm::dvec3 g(2 * a * l.x, 2 * b * l.y, 2 * cz * l.z + e);
        const double gl = glm::length(g);
        if (!(gl > 0)) continue;
        g /= gl;
        hit.t = t;
        hit.point = p;
        hit.outwardNormal = g;
        hit.uv = glm::dvec2(0.0); // textureCoords computes them from hit.point
        hit.hasUv = true;
        finishHit(ray, hit);
        return true;
    }
    return false;
}

glm::dvec2 Quadric::textureCoords(const Hit& hit) const {
    const glm::dvec3& p = hit.point;
    const glm::dvec3 l = p - centre;
    if (kind == Kind::Ellipsoid) {
        const glm::dvec3 s = l / axes; // on the unit sphere
        return {std::atan2(s.y, s.x) / (2 * kPi) + 0.5,
                0.5 + std::asin(glm::clamp(s.z, -1.0, 1.0)) / kPi};
    }
    const double span = zHigh - zLow;
    return {std::atan2(l.y / axes.y, l.x / axes.x) / (2 * kPi) + 0.5,
            std::isfinite(span) && span < 1e300 ? (p.z - zLow) / span : l.z};
}

Aabb Quadric::bounds() const {
    const double inf = std::numeric_limits<double>::infinity();
    auto clampCut = [&](double v) { return std::fabs(v) >= 1e300 ? (v < 0 ? -inf : inf) : v; };
    const double lo = clampCut(zLow), hi = clampCut(zHigh);
    double zl, zh, ext; // z range and the largest |x|/A = |y|/B over it
    if (kind == Kind::Ellipsoid) {
        zl = std::max(lo, centre.z - axes.z);
        zh = std::min(hi, centre.z + axes.z);
        ext = 1;
    } else if (kind == Kind::Paraboloid) { // radius² = (z − z0)/C, z >= z0
        zl = std::max(lo, centre.z);
        zh = hi;
        ext = std::sqrt(std::max(0.0, (zh - centre.z) / axes.z));
    } else { // radius² = 1 + (z − z0)²/C², largest at the cut farthest from z0
        zl = lo;
        zh = hi;
        const double m = std::max(std::fabs(lo - centre.z), std::fabs(hi - centre.z)) / axes.z;
        ext = std::sqrt(1 + m * m);
    }
    if (!std::isfinite(ext) || !std::isfinite(zl) || !std::isfinite(zh)) return Aabb::infinite();
    return Aabb{{centre.x - ext * axes.x, centre.y - ext * axes.y, zl},
                {centre.x + ext * axes.x, centre.y + ext * axes.y, zh}};
}

} // namespace wb::rt
