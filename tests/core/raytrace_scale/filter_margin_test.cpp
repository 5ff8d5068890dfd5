// Issue 21 (branch rtfilt): the wide tree's leaf filters in float (bvh_wide_kinds.h: the
// sphere margin kSphereMargin; the triangle filter's bound B = X·P1 + Y·P2 + Z from
// kMtEdgeMargin, kMtNormalMargin, kMtDoubleMargin, built per ray by mtSetup and for a
// packet's lanes by triangleLanes) may only over-report. These tests aim rays whose float
// rounding puts them as far outside the primitive as float allows, while the exact double
// code hits, so that a margin cut by a small factor loses hits the plain loop finds.
//
// How the rays are made adversarial (only through the inputs every float filter rounds:
// the origin, the direction, the vertices or centre, and the first difference v − o):
// - a ray goes from ~1040 away (every origin or vertex coordinate in [1024, 2048), where
//   float's rounding is largest relative to the value) through a point of an edge
//   (nudged 1e-9 of the way inside, far below float's error and far above double's, so
//   the exact code always hits) or tangent to a sphere (1e-9 of r inside);
// - geometry at the extreme of the bound's norm inequalities: the direction's two large
//   components equal (D = |d|∞ attained twice), the edge along the third axis, the
//   triangle a sliver whose apex v0 sits near the middle of the edge v1v2 (the edge
//   function F0 = n·d − F1 − F2 takes F1's and F2's errors together while E = max(|e1|₁,
//   |e2|₁) is half the edge v1v2), the sphere's tangent point off the line by (1, −1, 0);
// - the vertex (or centre) coordinates a hair from the middle between two floats, so the
//   build's rounding, and the difference v − o's, moves them by almost half a float step,
//   either way (all four sign patterns over a scene's triangles);
// - of 512 candidate rays per target (the origin slid along the line over one float
//   step of 1040, the direction's two large components rounding either way), the one
//   whose float-rounded inputs put the line farthest outside the target's edge or sphere
//   (worst*: exact arithmetic on the rounded inputs, so the choice does not depend on the
//   filter's own operation order).
// Every SIMD path (SSE2 4, AVX2 4 and 8, AVX-512 8, quantised 8) is checked against the
// plain loop: single rays (intersect, occluded, forEachHit) and packets of 8 lanes, one
// triangle or sphere per packet, each lane its own adversarial ray (the transposed leaf
// test, kTransposeLanes: triangleLanes' X, Y, Z and sphereLanes' per-lane margin).
//
// Measured strength (each term alone cut by a temporary local mutation; docs/raytrace-
// scale.md, "Issue 21, ninth session (branch rtfilt)"): in each test's comment.
#include "core/raytrace/bvh.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include "random_scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <vector>

using namespace wb::rt;
using wb::test::kInf;

namespace {

constexpr double kU = 0x1p-24;    // float's unit roundoff
constexpr double kStep = 0x1p-13; // float's spacing in [1024, 2048)
// A coordinate this far from a float of [1024, 2048) (or a multiple of kStep) is 1/64 of a
// float step short of the midpoint: it rounds to that float, by almost half a step.
constexpr double kHalfStep = 0x1p-14 - 0x1p-20;
// Candidate origins per target and direction rounding.
constexpr int kSlides = 512;

double l1(const glm::dvec3& v) {
    return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
}
double linf(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
glm::dvec3 toFloat(const glm::dvec3& v) {
    return {double(float(v.x)), double(float(v.y)), double(float(v.z))};
}
// v − o as a float filter computes it: both rounded to float, then a float difference.
glm::dvec3 floatDiff(const glm::dvec3& v, const glm::dvec3& o) {
    glm::dvec3 a;
    for (int i = 0; i < 3; ++i)
        a[i] = double(float(v[i]) - float(o[i]));
    return a;
}

// An exact change of axes (a permutation and sign flips), so the canonical construction
// below meets every axis and every sign of the direction.
struct Frame {
    int p[3];
    double s[3];
    glm::dvec3 operator()(const glm::dvec3& v) const {
        return {s[0] * v[p[0]], s[1] * v[p[1]], s[2] * v[p[2]]};
    }
};
Frame frameOf(int k) {
    static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    Frame f;
    for (int i = 0; i < 3; ++i) {
        f.p[i] = perms[k % 6][i];
        f.s[i] = ((k / 6) >> i) & 1 ? -1.0 : 1.0;
    }
    return f;
}

// Every SIMD path of the wide tree this CPU can run, each forced, packets on.
std::vector<std::unique_ptr<Bvh>> allPaths(const std::vector<std::unique_ptr<Primitive>>& prims) {
    std::vector<std::unique_ptr<Bvh>> trees;
    const bool avx2 = __builtin_cpu_supports("avx2");
    const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
    auto add = [&](int width, BvhSimd simd, BvhNodes nodes) {
        BvhOptions o;
        o.width = width;
        o.simd = simd;
        o.nodes = nodes;
        trees.push_back(std::make_unique<Bvh>(prims, o));
    };
    add(4, BvhSimd::Sse2, BvhNodes::Auto);
    if (avx2) {
        add(4, BvhSimd::Avx2, BvhNodes::Auto);
        add(8, BvhSimd::Avx2, BvhNodes::Float);
        add(8, BvhSimd::Avx2, BvhNodes::Quantised);
    }
    if (avx512) {
        add(8, BvhSimd::Avx512, BvhNodes::Float);
        add(8, BvhSimd::Avx512, BvhNodes::Quantised);
    }
    return trees;
}

std::string pathName(const Bvh& b) {
    const BvhStats& s = b.stats();
    return std::to_string(s.width) +
           (s.avx512 ? " AVX-512"
            : s.avx2 ? " AVX2"
                     : " SSE2") +
           (s.quantised ? " quantised" : "");
}

// One ray on every path against the plain loop: the nearest hit (primitive and t), the
// any-hit verdict and the set of every hit.
void checkRay(const BruteForce& brute, const std::vector<std::unique_ptr<Bvh>>& trees,
              const Ray& ray) {
    Hit hb;
    const bool fb = brute.intersect(ray, 0, kInf, hb);
    std::set<const Primitive*> sb;
    brute.forEachHit(ray, 0, kInf, [&](const Hit& h) { return sb.insert(h.primitive), true; });
    for (const auto& t : trees) {
        INFO("path " << pathName(*t));
        Hit h;
        REQUIRE(t->intersect(ray, 0, kInf, h) == fb);
        if (fb) {
            REQUIRE(h.primitive == hb.primitive);
            REQUIRE(h.t == hb.t);
        }
        REQUIRE(t->occluded(ray, 0, kInf) == fb);
        std::set<const Primitive*> s;
        t->forEachHit(ray, 0, kInf, [&](const Hit& x) { return s.insert(x.primitive), true; });
        REQUIRE(s == sb);
    }
}

// Eight rays as one packet on every path, lane by lane against the plain loop.
void checkPacket(const BruteForce& brute, const std::vector<std::unique_ptr<Bvh>>& trees,
                 const Ray* rays) {
    double tMin[kMaxPacket], tMax[kMaxPacket];
    Hit want[kMaxPacket];
    unsigned wantFound = 0;
    for (int j = 0; j < kMaxPacket; ++j) {
        tMin[j] = 0;
        tMax[j] = kInf;
        if (brute.intersect(rays[j], 0, kInf, want[j])) wantFound |= 1u << j;
    }
    for (const auto& t : trees) {
        INFO("path " << pathName(*t) << ", packet " << t->packetWidth());
        Hit got[kMaxPacket];
        REQUIRE(t->intersectPacket(rays, tMin, tMax, got, 0xFFu) == wantFound);
        for (int j = 0; j < kMaxPacket; ++j)
            if ((wantFound >> j) & 1) {
                INFO("lane " << j);
                REQUIRE(got[j].primitive == want[j].primitive);
                REQUIRE(got[j].t == want[j].t);
            }
        REQUIRE(t->occludedPacket(rays, tMin, tMax, nullptr, 0xFFu) == wantFound);
    }
}

// How far the float-rounded ray (origin, direction, the first difference v0 − o, the
// edges and normal rounded from double) lies outside edge v1v2 of t, in units of
// u·D·E·(V + |o|₁) (the scale of the filter's bound, bvh_wide_kinds.h): the edge function
// F0 = n·d − F1 − F2 (F1 = R·e2, F2 = −R·e1, R = (v0 − o) × d) of those inputs, in double.
double outsideEdge(const Triangle& t, const Ray& r) {
    const glm::dvec3 a = floatDiff(t.v0, r.origin), fd = toFloat(r.direction);
    const glm::dvec3 e1 = t.v1 - t.v0, e2 = t.v2 - t.v0;
    const glm::dvec3 R = glm::cross(a, fd);
    const double f1 = glm::dot(R, toFloat(e2)), f2 = -glm::dot(R, toFloat(e1));
    const double nd = glm::dot(toFloat(glm::cross(e1, e2)), fd);
    const double f0 = nd - f1 - f2;
    const double v = std::max({l1(t.v0), l1(t.v1), l1(t.v2)});
    const double scale = kU * linf(r.direction) * std::max(l1(e1), l1(e2)) * (v + l1(r.origin));
    return -(nd > 0 ? f0 : -f0) / scale;
}

// The canonical direction (−1, −1, η)·2^k with its two large components a hair beside
// the midpoint between two floats, each rounding up or down by `variant`'s bits.
// (y's is 1 + 2^-8 times x's, so that sliding the origin along the line moves o's x and y
// at different rates across float's grid: some slide rounds them, or v0 − o's, apart.)
glm::dvec3 roundingDirection(double eta, int k, int variant) {
    const double rx = variant & 1 ? kU * (1 - 0x1p-6) : kU * (1 + 0x1p-6);
    const double ry = variant & 2 ? kU * (1 - 0x1p-6) : kU * (1 + 0x1p-6);
    return std::ldexp(1.0, k) * glm::dvec3(-(1 + rx), -(1 + 0x1p-8 + ry), eta);
}

struct Stats {
    int rays = 0, hits = 0;
    double worst = 0, sum = 0;
    void add(double b, bool hit) {
        ++rays;
        hits += hit;
        worst = std::max(worst, b);
        sum += b;
    }
};

} // namespace

TEST_CASE("rt_bvh_wide: the triangle filter's bound holds against rays its float rounding "
          "puts outside an edge (single rays and packets)",
          "[raytrace][bvh][packet]") {
    // Strength, each term alone divided by a factor in a temporary local mutation (not
    // committed): red at 12 and above, green at 10, for kMtEdgeMargin, for mtSetup's X and Y
    // (the single ray; also the SSE2/AVX2 4-wide packets, which copy them) and for
    // triangleLanes' X and Y (8-wide packets). The largest error of these rays is ~7.2
    // against 64 (the input roundings' 5.4 below, the products' 1.8; ~8 for any ray to
    // first order), so no ray makes a cut by 8 red. Not reachable by any ray (green even divided by
    // 1e9): kMtNormalMargin (its term is at most the edge term, |n|₁ <= E² <= 2E·V, and the float
    // error stays far below the edge term alone); kMtDoubleMargin and Z (the double code's own
    // error for a ray it hits is ~u_d·D·E·(V + |o|₁), its sheared coordinates being the vertices'
    // offsets from the hit point: ~2^-35 of the edge term; the floor has ~2^25 to spare).
    std::mt19937_64 g(2121);
    std::uniform_real_distribution<double> u(0, 1);
    Stats st[2];
    // Scenes: far origins and triangles near the coordinate origin (X = D·|o|₁ carries the
    // bound: the origin's part), and origins near the coordinate origin with triangles far
    // out (Y = D with P2's V part); 12 frames each, direction scales 2^-20, 1 and 2^20.
    // The direction's z small, so that |o_z| adds little to |o|₁: X·P1 is then ~1% of B
    // where Y·P2 carries it.
    for (int far = 0; far < 2; ++far)
        for (int fk = 0; fk < 12; ++fk) {
            const Frame frame = frameOf(fk * 4 + far);
            const int k = (fk % 3 - 1) * 20;
            const double eta = (fk & 1 ? 1 : -1) * (0.002 + 0.01 * u(g));
            // Base of the triangles (canonical frame): near 0, or at (−1040, −1040, 0).
            const double base = far ? -1040.0 : 0.0;
            Scene sc;
            std::vector<Triangle> tris; // canonical
            for (int i = 0; i < 8; ++i) {
                const double len = 0.5 + 0.5 * u(g);
                const double cx = base + kStep * double(int(u(g) * 4096)) + 0.25;
                const double cy = base + kStep * double(int(u(g) * 4096)) - 0.75;
                const double cz = 4.0 * i - 16 + 0.3 * u(g);
                const double h = kStep * double(int(len * (0.02 + 0.06 * u(g)) / kStep));
                // The apex near the edge's middle, its x and y half a float step (of [1024,
                // 2048)) off either way: the build's rounding (far) or v0 − o's (near).
                const double sx = i & 1 ? kHalfStep : -kHalfStep;
                const double sy = i & 2 ? kHalfStep : -kHalfStep;
                tris.emplace_back(glm::dvec3(cx + h + sx, cy - h + sy, cz + 0.1 * len * u(g)),
                                  glm::dvec3(cx, cy, cz - len), glm::dvec3(cx, cy, cz + len));
            }
            for (const Triangle& t : tris)
                sc.add(Triangle(frame(t.v0), frame(t.v1), frame(t.v2)), 0);
            const BruteForce brute(sc.primitives);
            const auto trees = allPaths(sc.primitives);
            for (const Triangle& t : tris) {
                const Triangle& world = static_cast<const Triangle&>(*sc.primitives[&t - &tris[0]]);
                Ray packet[kMaxPacket];
                for (int j = 0; j < kMaxPacket; ++j) {
                    // A point of the edge v1v2, 1e-9 of the way towards v0.
                    const double at = (j + 0.2 + 0.6 * u(g)) / kMaxPacket;
                    glm::dvec3 q = t.v1 + at * (t.v2 - t.v1);
                    q += 1e-9 * (t.v0 - q);
                    const double s0 = (far ? 1037.0 : 1040.0) + 2 * u(g);
                    Ray best;
                    double worst = -kInf;
                    for (int variant = 0; variant < 4; ++variant) {
                        const glm::dvec3 d = roundingDirection(eta, k, variant);
                        for (int slide = 0; slide < kSlides; ++slide) {
                            Ray r;
                            r.direction = d;
                            r.origin = q - std::ldexp(s0 + 2 * u(g), -k) * d;
                            const double b = outsideEdge(t, r);
                            if (b > worst) worst = b, best = r;
                        }
                    }
                    Ray ray;
                    ray.origin = frame(best.origin);
                    ray.direction = frame(best.direction);
                    Hit h;
                    const bool own = world.intersect(ray, 0, kInf, h);
                    st[far].add(worst, own);
                    INFO("frame " << fk << (far ? ", far triangles" : ", far origins")
                                  << ", outside by " << worst << " u·D·E·(V + |o|₁)");
                    checkRay(brute, trees, ray);
                    packet[j] = ray;
                }
                checkPacket(brute, trees, packet);
            }
        }
    for (const Stats& s : st) {
        INFO(s.rays << " rays, " << s.hits << " hit their own triangle; outside by up to "
                    << s.worst << ", mean " << s.sum / s.rays << " u·D·E·(V + |o|₁)");
        // Nudged inside by 1e-9, every ray hits its triangle in double.
        CHECK(s.hits == s.rays);
        // The construction's own strength (measured 5.5 and 5.3, means 3.3): the input
        // roundings alone reach most of their sum's largest value, ~5.4 (two coordinates
        // each of o, v0 − o and d, ~0.9 apiece); the filter's products add up to ~1.8 more.
        // Against these, B's edge part is 64 (2^-18 = 64u) and a cut by 12 leaves 5.3.
        CHECK(s.worst > 4.5);
        CHECK(s.sum / s.rays > 2.5);
    }
}

namespace {
// How far the float-rounded ray (origin, direction, the difference o − c) passes outside
// sphere s, in units of u·(|o|₁ + |c|₁ + r) (the scale of the sphere filter's margin,
// bvh_wide_kinds.h): the distance of the centre from the line, |f − (f·d)d| with f = o − c,
// of those inputs, in double.
double outsideSphere(const Sphere& s, const Ray& r) {
    const glm::dvec3 f = floatDiff(r.origin, s.centre), fd = toFloat(r.direction);
    const glm::dvec3 l = f - glm::dot(f, fd) * fd;
    return (glm::length(l) - s.radius) / (kU * (l1(r.origin) + l1(s.centre) + s.radius));
}
} // namespace

TEST_CASE("rt_bvh_wide: the sphere filter's margin holds against rays its float rounding "
          "puts outside the sphere (single rays and packets)",
          "[raytrace][bvh][packet]") {
    // The same construction as the triangles' above, for the tangent rays of spheres: the
    // direction's x and y near −0.707 (y 1 + 2^-8 times x) and z small, the tangent point
    // off the line towards (1, −1, 0) (where the rounding of o's, or c's, two large
    // coordinates counts most against |o|₁ + |c|₁), the ray 1e-7 of r inside (the exact
    // code always hits: its own error is ~1e-9 of r here).
    // Strength, kSphereMargin alone divided (temporary local mutation, not committed): red at
    // 128 and above, green at 96 (the existing test "the leaves' float filters keep their
    // margins": red at 512, green at 256). The margin is ~100 times the largest error any
    // unit-direction ray can have (the sum above, ~2.6 against 256), so no ray makes a cut
    // by 16 or 32 red. The packets' own origin term alone (sphereLanes' som): red at 192,
    // green at 128.
    std::mt19937_64 g(2122);
    std::uniform_real_distribution<double> u(0, 1);
    Stats st[2];
    for (int far = 0; far < 2; ++far)
        for (int fk = 0; fk < 12; ++fk) {
            const Frame frame = frameOf(fk * 4 + far);
            const double eta = (fk & 1 ? 1 : -1) * (0.02 + 0.1 * u(g));
            const double base = far ? -1040.0 : 0.0;
            Scene sc;
            std::vector<Sphere> balls; // canonical
            for (int i = 0; i < 8; ++i) {
                // The centre's x and y half a float step (of [1024, 2048)) off either way:
                // the build's rounding (far) or o − c's (near).
                const double sx = i & 1 ? kHalfStep : -kHalfStep;
                const double sy = i & 2 ? kHalfStep : -kHalfStep;
                const glm::dvec3 c(base + kStep * double(int(u(g) * 4096)) + 0.25 + sx,
                                   base + kStep * double(int(u(g) * 4096)) - 0.75 + sy,
                                   4.0 * i - 16 + 0.3 * u(g));
                balls.emplace_back(c, 0.5 + 0.5 * u(g));
            }
            for (const Sphere& b : balls)
                sc.add(Sphere(frame(b.centre), b.radius), 0);
            // Out of the rays' way: eight spheres alone would be one leaf, which the walk
            // tests in double without the filter (rootLeafCount_).
            for (int i = 0; i < 16; ++i)
                sc.add(Sphere(frame(glm::dvec3(base, base, 100.0 + 4 * i)), 1.0), 0);
            const BruteForce brute(sc.primitives);
            const auto trees = allPaths(sc.primitives);
            const glm::dvec3 dn = glm::normalize(glm::dvec3(-1, -(1 + 0x1p-8), eta));
            for (const Sphere& b : balls) {
                const Sphere& world = static_cast<const Sphere&>(*sc.primitives[&b - &balls[0]]);
                Ray packet[kMaxPacket];
                for (int j = 0; j < kMaxPacket; ++j) {
                    const double s0 = (far ? 1467.0 : 1471.0) + 2 * u(g);
                    Ray best;
                    double worst = -kInf;
                    for (int variant = 0; variant < 4; ++variant) {
                        // x and y a hair from the midpoint to the next float (down or up,
                        // by variant): unit within 1e-7 (the float test's condition).
                        glm::dvec3 d = dn;
                        for (int a = 0; a < 2; ++a) {
                            const float fa = float(dn[a]);
                            const float next =
                                std::nextafter(fa, (variant >> a) & 1 ? 1.0f : -1.0f);
                            d[a] = double(fa) + (1 - 0x1p-6) * 0.5 * (double(next) - double(fa));
                        }
                        // The tangent point: off the line towards ±(1, −1, 0), turned by up
                        // to ±0.2 rad about d from lane to lane.
                        const glm::dvec3 w0 = glm::normalize(glm::cross(d, glm::dvec3(0, 0, 1)));
                        const double phi = (j % 4 - 1.5) * 0.12;
                        const glm::dvec3 w =
                            (j < 4 ? 1.0 : -1.0) *
                            glm::normalize(std::cos(phi) * w0 + std::sin(phi) * glm::cross(d, w0));
                        const glm::dvec3 tp = b.centre + (1 - 1e-7) * b.radius * w;
                        for (int slide = 0; slide < kSlides; ++slide) {
                            Ray r;
                            r.direction = d;
                            r.origin = tp - (s0 + 2 * u(g)) * d;
                            const double bad = outsideSphere(b, r);
                            if (bad > worst) worst = bad, best = r;
                        }
                    }
                    Ray ray;
                    ray.origin = frame(best.origin);
                    ray.direction = frame(best.direction);
                    Hit h;
                    st[far].add(worst, world.intersect(ray, 0, kInf, h));
                    INFO("frame " << fk << (far ? ", far spheres" : ", far origins")
                                  << ", outside by " << worst << " u·(|o|₁ + |c|₁ + r)");
                    checkRay(brute, trees, ray);
                    packet[j] = ray;
                }
                checkPacket(brute, trees, packet);
            }
        }
    for (const Stats& s : st) {
        INFO(s.rays << " rays, " << s.hits << " hit their own sphere; outside by up to " << s.worst
                    << ", mean " << s.sum / s.rays << " u·(|o|₁ + |c|₁ + r)");
        CHECK(s.hits == s.rays);
        // The construction's own strength (measured 1.83 and 1.82, means 1.10): the input
        // roundings' largest sum here is ~1.9 (o's, o − c's and d's two large coordinates,
        // u|o_i| apiece, d's 0.7u|o_i|, each times |w_i| = 0.707), the filter's products
        // add up to ~0.7 more; the margin is 256 (2^-16 = 256u).
        CHECK(s.worst > 1.6);
        CHECK(s.sum / s.rays > 0.9);
    }
}
