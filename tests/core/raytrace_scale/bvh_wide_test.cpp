// The 4-wide float BVH (BvhOptions::width 4, the default) against two independent
// references, the plain loop (BruteForce) and the binary double-box tree (width 2):
// the nearest hit is the same primitive with the same t, point and normals bit for bit,
// any-hit and the sets of every hit and every shadow blocker agree, on every primitive
// kind, for random rays and for the rays a float traversal gets wrong first: through
// the corners and along the edges of the wide nodes' float boxes, axis-parallel rays
// with zero direction components lying in box faces, origins exactly on box faces,
// rays through shared mesh edges and vertices, exact ties (duplicated primitives: the
// later one wins, as in the plain loop), scenes at 1e-30 and 1e25 scale, origins beyond
// float's comfortable range (the double path), non-unit directions. The renders are
// bit-identical to the plain loop's and the binary tree's for 1 and 2 threads.
#include "core/raytrace/box.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/bvh_slots.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/spd.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include "random_scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <set>
#include <string>

using namespace wb::rt;
using wb::test::kInf;
using wb::test::mixedScene;
using wb::test::rnd3;

namespace {

bool sameBits(const glm::dvec3& a, const glm::dvec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Every SIMD path of the wide tree this CPU can run, each forced: SSE2 4-wide (the
// portable baseline), and with AVX2 the 4- and 8-wide AVX2 walks.
struct WidePaths {
    std::vector<std::unique_ptr<Bvh>> trees;
    explicit WidePaths(const std::vector<std::unique_ptr<Primitive>>& prims,
                       const BvhOptions& base = {}) {
        const bool avx2 = __builtin_cpu_supports("avx2");
        for (int k = 0; k < (avx2 ? 3 : 1); ++k) {
            BvhOptions o = base;
            o.width = k == 2 ? 8 : 4;
            o.simd = k == 0 ? BvhSimd::Sse2 : BvhSimd::Avx2;
            trees.push_back(std::make_unique<Bvh>(prims, o));
            REQUIRE(trees.back()->stats().width == o.width);
            REQUIRE(trees.back()->stats().avx2 == (k > 0));
        }
        // Issue 21: the AVX-512 (F + VL) 8-wide walk, where the CPU has it.
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) {
            BvhOptions o = base;
            o.width = 8;
            o.simd = BvhSimd::Avx512;
            trees.push_back(std::make_unique<Bvh>(prims, o));
            REQUIRE(trees.back()->stats().avx512);
        }
        // Issue 21: the quantised 8-wide nodes on each 8-wide path (a scene float cannot
        // quantise keeps float nodes: quantisedNodes tests that).
        if (avx2)
            for (BvhSimd simd : {BvhSimd::Avx2, BvhSimd::Avx512}) {
                if (simd == BvhSimd::Avx512 &&
                    !(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")))
                    continue;
                BvhOptions o = base;
                o.width = 8;
                o.simd = simd;
                o.nodes = BvhNodes::Quantised;
                trees.push_back(std::make_unique<Bvh>(prims, o));
            }
    }
};

BvhOptions binaryTree() {
    BvhOptions o;
    o.width = 2;
    return o;
}

// What every wide answer is checked against, over one scene: the plain loop, the binary
// double tree, and the wide tree of every SIMD path (built with `wide`).
struct Refs {
    BruteForce brute;
    Bvh binary;
    WidePaths paths;
    explicit Refs(const std::vector<std::unique_ptr<Primitive>>& prims, const BvhOptions& wide = {})
        : brute(prims), binary(prims, binaryTree()), paths(prims, wide) {}
};

bool compareRayOn(const Refs& r, const Bvh& wide, const Ray& ray, double tMin, double tMax);

// Returns whether the ray hit something; REQUIREs that the plain loop, the binary tree
// and every path of the wide tree agree exactly.
bool compareRay(const Refs& r, const Ray& ray, double tMin = 0.0, double tMax = kInf) {
    bool hit = false;
    for (const auto& w : r.paths.trees) {
        INFO("width " << w->stats().width << (w->stats().avx2 ? " AVX2" : " SSE2"));
        hit = compareRayOn(r, *w, ray, tMin, tMax);
    }
    return hit;
}

bool compareRayOn(const Refs& r, const Bvh& wide, const Ray& ray, double tMin, double tMax) {
    Hit hb, h2, h4;
    const bool fb = r.brute.intersect(ray, tMin, tMax, hb);
    const bool f4 = wide.intersect(ray, tMin, tMax, h4);
    REQUIRE(f4 == fb);
    if (fb) {
        REQUIRE(h4.primitive == hb.primitive);
        REQUIRE(h4.t == hb.t); // the same primitive's exact code: the same bits
        REQUIRE(sameBits(h4.point, hb.point));
        REQUIRE(sameBits(h4.normal, hb.normal));
        REQUIRE(sameBits(h4.outwardNormal, hb.outwardNormal));
        REQUIRE(h4.cosVN == hb.cosVN);
    }
    // The binary tree may pick another primitive on an exact tie; t must agree.
    REQUIRE(r.binary.intersect(ray, tMin, tMax, h2) == fb);
    if (fb) REQUIRE(h2.t == hb.t);
    REQUIRE(wide.occluded(ray, tMin, tMax) == fb);
    std::set<const Primitive*> sb, s4, ob, o4;
    r.brute.forEachHit(ray, tMin, tMax, [&](const Hit& h) { return sb.insert(h.primitive), true; });
    wide.forEachHit(ray, tMin, tMax, [&](const Hit& h) { return s4.insert(h.primitive), true; });
    REQUIRE(s4 == sb);
    r.brute.forEachBlocker(ray, tMin, tMax,
                           [&](const Primitive& p) { return ob.insert(&p), true; });
    wide.forEachBlocker(ray, tMin, tMax, [&](const Primitive& p) { return o4.insert(&p), true; });
    REQUIRE(o4 == ob);
    if (fb) {
        // A segment ending at the nearest hit still meets it; one ending just before does not.
        REQUIRE(wide.occluded(ray, tMin, hb.t));
        bool before = false;
        r.brute.forEachBlocker(ray, tMin, std::nextafter(hb.t, 0.0),
                               [&](const Primitive&) { return before = true, false; });
        REQUIRE(wide.occluded(ray, tMin, std::nextafter(hb.t, 0.0)) == before);
    }
    return fb;
}

// Rays aimed at corners, along edges and from faces of the wide nodes' child boxes.
template <class Node, class A>
int adversarialRaysOf(const Refs& r, const std::vector<Node, A>& nodes, std::mt19937_64& g, int count,
                      double scale) {
    REQUIRE_FALSE(nodes.empty());
    constexpr int kW = int(sizeof(Node::count) / sizeof(Node::count[0]));
    int hits = 0;
    for (int i = 0; i < count; ++i) {
        const Node& nd = nodes[g() % nodes.size()];
        const int c = int(g() % kW);
        if (nd.lo[0][c] > nd.hi[0][c]) continue; // empty slot
        glm::dvec3 lo, hi, corner;
        for (int a = 0; a < 3; ++a) {
            lo[a] = nd.lo[a][c];
            hi[a] = nd.hi[a][c];
            corner[a] = (g() & 1) ? lo[a] : hi[a];
        }
        Ray ray;
        switch (i % 5) {
        case 0: // through a corner from anywhere
            ray.origin = rnd3(g, -14 * scale, 14 * scale);
            ray.direction = glm::normalize(corner - ray.origin);
            break;
        case 4: // through a corner from the origin 0: no widening of the origin, only the
                // exit distances' stretch keeps entry <= exit there
            ray.origin = glm::dvec3(0.0);
            ray.direction = glm::normalize(corner);
            break;
        case 1: { // along an edge: two zero direction components, in two face planes
            const int a = int(g() % 3);
            glm::dvec3 d(0.0);
            d[a] = (g() & 1) ? 1.0 : -1.0;
            ray.origin = corner - d * (20 * scale);
            ray.direction = d;
            break;
        }
        case 2: { // in a face plane: one zero component
            const int a = int(g() % 3);
            ray.origin = corner + rnd3(g, -3 * scale, 3 * scale);
            ray.origin[a] = corner[a];
            glm::dvec3 d = rnd3(g, -1, 1);
            d[a] = 0;
            if (glm::length(d) == 0) continue;
            ray.direction = glm::normalize(d);
            break;
        }
        default: { // origin exactly on a face, random direction
            const int a = int(g() % 3);
            std::uniform_real_distribution<double> u(0, 1);
            for (int b = 0; b < 3; ++b)
                ray.origin[b] = lo[b] + u(g) * (hi[b] - lo[b]);
            ray.origin[a] = corner[a];
            ray.direction = glm::normalize(rnd3(g, -1, 1));
            break;
        }
        }
        hits += compareRay(r, ray);
    }
    return hits;
}

// The same on the boxes of the 4-wide and of the 8-wide float tree, and on the rounded
// boxes of the quantised one (decoded as the walk decodes them: their corners and edges
// are where an inward rounding would lose a hit).
int adversarialRays(const Refs& r, std::mt19937_64& g, int count, double scale) {
    int hits = adversarialRaysOf(r, r.paths.trees.front()->wideNodes(), g, count, scale);
    bool float8 = false, quant8 = false;
    for (const auto& t : r.paths.trees) {
        if (!float8 && !t->wideNodes8().empty()) {
            hits += adversarialRaysOf(r, t->wideNodes8(), g, count, scale);
            float8 = true;
        }
        if (!quant8 && !t->quantNodes8().empty()) {
            hits += adversarialRaysOf(r, t->decodedQuantNodes8(), g, count, scale);
            quant8 = true;
        }
    }
    return hits;
}

} // namespace

TEST_CASE("rt_bvh_wide: the wide tree is the default, by CPU, and collapses the binary tree",
          "[raytrace][bvh]") {
    std::mt19937_64 g(3);
    Scene s;
    mixedScene(s, 3000, g, 1.0);
    const char* env = std::getenv("WB_BVH_PATH");
    const bool avx2 = __builtin_cpu_supports("avx2");
    if (!env) { // the automatic choice (ctest may force a path through the variable)
        Bvh wide(s.primitives);
        CHECK(wide.stats().avx2 == avx2);
        CHECK(wide.stats().width == (avx2 ? 8 : 4));
        // Issue 21: AVX-512 (F + VL) where the CPU has it.
        CHECK(wide.stats().avx512 ==
              (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")));
        CHECK(wide.options().width == wide.stats().width);
    }
    for (int width : {4, 8}) {
        INFO("width " << width);
        BvhOptions o;
        o.width = width;
        o.simd = BvhSimd::Avx2;
        Bvh wide(s.primitives, o);
        const BvhStats& st = wide.stats();
        CHECK(st.wideNodes > 0);
        // Every inner binary node ends up in some wide node or inside a merged leaf; a wide
        // node replaces 1 to width − 1 of them.
        const int w = avx2 ? width : 4;
        CHECK(st.width == w);
        CHECK(st.wideNodes <= st.nodes - st.leaves);
        // Leaves: every primitive in exactly one leaf slot, at most 4 (kMergePrims and
        // maxLeafSize) per leaf, 8 for spheres only; an inner subtree of 4 or fewer
        // primitives is one leaf (the collapse merges it: one float leaf test takes four),
        // so every inner slot holds more; the nodes are full enough: N·(w − 1) >= leaf
        // slots − 1.
        auto checkLeaves = [&](const auto& nodes) {
            std::vector<int> seen(st.primitives, 0);
            std::vector<std::size_t> under(nodes.size(), 0); // primitives under each node
            int leafSlots = 0, smallInner = 0;
            // Children follow their parent in the array (depth first, tasks appended).
            for (std::size_t n = nodes.size(); n-- > 0;)
                for (int c = 0; c < w; ++c) {
                    const auto& nd = nodes[n];
                    if (nd.lo[0][c] > nd.hi[0][c]) continue; // empty slot
                    if (nd.count[c] > 0) {
                        ++leafSlots;
                        CHECK(nd.count[c] <= 8);
                        under[n] += nd.count[c];
                        for (std::uint32_t i = nd.child[c]; i < nd.child[c] + nd.count[c]; ++i)
                            if (i < seen.size()) ++seen[i];
                    } else {
                        REQUIRE(nd.child[c] > n);
                        REQUIRE(nd.child[c] < nodes.size());
                        under[n] += under[nd.child[c]];
                        if (under[nd.child[c]] <= 4) ++smallInner;
                    }
                }
            CHECK(std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(seen.size()));
            CHECK(under[0] == st.primitives);
            CHECK(smallInner == 0);
            CHECK(st.wideNodes * (w - 1) >= leafSlots - 1);
        };
        if (w == 8)
            checkLeaves(wide.wideNodes8());
        else
            checkLeaves(wide.wideNodes());
        CHECK(int(wide.wideNodes().size() + wide.wideNodes8().size()) == st.wideNodes);
        CHECK((w == 8 ? wide.wideNodes8().size() : wide.wideNodes().size()) ==
              std::size_t(st.wideNodes));
    }
    // SSE2 is never wider than 4.
    BvhOptions sse;
    sse.width = 8;
    sse.simd = BvhSimd::Sse2;
    CHECK(Bvh(s.primitives, sse).stats().width == 4);
    CHECK_FALSE(Bvh(s.primitives, sse).stats().avx2);
    for (int bad : {1, 3, 16, -4}) {
        BvhOptions o;
        o.width = bad;
        CHECK_THROWS_AS(Bvh(s.primitives, o), std::invalid_argument);
    }
}

TEST_CASE("rt_bvh_wide: WB_BVH_PATH forces a path, and a bad value is ignored", "[raytrace][bvh]") {
    std::mt19937_64 g(4);
    Scene s;
    mixedScene(s, 200, g, 1.0);
    const char* old = std::getenv("WB_BVH_PATH");
    const std::string saved = old ? old : "";
    const bool avx2 = __builtin_cpu_supports("avx2");
    const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
    struct Case {
        const char* value;
        int width;
        bool avx2, avx512;
    };
    for (const Case& c : {Case{"sse4", 4, false, false}, Case{"avx4", 4, avx2, false},
                          Case{"avx8", avx2 ? 8 : 4, avx2, false},
                          Case{"avx512", avx2 ? 8 : 4, avx2, avx512}}) {
        INFO(c.value);
        setenv("WB_BVH_PATH", c.value, 1);
        Bvh b(s.primitives);
        CHECK(b.stats().width == c.width);
        CHECK(b.stats().avx2 == c.avx2);
        CHECK(b.stats().avx512 == c.avx512);
        BvhOptions explicitOpt; // explicit options win over the variable
        explicitOpt.width = 4;
        explicitOpt.simd = BvhSimd::Sse2;
        CHECK_FALSE(Bvh(s.primitives, explicitOpt).stats().avx2);
    }
    // A bad value: the automatic choice (said on stderr once), not an exception that would
    // end whichever program happens to build a BVH.
    unsetenv("WB_BVH_PATH");
    const Bvh automatic(s.primitives);
    setenv("WB_BVH_PATH", "avx1024", 1);
    const Bvh bad(s.primitives);
    CHECK(bad.stats().width == automatic.stats().width);
    CHECK(bad.stats().avx2 == automatic.stats().avx2);
    CHECK(bad.stats().avx512 == automatic.stats().avx512);
    if (old)
        setenv("WB_BVH_PATH", saved.c_str(), 1);
    else
        unsetenv("WB_BVH_PATH");
}

TEST_CASE("rt_bvh_wide: random and adversarial rays on every kind, exact hits", "[raytrace][bvh]") {
    for (double scale : {1.0, 1e-30, 1e25}) {
        INFO("scale " << scale);
        std::mt19937_64 g(std::uint64_t(scale * 1000) + 17);
        Scene s;
        mixedScene(s, 700, g, scale);
        const Refs r(s.primitives);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            Ray ray;
            ray.origin = rnd3(g, -14 * scale, 14 * scale);
            const Aabb b = s.primitives[g() % (s.primitives.size() - 1)]->bounds();
            ray.direction =
                glm::normalize(0.5 * (b.lo + b.hi) + 0.3 * scale * rnd3(g, -1, 1) - ray.origin);
            hits += compareRay(r, ray);
        }
        CHECK(hits > 100); // the rays mostly hit: not vacuous
        CHECK(adversarialRays(r, g, 800, scale) > 50);
    }
}

TEST_CASE("rt_bvh_wide: ties, shared mesh edges and vertices, duplicates", "[raytrace][bvh]") {
    // A grid of triangles on integer vertices: rays through the vertices and along the
    // shared edges meet two to six triangles at the same t. Each triangle is there twice
    // (the copy later in the scene must win, as in the plain loop), and spheres too.
    Scene s;
    for (int x = 0; x < 12; ++x)
        for (int y = 0; y < 12; ++y) {
            const glm::dvec3 a(x, y, 0), b(x + 1, y, 0), c(x, y + 1, 0), d(x + 1, y + 1, 0);
            for (int copy = 0; copy < 2; ++copy) {
                s.add(Triangle(a, b, d), 0);
                s.add(Triangle(a, d, c), 0);
            }
        }
    for (int i = 0; i < 20; ++i) {
        s.add(Sphere({i * 0.6, 3, 2}, 0.5), 0);
        s.add(Sphere({i * 0.6, 3, 2}, 0.5), 0);
    }
    const Refs r(s.primitives);
    std::mt19937_64 g(21);
    int hits = 0;
    for (int x = 0; x <= 12; ++x)
        for (int y = 0; y <= 12; ++y) {
            for (int k = 0; k < 3; ++k) {
                Ray ray;
                ray.origin = rnd3(g, -5, 17) + glm::dvec3(0, 0, 25);
                const glm::dvec3 target = k == 0   ? glm::dvec3(x, y, 0)
                                          : k == 1 ? glm::dvec3(x + 0.5, y, 0)
                                                   : glm::dvec3(x + 0.5, y + 0.5, 0);
                ray.direction = glm::normalize(target - ray.origin);
                hits += compareRay(r, ray);
            }
            Ray down; // straight down through the vertex: zero x and y components
            down.origin = {x, y, 7};
            down.direction = {0, 0, -1};
            hits += compareRay(r, down);
        }
    CHECK(hits > 400);
    // Sphere ties: the later copy.
    Ray ray;
    ray.origin = {0.6, 3, 10};
    ray.direction = {0, 0, -1};
    for (const auto& w : r.paths.trees) {
        Hit h;
        REQUIRE(w->intersect(ray, 0, kInf, h));
        CHECK(h.primitive == s.primitives[s.primitives.size() - 40 + 3].get());
    }
}

TEST_CASE("rt_bvh_wide: far origins, tiny direction components and non-unit directions",
          "[raytrace][bvh]") {
    // Scale 1e26, so that from 3e31 away (beyond 1e30: the double walk) the primitives'
    // own double answers are still meaningful (a hit's error ~|o|·1e-16 ≪ their size).
    constexpr double kS = 1e26;
    std::mt19937_64 g(8);
    Scene s;
    mixedScene(s, 300, g, kS);
    const Refs r(s.primitives);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Aabb b = s.primitives[g() % (s.primitives.size() - 1)]->bounds();
        const glm::dvec3 target = 0.5 * (b.lo + b.hi);
        Ray ray;
        switch (i % 4) {
        case 0: // origin beyond 1e30: the walk tests boxes in double
            ray.direction = glm::normalize(rnd3(g, -1, 1));
            ray.origin = target - 3e31 * ray.direction;
            REQUIRE(std::abs(ray.origin.x) + std::abs(ray.origin.y) + std::abs(ray.origin.z) >
                    1e30);
            break;
        case 1: { // a direction component of 1e-35 (1/d overflows float)
            ray.origin = target + glm::dvec3(0, 0, 30 * kS);
            ray.direction = glm::normalize(glm::dvec3(1e-35, 1e-35, -1));
            break;
        }
        case 2: // non-unit direction (the sphere test in float is skipped)
            ray.origin = rnd3(g, -14 * kS, 14 * kS);
            ray.direction = 3.7 * glm::normalize(target - ray.origin);
            break;
        default: // a segment from inside the scene
            ray.origin = target + rnd3(g, -2 * kS, 2 * kS);
            ray.direction = glm::normalize(rnd3(g, -1, 1));
            compareRay(r, ray, 0.3 * kS, 4.0 * kS);
            continue;
        }
        hits += compareRay(r, ray);
    }
    CHECK(hits > 60);
}

TEST_CASE("rt_bvh_wide: images bit-identical to the plain loop and the binary tree",
          "[raytrace][bvh]") {
    for (int which = 0; which < 2; ++which) {
        SceneFile sf = toScene(which ? spdJacks(2) : spdBalls(2));
        const LookAtCamera cam = sf.camera();
        PhongModel model;
        constexpr int kW = 64, kH = 56; // small: the sanitizer build runs this too
        ParallelRenderOptions opt;
        opt.threads = 1;
        const wb::Image plain = renderParallel(*sf.scene, cam, model, kW, kH, opt);
        Bvh binary(sf.scene->primitives, binaryTree());
        sf.scene->setAggregate(&binary);
        const wb::Image bin = renderParallel(*sf.scene, cam, model, kW, kH, opt);
        CHECK(bin.data == plain.data);
        const WidePaths wide(sf.scene->primitives);
        for (const auto& w : wide.trees) {
            INFO("width " << w->stats().width << (w->stats().avx2 ? " AVX2" : " SSE2"));
            sf.scene->setAggregate(w.get());
            opt.threads = 1;
            const wb::Image w1 = renderParallel(*sf.scene, cam, model, kW, kH, opt);
            opt.threads = 2;
            opt.tileSize = 8;
            const wb::Image w2 = renderParallel(*sf.scene, cam, model, kW, kH, opt);
            CHECK(w1.data == plain.data);
            CHECK(w2.data == w1.data);
        }
        sf.scene->setAggregate(nullptr);
    }
}

TEST_CASE("rt_bvh_wide: rays grazing spheres and through triangle edges and corners",
          "[raytrace][bvh]") {
    // Where the leaves' float tests decide: lines at r·(1 + k·1e-9) from a sphere's
    // centre (the float test's margin is ~1e-5 here, the float error ~1e-7), rays
    // through a triangle's vertices and edge points.
    std::mt19937_64 g(44);
    Scene s;
    mixedScene(s, 700, g, 1.0);
    const Refs r(s.primitives);
    int hits = 0, grazes = 0;
    for (const auto& p : s.primitives) {
        if (const auto* sp = dynamic_cast<const Sphere*>(p.get())) {
            for (int k = -3; k <= 3; ++k) {
                const glm::dvec3 d = glm::normalize(rnd3(g, -1, 1));
                const glm::dvec3 side = glm::normalize(glm::cross(d, rnd3(g, -1, 1)));
                Ray ray;
                ray.direction = d;
                ray.origin = sp->centre + side * (sp->radius * (1 + k * 1e-9)) - 25.0 * d;
                const bool h = compareRay(r, ray);
                hits += h;
                Hit hh;
                grazes += h && sp->intersect(ray, 0, kInf, hh);
            }
        } else if (const auto* tp = dynamic_cast<const Triangle*>(p.get())) {
            const glm::dvec3 pts[4] = {tp->v0, tp->v1, 0.5 * (tp->v0 + tp->v2),
                                       0.25 * tp->v1 + 0.75 * tp->v2};
            for (const glm::dvec3& q : pts) {
                Ray ray;
                ray.origin = rnd3(g, -14, 14);
                ray.direction = glm::normalize(q - ray.origin);
                hits += compareRay(r, ray);
            }
        }
    }
    CHECK(grazes > 100); // many of the grazing rays do touch their sphere
    CHECK(hits > 500);
}

TEST_CASE("rt_bvh_wide: the parallel build gives the same tree for any thread count",
          "[raytrace][bvh]") {
    // 30,000 primitives: subtrees above 2048 are split into TBB tasks (12,000 were enough
    // before the build stopped at the wide leaves, issue 21).
    std::mt19937_64 g(5);
    Scene s;
    mixedScene(s, 30000, g, 1.0);
    auto build = [&](int threads) {
        BvhOptions o;
        o.buildThreads = threads;
        return std::make_unique<Bvh>(s.primitives, o);
    };
    const auto one = build(1);
    // Above 2·4096 build nodes the collapse, too, runs subtrees as tasks (bvh_wide.cpp).
    REQUIRE(one->stats().nodes > 2 * 4096);
    for (int threads : {0, 2, 3}) {
        INFO("threads " << threads);
        const auto other = build(threads);
        CHECK(other->stats().nodes == one->stats().nodes);
        CHECK(other->stats().leaves == one->stats().leaves);
        CHECK(other->stats().maxDepth == one->stats().maxDepth);
        const auto& a = one->wideNodes();
        const auto& b = other->wideNodes();
        REQUIRE(a.size() == b.size());
        const auto& a8 = one->wideNodes8();
        const auto& b8 = other->wideNodes8();
        REQUIRE(a8.size() == b8.size());
        REQUIRE(a.size() + a8.size() > 0); // one of them is the tree (the other is empty)
        if (!a.empty())
            CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(Bvh::WideNode)) == 0);
        if (!a8.empty())
            CHECK(std::memcmp(a8.data(), b8.data(), a8.size() * sizeof(Bvh::WideNode8)) == 0);
        // And the same answers, primitive for primitive.
        for (int i = 0; i < 200; ++i) {
            Ray ray;
            ray.origin = rnd3(g, -14, 14);
            ray.direction = glm::normalize(rnd3(g, -5, 5) - ray.origin);
            Hit h1, h2;
            const bool f1 = one->intersect(ray, 0, kInf, h1);
            REQUIRE(other->intersect(ray, 0, kInf, h2) == f1);
            if (f1) CHECK(h1.primitive == h2.primitive);
        }
    }
    CHECK_THROWS_AS(build(-1), std::invalid_argument);
    // The tree collapsed from tasks, on every path, against the plain loop (60 rays: the
    // plain loop's every-hit walks over 12,000 primitives are slow under the sanitizers).
    const Refs r(s.primitives);
    int hits = 0;
    for (int i = 0; i < 60; ++i) {
        Ray ray;
        ray.origin = rnd3(g, -14, 14);
        ray.direction = glm::normalize(rnd3(g, -5, 5) - ray.origin);
        hits += compareRay(r, ray);
    }
    CHECK(hits > 20);
}

TEST_CASE("rt_bvh_wide: builds in memory an earlier build freed give the same tree",
          "[raytrace][bvh]") {
    // Issue 21: the build keeps the large mappings it frees (bvh.cpp, KeptMappings) and
    // hands them to the next build, dirty. 70,000 and 140,000 primitives: reference
    // buffers of 2.2 and 4.5 MB, both over the 2 MiB of the kept path. A small build in
    // a large build's memory, then a large one after it (never in a smaller mapping), each
    // against the same scene's tree built before.
    std::mt19937_64 g(17);
    Scene small, large;
    mixedScene(small, 70000, g, 1.0);
    mixedScene(large, 140000, g, 2.0);
    auto hash = [](const Bvh& b) {
        const auto& w = b.wideNodes8();
        const auto& v = b.wideNodes();
        std::uint64_t h = 1469598103934665603ull;
        auto mix = [&](const void* p, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i) {
                h ^= static_cast<const unsigned char*>(p)[i];
                h *= 1099511628211ull;
            }
        };
        mix(w.data(), w.size() * sizeof(Bvh::WideNode8));
        mix(v.data(), v.size() * sizeof(Bvh::WideNode));
        return h;
    };
    for (int threads : {1, 2}) {
        INFO("threads " << threads);
        BvhOptions o;
        o.buildThreads = threads;
        const auto firstSmall = hash(Bvh(small.primitives, o));
        const auto firstLarge = hash(Bvh(large.primitives, o));
        for (int round = 0; round < 2; ++round) {
            CHECK(hash(Bvh(small.primitives, o)) == firstSmall);
            CHECK(hash(Bvh(large.primitives, o)) == firstLarge);
        }
        // Both alive at once: two sets of buffers, each its own.
        const Bvh a(small.primitives, o), b(large.primitives, o);
        CHECK(hash(a) == firstSmall);
        CHECK(hash(b) == firstLarge);
    }
}

TEST_CASE("rt_bvh_wide: rays from the origin 0 through box corners that are triangle vertices",
          "[raytrace][bvh]") {
    // Triangles on float-exact vertices whose first vertex is the least in every
    // coordinate, so it is a corner of the triangle's box and, for some, of the leaf's
    // and the nodes' boxes (floats, not widened by the build). A ray from the origin 0
    // (not widened either) through that vertex enters and leaves the box at the same
    // exact t: only the exit distances' stretch keeps the computed entry <= exit.
    std::mt19937_64 g(91);
    std::uniform_real_distribution<float> u(-20.0f, 20.0f), e(0.01f, 2.0f);
    Scene s;
    std::vector<glm::dvec3> corners;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 a(u(g), u(g), u(g));
        const glm::dvec3 b = a + glm::dvec3(e(g), e(g), e(g)), c = a + glm::dvec3(e(g), e(g), e(g));
        if (glm::length(a) < 1) continue;
        s.add(Triangle(a, b, c), 0);
        corners.push_back(a);
    }
    const Refs r(s.primitives);
    int hits = 0;
    for (const glm::dvec3& a : corners) {
        Ray ray;
        ray.origin = glm::dvec3(0.0);
        ray.direction = glm::normalize(a);
        hits += compareRay(r, ray);
        ray.direction = a; // not normalised: t = 1 at the vertex
        hits += compareRay(r, ray);
    }
    CHECK(hits > 200);
}

TEST_CASE("rt_bvh_wide: scenes of one kind, so leaves hold full runs of four", "[raytrace][bvh]") {
    // In the mixed scene the kinds alternate, and the SAH makes small leaves, so a leaf
    // rarely holds four of one run; here every leaf's run is as long as the leaf, and
    // costly nodes make leaves of up to 7, so every lane of the leaves' float tests
    // (spheres, triangles, the other kinds' boxes) and the tail mask decide something.
    for (int kind = 0; kind < 3; ++kind) {
        INFO("kind " << kind);
        std::mt19937_64 g(std::uint64_t(60 + kind));
        std::uniform_real_distribution<double> rr(0.05, 0.6);
        Scene s;
        for (int i = 0; i < 600; ++i) {
            const glm::dvec3 c = rnd3(g, -10, 10);
            if (kind == 0)
                s.add(Sphere(c, rr(g)), 0);
            else if (kind == 1)
                s.add(Triangle(c, c + rnd3(g, -1, 1), c + rnd3(g, -1, 1)), 0);
            else if (i % 3 == 0)
                s.add(Cone(c, rr(g), c + rnd3(g, -1, 1) + glm::dvec3(0.01), rr(g)), 0);
            else if (i % 3 == 1)
                s.add(Quadric(Quadric::Kind::Ellipsoid, c, glm::dvec3(rr(g), rr(g), rr(g))), 0);
            else
                s.add(Box::axisAligned(c, c + glm::abs(rnd3(g, 0.1, 1))), 0);
        }
        BvhOptions big;
        big.maxLeafSize = 7;
        big.traversalCost = 8;
        const Refs r(s.primitives, big);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            Ray ray;
            ray.origin = rnd3(g, -14, 14);
            const Aabb b = s.primitives[g() % s.primitives.size()]->bounds();
            ray.direction = glm::normalize(0.5 * (b.lo + b.hi) + 0.3 * rnd3(g, -1, 1) - ray.origin);
            hits += compareRay(r, ray);
        }
        CHECK(hits > 150);
        CHECK(adversarialRays(r, g, 400, 1.0) > 50);
    }
}

TEST_CASE("rt_bvh_wide: the build that stops at the wide leaves gives the wide tree of the "
          "whole binary tree, for 1 and 2 threads",
          "[raytrace][bvh]") {
    // Issue 21: subtrees of at most 4 primitives (8 spheres) are one wide leaf after the
    // collapse, so the build no longer splits them. The wide tree must be the same slot
    // for slot (boxes, leaf ranges) as the collapse of the full binary tree, and the hits
    // the same: mixed kinds (leaves of 4), spheres only (leaves of up to 8), triangles.
    std::mt19937_64 g(77);
    Scene mixed, spheres, tris;
    mixedScene(mixed, 12000, g, 1.0);
    for (int i = 0; i < 9000; ++i) {
        const glm::dvec3 c = rnd3(g, -10, 10);
        spheres.add(Sphere(c, 0.01 + 0.3 * rnd3(g, 0, 1).x), 0);
        tris.add(Triangle(c, c + rnd3(g, -1, 1), c + rnd3(g, -1, 1)), 0);
    }
    std::vector<int> widths{4};
    if (__builtin_cpu_supports("avx2")) widths.push_back(8);
    for (const Scene* s : {&mixed, &spheres, &tris})
        for (int width : widths)
            for (int threads : {1, 2}) {
                INFO("scene " << (s == &mixed     ? "mixed"
                                  : s == &spheres ? "spheres"
                                                  : "triangles")
                              << ", width " << width << ", threads " << threads);
                BvhOptions full, fast;
                full.width = fast.width = width;
                full.buildThreads = fast.buildThreads = threads;
                full.fullBinary = true;
                const Bvh a(s->primitives, full), b(s->primitives, fast);
                CHECK(b.stats().nodes < a.stats().nodes); // it did stop early
                const auto sa = wideSlots(a), sb = wideSlots(b);
                CHECK(sa.size() > 100);
                CHECK(sa == sb);
                CHECK(a.stats().wideNodes == b.stats().wideNodes);
                for (int i = 0; i < 300; ++i) {
                    Ray ray;
                    ray.origin = rnd3(g, -12, 12);
                    ray.direction = rnd3(g, -1, 1);
                    Hit ha, hb;
                    const bool ka = a.intersect(ray, 1e-9, 1e9, ha),
                               kb = b.intersect(ray, 1e-9, 1e9, hb);
                    REQUIRE(ka == kb);
                    if (ka) {
                        CHECK(ha.primitive == hb.primitive);
                        CHECK(ha.t == hb.t);
                    }
                    CHECK(a.occluded(ray, 1e-9, 1e9) == b.occluded(ray, 1e-9, 1e9));
                }
            }
}

// Issue 21, item 2: quantised 8-wide nodes. Each decoded child box holds the float box
// it replaces (same tree, same links), nodes take half the bytes, and the walk on them
// gives the plain loop's hits for rays through the rounded boxes' corners and edges, on
// tiny and huge scenes and near float's limits; boxes float cannot quantise keep the
// tree float (and exact).
TEST_CASE("rt_bvh_wide: quantised nodes hold the float boxes and lose no hit",
          "[raytrace][bvh][quantised]") {
    if (!__builtin_cpu_supports("avx2")) return; // 8-wide nodes need AVX2
    auto checkHolds = [](const std::vector<std::unique_ptr<Primitive>>& prims) {
        BvhOptions fo, qo;
        fo.width = qo.width = 8;
        fo.simd = qo.simd = BvhSimd::Avx2;
        fo.nodes = BvhNodes::Float;
        qo.nodes = BvhNodes::Quantised;
        const Bvh f(prims, fo), q(prims, qo);
        REQUIRE(q.stats().quantised);
        REQUIRE_FALSE(f.stats().quantised);
        const auto& fn = f.wideNodes8();
        const auto dn = q.decodedQuantNodes8();
        REQUIRE(fn.size() == dn.size());
        REQUIRE(q.stats().nodeBytes * 2 == f.stats().nodeBytes); // 128 bytes against 256
        int tight = 0, boxes = 0;
        for (std::size_t i = 0; i < fn.size(); ++i)
            for (int c = 0; c < 8; ++c) {
                REQUIRE(dn[i].child[c] == fn[i].child[c]);
                REQUIRE(dn[i].count[c] == fn[i].count[c]);
                if (fn[i].lo[0][c] > fn[i].hi[0][c]) {
                    REQUIRE_FALSE((q.quantNodes8()[i].valid >> c) & 1); // empty slot
                    continue;
                }
                ++boxes;
                bool same = true;
                for (int a = 0; a < 3; ++a) {
                    REQUIRE(dn[i].lo[a][c] <= fn[i].lo[a][c]); // rounded outward
                    REQUIRE(dn[i].hi[a][c] >= fn[i].hi[a][c]);
                    same = same && dn[i].lo[a][c] == fn[i].lo[a][c] &&
                           dn[i].hi[a][c] == fn[i].hi[a][c];
                }
                tight += same;
            }
        // Rounded outward: on a scene of many boxes most move a little (not all exact).
        if (boxes > 50) CHECK(tight < boxes);
        return boxes;
    };
    for (double s : {1.0, 1e-30, 1e25, 1e36}) {
        INFO("scale " << s);
        std::mt19937_64 g(21);
        Scene sc;
        mixedScene(sc, 1200, g, s);
        REQUIRE(checkHolds(sc.primitives) > 100);
        const Refs r(sc.primitives);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            Ray ray;
            ray.origin = rnd3(g, -12 * s, 12 * s);
            ray.direction = glm::normalize(rnd3(g, -1, 1));
            hits += compareRay(r, ray);
        }
        hits += adversarialRays(r, g, 600, s);
        CHECK(hits > 100);
    }
    SECTION("tiny scenes: two primitives, one wide node") {
        Scene sc;
        sc.add(Sphere({0, 0, 0}, 1), 0);
        sc.add(Triangle({2, 0, 0}, {3, 0, 0}, {2, 1, 0}), 0);
        for (int k = 0; k < 3; ++k)
            sc.add(Sphere({5.0 + k, 1, 0}, 0.25), 0);
        sc.add(Triangle({-3, -3, 0.5}, {-3, -2, 0.5}, {-2, -3, 0.5}), 0);
        checkHolds(sc.primitives);
        const Refs r(sc.primitives);
        std::mt19937_64 g(22);
        CHECK(adversarialRays(r, g, 400, 1.0) > 20);
    }
    SECTION("flat scene: a zero-width axis (every box in z = 0)") {
        Scene sc;
        std::mt19937_64 g(23);
        for (int i = 0; i < 300; ++i) {
            glm::dvec3 a = rnd3(g, -10, 10), b = a + rnd3(g, -1, 1), c = a + rnd3(g, -1, 1);
            a.z = b.z = c.z = 0;
            sc.add(Triangle(a, b, c), 0);
        }
        checkHolds(sc.primitives);
        const Refs r(sc.primitives);
        CHECK(adversarialRays(r, g, 600, 1.0) > 10); // rays in z = 0 planes mostly graze
    }
    SECTION("boxes at float's limit stay float, and exact") {
        // Spheres near ±3e38: their boxes round to ±FLT_MAX or infinity in float.
        Scene sc;
        for (int i = 0; i < 40; ++i)
            sc.add(Sphere({(i % 2 ? 1 : -1) * 3.3e38, double(i), 0}, 1e37), 0);
        BvhOptions qo;
        qo.width = 8;
        qo.simd = BvhSimd::Avx2;
        qo.nodes = BvhNodes::Quantised;
        const Bvh q(sc.primitives, qo);
        CHECK_FALSE(q.stats().quantised);
        CHECK(q.quantNodes8().empty());
        const Refs r(sc.primitives);
        std::mt19937_64 g(24);
        for (int i = 0; i < 200; ++i) {
            Ray ray;
            ray.origin = {0, 20, 1e36};
            ray.direction = glm::normalize(rnd3(g, -1, 1));
            compareRay(r, ray);
        }
    }
}

// Primitives in a box of ±40 around kFarCentre (~1000 from the origin, where float rounds a
// coordinate by ~6e-5): small random triangles, and with withSpheres every even one a sphere.
static const glm::dvec3 kFarCentre{1000.0, -700.0, 600.0};

// A ray from `from` through q (a vertex or edge point of t): compares every tree with the
// plain loop and returns whether the exact code says it hits t itself.
static bool aimAtOwn(const Refs& r, const Triangle& t, const glm::dvec3& from,
                     const glm::dvec3& q) {
    Ray ray;
    ray.origin = from;
    ray.direction = glm::normalize(q - from);
    Hit h;
    const bool own = t.intersect(ray, 0, kInf, h);
    compareRay(r, ray);
    return own;
}

static void addFarPrimitives(Scene& s, std::mt19937_64& g, int count, bool withSpheres) {
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 c = kFarCentre + rnd3(g, -40, 40);
        if (!withSpheres || i % 2)
            s.add(Triangle(c, c + rnd3(g, -2, 2), c + rnd3(g, -2, 2)), 0);
        else
            s.add(Sphere(c, 0.3 + 0.01 * double(i % 13)), 0);
    }
}

TEST_CASE("rt_bvh_wide: the leaves' float filters keep their margins (hits closer to an edge "
          "than float's error)",
          "[raytrace][bvh]") {
    // Issue 21: a leaf's spheres and triangles are rejected four at a time by float tests
    // whose error bounds are written in bvh_wide_kinds.h (kSphereMargin, kTriMargin) and
    // bvh_wide_impl.h (visitLeaf). Here the primitives sit ~1000 from the origin and the
    // rays start ~1000 away too, so rounding a coordinate to float moves it by up to
    // 1000·2^-24 ≈ 6e-5, while the rays pass 1e-9 (spheres) or ~1e-13 (a point on an edge
    // in double) from the boundary the exact double code decides on. A filter with its
    // margin cut (e.g. kTriMargin 2^-19 → 2^-26, kSphereMargin 2^-16 → 2^-24) rejects some of
    // the hits the plain loop finds, and compareRay fails on every path.
    std::mt19937_64 g(2112);
    const glm::dvec3 far = kFarCentre;
    Scene s;
    addFarPrimitives(s, g, 160, true);
    const Refs r(s.primitives);
    int edgeHits = 0, grazes = 0;
    for (const auto& p : s.primitives) {
        const glm::dvec3 from = -far + rnd3(g, -300, 300); // ~2000 away, coordinates ~1000
        if (const auto* sp = dynamic_cast<const Sphere*>(p.get())) {
            for (int k = -3; k <= 3; ++k) {
                const glm::dvec3 d = glm::normalize(sp->centre - from);
                const glm::dvec3 side = glm::normalize(glm::cross(d, rnd3(g, -1, 1)));
                Ray ray;
                ray.direction = d;
                ray.origin = sp->centre + side * (sp->radius * (1 + k * 1e-9)) - 1500.0 * d;
                Hit h;
                const bool own = sp->intersect(ray, 0, kInf, h);
                grazes += own && compareRay(r, ray);
                if (!own) compareRay(r, ray);
            }
        } else if (const auto* tp = dynamic_cast<const Triangle*>(p.get())) {
            std::uniform_real_distribution<double> u(0, 1);
            const glm::dvec3 pts[5] = {tp->v0, tp->v2, 0.5 * (tp->v0 + tp->v1),
                                       tp->v1 + u(g) * (tp->v2 - tp->v1),
                                       tp->v2 + u(g) * (tp->v0 - tp->v2)};
            for (const glm::dvec3& q : pts)
                edgeHits += aimAtOwn(r, *tp, from, q);
        }
    }
    // Enough of the boundary rays do hit their own primitive (the exact code decides about
    // half of them either way) for a cut margin to lose some of them.
    CHECK(grazes > 60);
    CHECK(edgeHits > 100);
}

TEST_CASE("rt_bvh_wide: the triangle filter's verdict for every dominant axis and either sign "
          "of it",
          "[raytrace][bvh]") {
    // Issue 21 (branch rtmesh): the leaves' float triangle filter orders its axes as kz and
    // the next two cyclically for either sign of d[kz], where the exact watertight test swaps
    // kx and ky when d[kz] < 0 (the swap negates every edge function exactly, so the
    // verdict is the same). Rays through triangle vertices and edge points ~1000 from the
    // origin (float rounding moves a coordinate by ~6e-5, far more than the rays' distance
    // to the edge) arrive along +x, −x, +y, −y, +z and −z: a filter with the shear of the
    // wrong axis for one of the six (e.g. the swapped shears not exchanged) rejects hits the
    // plain loop finds.
    std::mt19937_64 g(2113);
    Scene s;
    addFarPrimitives(s, g, 120, false);
    const Refs r(s.primitives);
    int hits[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    std::uniform_real_distribution<double> u(0, 1);
    for (const auto& p : s.primitives) {
        const auto* tp = dynamic_cast<const Triangle*>(p.get());
        REQUIRE(tp);
        const glm::dvec3 pts[4] = {tp->v1, 0.5 * (tp->v0 + tp->v1),
                                   tp->v1 + u(g) * (tp->v2 - tp->v1),
                                   tp->v2 + u(g) * (tp->v0 - tp->v2)};
        for (int axis = 0; axis < 3; ++axis)
            for (int sign = 0; sign < 2; ++sign)
                for (const glm::dvec3& q : pts) {
                    glm::dvec3 d = rnd3(g, -0.4, 0.4);
                    d[axis] = sign ? -1.0 : 1.0; // the dominant axis and its sign
                    Ray ray;
                    ray.direction = glm::normalize(d);
                    ray.origin = q - 1500.0 * ray.direction;
                    hits[axis][sign] += compareRay(r, ray);
                }
    }
    // Edge rays hit their triangle about half the time; each of the six cases has 480.
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = 0; sign < 2; ++sign) {
            INFO("axis " << axis << " sign " << sign);
            CHECK(hits[axis][sign] > 100);
        }
}

TEST_CASE("rt_bvh_wide: the precomputed-edge triangle filter keeps its bound (slivers, scales, "
          "far origins)",
          "[raytrace][bvh]") {
    // Issue 21 (branch rtmesh4): the single ray's triangle filter works on edges and normals
    // precomputed in float and rejects only beyond B = D·(kMtEdgeMargin·E·(V + |o|₁) +
    // kMtNormalMargin·|n|₁ + kMtDoubleMargin·(V + |o|₁)²) + kMtFloor (bvh_wide_kinds.h).
    // Triangles of 2 down to 1e-3 across, slivers (one vertex 1e-7 of the edge's length off
    // the edge), ~1000 and ~1e5 from the origin and a copy of the set at 1e-20 scale (edge
    // functions near float's underflow, where kMtFloor counts); rays from ~2000 (scaled) away
    // through their vertices and points on their edges, which the exact code decides by its
    // own rounding. With kMtEdgeMargin cut to 2^-30 the filter rejects hits the plain loop
    // finds and compareRay fails (AVX2 and SSE2 alike: one leaf test for every path).
    std::mt19937_64 g(2114);
    std::uniform_real_distribution<double> u(0, 1);
    int edgeHits[3] = {0, 0, 0};
    const double scales[3] = {1.0, 100.0, 1e-20};
    for (int si = 0; si < 3; ++si) {
        const double sc = scales[si];
        Scene s;
        for (int i = 0; i < 90; ++i) {
            const glm::dvec3 c = (kFarCentre + rnd3(g, -40, 40)) * sc;
            const double size = sc * (i % 3 == 0 ? 2.0 : i % 3 == 1 ? 0.05 : 1e-3);
            const glm::dvec3 b = c + rnd3(g, -size, size);
            glm::dvec3 d = c + rnd3(g, -size, size);
            if (i % 5 == 0) // a sliver: d 1e-7 of the edge's length off the edge c–b
                d = c + 0.37 * (b - c) + 1e-7 * glm::length(b - c) * glm::normalize(rnd3(g, -1, 1));
            s.add(Triangle(c, b, d), 0);
        }
        const Refs r(s.primitives);
        for (const auto& p : s.primitives) {
            const auto* tp = dynamic_cast<const Triangle*>(p.get());
            REQUIRE(tp);
            const glm::dvec3 from = (-kFarCentre + rnd3(g, -300, 300)) * sc;
            const glm::dvec3 pts[6] = {tp->v0,
                                       tp->v1,
                                       tp->v2,
                                       0.5 * (tp->v0 + tp->v1),
                                       tp->v1 + u(g) * (tp->v2 - tp->v1),
                                       tp->v2 + u(g) * (tp->v0 - tp->v2)};
            for (const glm::dvec3& q : pts)
                edgeHits[si] += aimAtOwn(r, *tp, from, q);
        }
    }
    // The exact code hits about half of these boundary rays: enough for a cut bound to lose
    // some at every scale.
    for (int si = 0; si < 3; ++si) {
        INFO("scale " << scales[si]);
        CHECK(edgeHits[si] > 120);
    }
}

TEST_CASE("rt_bvh_wide: boxes met at a vertex from far origins, some in an axis plane",
          "[raytrace][bvh]") {
    // Issue 21 (branch rtmesh4): the node test widens the ray's float origin by |o|max·2^-21
    // for its rounding (bvh_wide_kinds.h). Triangles with float-exact vertices (so their
    // boxes are tight at the vertices), a third of them flat in an axis plane, and rays
    // through the vertices from 1e3, 3e4 and 1e6 away, half of them nearly in that plane:
    // with the widening cut to 2^-60 the FMA node test this was written for (built and taken
    // back, see kinds.h) lost boxes the plain loop's hits lie in, while the SSE2 and AVX2
    // 4-wide paths of then kept them; every path must keep them.
    std::mt19937_64 g(2115);
    auto fexact = [](const glm::dvec3& v) { return glm::dvec3(glm::vec3(v)); };
    Scene s;
    for (int i = 0; i < 150; ++i) {
        // Every third one flat in an axis plane: its box has no depth on that axis, so the
        // ray's slab there is a point the other slabs must reach.
        const glm::dvec3 c = fexact(rnd3(g, -50, 50));
        glm::dvec3 b = fexact(c + rnd3(g, -1, 1)), e = fexact(c + rnd3(g, -1, 1));
        if (i % 3 == 0) b[i % 9 / 3] = e[i % 9 / 3] = c[i % 9 / 3];
        s.add(Triangle(c, b, e), 0);
    }
    const Refs r(s.primitives);
    int hits = 0;
    for (const auto& p : s.primitives) {
        const auto* tp = dynamic_cast<const Triangle*>(p.get());
        REQUIRE(tp);
        for (const glm::dvec3& q : {tp->v0, tp->v1, tp->v2})
            for (double dist : {1e3, 3e4, 1e6, 1e3, 3e4, 1e6}) {
                Ray ray;
                ray.direction = glm::normalize(rnd3(g, -1, 1));
                // Half of them nearly in the flat triangle's plane (grazing its box).
                if (g() & 1) ray.direction[int(g() % 3)] *= 1e-3;
                ray.direction = glm::normalize(ray.direction);
                ray.origin = q - dist * ray.direction;
                hits += compareRay(r, ray);
            }
    }
    // Most rays through a vertex hit that triangle or a nearer one.
    CHECK(hits > 400);
}

TEST_CASE("rt_bvh_wide: rays meeting primitives on the root box's faces, edges and corners",
          "[raytrace][bvh]") {
    // Issue 21 (branch rtmesh): a nearest-hit ray first meets the union of the root node's
    // float child boxes (Bvh::rootF_) in four lanes and stops there if it misses. Here the
    // scene's box is attained by primitives: triangles lying in its faces, with vertices
    // on its edges and at its corners, and spheres touching its faces. Rays from outside
    // aim at those vertices and edge points, some along the faces' planes (a zero
    // direction component: 0·inf in the slab test), with tMin and tMax cut at the hit.
    // A root test without the node test's margins (the origin not widened, or the exit
    // distances not stretched) loses some of these hits.
    std::mt19937_64 g(2114);
    Scene s;
    const glm::dvec3 lo{-3.25, -1.5, 0.75}, hi{2.5, 4.0, 3.125};
    const glm::dvec3 mid = 0.5 * (lo + hi);
    // Two triangles per face, in the face's plane, sharing the face's corners.
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            glm::dvec3 k[4];
            for (int m = 0; m < 4; ++m) {
                k[m][a] = side ? hi[a] : lo[a];
                k[m][b] = (m & 1) ? hi[b] : lo[b];
                k[m][c] = (m & 2) ? hi[c] : lo[c];
            }
            s.add(Triangle(k[0], k[1], k[3]), 0);
            s.add(Triangle(k[0], k[3], k[2]), 0);
            // And a sphere inside touching this face at its centre.
            glm::dvec3 sc = mid;
            sc[a] = (side ? hi[a] : lo[a]) + (side ? -0.5 : 0.5);
            s.add(Sphere(sc, 0.5), 0);
        }
    const Refs r(s.primitives);
    int hits = 0, rays = 0;
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 600; ++i) {
        // A point on the box's surface: a corner, a point on an edge or on a face.
        glm::dvec3 q;
        for (int a = 0; a < 3; ++a)
            q[a] = (g() & 1) ? hi[a] : lo[a];
        const int kind = i % 3, a0 = int(g() % 3);
        if (kind >= 1) q[a0] = lo[a0] + u(g) * (hi[a0] - lo[a0]);
        if (kind == 2) {
            const int a1 = (a0 + 1) % 3;
            q[a1] = lo[a1] + u(g) * (hi[a1] - lo[a1]);
        }
        // From outside towards q; every fourth ray in the plane of a face through q.
        glm::dvec3 d = glm::normalize(mid - q + rnd3(g, -2, 2));
        if (i % 4 == 0) {
            for (int a = 0; a < 3; ++a)
                if (q[a] == lo[a] || q[a] == hi[a]) {
                    d[a] = 0;
                    break;
                }
            if (glm::length(d) == 0) continue;
            d = glm::normalize(d);
        }
        Ray ray;
        ray.direction = d;
        ray.origin = q - (5.0 + 10.0 * u(g)) * d;
        ++rays;
        hits += compareRay(r, ray);
        Hit h;
        if (r.brute.intersect(ray, 0, kInf, h)) {
            // The limit at the hit (and tMin before it): every wide path against the plain
            // loop. (Not compareRay: the binary double tree, the tests' other reference,
            // loses some of these hits at t == tMax on the flat faces; noticed here,
            // docs/raytrace-scale.md, not mended on this branch.)
            for (const double tMin : {0.0, 0.5 * h.t})
                for (const auto& w : r.paths.trees) {
                    INFO("ray " << i << ", width " << w->stats().width << ", tMin " << tMin);
                    Hit hw;
                    REQUIRE(w->intersect(ray, tMin, h.t, hw));
                    REQUIRE(hw.primitive == h.primitive);
                    REQUIRE(hw.t == h.t);
                    REQUIRE(w->occluded(ray, tMin, h.t));
                }
        }
    }
    CHECK(rays > 500);
    CHECK(hits > 300);
}
