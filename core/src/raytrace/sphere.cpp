#include "core/raytrace/sphere.h"

#include <emmintrin.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace wb::rt {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

namespace {
// std::sqrt's sqrtsd without the library call GCC puts beside it for a negative operand (to
// set errno): the same correctly rounded root, two instructions less a root; |v| as
// glm::length computes it, sqrt(dot(v, v)) (issue 21, ninth session).
inline double root(double x) {
    return _mm_cvtsd_f64(_mm_sqrt_pd(_mm_set_sd(x)));
}
inline double len(const glm::dvec3& v) {
    return root(glm::dot(v, v));
}

// c = |f|² − r² as (|f| − r)(|f| + r), f the origin's offset from the centre: nearest's
// constant term, and what Sphere::feelerSelfTerms hands the tracer's self-skip proof, which
// needs these very bits (tracer.cpp, sphereCannotBlock). One expression for both.
inline double offsetTerm(const glm::dvec3& f, double radius) {
    const double fl = len(f);
    return (fl - radius) * (fl + radius);
}

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
} // namespace

Sphere::Sphere(const glm::dvec3& c, double r) : centre(c), radius(r) {
    if (!(r >= 0) || !std::isfinite(r) || !finite3(c))
        throw std::invalid_argument("Sphere: radius must be finite and >= 0, centre finite");
}

namespace {
// The nearest root in (tMin, tMax] and the unit outward normal there (false: no hit).
// Shared by intersect and occluded so both decide alike, bit for bit; occluded
// (kNormal = false) needs only whether the normal exists, not its length.
// solveQuadratic(1, h, c, disc) written out for a = 1 (q / 1 is q): the same roots bit
// for bit, and a ray that misses (disc < 0) costs one square root, not three.
template <bool kNormal>
inline bool nearest(const glm::dvec3& centre, double radius, const Ray& ray, double tMin,
                    double tMax, double& tOut, glm::dvec3& nOut) {
    if (radius == 0) return false;
    const glm::dvec3 f = ray.origin - centre;
    const double h = glm::dot(f, ray.direction); // half b; a = 1 for a unit direction
    // Distance from the centre to the ray's line (practical 11.1): r² − l² is the
    // discriminant without the cancellation of h² − (|f|² − r²) for grazing rays.
    const glm::dvec3 l = f - h * ray.direction;
    const double ll = len(l);
    const double disc = (radius - ll) * (radius + ll);
    if (!(disc >= 0) || !std::isfinite(h)) return false; // no real root
    const double c = offsetTerm(f, radius);
    if (!std::isfinite(c)) return false;
    const double q = -(h + std::copysign(root(disc), h));
    double t0 = 0.0, t1 = 0.0; // q == 0: h == 0 and disc == 0, so c == 0: double root at 0
    if (q != 0) {
        t0 = q;
        t1 = c / q;
        if (t0 > t1) std::swap(t0, t1);
    }
    double t = t0;
    if (!(t > tMin && t <= tMax)) {
        t = t1;
        if (!(t > tMin && t <= tMax)) return false;
    }
    const glm::dvec3 n = ray.at(t) - centre;
    if constexpr (!kNormal) {
        tOut = t;
        return glm::dot(n, n) > 0; // |n| > 0 without the square root
    } else {
        const double nl = len(n);
        if (!(nl > 0)) return false;
        tOut = t;
        nOut = n / nl;
        return true;
    }
}
} // namespace

bool Sphere::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    double t;
    glm::dvec3 n;
    if (!nearest<true>(centre, radius, ray, tMin, tMax, t, n)) return false;
    const glm::dvec3 p = centre + radius * n; // refine onto the surface: error relative to |p|
    hit.t = t;
    hit.point = p;
    hit.outwardNormal = n;
    hit.uv = glm::dvec2(0.0); // textureCoords computes them from outwardNormal
    hit.hasUv = true;
    finishHit(ray, hit, true); // solid() is true (final)
    return true;
}

glm::dvec2 Sphere::textureCoords(const Hit& hit) const {
    const glm::dvec3& n = hit.outwardNormal;
    return glm::dvec2(std::atan2(n.y, n.x) / (2 * kPi) + 0.5,
                      0.5 + std::asin(glm::clamp(n.z, -1.0, 1.0)) / kPi);
}

bool Sphere::occluded(const Ray& ray, double tMin, double tMax) const {
    double t;
    glm::dvec3 n;
    return nearest<false>(centre, radius, ray, tMin, tMax, t, n);
}

bool Sphere::feelerSelfTerms(const glm::dvec3& point, glm::dvec3& f, double& c) const {
    // nearest's f and c for ray.origin = point: the same expressions (the library is built
    // without FMA contraction: the same bits).
    f = point - centre;
    c = offsetTerm(f, radius);
    return true;
}

Aabb Sphere::bounds() const {
    return Aabb{centre - glm::dvec3(radius), centre + glm::dvec3(radius)};
}

} // namespace wb::rt
