// Each primitive against closed-form answers: hit, miss, origin inside, tangent,
// grazing, parallel, behind the origin, far origin (|o| ~ 1e6), very near (t ~ 1e-7)
// and very far (t ~ 1e7) hits. The expected t is exact by construction (the ray is
// built from the hit point backwards with exactly representable numbers, or the
// answer is computed in long double from a closed form).
//
// Tolerances: a correct double algorithm loses a few ULPs of the largest quantity it
// combines, max(|origin|, t, size of the primitive). We allow 16 ULPs of that
// (16·2^-52·scale), which still fails any cancellation-prone formula: e.g. the naive
// h² − (|f|² − r²) discriminant for a grazing ray or a 1e6-far origin is wrong in
// the 4th–8th digit (checked below against the reference).
#include "core/raytrace/box.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/polyhedron.h"
#include "core/raytrace/quadratic.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>

using namespace wb::rt;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

__extension__ typedef __float128 Quad; // GCC's 113-bit binary128, for references

// Square root in binary128: Newton's iteration from the double root, quadratic
// convergence from 53 to >113 bits in two steps.
Quad sqrtQ(Quad a) {
    if (a <= 0) return 0;
    Quad x = std::sqrt(double(a));
    for (int i = 0; i < 3; ++i)
        x = (x + a / x) / 2;
    return x;
}

Ray makeRay(const glm::dvec3& o, const glm::dvec3& d) {
    Ray r;
    r.origin = o;
    r.direction = glm::normalize(d);
    return r;
}

double tol(double scale) {
    return 16 * kEps * scale;
}

// Expects a hit at t with the given outward normal; checks the hit record's invariants.
void expectHit(const Primitive& p, const Ray& r, double t, const glm::dvec3& outward, double scale,
               double tMin = 0.0, double tMax = kInf) {
    Hit h;
    REQUIRE(p.intersect(r, tMin, tMax, h));
    INFO("t " << h.t << " expected " << t);
    CHECK(std::fabs(h.t - t) <= tol(scale));
    CHECK(glm::length(h.outwardNormal - outward) <= 1e-9);
    CHECK(std::fabs(glm::length(h.normal) - 1) <= 4 * kEps);
    CHECK(h.cosVN <= 0);
    CHECK(glm::dot(h.normal, r.direction) == Approx(h.cosVN).margin(1e-15));
    CHECK(std::isfinite(h.point.x));
    CHECK(std::isfinite(h.point.y));
    CHECK(std::isfinite(h.point.z));
    // Entering is decided by the sign of d·n, undefined for a tangent ray (d·n ~ 0).
    if (std::fabs(glm::dot(r.direction, outward)) > 1e-12)
        CHECK(h.entering == (p.solid() && glm::dot(r.direction, outward) < 0));
}

void expectMiss(const Primitive& p, const Ray& r, double tMin = 0.0, double tMax = kInf) {
    Hit h;
    CHECK_FALSE(p.intersect(r, tMin, tMax, h));
}

} // namespace

TEST_CASE("quadratic: cancellation-free roots", "[raytrace][primitives]") {
    // t² − 2·1e8·t + 1 = 0: roots 1e8 ± sqrt(1e16 − 1); the small one is 5e-9 (to 1e-25),
    // which the textbook formula gets as 0 or 7.45e-9.
    const QuadraticRoots r = solveQuadratic(1, -1e8, 1);
    REQUIRE(r.count == 2);
    CHECK(r.t0 == Approx(5e-9).epsilon(1e-15));
    CHECK(r.t1 == Approx(2e8).epsilon(1e-15));
    CHECK(solveQuadratic(1, 0, 1).count == 0);
    const QuadraticRoots lin = solveQuadratic(0, 1, -4); // 2t − 4 = 0
    REQUIRE(lin.count == 1);
    CHECK(lin.t0 == 2);
    CHECK(solveQuadratic(0, 0, 1).count == 0);
    CHECK(solveQuadratic(1, 0, 0).count == 1);
    CHECK(solveQuadratic(std::nan(""), 1, 1).count == 0);
}

TEST_CASE("sphere: hard cases", "[raytrace][primitives]") {
    const Sphere s({0, 0, 0}, 1);
    expectHit(s, makeRay({0, 0, 5}, {0, 0, -1}), 4, {0, 0, 1}, 5); // hit
    expectMiss(s, makeRay({0, 2, 5}, {0, 0, -1}));                 // miss
    expectHit(s, makeRay({0, 0, 0}, {1, 0, 0}), 1, {1, 0, 0}, 1);  // inside origin
    expectHit(s, makeRay({0.5, 0, 0}, {-1, 0, 0}), 1.5, {-1, 0, 0}, 2);
    expectMiss(s, makeRay({0, 0, 5}, {0, 0, 1}));                  // behind the origin
    expectHit(s, makeRay({1, 0, 5}, {0, 0, -1}), 5, {1, 0, 0}, 5); // tangent: touches
    expectMiss(s, makeRay({1 + 1e-9, 0, 5}, {0, 0, -1}));          // just outside
    SECTION("grazing: x = 1 − 1e-9, exact answer 5 − sqrt((1−x)(1+x))") {
        const double x = 1 - 1e-9; // 1 − x is exact (Sterbenz)
        const long double a = sqrtl((1.0L - x) * (1.0L + x));
        const Ray r = makeRay({x, 0, 5}, {0, 0, -1});
        Hit h;
        REQUIRE(s.intersect(r, 0, kInf, h));
        CHECK(std::fabs(h.t - double(5.0L - a)) <= tol(5));
        // The naive discriminant loses ~half the digits of a here.
        const double naive = 5 - std::sqrt(25 - (x * x + 25 - 1));
        CHECK(std::fabs(naive - double(5.0L - a)) > 100 * tol(5));
        // The far root, from inside-out.
        REQUIRE(s.intersect(r, h.t, kInf, h));
        CHECK(std::fabs(h.t - double(5.0L + a)) <= tol(5));
    }
    SECTION("far origin |o| = 1e6, oblique") {
        // Aimed from 1e6 away along −(0.8, 0, 0.6) at the surface point (0.6, 0, 0.8). The
        // origin and direction are rounded to double; the reference is the textbook
        // formula t = (−b − sqrt(b² − a(|f|² − r²)))/a, a = |d|², evaluated in 113-bit
        // __float128 on the rounded ray: the cancellation b² − ac (1e12 − 1e12 -> ~1)
        // costs ~40 of the 113 bits, leaving the root good to ~1e-22.
        const glm::dvec3 o(800000.6, 0, 600000.8);
        const Ray r = makeRay(o, {-0.8, 0, -0.6});
        const Quad fx = o.x, fz = o.z, dx = r.direction.x, dy = r.direction.y, dz = r.direction.z;
        const Quad b = fx * dx + fz * dz;
        const Quad c = fx * fx + fz * fz - 1;
        const Quad a = dx * dx + dy * dy + dz * dz;
        const Quad ref = (-b - sqrtQ(b * b - a * c)) / a;
        Hit hit;
        REQUIRE(s.intersect(r, 0, kInf, hit));
        CHECK(std::fabs(hit.t - double(ref)) <= tol(1e6));
        // The textbook formula in double is off by ~1e-5 here (|f|² has ULPs of 1e-4).
        const double bd = glm::dot(o, r.direction), cd = glm::dot(o, o) - 1;
        CHECK(std::fabs(-bd - std::sqrt(bd * bd - cd) - double(ref)) > 100 * tol(1e6));
        CHECK(std::fabs(glm::length(hit.point) - 1) <= 4 * kEps); // refined onto the surface
        CHECK(glm::length(hit.point - glm::dvec3(0.6, 0, 0.8)) < 1e-9);
    }
    expectHit(s, makeRay({0, 0, 1e6}, {0, 0, -1}), 1e6 - 1, {0, 0, 1}, 1e6); // far, exact
    expectHit(s, makeRay({0, 0, 1 + 1.0 / 8388608}, {0, 0, -1}), 1.0 / 8388608, {0, 0, 1},
              1); // t ~ 1.2e-7
    const Sphere farS({0, 0, -1e7}, 1);
    expectHit(farS, makeRay({0, 0, 0}, {0, 0, -1}), 1e7 - 1, {0, 0, 1}, 1e7); // t ~ 1e7
    expectMiss(s, makeRay({0, 0, 5}, {0, 0, -1}), 0, 3.9);                    // tMax respected
    expectMiss(Sphere({0, 0, 0}, 0), makeRay({0, 0, 5}, {0, 0, -1}));         // zero radius
    CHECK_THROWS_AS(Sphere({0, 0, 0}, -1), std::invalid_argument);
}

TEST_CASE("plane: hard cases", "[raytrace][primitives]") {
    const Plane p({0, 0, 2}, {0, 0, 3}); // z = 2, normal normalised
    CHECK(p.normal == glm::dvec3(0, 0, 1));
    expectHit(p, makeRay({1, 1, 5}, {0, 0, -1}), 3, {0, 0, 1}, 5);
    expectHit(p, makeRay({1, 1, -5}, {0, 0, 1}), 7, {0, 0, 1}, 7); // from the back
    expectMiss(p, makeRay({0, 0, 5}, {0, 0, 1}));                  // behind
    expectMiss(p, makeRay({0, 0, 5}, {1, 0, 0}));                  // parallel
    expectMiss(p, makeRay({0, 0, 2}, {1, 0, 0}));                  // parallel, inside the plane
    // Nearly parallel: d = (1, 0, −1e-9) normalised, from height 5: t = 3/|dz| ~ 3e9.
    const Ray np = makeRay({0, 0, 5}, {1, 0, -1e-9});
    Hit h;
    REQUIRE(p.intersect(np, 0, kInf, h));
    CHECK(h.t == Approx(3.0 / -np.direction.z).epsilon(1e-14));
    CHECK(h.point.z == 2.0); // projected back onto the plane
    expectMiss(p, np, 0, 1e9);
    expectHit(p, makeRay({1e6, -1e6, 1e6}, {0, 0, -1}), 1e6 - 2, {0, 0, 1}, 1e6); // far origin
    expectHit(p, makeRay({0, 0, 2 + 1.0 / 8388608}, {0, 0, -1}), 1.0 / 8388608, {0, 0, 1}, 2);
    expectHit(p, makeRay({0, 0, 2 + 1e7}, {0, 0, -1}), 1e7, {0, 0, 1}, 1e7);
    CHECK_THROWS_AS(Plane({0, 0, 0}, {0, 0, 0}), std::invalid_argument);
    SECTION("texture bound by three points") {
        Plane t({0, 0, 0}, {0, 0, 1});
        t.bindTexture({1, 1, 0}, {3, 1, 0}, {1, 5, 0});
        REQUIRE(t.intersect(makeRay({2, 3, 1}, {0, 0, -1}), 0, kInf, h));
        REQUIRE(h.hasUv);
        CHECK(h.uv.x == Approx(0.5));
        CHECK(h.uv.y == Approx(0.5));
        CHECK_THROWS_AS(t.bindTexture({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), std::invalid_argument);
    }
}

TEST_CASE("rectangle: hard cases", "[raytrace][primitives]") {
    const Rectangle r({0, 0, 0}, {2, 0, 0}, {0, 1, 0}); // 2×1 in z = 0
    expectHit(r, makeRay({1, 0.5, 3}, {0, 0, -1}), 3, {0, 0, 1}, 3);
    expectMiss(r, makeRay({3, 0.5, 3}, {0, 0, -1}));
    expectHit(r, makeRay({2, 1, 3}, {0, 0, -1}), 3, {0, 0, 1}, 3);   // corner counts
    expectHit(r, makeRay({0, 0.5, 3}, {0, 0, -1}), 3, {0, 0, 1}, 3); // edge counts
    expectMiss(r, makeRay({2 + 1e-9, 0.5, 3}, {0, 0, -1}));          // just outside
    expectMiss(r, makeRay({1, 0.5, 3}, {0, 0, 1}));                  // behind
    expectMiss(r, makeRay({-1, 0.5, 0}, {1, 0, 0}));                 // parallel, in the plane
    expectHit(r, makeRay({1, 0.5, -3}, {0, 0, 1}), 3, {0, 0, 1}, 3); // back side
    expectHit(r, makeRay({1, 0.5, 1e6}, {0, 0, -1}), 1e6, {0, 0, 1}, 1e6);
    expectHit(r, makeRay({1, 0.5, 1.0 / 8388608}, {0, 0, -1}), 1.0 / 8388608, {0, 0, 1}, 1);
    // Grazing: nearly in-plane ray from far away still finds the right u.
    const Ray g = makeRay({-1e3, 0.5, 1e-3}, {1e3 + 1, 0, -1e-3});
    Hit h;
    REQUIRE(r.intersect(g, 0, kInf, h));
    CHECK(h.uv.x == Approx(1.0 / 2).margin(1e-9));
    CHECK_THROWS_AS(Rectangle({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), std::invalid_argument);
}

TEST_CASE("triangle: hard cases", "[raytrace][primitives]") {
    const Triangle t({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    expectHit(t, makeRay({0.25, 0.25, 2}, {0, 0, -1}), 2, {0, 0, 1}, 2);
    expectMiss(t, makeRay({0.75, 0.75, 2}, {0, 0, -1}));
    expectHit(t, makeRay({0, 0, 2}, {0, 0, -1}), 2, {0, 0, 1}, 2);       // through a vertex
    expectHit(t, makeRay({0.5, 0.5, 2}, {0, 0, -1}), 2, {0, 0, 1}, 2);   // on the hypotenuse
    expectMiss(t, makeRay({0.25, 0.25, 2}, {0, 0, 1}));                  // behind
    expectMiss(t, makeRay({-1, 0.25, 0}, {1, 0, 0}));                    // in its plane
    expectHit(t, makeRay({0.25, 0.25, -2}, {0, 0, 1}), 2, {0, 0, 1}, 2); // back side
    // Far origin, oblique: aim at barycentric point (1/4, 1/4) from 1e6 away along an
    // exactly representable direction (3, 4, 12)/13.
    const glm::dvec3 q(0.25, 0.25, 0);
    const glm::dvec3 d = glm::dvec3(3, 4, 12) / 13.0;
    expectHit(t, makeRay(q + 1e6 * d, -d), 1e6, {0, 0, 1}, 1e6);
    expectHit(t, makeRay({0.25, 0.25, 1.0 / 8388608}, {0, 0, -1}), 1.0 / 8388608, {0, 0, 1}, 1);
    expectHit(t, makeRay({0.25, 0.25, 1e7}, {0, 0, -1}), 1e7, {0, 0, 1}, 1e7);
    expectMiss(Triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2}),
               makeRay({1, 1, 5}, {0, 0, -1})); // zero area
    { // Grazing: 1e-6 rad above the plane from 1e3 away, aimed at (0.25, 0.25, 0).
        const glm::dvec3 aim(0.25, 0.25, 0), o(-1e3 + 0.25, 0.25, 1e-3);
        Hit g;
        REQUIRE(t.intersect(makeRay(o, aim - o), 0, kInf, g));
        CHECK(glm::length(g.point - aim) <= 1e-9); // |o|·eps/sin(1e-6) ~ 2e-7 is the naive bound
        CHECK(g.point.z == 0);                     // on the triangle: from the barycentrics
    }
    Hit h;
    REQUIRE(t.intersect(makeRay({0.2, 0.3, 1}, {0, 0, -1}), 0, kInf, h));
    CHECK(h.uv.x == Approx(0.2)); // barycentrics of v1, v2
    CHECK(h.uv.y == Approx(0.3));
}

TEST_CASE("box (slab method of seed 000): hard cases", "[raytrace][primitives]") {
    const Box b = Box::axisAligned({-1, -1, -1}, {1, 1, 1});
    expectHit(b, makeRay({0, 0, 5}, {0, 0, -1}), 4, {0, 0, 1}, 5);
    expectHit(b, makeRay({5, 0.5, 0}, {-1, 0, 0}), 4, {1, 0, 0}, 5);
    expectMiss(b, makeRay({0, 2, 5}, {0, 0, -1}));
    expectHit(b, makeRay({0, 0, 0}, {0, 1, 0}), 1, {0, 1, 0}, 1);  // inside
    expectMiss(b, makeRay({0, 0, 5}, {0, 0, 1}));                  // behind
    expectMiss(b, makeRay({0, 1.5, 5}, {0, 0, -1}));               // parallel to a slab, outside
    expectHit(b, makeRay({1, 0, 5}, {0, 0, -1}), 4, {0, 0, 1}, 5); // grazing along a face
    { // through a corner: t exact up to the direction's rounding, some face's normal
        Hit h;
        REQUIRE(b.intersect(makeRay({3, 3, 3}, {-1, -1, -1}), 0, kInf, h));
        CHECK(std::fabs(h.t - 2 * std::sqrt(3.0)) <= tol(6));
        CHECK(std::fabs(glm::length(h.outwardNormal) - 1) <= 4 * kEps);
    }
    expectHit(b, makeRay({0, 0, 1e6}, {0, 0, -1}), 1e6 - 1, {0, 0, 1}, 1e6);
    expectHit(b, makeRay({0, 0, 1 + 1.0 / 8388608}, {0, 0, -1}), 1.0 / 8388608, {0, 0, 1}, 1);
    expectHit(b, makeRay({0, 0, 1e7 + 1}, {0, 0, -1}), 1e7, {0, 0, 1}, 1e7);
    // A sheared parallelepiped: loc 0, E1 = (2,0,0), E2 = (1,1,0), E3 = (0,0,1).
    const Box p({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {0, 0, 1});
    expectHit(p, makeRay({1.5, 0.5, 3}, {0, 0, -1}), 2, {0, 0, 1}, 3);
    expectMiss(p, makeRay({0.25, 0.75, 3}, {0, 0, -1})); // left of the slanted face
    const double s = std::sqrt(0.5);
    expectHit(p, makeRay({-1, 0.5, 0.5}, {1, 0, 0}), 1.5, {-s, s, 0}, 2);
    CHECK_THROWS_AS(Box({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}), std::invalid_argument);
}

TEST_CASE("convex polyhedron (practical 11.4): hard cases", "[raytrace][primitives]") {
    // The unit cube |x|,|y|,|z| <= 1 as six half-spaces, and a tetrahedron.
    std::vector<ConvexPolyhedron::Face> cube;
    for (int i = 0; i < 3; ++i)
        for (int s = -1; s <= 1; s += 2) {
            glm::dvec3 n(0.0);
            n[i] = s * 2.0; // unnormalised on purpose
            cube.push_back({n, 2.0});
        }
    const ConvexPolyhedron c(cube);
    const Aabb bb = c.bounds();
    CHECK(bb.lo == glm::dvec3(-1));
    CHECK(bb.hi == glm::dvec3(1));
    expectHit(c, makeRay({0, 0, 5}, {0, 0, -1}), 4, {0, 0, 1}, 5);
    expectMiss(c, makeRay({0, 2, 5}, {0, 0, -1}));
    expectHit(c, makeRay({0, 0, 0}, {0, 1, 0}), 1, {0, 1, 0}, 1);  // inside: bMin
    expectMiss(c, makeRay({0, 0, 5}, {0, 0, 1}));                  // behind
    expectMiss(c, makeRay({0, 1.5, 5}, {0, 0, -1}));               // parallel, outside a face
    expectHit(c, makeRay({0, 1, 5}, {0, 0, -1}), 4, {0, 0, 1}, 5); // grazing along a face
    expectHit(c, makeRay({0, 0, 1e6}, {0, 0, -1}), 1e6 - 1, {0, 0, 1}, 1e6);
    expectHit(c, makeRay({0, 0, 1 + 1.0 / 8388608}, {0, 0, -1}), 1.0 / 8388608, {0, 0, 1}, 1);
    expectHit(c, makeRay({0, 0, 1e7 + 1}, {0, 0, -1}), 1e7, {0, 0, 1}, 1e7);
    // fbfbb-type miss of the course's figure: passes beside an edge.
    expectMiss(c, makeRay({-3, 0, 1.5}, {1, 0, -0.1}));
    // Tetrahedron x, y, z >= 0, x + y + z <= 1.
    const double s3 = 1 / std::sqrt(3.0);
    const ConvexPolyhedron tet({{{-1, 0, 0}, 0}, {{0, -1, 0}, 0}, {{0, 0, -1}, 0}, {{1, 1, 1}, 1}});
    expectHit(tet, makeRay({0.25, 0.25, 5}, {0, 0, -1}), 4.5, {s3, s3, s3}, 5);
    expectHit(tet, makeRay({0.25, 0.25, -5}, {0, 0, 1}), 5, {0, 0, -1}, 5);
    // Unbounded: a half-space has an infinite box.
    const ConvexPolyhedron half({{{0, 0, 1}, 0}});
    CHECK_FALSE(half.bounds().bounded());
    expectHit(half, makeRay({0, 0, 3}, {0, 0, -1}), 3, {0, 0, 1}, 3);
    CHECK_THROWS_AS(ConvexPolyhedron({{{0, 0, 0}, 1}}), std::invalid_argument);
}

TEST_CASE("cylinder and cone with caps (practical 11.5): hard cases", "[raytrace][primitives]") {
    const Cone cyl = makeCylinder({0, 0, 0}, {0, 0, 2}, 1);             // axis z, 0 <= z <= 2
    expectHit(cyl, makeRay({5, 0, 1}, {-1, 0, 0}), 4, {1, 0, 0}, 5);    // side
    expectHit(cyl, makeRay({0.5, 0, 5}, {0, 0, -1}), 3, {0, 0, 1}, 5);  // top cap
    expectHit(cyl, makeRay({0.5, 0, -5}, {0, 0, 1}), 5, {0, 0, -1}, 5); // bottom cap
    expectMiss(cyl, makeRay({5, 0, 3}, {-1, 0, 0}));                    // above
    expectMiss(cyl, makeRay({5, 0, 1}, {1, 0, 0}));                     // behind
    expectHit(cyl, makeRay({0, 0, 1}, {1, 0, 0}), 1, {1, 0, 0}, 1);     // inside
    expectHit(cyl, makeRay({0, 0, 1}, {0, 0, 1}), 1, {0, 0, 1}, 1);     // inside, along the axis
    expectMiss(cyl, makeRay({1.5, 0, 5}, {0, 0, -1})); // parallel to the axis, outside
    expectHit(cyl, makeRay({1, 5, 1}, {0, -1, 0}), 5, {1, 0, 0}, 5); // tangent to the side
    expectMiss(cyl, makeRay({1 + 1e-9, 5, 1}, {0, -1, 0}));
    SECTION("grazing the side: x = 1 − 1e-9, exact 5 − sqrt((1−x)(1+x))") {
        const double x = 1 - 1e-9;
        const long double a = sqrtl((1.0L - x) * (1.0L + x));
        Hit h;
        REQUIRE(cyl.intersect(makeRay({x, 5, 1}, {0, -1, 0}), 0, kInf, h));
        CHECK(std::fabs(h.t - double(5.0L - a)) <= tol(5));
    }
    expectHit(cyl, makeRay({1e6, 0, 1}, {-1, 0, 0}), 1e6 - 1, {1, 0, 0}, 1e6);
    expectHit(cyl, makeRay({1 + 1.0 / 8388608, 0, 1}, {-1, 0, 0}), 1.0 / 8388608, {1, 0, 0}, 1);
    expectHit(cyl, makeRay({1e7 + 1, 0, 1}, {-1, 0, 0}), 1e7, {1, 0, 0}, 1e7);
    // Truncated cone: radius 2 at z = 0, 1 at z = 2 (k = −1/2). Side point at z = 1 has
    // radius 1.5; outward normal ∝ (1, 0, 0.5) (gradient (x, y, −k·r(z))).
    const Cone cone({0, 0, 0}, 2, {0, 0, 2}, 1);
    const glm::dvec3 nc = glm::normalize(glm::dvec3(1, 0, 0.5));
    expectHit(cone, makeRay({5, 0, 1}, {-1, 0, 0}), 3.5, nc, 5);
    expectHit(cone, makeRay({0, 0, 1}, {1, 0, 0}), 1.5, nc, 2); // inside
    expectHit(cone, makeRay({0.5, 0, 5}, {0, 0, -1}), 3, {0, 0, 1}, 5);
    expectMiss(cone, makeRay({1.5, 0, 5}, {0, 0, -1}), 0, 2.9);  // misses the top cap ...
    expectHit(cone, makeRay({1.5, 0, 5}, {0, 0, -1}), 4, nc, 5); // ... hits the side at z = 1
    // A cone to a point: its apex is on the axis, the side still has a normal.
    const Cone tip({0, 0, 0}, 1, {0, 0, 1}, 0);
    expectHit(tip, makeRay({0, 0, -3}, {0, 0, 1}), 3, {0, 0, -1}, 3);
    CHECK_THROWS_AS(Cone({0, 0, 0}, 1, {0, 0, 0}, 1), std::invalid_argument);
    CHECK_THROWS_AS(Cone({0, 0, 0}, 0, {0, 0, 1}, 0), std::invalid_argument);
    const Aabb cb = cyl.bounds();
    CHECK(cb.lo == glm::dvec3(-1, -1, 0));
    CHECK(cb.hi == glm::dvec3(1, 1, 2));
}

TEST_CASE("ellipsoid, paraboloid, hyperboloid with cutting planes (seed 001)",
          "[raytrace][primitives]") {
    const Quadric e(Quadric::Kind::Ellipsoid, {0, 0, 0}, {2, 1, 0.5});
    CHECK(e.solid());
    expectHit(e, makeRay({5, 0, 0}, {-1, 0, 0}), 3, {1, 0, 0}, 5);
    expectHit(e, makeRay({0, 0, 5}, {0, 0, -1}), 4.5, {0, 0, 1}, 5);
    expectMiss(e, makeRay({0, 1.5, 5}, {0, 0, -1}));
    expectHit(e, makeRay({0, 0, 0}, {0, 1, 0}), 1, {0, 1, 0}, 1);  // inside
    expectMiss(e, makeRay({5, 0, 0}, {1, 0, 0}));                  // behind
    expectHit(e, makeRay({0, 1, 5}, {0, 0, -1}), 5, {0, 1, 0}, 5); // tangent
    expectHit(e, makeRay({1e6, 0, 0}, {-1, 0, 0}), 1e6 - 2, {1, 0, 0}, 1e6);
    expectHit(e, makeRay({2 + 1.0 / 4194304, 0, 0}, {-1, 0, 0}), 1.0 / 4194304, {1, 0, 0}, 2);
    expectHit(e, makeRay({1e7 + 2, 0, 0}, {-1, 0, 0}), 1e7, {1, 0, 0}, 1e7);
    SECTION("grazing, against long double") {
        const double y = 1 - 1e-9; // x²/4 + y² = 1 at x = 2·sqrt((1−y)(1+y))
        const long double a = 2 * sqrtl((1.0L - y) * (1.0L + y));
        Hit h;
        REQUIRE(e.intersect(makeRay({5, y, 0}, {-1, 0, 0}), 0, kInf, h));
        CHECK(std::fabs(h.t - double(5.0L - a)) <= tol(5));
    }
    // Cut at z <= 0.25: the top is open, a ray down the axis enters through the inside.
    const Quadric cut(Quadric::Kind::Ellipsoid, {0, 0, 0}, {1, 1, 1}, -2, 0.25);
    CHECK_FALSE(cut.solid());
    expectHit(cut, makeRay({0, 0, 5}, {0, 0, -1}), 6, {0, 0, -1}, 6);
    // Paraboloid z = x² + y² (A = B = C = 1), cut at z <= 4.
    const Quadric par(Quadric::Kind::Paraboloid, {0, 0, 0}, {1, 1, 1}, -1e300, 4);
    const glm::dvec3 np = glm::normalize(glm::dvec3(2, 0, -1)); // gradient (2x, 2y, −1) at x = 1
    expectHit(par, makeRay({5, 0, 1}, {-1, 0, 0}), 4, np, 5);
    expectHit(par, makeRay({0, 0, 5}, {0, 0, -1}), 5, {0, 0, -1}, 5); // vertex, from inside the cup
    expectMiss(par, makeRay({5, 0, 5}, {-1, 0, 0}));                  // above the cut
    expectHit(par, makeRay({1e6, 0, 1}, {-1, 0, 0}), 1e6 - 1, np, 1e6);
    CHECK(par.bounds().hi == glm::dvec3(2, 2, 4));
    // Seed 001's "paraboloid" equation: x² + y² − z² = 1 between z = −1 and 1.
    const Quadric hyp(Quadric::Kind::Hyperboloid, {0, 0, 0}, {1, 1, 1}, -1, 1);
    expectHit(hyp, makeRay({5, 0, 0}, {-1, 0, 0}), 4, {1, 0, 0}, 5);
    expectMiss(hyp, makeRay({0, 0, 5}, {0, 0, -1})); // through the open axis
    CHECK_THROWS_AS(Quadric(Quadric::Kind::Ellipsoid, {0, 0, 0}, {1, 0, 1}), std::invalid_argument);
    Hit h;
    REQUIRE(e.intersect(makeRay({5, 0, 0}, {-1, 0, 0}), 0, kInf, h));
    REQUIRE(h.hasUv);
    CHECK(e.textureCoords(h).x == Approx(0.5)); // longitude 0
    CHECK(e.textureCoords(h).y == Approx(0.5)); // equator
}

namespace {
// The exact tests written out plainly, as they were before issue 21's ninth session rewrote
// their code for fewer instructions (the BVH confirms every hit with them, so images are
// bit-identical only while they give these bits): the watertight triangle test through local
// arrays, with the long double edge fallback and the overflow-scaled t inline, and the
// sphere's nearest root with std::sqrt and glm::length.
bool plainTriangle(const glm::dvec3& v0, const glm::dvec3& v1, const glm::dvec3& v2, const Ray& ray,
                   double tMin, double tMax, double& tOut, glm::dvec3& point, glm::dvec2& uv,
                   int& paths) {
    const TriangleShear sh = triangleShear(ray.direction);
    const int kx = sh.kx, ky = sh.ky, kz = sh.kz;
    const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double a[3] = {v0.x - o[0], v0.y - o[1], v0.z - o[2]};
    const double b[3] = {v1.x - o[0], v1.y - o[1], v1.z - o[2]};
    const double c[3] = {v2.x - o[0], v2.y - o[1], v2.z - o[2]};
    const double ax = a[kx] - sh.sx * a[kz], ay = a[ky] - sh.sy * a[kz];
    const double bx = b[kx] - sh.sx * b[kz], by = b[ky] - sh.sy * b[kz];
    const double cx = c[kx] - sh.sx * c[kz], cy = c[ky] - sh.sy * c[kz];
    double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if (u == 0 || v == 0 || w == 0) {
        using LD = long double;
        u = double(LD(cx) * LD(by) - LD(cy) * LD(bx));
        v = double(LD(ax) * LD(cy) - LD(ay) * LD(cx));
        w = double(LD(bx) * LD(ay) - LD(by) * LD(ax));
        paths |= 1;
    }
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
    const double det = u + v + w;
    if (det == 0) return false;
    const double az = sh.sz * a[kz], bz = sh.sz * b[kz], cz = sh.sz * c[kz];
    double t = (u * az + v * bz + w * cz) / det;
    if (!std::isfinite(t)) {
        const double m = std::max({std::abs(u), std::abs(v), std::abs(w)});
        const double k = std::ldexp(1.0, -std::ilogb(m));
        t = ((u * k) * az + (v * k) * bz + (w * k) * cz) / (det * k);
        paths |= 2;
    }
    if (!(t > tMin && t <= tMax)) return false;
    const double b0 = u / det, b1 = v / det, b2 = w / det;
    tOut = t;
    point = b0 * v0 + b1 * v1 + b2 * v2;
    uv = {b1, b2};
    return true;
}

bool plainSphere(const glm::dvec3& centre, double radius, const Ray& ray, double tMin, double tMax,
                 double& tOut, glm::dvec3& nOut) {
    if (radius == 0) return false;
    const glm::dvec3 f = ray.origin - centre;
    const double h = glm::dot(f, ray.direction);
    const glm::dvec3 l = f - h * ray.direction;
    const double ll = glm::length(l);
    const double disc = (radius - ll) * (radius + ll);
    if (!(disc >= 0) || !std::isfinite(h)) return false;
    const double fl = glm::length(f);
    const double c = (fl - radius) * (fl + radius);
    if (!std::isfinite(c)) return false;
    const double q = -(h + std::copysign(std::sqrt(disc), h));
    double t0 = 0.0, t1 = 0.0;
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
    const double nl = glm::length(n);
    if (!(nl > 0)) return false;
    tOut = t;
    nOut = n / nl;
    return true;
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}
bool sameBits(const glm::dvec3& a, const glm::dvec3& b) {
    return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}
} // namespace

TEST_CASE("triangle and sphere: the exact tests give the plainly written formulas' bits",
          "[raytrace][primitives]") {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> uni(-1, 1);
    auto rv = [&](double s) { return glm::dvec3(uni(rng), uni(rng), uni(rng)) * s; };
    int paths = 0, triHits = 0, sphHits = 0, mismatches = 0;
    for (int k = 0; k < 40000; ++k) {
        const int mode = k % 8;
        const double s = std::ldexp(1.0, int(rng() % 40) - 20);
        glm::dvec3 a = rv(s), b = rv(s), c = rv(s);
        if (mode == 1) b = a + rv(s * 1e-9);       // a sliver
        if (mode == 2) a.z = b.z = c.z = -0.5 * s; // a floor, as balls 4's
        if (mode == 7) {                           // products beyond double's range: scaled t
            a = rv(1e120);
            b = rv(1e120);
            c = rv(1e120);
        }
        if (mode == 0 && k % 16 == 0) { // on a grid: edge functions exactly 0 (long double)
            a = glm::dvec3(0, 0, 0);
            b = glm::dvec3(1, 0, 0);
            c = glm::dvec3(0, 1, 0);
        }
        glm::dvec3 org = rv(2 * s), dir;
        if (mode == 3)
            dir = (a + b) * 0.5 - org; // through an edge
        else if (mode == 4)
            dir = a - org;    // through a vertex
        else if (mode == 5) { // in the plane
            org = a + (b - a) * 0.3 + (c - a) * 0.3;
            dir = glm::cross(glm::cross(b - a, c - a), rv(1));
        } else if (mode == 6) { // from a point of the triangle
            org = a * 0.25 + b * 0.25 + c * 0.5;
            dir = rv(1);
        } else if (mode == 0 && k % 16 == 0) {
            org = glm::dvec3(double(k % 5) * 0.25, 0.5, 2);
            dir = glm::dvec3(0, 0, -1); // x on the grid: through an edge or a vertex
        } else {
            dir = (a + b + c) / 3.0 + rv(0.4 * s) - org;
        }
        if (k % 3 == 0) dir.x = 0;
        const double dl = glm::length(dir);
        if (!(dl > 0) || !std::isfinite(dl)) continue;
        const Ray ray = makeRay(org, dir / dl);
        const double tMin = (k & 32) ? 0.0 : 1e-9, tMax = (k & 64) ? kInf : 3 * s;
        const Triangle tri(a, b, c, (k & 16) != 0);
        double t = 0;
        glm::dvec3 point(0.0);
        glm::dvec2 uv(0.0);
        // A zero-area triangle is never hit (|n| finite here: |v| <= 2e120).
        const bool plain = glm::length(glm::cross(b - a, c - a)) > 0 &&
                           plainTriangle(a, b, c, ray, tMin, tMax, t, point, uv, paths);
        Hit h;
        const bool got = tri.intersect(ray, tMin, tMax, h);
        bool same = got == plain;
        if (same && got) {
            triHits++;
            same = sameBits(h.t, t) && sameBits(h.point, point) && sameBits(h.uv.x, uv.x) &&
                   sameBits(h.uv.y, uv.y) && h.primitive == &tri && h.solid == ((k & 16) != 0) &&
                   h.cosVN == glm::dot(ray.direction, h.normal) && h.cosVN <= 0 &&
                   h.entering == (h.solid && glm::dot(ray.direction, h.outwardNormal) < 0);
        }
        // A sphere through the same points: centre a, radius |b − a| (0 sometimes).
        const double r = k % 17 == 0 ? 0.0 : glm::length(b - a);
        if (std::isfinite(r)) {
            const Sphere sph(a, r);
            glm::dvec3 n(0.0);
            double ts = 0;
            const bool plainS = plainSphere(a, r, ray, tMin, tMax, ts, n);
            Hit hs;
            const bool gotS = sph.intersect(ray, tMin, tMax, hs);
            same = same && gotS == plainS && sph.occluded(ray, tMin, tMax) == plainS;
            if (same && gotS) {
                sphHits++;
                same = sameBits(hs.t, ts) && sameBits(hs.outwardNormal, n) &&
                       sameBits(hs.point, a + r * n) && hs.solid && hs.primitive == &sph;
            }
        }
        if (!same && ++mismatches == 1) {
            CAPTURE(k, mode, got, plain, h.t, t, h.cosVN);
            CHECK(false);
        }
    }
    CHECK(mismatches == 0);
    CHECK((paths & 1) != 0); // the long double edge functions were taken
    CHECK((paths & 2) != 0); // and the overflow-scaled t
    CHECK(triHits > 1000);
    CHECK(sphHits > 1000);
}
