// Issue 21 point 3: packets of up to 8 rays sharing one walk (Bvh::intersectPacket,
// Bvh::occludedPacket) give, lane by lane, the single-ray walk's answers and the plain
// loop's: the same primitive, t, point and normals bit for bit, the same any-hit verdicts.
// Packets: coherent (a camera's neighbouring rays from one origin), same-sign rays from
// scattered origins (the interval test's origin intervals), rays aimed at the corners of
// the wide nodes' child boxes from one origin and from points on their faces, rays along
// edges and in face planes (zero direction components: those lanes go one by one),
// mixed signs, partially masked lanes, per-lane segments ending at or just before the
// nearest hit; every SIMD path (SSE2 4, AVX2 4 and 8 rays, AVX-512 8), the binary tree and packets
// switched off; scenes at scale 1, 1e-30 and 1e25. Renders with packets equal renders
// without, for 1 and 2 threads.
#include "core/raytrace/box.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/nff.h"
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

#include <array>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <random>
#include <utility>

using namespace wb::rt;
using wb::test::kInf;
using wb::test::mixedScene;
using wb::test::rnd3;

namespace {

bool sameBits(const glm::dvec3& a, const glm::dvec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

struct Trees {
    BruteForce brute;
    std::vector<std::unique_ptr<Bvh>> bvhs; // every packet path, the binary tree, packets off
    // binary: with the binary double-box tree.
    explicit Trees(const Scene& sc, const BvhOptions& base = {}, bool binary = true)
        : brute(sc.primitives) {
        const bool avx2 = __builtin_cpu_supports("avx2");
        for (int k = 0; k < (avx2 ? 3 : 1); ++k) {
            BvhOptions o = base;
            o.width = k == 2 ? 8 : 4;
            o.simd = k == 0 ? BvhSimd::Sse2 : BvhSimd::Avx2;
            bvhs.push_back(std::make_unique<Bvh>(sc.primitives, o));
            REQUIRE(bvhs.back()->packetWidth() == o.width);
        }
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) {
            BvhOptions o = base;
            o.simd = BvhSimd::Avx512;
            bvhs.push_back(std::make_unique<Bvh>(sc.primitives, o));
            REQUIRE(bvhs.back()->stats().avx512);
            REQUIRE(bvhs.back()->packetWidth() == 8);
        }
        if (binary) {
            BvhOptions bin = base;
            bin.width = 2;
            bvhs.push_back(std::make_unique<Bvh>(sc.primitives, bin));
        }
        // Issue 21: the quantised 8-wide nodes (BvhNodes::Quantised) on the 8-wide paths.
        if (avx2)
            for (BvhSimd simd : {BvhSimd::Avx2, BvhSimd::Avx512}) {
                if (simd == BvhSimd::Avx512 &&
                    !(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")))
                    continue;
                BvhOptions q = base;
                q.width = 8;
                q.simd = simd;
                q.nodes = BvhNodes::Quantised;
                bvhs.push_back(std::make_unique<Bvh>(sc.primitives, q));
                REQUIRE(bvhs.back()->packetWidth() == 8);
            }
        BvhOptions off = base;
        off.packets = false;
        bvhs.push_back(std::make_unique<Bvh>(sc.primitives, off));
        REQUIRE(bvhs.back()->packetWidth() == 1);
    }
};

struct PacketCounts {
    long lanes = 0, hits = 0, blocked = 0;
};

// Compares one packet on every tree against the plain loop and the single-ray walk.
void comparePacket(const Trees& t, const Ray* rays, const double* tMin, const double* tMax,
                   unsigned lanes, PacketCounts& n) {
    Hit want[kMaxPacket];
    unsigned wantFound = 0, wantBlocked = 0;
    for (int j = 0; j < kMaxPacket; ++j) {
        if (!((lanes >> j) & 1)) continue;
        ++n.lanes;
        if (t.brute.intersect(rays[j], tMin[j], tMax[j], want[j])) wantFound |= 1u << j;
        bool any = false;
        t.brute.forEachBlocker(rays[j], tMin[j], tMax[j],
                               [&](const Primitive&) { return any = true, false; });
        if (any) wantBlocked |= 1u << j;
    }
    n.hits += __builtin_popcount(wantFound);
    n.blocked += __builtin_popcount(wantBlocked);
    // Aggregate's default occludedPacket (ray by ray through forEachBlocker), which the
    // tracer's feeler packets would get from an aggregate without a packet walk.
    REQUIRE_FALSE(t.brute.hasOccludedPacket());
    REQUIRE(t.brute.occludedPacket(rays, tMin, tMax, nullptr, lanes) == wantBlocked);
    for (const auto& b : t.bvhs) {
        INFO("width " << b->stats().width << (b->stats().avx2 ? " AVX2" : "") << " packet "
                      << b->packetWidth() << " lanes " << lanes);
        Hit got[kMaxPacket];
        for (Hit& h : got)
            h.t = -7; // lanes outside the mask must stay untouched
        const unsigned found = b->intersectPacket(rays, tMin, tMax, got, lanes);
        REQUIRE(found == wantFound);
        for (int j = 0; j < kMaxPacket; ++j) {
            INFO("lane " << j);
            if (!((lanes >> j) & 1)) {
                REQUIRE(got[j].t == -7);
                continue;
            }
            if (!((found >> j) & 1)) continue;
            Hit single;
            REQUIRE(b->intersect(rays[j], tMin[j], tMax[j], single));
            REQUIRE(got[j].primitive == single.primitive);
            REQUIRE(got[j].t == single.t);
            if (b->stats().width == 2) { // the binary tree may pick another on a tie
                REQUIRE(got[j].t == want[j].t);
                continue;
            }
            REQUIRE(got[j].primitive == want[j].primitive);
            REQUIRE(got[j].t == want[j].t);
            REQUIRE(sameBits(got[j].point, want[j].point));
            REQUIRE(sameBits(got[j].normal, want[j].normal));
            REQUIRE(sameBits(got[j].outwardNormal, want[j].outwardNormal));
            REQUIRE(got[j].cosVN == want[j].cosVN);
        }
        REQUIRE(b->occludedPacket(rays, tMin, tMax, nullptr, lanes) == wantBlocked);
    }
}

// Packets of a scene at scale s: coherent, same-sign scattered, mixed, masked, segments.
void randomPackets(const Scene& sc, double s, std::mt19937_64& g, int count, PacketCounts& n) {
    const Trees t(sc);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < count; ++i) {
        Ray rays[kMaxPacket];
        double tMin[kMaxPacket], tMax[kMaxPacket];
        const glm::dvec3 o = rnd3(g, -14 * s, 14 * s);
        const glm::dvec3 aim = rnd3(g, -8 * s, 8 * s);
        const glm::dvec3 signs = glm::sign(rnd3(g, -1, 1));
        for (int j = 0; j < kMaxPacket; ++j) {
            switch (i % 4) {
            case 0: // coherent: one origin, neighbouring directions (a camera's row)
                rays[j].origin = o;
                rays[j].direction = glm::normalize(aim - o + glm::dvec3(j * 1e-2 * s, 0, 0));
                break;
            case 1: // scattered origins, directions of one octant
                rays[j].origin = o + rnd3(g, -2 * s, 2 * s);
                rays[j].direction = glm::normalize(signs * (glm::abs(rnd3(g, -1, 1)) + 0.01));
                break;
            case 2: // anything (mixed signs: those lanes go one by one)
                rays[j].origin = rnd3(g, -14 * s, 14 * s);
                rays[j].direction = glm::normalize(rnd3(g, -1, 1));
                break;
            default: // one origin, a wide fan: the interval test meets wide intervals
                rays[j].origin = o;
                rays[j].direction = glm::normalize(aim - o + rnd3(g, -4 * s, 4 * s));
                break;
            }
            tMin[j] = 0;
            tMax[j] = kInf;
        }
        unsigned lanes = 0xFF;
        if (i % 3 == 1) lanes = unsigned(g()) & 0xFF; // partially masked
        if (i % 7 == 3) {
            // Segments: each lane ends at its nearest hit, just before it, or midway.
            for (int j = 0; j < kMaxPacket; ++j) {
                Hit h;
                if (!t.brute.intersect(rays[j], 0, kInf, h)) continue;
                const int k = int(g() % 3);
                tMax[j] = k == 0 ? h.t : k == 1 ? std::nextafter(h.t, 0.0) : 0.5 * h.t;
                if (g() & 1) tMin[j] = 0.25 * h.t;
            }
        }
        comparePacket(t, rays, tMin, tMax, lanes, n);
    }
}

// Packets aimed at the corners of one wide node's child box: from one origin outside the
// box's lower corner (all directions in one octant), and from points on its faces.
template <class Node, class A>
void cornerPackets(const Trees& t, const std::vector<Node, A>& nodes, std::mt19937_64& g, int count,
                   double s, PacketCounts& n) {
    REQUIRE_FALSE(nodes.empty());
    constexpr int kW = int(sizeof(Node::count) / sizeof(Node::count[0]));
    for (int i = 0; i < count; ++i) {
        const Node& nd = nodes[g() % nodes.size()];
        const int c = int(g() % kW);
        if (nd.lo[0][c] > nd.hi[0][c]) continue; // empty slot
        glm::dvec3 lo, hi;
        for (int a = 0; a < 3; ++a) {
            lo[a] = nd.lo[a][c];
            hi[a] = nd.hi[a][c];
        }
        Ray rays[kMaxPacket];
        double tMin[kMaxPacket], tMax[kMaxPacket];
        const glm::dvec3 o = i % 3 == 2 ? glm::dvec3(0.0) : lo - glm::abs(rnd3(g, 0.1 * s, 3 * s));
        for (int j = 0; j < kMaxPacket; ++j) {
            const glm::dvec3 corner((j & 1) ? hi.x : lo.x, (j & 2) ? hi.y : lo.y,
                                    (j & 4) ? hi.z : lo.z);
            if (i % 3 == 1) {
                // Origins on the box's faces, directions of one octant.
                rays[j].origin = corner;
                const int a = int(g() % 3);
                rays[j].origin[a] = (g() & 1) ? lo[a] : hi[a];
                rays[j].direction = glm::normalize(glm::abs(rnd3(g, -1, 1)) + 1e-3);
            } else if (i % 5 == 4 && j >= 6) {
                // Along an edge (two zero components) and in a face plane (one).
                rays[j].origin = corner - glm::dvec3(20 * s, 0, 0);
                rays[j].direction = j == 6 ? glm::dvec3(1, 0, 0) : glm::normalize(glm::dvec3(1, 1, 0));
            } else {
                rays[j].origin = o;
                rays[j].direction = glm::normalize(corner - o);
            }
            tMin[j] = 0;
            tMax[j] = kInf;
        }
        comparePacket(t, rays, tMin, tMax, i % 4 == 3 ? unsigned(g()) & 0xFF : 0xFFu, n);
    }
}

} // namespace

TEST_CASE("packets: every lane is the single ray's and the plain loop's answer", "[bvh][packet]") {
    for (double s : {1.0, 1e-30, 1e25}) {
        INFO("scale " << s);
        std::mt19937_64 g(77);
        Scene sc;
        mixedScene(sc, 1500, g, s);
        PacketCounts n;
        randomPackets(sc, s, g, 300, n);
        INFO(n.lanes << " lanes, " << n.hits << " hits, " << n.blocked << " blocked");
        // The packets must meet things, or the comparisons above say little.
        REQUIRE(n.hits > n.lanes / 10);
        REQUIRE(n.blocked >= n.hits);
    }
}

TEST_CASE("packets: rays at the wide nodes' box corners, edges and faces", "[bvh][packet]") {
    for (double s : {1.0, 1e-30}) {
        INFO("scale " << s);
        std::mt19937_64 g(5);
        Scene sc;
        mixedScene(sc, 2000, g, s);
        const Trees t(sc);
        PacketCounts n;
        cornerPackets(t, t.bvhs.front()->wideNodes(), g, 300, s, n);
        if (!t.bvhs[2]->wideNodes8().empty())
            cornerPackets(t, t.bvhs[2]->wideNodes8(), g, 300, s, n);
        for (const auto& b : t.bvhs) // the quantised trees' rounded boxes
            if (!b->quantNodes8().empty()) cornerPackets(t, b->decodedQuantNodes8(), g, 300, s, n);
        INFO(n.lanes << " lanes, " << n.hits << " hits");
        REQUIRE(n.hits > n.lanes / 10);
    }
}

TEST_CASE("packets: a mesh with shared edges and vertices, ties", "[bvh][packet]") {
    // A grid of triangles, each twice (ties: the later copy wins), rays through vertices.
    Scene sc;
    const int m = 24;
    for (int y = 0; y < m; ++y)
        for (int x = 0; x < m; ++x) {
            const glm::dvec3 a(x, y, 0.1 * ((x * 7 + y * 3) % 5)), b(x + 1, y, 0.1 * ((x + y) % 3)),
                c(x, y + 1, 0.0), d(x + 1, y + 1, 0.05 * (x % 4));
            for (int k = 0; k < 2; ++k) {
                sc.add(Triangle(a, b, c), 0);
                sc.add(Triangle(b, d, c), 0);
            }
        }
    const Trees t(sc);
    std::mt19937_64 g(9);
    PacketCounts n;
    for (int i = 0; i < 400; ++i) {
        Ray rays[kMaxPacket];
        double tMin[kMaxPacket], tMax[kMaxPacket];
        const glm::dvec3 o(m * 0.5 + (double(g() % 100) - 50) * 0.1, m * 0.5, 10 + double(g() % 7));
        for (int j = 0; j < kMaxPacket; ++j) {
            const glm::dvec3 v(double(g() % (m + 1)), double(g() % (m + 1)), 0.0);
            rays[j].origin = o;
            rays[j].direction = glm::normalize(v + glm::dvec3(0.5 * (j % 2), 0, 0) * double(i % 2) - o);
            tMin[j] = 0;
            tMax[j] = kInf;
        }
        comparePacket(t, rays, tMin, tMax, 0xFF, n);
    }
    REQUIRE(n.hits > n.lanes / 2);
}

TEST_CASE("packets: a packet whose one hitting ray grazes the root box keeps its hit",
          "[bvh][packet]") {
    // Nearest-hit packets are first tested against the root's box (the union of the root
    // node's child boxes, bvh_wide_impl.h's rootLanes): a packet none of whose rays passes
    // is done before the walk, and the rays that fail leave it. Here one lane (each lane in
    // turn) aims at a point of the box's surface, where triangles cover the near faces: at
    // its corners and edges, just inside them, or anywhere on a near face; the other lanes,
    // in the same octant, miss the box by 5% of its size or more. So the one lane's hit
    // enters the box where the test is tight (entry and hit at one t; next to an edge
    // shared with a far face, entry and exit too), sometimes with a segment ending at the
    // hit. A test that turns the packet away, or the lane, loses the hit: comparePacket
    // compares every lane with the plain loop.
    for (double s : {1.0, 1e-30, 1e25}) {
        INFO("scale " << s);
        std::mt19937_64 g(31);
        Scene sc;
        // The box [-s, s]^3: two triangles a face, and small triangles inside (a tree of
        // more than one leaf, so the packet walk runs).
        for (int a = 0; a < 3; ++a)
            for (double side : {-s, s}) {
                glm::dvec3 v[4];
                for (int k = 0; k < 4; ++k) {
                    v[k][a] = side;
                    v[k][(a + 1) % 3] = (k == 1 || k == 2) ? s : -s;
                    v[k][(a + 2) % 3] = k >= 2 ? s : -s;
                }
                sc.add(Triangle(v[0], v[1], v[2]), 0);
                sc.add(Triangle(v[0], v[2], v[3]), 0);
            }
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 c = rnd3(g, -0.9 * s, 0.9 * s);
            sc.add(Triangle(c, c + rnd3(g, -0.1 * s, 0.1 * s), c + rnd3(g, -0.1 * s, 0.1 * s)), 0);
        }
        const Trees t(sc); // the binary tree too: its root test once lost these hits at tMax
        std::uniform_real_distribution<double> u(-1, 1);
        // Misses the box grown by 5% on every side (a double slab test; d has no zero part).
        auto missesBox = [&](const glm::dvec3& o, const glm::dvec3& d) {
            double t0 = 0, t1 = kInf;
            for (int a = 0; a < 3; ++a) {
                const double n = (-1.05 * s - o[a]) / d[a], f = (1.05 * s - o[a]) / d[a];
                t0 = std::max(t0, std::min(n, f));
                t1 = std::min(t1, std::max(n, f));
            }
            return t0 > t1;
        };
        PacketCounts n;
        int alone = 0; // packets whose grazing lane is their only hit
        for (int i = 0; i < 800; ++i) {
            Ray rays[kMaxPacket];
            double tMin[kMaxPacket], tMax[kMaxPacket];
            // The eye below the box's lower corner: every direction of the packet positive.
            const glm::dvec3 o = -s * (glm::dvec3(1.2) + glm::abs(rnd3(g, 0, 4)));
            // The target: on a near face (axis a at -s), its other two coordinates at the
            // face's edges (exactly, or 1e-12 / 1e-7 of the size inside) or anywhere.
            const int a = int(g() % 3);
            glm::dvec3 target;
            target[a] = -s;
            for (int b : {(a + 1) % 3, (a + 2) % 3}) {
                const int k = int(g() % 5);
                const double in = k == 0 ? 0 : k == 1 ? 1e-12 : 1e-7;
                const double edge = (g() & 1) ? s : -s;
                target[b] = k < 3 ? edge - std::copysign(in * s, edge) : u(g) * s;
            }
            const int hitLane = i % kMaxPacket;
            for (int j = 0; j < kMaxPacket; ++j) {
                rays[j].origin = o;
                tMin[j] = 0;
                tMax[j] = kInf;
                if (j == hitLane) {
                    rays[j].direction = glm::normalize(target - o);
                    continue;
                }
                do
                    rays[j].direction = glm::normalize(glm::abs(rnd3(g, 0, 1)) + 1e-3);
                while (!missesBox(o, rays[j].direction));
            }
            if (i % 4 == 3) {
                // The hitting lane's segment ends at its hit (the test's limit side).
                Hit h;
                if (t.brute.intersect(rays[hitLane], 0, kInf, h)) tMax[hitLane] = h.t;
            }
            INFO("packet " << i << " lane " << hitLane << " target " << target.x << ' ' << target.y
                           << ' ' << target.z << " tMax " << tMax[hitLane]);
            const long before = n.hits;
            comparePacket(t, rays, tMin, tMax, i % 5 == 4 ? unsigned(g()) | 1u << hitLane : 0xFFu,
                          n);
            if (n.hits == before + 1) ++alone;
        }
        INFO(n.lanes << " lanes, " << n.hits << " hits, " << alone << " packets of one hit");
        // Most targets are hit (those exactly on an edge or corner may fall to a neighbour or
        // to no triangle: the exact code decides), and the other lanes never are.
        REQUIRE(alone > 600);
        REQUIRE(n.hits == alone);
    }
}

TEST_CASE("packets: renders with packets equal renders without, any thread count",
          "[bvh][packet]") {
    for (const char* name : {"balls", "jacks", "teapot", "gears"}) {
        INFO(name);
        SceneFile sf = toScene(spdScene(name, 2));
        Bvh bvh(sf.scene->primitives);
        sf.scene->setAggregate(&bvh);
        PhongModel model;
        const LookAtCamera cam = sf.camera();
        ParallelRenderOptions opt;
        opt.trace.maxDepth = 4;
        opt.cornerRays = true;
        opt.threads = 1;
        opt.packets = false;
        const wb::Image single = renderParallel(*sf.scene, cam, model, 80, 64, opt);
        for (int threads : {1, 2}) {
            opt.threads = threads;
            opt.packets = true;
            ParallelRenderStats st;
            const wb::Image packets = renderParallel(*sf.scene, cam, model, 80, 64, opt, &st);
            REQUIRE(packets.data == single.data);
            REQUIRE(st.primaryRays == 81 * 65);
        }
        opt.cornerRays = false;
        opt.packets = false;
        const wb::Image centresSingle = renderParallel(*sf.scene, cam, model, 70, 50, opt);
        opt.packets = true;
        REQUIRE(renderParallel(*sf.scene, cam, model, 70, 50, opt).data == centresSingle.data);
        sf.scene->setAggregate(nullptr);
    }
}

TEST_CASE("packets: leaves tested transposed keep every grazing hit", "[bvh][packet]") {
    // A leaf entered by 3 or more rays of a packet tests its spheres and triangles one
    // primitive against all the lanes (bvh_wide_impl.h, kTransposeLanes), each lane doing its
    // ray's own float test with that test's margin. Rays from one origin (all 8 lanes, so
    // the transposed path runs) aimed exactly at triangle vertices and at points on their
    // edges, and tangent to spheres: the exact code hits (or just misses) them, and a
    // float test without its margin loses some of those hits (cut either margin to 0 in
    // sphereLanesTest / triangleLanesTest and this test goes red).
    std::mt19937_64 g(21);
    for (double s : {1.0, 1e-30, 1e25}) {
        INFO("scale " << s);
        Scene sc;
        std::vector<std::array<glm::dvec3, 3>> tris;
        std::vector<std::pair<glm::dvec3, double>> balls;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 c = rnd3(g, -10 * s, 10 * s);
            if (i % 2) {
                const std::array<glm::dvec3, 3> v = {c, c + rnd3(g, -s, s), c + rnd3(g, -s, s)};
                sc.add(Triangle(v[0], v[1], v[2]), 0);
                tris.push_back(v);
            } else {
                const double r = std::uniform_real_distribution<double>(0.05 * s, 0.6 * s)(g);
                sc.add(Sphere(c, r), 0);
                balls.emplace_back(c, r);
            }
        }
        const Trees t(sc);
        PacketCounts n;
        std::uniform_real_distribution<double> u(0, 1);
        for (int i = 0; i < 400; ++i) {
            Ray rays[kMaxPacket];
            double tMin[kMaxPacket], tMax[kMaxPacket];
            const glm::dvec3 o = rnd3(g, -20 * s, 20 * s);
            // Eight targets near one another (so the lanes share leaves): on one triangle
            // (its vertices and points on its edges) or on one sphere's silhouette.
            glm::dvec3 target[kMaxPacket];
            if (i % 2) {
                const auto& v = tris[g() % tris.size()];
                for (int j = 0; j < kMaxPacket; ++j) {
                    const int e = j % 3;
                    target[j] = j < 3 ? v[e] : v[e] + u(g) * (v[(e + 1) % 3] - v[e]);
                }
            } else {
                const auto& [c, r] = balls[g() % balls.size()];
                const glm::dvec3 w = glm::normalize(c - o);
                const glm::dvec3 a = glm::normalize(glm::cross(w, glm::dvec3(0.3, 0.5, 0.7)));
                const glm::dvec3 b = glm::cross(w, a);
                for (int j = 0; j < kMaxPacket; ++j) {
                    // Tangent: the point of the silhouette seen from o at angle φ.
                    const double phi = 0.1 * j + 0.01 * double(i % 7);
                    const double d = glm::length(c - o);
                    const double back = r * r / d, rad = r * std::sqrt(1 - (r / d) * (r / d));
                    target[j] = c - back * w + rad * (std::cos(phi) * a + std::sin(phi) * b);
                }
            }
            for (int j = 0; j < kMaxPacket; ++j) {
                rays[j].origin = o;
                rays[j].direction = glm::normalize(target[j] - o);
                tMin[j] = 0;
                tMax[j] = kInf;
            }
            comparePacket(t, rays, tMin, tMax, i % 5 == 4 ? 0x7Fu : 0xFFu, n);
        }
        INFO(n.lanes << " lanes, " << n.hits << " hits");
        REQUIRE(n.hits > n.lanes / 4);
    }
}

TEST_CASE("packets: leaves of up to seven triangles, tested transposed past the first four",
          "[bvh][packet]") {
    // The packet tests' other scenes have leaves of at most four primitives (the default
    // maxLeafSize), so a transposed triangle run never went past four: the single walk's
    // filter takes four triangles at a time, the last chunk partly filled, and the leaf
    // data layouts of issue 21's ninth session (blocks of four) split runs there. Costly
    // nodes make leaves of up to 7 (as the single-ray test "scenes of one kind" does), a mesh
    // of 601 triangles, and rays from one origin at one triangle's vertices and edges enter
    // its leaf together, so the transposed test reads its fifth to seventh triangles.
    std::mt19937_64 g(31);
    Scene sc;
    std::vector<std::array<glm::dvec3, 3>> tris;
    for (int i = 0; i < 601; ++i) {
        const glm::dvec3 c = rnd3(g, -10, 10);
        const std::array<glm::dvec3, 3> v = {c, c + rnd3(g, -1, 1), c + rnd3(g, -1, 1)};
        sc.add(Triangle(v[0], v[1], v[2]), 0);
        tris.push_back(v);
    }
    BvhOptions big;
    big.maxLeafSize = 7;
    big.traversalCost = 8;
    const Trees t(sc, big);
    // Not vacuous: some leaves hold more than four triangles (one run: the scene has one
    // kind).
    int longRuns = 0;
    for (const auto& nd : t.bvhs.front()->wideNodes())
        for (const auto c : nd.count)
            longRuns += c > 4;
    INFO(longRuns << " leaves of more than four triangles");
    REQUIRE(longRuns > 20);
    PacketCounts n;
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 400; ++i) {
        Ray rays[kMaxPacket];
        double tMin[kMaxPacket], tMax[kMaxPacket];
        const glm::dvec3 o = rnd3(g, -20, 20);
        const auto& v = tris[g() % tris.size()];
        for (int j = 0; j < kMaxPacket; ++j) {
            const int e = j % 3;
            const glm::dvec3 target = j < 3 ? v[e] : v[e] + u(g) * (v[(e + 1) % 3] - v[e]);
            rays[j].origin = o;
            rays[j].direction = glm::normalize(target - o);
            tMin[j] = 0;
            tMax[j] = kInf;
        }
        comparePacket(t, rays, tMin, tMax, i % 5 == 4 ? 0x7Fu : 0xFFu, n);
    }
    INFO(n.lanes << " lanes, " << n.hits << " hits");
    REQUIRE(n.hits > n.lanes / 2);
}

TEST_CASE("packets: transposed sphere lanes keep grazing hits from far origins", "[bvh][packet]") {
    // The sphere lanes' margin has a term for the ray's origin, |o|₁·kSphereMargin
    // (sphereLanes builds it for all lanes at once from the packet's doubles): rays from
    // origins 10^4 times farther out than the spheres, tangent to them, in packets of 8
    // from one origin (the transposed path). The origin's float rounding is then larger
    // than the spheres' own margin, so a lane test without the origin term loses grazing
    // hits (set som to 0 in sphereLanes and this test goes red).
    std::mt19937_64 g(2107);
    for (double s : {1.0, 1e-30, 1e25}) {
        INFO("scale " << s);
        Scene sc;
        std::vector<std::pair<glm::dvec3, double>> balls;
        for (int i = 0; i < 200; ++i) {
            const glm::dvec3 c = rnd3(g, -10 * s, 10 * s);
            const double r = std::uniform_real_distribution<double>(0.05 * s, 0.6 * s)(g);
            sc.add(Sphere(c, r), 0);
            balls.emplace_back(c, r);
        }
        const Trees t(sc);
        PacketCounts n;
        for (int i = 0; i < 300; ++i) {
            Ray rays[kMaxPacket];
            double tMin[kMaxPacket], tMax[kMaxPacket];
            const glm::dvec3 o = 1e5 * s * glm::normalize(rnd3(g, -1, 1));
            const auto& [c, r] = balls[g() % balls.size()];
            const glm::dvec3 w = glm::normalize(c - o);
            const glm::dvec3 a = glm::normalize(glm::cross(w, glm::dvec3(0.3, 0.5, 0.7)));
            const glm::dvec3 b = glm::cross(w, a);
            const double d = glm::length(c - o);
            const double back = r * r / d, rad = r * std::sqrt(1 - (r / d) * (r / d));
            for (int j = 0; j < kMaxPacket; ++j) {
                const double phi = 0.1 * j + 0.01 * double(i % 7);
                const glm::dvec3 target =
                    c - back * w + rad * (std::cos(phi) * a + std::sin(phi) * b);
                rays[j].origin = o;
                rays[j].direction = glm::normalize(target - o);
                tMin[j] = 0;
                tMax[j] = kInf;
            }
            comparePacket(t, rays, tMin, tMax, i % 5 == 4 ? 0x7Fu : 0xFFu, n);
        }
        INFO(n.lanes << " lanes, " << n.hits << " hits");
        REQUIRE(n.hits > n.lanes / 4);
    }
}

// The packet path's shadow cache (Tracer::traceFrom: each light's last opaque blocker, one
// level per depth, asked first by its exact test). A floor under rows of opaque spheres
// (shadow edges along every packet row), transparent spheres in front of them (a feeler
// meets a transparent blocker, then an opaque one, or only the transparent one: its
// transmittance is kt, never the cache's 0), mirror spheres (the cache of the reflected
// rays' level) and a light placed between the floor and a sphere above it (that sphere
// lies beyond the light on the floor's feelers: the cache must ask the segment, not the
// ray). Every picture equals the single path's, for 1, 2 and 3 threads and every tree.
namespace {
// The frames with packets (for each thread count) equal the one-thread single-ray frame byte
// for byte, with the same ray counts, for corner and centre rays (phong model, depth 4).
void requireSingleFrame(const Scene& sc, const LookAtCamera& cam, int w, int h,
                        std::initializer_list<int> threadCounts) {
    PhongModel model;
    for (bool corners : {true, false}) {
        ParallelRenderOptions opt;
        opt.trace.maxDepth = 4;
        opt.cornerRays = corners;
        opt.threads = 1;
        opt.packets = false;
        ParallelRenderStats sst;
        const wb::Image single = renderParallel(sc, cam, model, w, h, opt, &sst);
        for (int threads : threadCounts) {
            opt.threads = threads;
            opt.packets = true;
            ParallelRenderStats st;
            REQUIRE(renderParallel(sc, cam, model, w, h, opt, &st).data == single.data);
            REQUIRE(st.primaryRays == sst.primaryRays);
            REQUIRE(st.shadowRays == sst.shadowRays);
            REQUIRE(st.secondaryRays == sst.secondaryRays);
        }
    }
}

// The shadow cache's scene (below).
void shadowCacheScene(Scene& sc) {
    Material floor;
    floor.colour = {0.9, 0.8, 0.6};
    floor.kd = 0.8;
    const int mFloor = sc.addMaterial(floor);
    Material opaque;
    opaque.colour = {0.8, 0.2, 0.2};
    const int mOpaque = sc.addMaterial(opaque);
    Material glass;
    glass.colour = {0.6, 0.9, 0.9};
    glass.kt = 0.6;
    glass.medium.refract = 1.3;
    const int mGlass = sc.addMaterial(glass);
    Material mirror;
    mirror.kr = 0.5;
    const int mMirror = sc.addMaterial(mirror);
    sc.add(Triangle({-20, -20, 0}, {20, -20, 0}, {20, 20, 0}), mFloor);
    sc.add(Triangle({-20, -20, 0}, {20, 20, 0}, {-20, 20, 0}), mFloor);
    for (int i = 0; i < 5; ++i)
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 c(-4.0 + 2.0 * i, -3.0 + 2.5 * k, 1.0 + 0.3 * k);
            const int m = (i + k) % 3 == 0 ? mGlass : (i + k) % 3 == 1 ? mOpaque : mMirror;
            sc.add(Sphere(c, 0.7), m);
        }
    sc.add(Sphere({1, 1, 5.5}, 1.0), mOpaque); // above the low light
    sc.lights.push_back(Light::point({1, 1, 3.5}));
    sc.lights.push_back(Light::point({-8, -6, 12}));
    sc.lights.push_back(Light::directional({0.3, 0.5, -1}));
}
} // namespace

TEST_CASE("packets: the shadow cache along a row keeps the single path's picture",
          "[bvh][packet][shadow]") {
    Scene sc;
    shadowCacheScene(sc);
    const LookAtCamera cam({9, -12, 9}, {0, 0, 0.5}, {0, 0, 1}, 45);
    Trees trees(sc);
    for (const auto& bvh : trees.bvhs) {
        INFO("width " << bvh->stats().width << " avx2 " << bvh->stats().avx2 << " avx512 "
                      << bvh->stats().avx512 << " packets " << bvh->packetWidth());
        sc.setAggregate(bvh.get());
        requireSingleFrame(sc, cam, 96, 72, {1, 2, 3});
    }
    sc.setAggregate(nullptr);
}

// The cache's contract, adversarially: whatever primitive each entry holds (opaque,
// transparent, a mirror, the hit's own floor triangle, the sphere beyond the low light on
// the floor's feelers, or null), traceFrom's colour is the uncached one bit for bit.
TEST_CASE("packets: any shadow cache content gives the uncached colour", "[bvh][packet][shadow]") {
    Scene sc;
    shadowCacheScene(sc);
    Bvh bvh(sc.primitives);
    sc.setAggregate(&bvh);
    PhongModel model;
    TraceSettings settings;
    settings.maxDepth = 4;
    const Tracer tracer(sc, model, settings);
    const LookAtCamera cam({9, -12, 9}, {0, 0, 0.5}, {0, 0, 1}, 45);
    const std::size_t levels = std::size_t(settings.maxDepth + 1) * sc.lights.size();
    std::vector<const Primitive*> contents{nullptr};
    for (const auto& p : sc.primitives)
        contents.push_back(p.get());
    int hits = 0, changed = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            const Ray ray = cam.primaryRay(x, y, 48, 36);
            Hit hit;
            if (!sc.intersect(ray, 0.0, kInf, hit)) hit.primitive = nullptr;
            hits += hit.primitive != nullptr;
            RayCounts plainCounts;
            const Color plain = tracer.traceFrom(ray, hit, plainCounts);
            for (const Primitive* q : contents) {
                std::vector<const Primitive*> cache(levels, q);
                RayCounts counts;
                const Color c = tracer.traceFrom(ray, hit, counts, cache.data());
                INFO("pixel " << x << " " << y);
                REQUIRE(sameBits(c, plain));
                REQUIRE(counts.shadow == plainCounts.shadow);
                for (const Primitive* left : cache)
                    changed += left != q;
            }
        }
    REQUIRE(hits > 48 * 36 / 2);
    REQUIRE(changed > 0); // the feelers wrote their blockers back
    sc.setAggregate(nullptr);
}

// The packet path's direct light in lanes (Tracer::traceFromPacket, PhongModel::directLanes):
// each frame equals the single-ray frame byte for byte, with the same ray counts. SPD
// scenes (balls: mirrors; jacks: cylinders and mirrors; gears: glass, refraction; teapot:
// a triangle mesh; rings), and the shadow cache's scene with point lights only (so the
// lanes are used) and a textured sphere, emission, attenuated lights (a textured hit
// falls back to the single path, its neighbours in the lanes), and with its directional
// light kept (lanesApply refuses: every hit the single path).
TEST_CASE("packets: direct light in lanes keeps the single path's picture",
          "[bvh][packet][phong]") {
    // `lanes`: whether the scene's lights let the packet path shade in lanes.
    const auto check = [](Scene& sc, const LookAtCamera& cam, int w, int h, bool lanes) {
        REQUIRE(PhongModel::lanesApply(sc) == lanes);
        Bvh bvh(sc.primitives);
        sc.setAggregate(&bvh);
        requireSingleFrame(sc, cam, w, h, {1, 2});
        sc.setAggregate(nullptr);
    };
    for (const char* name : {"balls", "jacks", "gears", "teapot", "rings"}) {
        INFO(name);
        SceneFile sf = toScene(spdScene(name, 2));
        check(*sf.scene, sf.camera(), 96, 80, true);
    }
    Scene sc;
    shadowCacheScene(sc);
    const LookAtCamera cam({9, -12, 9}, {0, 0, 0.5}, {0, 0, 1}, 45);
    INFO("shadow cache scene, directional light");
    check(sc, cam, 96, 72, false);
    sc.lights.pop_back(); // point lights only: the lanes
    sc.lights[0].constantAttenuation = 0.5;
    sc.lights[0].linearAttenuation = 0.05;
    sc.lights[0].quadraticAttenuation = 0.01;
    sc.lights[1].ambient = {0.1, 0.05, 0.0};
    sc.globalAmbient = {0.05, 0.05, 0.1};
    wb::Image tex(2, 2, 3);
    for (int i = 0; i < 12; ++i)
        tex.data[std::size_t(i)] = uint8_t(40 * i);
    Material textured;
    textured.texture = &tex;
    textured.kr = 0.3;
    textured.emission = {0.1, 0.0, 0.05};
    sc.add(Sphere({-2, 3, 1.5}, 1.2), sc.addMaterial(textured));
    INFO("shadow cache scene, point lights, a textured sphere");
    check(sc, cam, 96, 72, true);
}

// The eye hits' feelers of one point light as one occludedPacket walk (Tracer::traceFromPacket,
// issue 21), taken only when every material is opaque (kt < opaqueKt: then a feeler's
// transmittance is 0 when anything blocks its segment, else 1). The shadow cache's scene
// made opaque, point lights only: feelers from the floor (flat: skipped) and from spheres
// (curved: asked), the low light between the floor and the sphere above it (the packet
// must ask each lane's segment, not its ray), every tree and SIMD path, 1–3 threads. Then
// one material at kt = opaqueKt exactly (not opaque: its shadow is kt, so every feeler goes
// the single path).
TEST_CASE("packets: an opaque scene's eye feelers walk as packets with the single path's picture",
          "[bvh][packet][shadow]") {
    Scene sc;
    shadowCacheScene(sc);
    sc.lights.pop_back(); // point lights only: the lanes
    for (Material& m : sc.materials)
        m.kt = 0.0;
    const LookAtCamera cam({9, -12, 9}, {0, 0, 0.5}, {0, 0, 1}, 45);
    Trees trees(sc);
    for (const auto& bvh : trees.bvhs) {
        INFO("width " << bvh->stats().width << " avx2 " << bvh->stats().avx2 << " avx512 "
                      << bvh->stats().avx512 << " packets " << bvh->packetWidth());
        sc.setAggregate(bvh.get());
        requireSingleFrame(sc, cam, 96, 72, {1, 2, 3});
    }
    INFO("one material at kt = opaqueKt");
    sc.materials[2].kt = TraceSettings{}.opaqueKt;
    sc.setAggregate(trees.bvhs.front().get());
    requireSingleFrame(sc, cam, 96, 72, {1, 2});
    sc.setAggregate(nullptr);
}

TEST_CASE("packets: a row of corner rays in lanes is rayAt's bit for bit", "[packet][camera]") {
    // Cameras off the axes (every component of the frame nonzero), with and without the
    // hither plane (the SPD scenes set one), image sizes odd and even, rows of 1..8 rays
    // starting at even and odd x (the last ray of an odd row goes through rayAt itself).
    const auto same = [](const Ray& a, const Ray& b) {
        return std::memcmp(&a.origin, &b.origin, sizeof a.origin) == 0 &&
               std::memcmp(&a.direction, &b.direction, sizeof a.direction) == 0 &&
               a.weight == b.weight && a.depth == b.depth && a.medium.refract == b.medium.refract &&
               a.medium.atten == b.medium.atten;
    };
    int rows = 0;
    for (const double hither : {0.0, 0.3, 1.7}) {
        LookAtCamera cam({2.1, -3.7, 1.3}, {0.2, 0.4, -0.35}, {0.1, 0.2, 1.0}, 37.5);
        cam.setHither(hither);
        for (const auto& [w, h] : {std::pair{512, 512}, std::pair{97, 61}}) {
            for (int y = 0; y <= h; y += 7) {
                for (int x0 = 0; x0 <= w; x0 += 5) {
                    const int n = 1 + (x0 + y) % kMaxPacket;
                    Ray row[kMaxPacket];
                    cam.rowRays(x0, y, n, w, h, row);
                    for (int k = 0; k < n; ++k) {
                        INFO("hither " << hither << " size " << w << "x" << h << " ray (" << x0 + k
                                       << ", " << y << ")");
                        REQUIRE(same(row[k], cam.rayAt(x0 + k, y, w, h)));
                    }
                    ++rows;
                }
            }
        }
    }
    CHECK(rows > 1000);
}

TEST_CASE("packets: offsetRayOrigins in lanes is offsetRayOrigin bit for bit", "[packet]") {
    // Coordinates on both sides of offsetRayOrigin's 1/32 switch (and exactly at it), ±0,
    // negative and positive, tiny (2^-60) and huge (2^60) scales; unit normals with every
    // sign and axis-aligned ones (a zero component: no offset along that axis).
    std::mt19937_64 g(6);
    std::uniform_real_distribution<double> u(-1, 1);
    const double special[] = {0.0, -0.0, 1.0 / 32, -1.0 / 32, std::nextafter(1.0 / 32, 0.0),
                              -std::nextafter(1.0 / 32, 0.0), 1e-300, -3.5, 7.0};
    int points = 0, nearZero = 0, negative = 0;
    for (int i = 0; i < 4000; ++i) {
        double p[3][kMaxPacket], n[3][kMaxPacket], o[3][kMaxPacket];
        for (int k = 0; k < kMaxPacket; ++k) {
            const double scale = std::ldexp(1.0, int(g() % 121) - 60);
            glm::dvec3 nv(u(g), u(g), u(g));
            if (k == 3) nv = {0, 0, -1};
            nv = glm::normalize(nv);
            for (int a = 0; a < 3; ++a) {
                p[a][k] = (i + k + a) % 7 == 0 ? special[(i + a) % 9] : scale * u(g);
                n[a][k] = nv[a];
            }
        }
        const double* const pp[3] = {p[0], p[1], p[2]};
        const double* const nn[3] = {n[0], n[1], n[2]};
        double* const oo[3] = {o[0], o[1], o[2]};
        offsetRayOrigins(pp, nn, oo, kMaxPacket);
        for (int k = 0; k < kMaxPacket; ++k) {
            const glm::dvec3 pk(p[0][k], p[1][k], p[2][k]), nk(n[0][k], n[1][k], n[2][k]);
            const glm::dvec3 want = offsetRayOrigin(pk, nk);
            const glm::dvec3 got(o[0][k], o[1][k], o[2][k]);
            INFO("packet " << i << " lane " << k);
            REQUIRE(std::memcmp(&got, &want, sizeof want) == 0);
            ++points;
            for (int a = 0; a < 3; ++a) {
                nearZero += std::fabs(pk[a]) < 1.0 / 32;
                negative += pk[a] < 0;
            }
        }
    }
    CHECK(nearZero > points / 4);
    CHECK(negative > points);
}
