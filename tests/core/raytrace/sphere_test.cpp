// Sphere::intersect and Sphere::occluded (issue 13: the root solver written out for
// a = 1, the discriminant's sign tested before |f| is taken, occluded without the
// normal's length) against the code they replaced, copied below with
// wb::rt::solveQuadratic: the same decision, t and normal bit for bit on random,
// grazing (r·(1 ± k·1e-12) from the centre), tangent, inside, on-surface, far and
// degenerate rays (zero and subnormal radius, NaN, infinite origin). Closed-form
// accuracy of the sphere is primitives_test's; this is the bit-identity the images
// depend on.
#include "core/raytrace/quadratic.h"
#include "core/raytrace/sphere.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace wb::rt;

namespace {

// Sphere.cpp's nearest() before issue 13 (commit e6c89b3), verbatim.
bool referenceNearest(const glm::dvec3& centre, double radius, const Ray& ray, double tMin,
                      double tMax, double& tOut, glm::dvec3& nOut) {
    if (radius == 0) return false;
    const glm::dvec3 f = ray.origin - centre;
    const double h = glm::dot(f, ray.direction);
    const glm::dvec3 l = f - h * ray.direction;
    const double ll = glm::length(l);
    const double disc = (radius - ll) * (radius + ll);
    const double fl = glm::length(f);
    const double c = (fl - radius) * (fl + radius);
    const QuadraticRoots roots = solveQuadratic(1.0, h, c, disc);
    if (roots.count == 0) return false;
    double t = roots.t0;
    if (!(t > tMin && t <= tMax)) {
        t = roots.t1;
        if (!(t > tMin && t <= tMax)) return false;
    }
    glm::dvec3 n = ray.at(t) - centre;
    const double nl = glm::length(n);
    if (!(nl > 0)) return false;
    tOut = t;
    nOut = n / nl;
    return true;
}

bool sameBits(const void* a, const void* b, std::size_t n) {
    return std::memcmp(a, b, n) == 0;
}

struct Tally {
    long hits = 0, misses = 0;
};

void check(const Sphere& s, const Ray& ray, double tMin, double tMax, Tally& tally) {
    double t = 0;
    glm::dvec3 n(0.0);
    const bool want = referenceNearest(s.centre, s.radius, ray, tMin, tMax, t, n);
    Hit hit;
    const bool got = s.intersect(ray, tMin, tMax, hit);
    INFO("centre " << s.centre.x << ' ' << s.centre.y << ' ' << s.centre.z << " r " << s.radius
                   << ", origin " << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z
                   << ", dir " << ray.direction.x << ' ' << ray.direction.y << ' '
                   << ray.direction.z << ", (" << tMin << ", " << tMax << "]");
    REQUIRE(got == want);
    REQUIRE(s.occluded(ray, tMin, tMax) == want);
    if (want) {
        REQUIRE(sameBits(&hit.t, &t, sizeof t));
        REQUIRE(sameBits(&hit.outwardNormal, &n, sizeof n));
        ++tally.hits;
    } else {
        ++tally.misses;
    }
}

glm::dvec3 randomUnit(std::mt19937_64& g) {
    std::normal_distribution<double> nd;
    for (;;) {
        const glm::dvec3 v(nd(g), nd(g), nd(g));
        const double len = glm::length(v);
        if (len > 1e-3) return v / len;
    }
}

} // namespace

TEST_CASE("rt_sphere: intersect and occluded equal the solveQuadratic code bit for bit",
          "[raytrace][sphere]") {
    std::mt19937_64 g(1313);
    std::uniform_real_distribution<double> u(-1, 1);
    Tally tally;
    const double kInf = std::numeric_limits<double>::infinity();
    for (double scale : {1e-30, 1e-3, 1.0, 1e6, 1e25}) {
        for (int i = 0; i < 4000; ++i) {
            const Sphere s(scale * glm::dvec3(u(g), u(g), u(g)), scale * (0.05 + std::fabs(u(g))));
            Ray ray;
            const int kind = i % 5;
            if (kind == 0) { // from outside at a random point near the sphere
                ray.origin = s.centre + scale * 4.0 * glm::dvec3(u(g), u(g), u(g));
                ray.direction =
                    glm::normalize(s.centre + s.radius * 1.2 * randomUnit(g) - ray.origin);
            } else if (kind == 1) { // grazing: aimed at r·(1 ± k·1e-12) off the centre
                ray.origin = s.centre + scale * 5.0 * randomUnit(g);
                const glm::dvec3 toC = glm::normalize(s.centre - ray.origin);
                glm::dvec3 side = glm::normalize(glm::cross(toC, randomUnit(g)));
                const double k = double(int(i / 5 % 7) - 3) * 1e-12;
                const glm::dvec3 aim = s.centre + s.radius * (1 + k) * side;
                ray.direction = glm::normalize(aim - ray.origin);
            } else if (kind == 2) { // from inside
                ray.origin = s.centre + 0.9 * s.radius * u(g) * randomUnit(g);
                ray.direction = randomUnit(g);
            } else if (kind == 3) { // from a point on the surface, any direction
                ray.origin = s.centre + s.radius * randomUnit(g);
                ray.direction = randomUnit(g);
            } else { // far away, towards the sphere
                ray.origin = s.centre + scale * 1e7 * randomUnit(g);
                ray.direction =
                    glm::normalize(s.centre + s.radius * 0.9 * randomUnit(g) - ray.origin);
            }
            check(s, ray, 0.0, kInf, tally);
            check(s, ray, -kInf, kInf, tally);             // both roots in the window
            check(s, ray, 0.0, scale * 3.0 * u(g), tally); // cut by tMax (or empty)
        }
    }
    CHECK(tally.hits > 20000); // both outcomes, many times each
    CHECK(tally.misses > 10000);

    // Tangent at the surface point itself: h = 0 and disc = 0, the double root q = 0.
    const Sphere unit(glm::dvec3(0.0), 1.0);
    Ray tangent;
    tangent.origin = {1, 0, 0};
    tangent.direction = {0, 1, 0};
    check(unit, tangent, -1.0, 1.0, tally);
    Hit hit;
    REQUIRE(unit.intersect(tangent, -1.0, 1.0, hit));
    const double zero = 0.0;
    CHECK(sameBits(&hit.t, &zero, sizeof zero)); // +0, not −0
    check(unit, tangent, 0.0, 1.0, tally);       // t = 0 is not in (0, 1]
    // Exactly tangent further away (disc = 0, one root), and a root exactly at tMax.
    tangent.origin = {1, -2, 0};
    check(unit, tangent, 0.0, kInf, tally);
    check(unit, tangent, 0.0, 2.0, tally);
    check(unit, tangent, 0.0, std::nextafter(2.0, 0.0), tally);
    // Degenerate input: zero radius, NaN and infinite origins or directions.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Ray odd;
    odd.origin = {0, 0, 5};
    odd.direction = {0, 0, -1};
    check(Sphere(glm::dvec3(0.0), 0.0), odd, 0.0, kInf, tally);
    for (const glm::dvec3& o : {glm::dvec3(nan, 0, 5), glm::dvec3(kInf, 0, 5),
                                glm::dvec3(0, 0, -kInf), glm::dvec3(1e300, 1e300, 1e300)}) {
        odd.origin = o;
        check(unit, odd, 0.0, kInf, tally);
    }
    odd.origin = {0, 0, 5};
    odd.direction = {nan, 0, -1};
    check(unit, odd, 0.0, kInf, tally);
    // The smallest radius: the root is the centre itself, n = 0, no hit (no normal).
    const Sphere speck(glm::dvec3(0.0), std::numeric_limits<double>::denorm_min());
    odd.direction = {0, 0, -1};
    check(speck, odd, 0.0, kInf, tally);
    double t = 0;
    glm::dvec3 n(0.0);
    CHECK_FALSE(referenceNearest(speck.centre, speck.radius, odd, 0.0, kInf, t, n));
    CHECK(solveQuadratic(1.0, -5.0, 25.0, 0.0).count == 1); // it is a root, though
}
