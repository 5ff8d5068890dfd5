// Issue 21 point 1: a shadow feeler never asks the flat primitive it starts on. A ray
// leaving a plane meets it again at no t > 0, so that primitive's exact test could only
// say "no" (or report its own rounding error); the aggregate now skips it by identity
// (Aggregate::forEachBlocker's / Bvh::occluded's `skip`) instead of testing it and
// letting the tracer's visitor throw the answer away. Checked here:
//  - every aggregate (plain loop, binary tree, every SIMD path of the wide tree) answers
//    exactly as "every primitive but `skip`, asked in turn" on triangles that each have a
//    parallel copy right above them (the next primitive in the scene: skipping it instead
//    changes the answers, and the test says so), among spheres and cones;
//  - a curved primitive keeps its test: from the inside of a sphere towards a light
//    outside it, the sphere itself is the blocker, so the tracer must not pass it;
//  - pictures: the tracer with the skip in the aggregate equals, bit for bit, the tracer
//    with the old visitor-side filter (an aggregate that ignores `skip`).
#include "core/raytrace/bvh.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/nff.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/spd.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/tracer.h"
#include "core/raytrace/triangle.h"

#include "random_scene.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <set>

using namespace wb::rt;
using wb::test::kInf;
using wb::test::rnd3;

namespace {

// The reference: every primitive but `skip`, asked in scene order.
bool referenceOccluded(const Scene& sc, const Ray& ray, double tMin, double tMax,
                       const Primitive* skip) {
    for (const auto& p : sc.primitives)
        if (p.get() != skip && p->occluded(ray, tMin, tMax)) return true;
    return false;
}

std::set<const Primitive*> referenceBlockers(const Scene& sc, const Ray& ray, double tMin,
                                             double tMax, const Primitive* skip) {
    std::set<const Primitive*> out;
    for (const auto& p : sc.primitives)
        if (p.get() != skip && p->occluded(ray, tMin, tMax)) out.insert(p.get());
    return out;
}

// Every aggregate the tracer may be given.
std::vector<std::unique_ptr<Aggregate>> aggregates(const Scene& sc) {
    std::vector<std::unique_ptr<Aggregate>> v;
    v.push_back(std::make_unique<BruteForce>(sc.primitives));
    BvhOptions bin;
    bin.width = 2;
    v.push_back(std::make_unique<Bvh>(sc.primitives, bin));
    const bool avx2 = __builtin_cpu_supports("avx2");
    for (int k = 0; k < (avx2 ? 3 : 1); ++k) {
        BvhOptions o;
        o.width = k == 2 ? 8 : 4;
        o.simd = k == 0 ? BvhSimd::Sse2 : BvhSimd::Avx2;
        v.push_back(std::make_unique<Bvh>(sc.primitives, o));
    }
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) {
        BvhOptions o;
        o.simd = BvhSimd::Avx512;
        v.push_back(std::make_unique<Bvh>(sc.primitives, o));
    }
    return v;
}

// An aggregate that ignores `skip` (the walk before issue 21: every primitive asked, the
// tracer's visitor dropping its own flat primitive afterwards).
class IgnoresSkip : public Aggregate {
  public:
    explicit IgnoresSkip(const Aggregate& a) : a_(a) {}
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override {
        return a_.intersect(ray, tMin, tMax, hit);
    }
    void forEachHit(const Ray& ray, double tMin, double tMax,
                    const std::function<bool(const Hit&)>& visit) const override {
        a_.forEachHit(ray, tMin, tMax, visit);
    }
    void forEachBlocker(const Ray& ray, double tMin, double tMax,
                        const std::function<bool(const Primitive&)>& visit,
                        const Primitive* skip) const override {
        a_.forEachBlocker(ray, tMin, tMax, [&](const Primitive& p) {
            return &p == skip || visit(p); // the old visitor-side filter
        });
    }

  private:
    const Aggregate& a_;
};

// An aggregate that asks every primitive, `skip` included, and walks no packets: the exact
// tests' own answer for every feeler (the tracer's visitor drops only a flat `self`).
class AsksEveryPrimitive : public Aggregate {
  public:
    explicit AsksEveryPrimitive(const Aggregate& a) : a_(a) {}
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override {
        return a_.intersect(ray, tMin, tMax, hit);
    }
    void forEachHit(const Ray& ray, double tMin, double tMax,
                    const std::function<bool(const Hit&)>& visit) const override {
        a_.forEachHit(ray, tMin, tMax, visit);
    }
    void forEachBlocker(const Ray& ray, double tMin, double tMax,
                        const std::function<bool(const Primitive&)>& visit,
                        const Primitive*) const override {
        a_.forEachBlocker(ray, tMin, tMax, visit, nullptr);
    }

  private:
    const Aggregate& a_;
};

// The sphere cases' scene: a unit sphere (primitive 0) and a neighbour of radius 0.4 0.1 off.
void addGrazingSpheres(Scene& sc) {
    sc.add(Sphere({0.25, -0.5, 0.125}, 1.0), 0);
    sc.add(Sphere({1.75, -0.5, 0.125}, 0.4), 0);
}

// An eye ray from above at addGrazingSpheres' unit sphere; true, with its hit, when that sphere
// is what it meets first.
bool eyeHitOnSphere(const Scene& sc, std::mt19937_64& g, Ray& eye, Hit& h) {
    std::uniform_real_distribution<double> u(-1, 1);
    eye.origin = {0.25 + 3 * u(g), -0.5 + 3 * u(g), 6};
    eye.direction =
        glm::normalize(glm::dvec3(0.25, -0.5, 0.125) + 0.6 * rnd3(g, -1, 1) - eye.origin);
    return sc.intersect(eye, 0.0, kInf, h) && h.primitive == sc.primitives[0].get();
}

// A point light 10 from the hit along a tangent direction tilted off the surface by cos.
Light grazingLight(const Hit& h, double cos, std::mt19937_64& g) {
    const glm::dvec3 t = glm::normalize(glm::cross(h.normal, rnd3(g, -1, 1)));
    const glm::dvec3 dir = glm::normalize(t + cos * h.normal);
    return Light::point(h.point + 10.0 * dir, glm::dvec3(1));
}

} // namespace

TEST_CASE("shadow self-skip: only the flat primitive the feeler leaves is skipped", "[bvh][skip]") {
    std::mt19937_64 g(21);
    Scene sc;
    // Triangles, each followed in the scene by a parallel copy 1e-3 above it (the "next"
    // primitive, which blocks rays leaving the first upwards), among spheres and cones.
    std::vector<const Triangle*> tris;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 c = rnd3(g, -5, 5);
        const glm::dvec3 a = c + rnd3(g, -0.5, 0.5), b = c + rnd3(g, -0.5, 0.5),
                         d = c + rnd3(g, -0.5, 0.5);
        Triangle& t = sc.add(Triangle(a, b, d), 0);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, d - a));
        sc.add(Triangle(a + 1e-3 * n, b + 1e-3 * n, d + 1e-3 * n), 0);
        tris.push_back(&t);
        if (i % 3 == 0) sc.add(Sphere(rnd3(g, -5, 5), 0.3), 0);
        if (i % 5 == 0) sc.add(Cone(rnd3(g, -5, 5), 0.2, rnd3(g, -5, 5), 0.1), 0);
    }
    std::map<const Primitive*, const Primitive*> nextOf; // in scene order
    for (std::size_t i = 0; i + 1 < sc.primitives.size(); ++i)
        nextOf[sc.primitives[i].get()] = sc.primitives[i + 1].get();
    const auto aggs = aggregates(sc);
    std::uniform_real_distribution<double> u(0, 1);
    int nextMatters = 0, selfMatters = 0, rays = 0;
    for (const Triangle* t : tris) {
        const glm::dvec3 n = glm::normalize(glm::cross(t->v1 - t->v0, t->v2 - t->v0));
        for (int k = 0; k < 12; ++k) {
            double a = u(g), b = u(g);
            if (a + b > 1) a = 1 - a, b = 1 - b;
            Ray ray;
            ray.origin = t->v0 + a * (t->v1 - t->v0) + b * (t->v2 - t->v0);
            glm::dvec3 dir = glm::normalize(rnd3(g, -1, 1));
            // Half the rays leave towards the copy above (the next primitive), half anywhere;
            // a few graze the plane.
            if (k % 2 == 0 && glm::dot(dir, n) < 0) dir = -dir;
            if (k == 11) dir = glm::normalize(dir - glm::dot(dir, n) * n + 1e-9 * n);
            ray.direction = dir;
            const double tMax = k % 3 == 0 ? kInf : 0.5 + 3 * u(g);
            const Primitive* next = nextOf.at(t);
            const bool want = referenceOccluded(sc, ray, 0.0, tMax, t);
            const auto wantSet = referenceBlockers(sc, ray, 0.0, tMax, t);
            // The scene must tell skipping `t` from skipping its neighbour or nothing,
            // or this test could not fail for those mistakes (counted below).
            nextMatters += want != referenceOccluded(sc, ray, 0.0, tMax, next);
            selfMatters += wantSet != referenceBlockers(sc, ray, 0.0, tMax, nullptr);
            ++rays;
            for (const auto& ag : aggs) {
                std::set<const Primitive*> got;
                ag->forEachBlocker(
                    ray, 0.0, tMax, [&](const Primitive& p) { return got.insert(&p), true; }, t);
                REQUIRE(got == wantSet);
                bool any = false;
                ag->forEachBlocker(
                    ray, 0.0, tMax, [&](const Primitive&) { return any = true, false; }, t);
                REQUIRE(any == want);
                if (const auto* bvh = dynamic_cast<const Bvh*>(ag.get())) {
                    INFO("width " << bvh->stats().width << (bvh->stats().avx2 ? " AVX2" : ""));
                    REQUIRE(bvh->occluded(ray, 0.0, tMax, t) == want);
                }
            }
        }
    }
    INFO(rays << " rays; the neighbour decides " << nextMatters << ", the triangle itself "
              << selfMatters);
    // Measured 2026-12-01: several hundred of 3600 rays each (the copy 1e-3 above blocks
    // every ray leaving upwards; origins off the plane by rounding make the triangle
    // itself a "blocker" at t ~ 1e-17 for some).
    REQUIRE(nextMatters > 100);
    REQUIRE(selfMatters > 0);
}

TEST_CASE("shadow self-skip: curved primitives keep their test", "[bvh][skip]") {
    // The eye inside a big opaque sphere, a light outside it: the inner surface faces the
    // light (its normal is turned against the eye ray), yet the sphere itself is between
    // them. Skipping the sphere as the feeler's own primitive would light the point.
    Scene sc;
    sc.add(Sphere({0, 0, 0}, 2.0), 0);
    sc.add(Triangle({50, 50, 50}, {51, 50, 50}, {50, 51, 50}), 0); // far away: a tree of 2
    sc.lights.push_back(Light::point({0, 5, 0}, glm::dvec3(1)));
    const auto aggs = aggregates(sc);
    PhongModel model;
    int checked = 0;
    for (const auto& ag : aggs) {
        sc.setAggregate(ag.get());
        Tracer tracer(sc, model);
        for (int k = 0; k < 16; ++k) {
            Ray eye;
            eye.origin = {0, 0, 0};
            eye.direction = glm::normalize(glm::dvec3(std::cos(k * 0.4), 0.3, std::sin(k * 0.4)));
            Hit h;
            REQUIRE(sc.intersect(eye, 0.0, kInf, h));
            REQUIRE(h.primitive == sc.primitives[0].get());
            const auto s = tracer.sampleLights(h);
            REQUIRE(s.size() == 1);
            if (glm::dot(s[0].toLight, h.normal) <= 0) continue; // faces away: not a feeler
            ++checked;
            REQUIRE(s[0].transmittance == 0.0); // blocked by the sphere itself
            if (const auto* bvh = dynamic_cast<const Bvh*>(ag.get())) {
                Ray f;
                f.origin = h.point;
                f.direction = s[0].toLight;
                REQUIRE(bvh->occluded(f, 1e-9, kInf)); // only the sphere is there
            }
        }
    }
    sc.setAggregate(nullptr);
    REQUIRE(checked > 0);
}

TEST_CASE("shadow self-skip: the same pictures as the visitor-side filter", "[bvh][skip]") {
    // SPD scenes with flat primitives (the floors, gears' polygons, the teapot's and
    // mount's triangles) and the jacks' cylinders: the tracer with the skip in the
    // aggregate against the same tracer on an aggregate that ignores it.
    for (const char* name : {"balls", "gears", "teapot", "mount", "jacks", "tetra"}) {
        INFO(name);
        SceneFile sf = toScene(spdScene(name, 1));
        auto bvh = makeAggregate(*sf.scene);
        const Aggregate& base = bvh ? static_cast<const Aggregate&>(*bvh) : sf.scene->aggregate();
        IgnoresSkip old(base);
        PhongModel model;
        ParallelRenderOptions opt;
        opt.threads = 1;
        opt.trace.maxDepth = 4;
        const LookAtCamera cam = sf.camera();
        sf.scene->setAggregate(bvh.get());
        const wb::Image now = renderParallel(*sf.scene, cam, model, 96, 96, opt);
        sf.scene->setAggregate(&old);
        const wb::Image before = renderParallel(*sf.scene, cam, model, 96, 96, opt);
        sf.scene->setAggregate(nullptr);
        REQUIRE(now.width == before.width);
        REQUIRE(now.data == before.data);
    }
}

TEST_CASE("shadow self-skip: a sphere's feeler skips it only where its exact test says no",
          "[bvh][skip]") {
    // Issue 21, twelfth session: a feeler leaving a sphere's outside skips the sphere when
    // sphereCannotBlock (tracer.cpp) proves its exact test would answer "no". A grazing
    // feeler from a point rounded to just inside the sphere is the case that proof must turn
    // down: its exit root ≈ −(|f| − r)/cos passes the start eps / max(cos, 1e-3) once
    // cos ≲ 1e-3·(r − |f|)/eps, and the exact test then finds the sphere blocking. Points are
    // eye hits on a unit sphere (refined onto the surface: |f| − r a few ULPs either side),
    // lights along directions at cos = 1e-12 … 0.5 with the normal; the tracer's answer must
    // be the exact tests' (every primitive asked, none skipped). A neighbour sphere 0.1
    // off blocks some feelers: skipping it instead of the feeler's own sphere fails too.
    Scene sc;
    addGrazingSpheres(sc);
    const auto aggs = aggregates(sc);
    PhongModel model;
    std::mt19937_64 g(2112);
    int selfBlocked = 0, lit = 0, neighbourBlocks = 0;
    for (int k = 0; k < 1200; ++k) {
        Ray eye;
        Hit h;
        if (!eyeHitOnSphere(sc, g, eye, h)) continue;
        sc.lights.assign(1, grazingLight(h, std::pow(10.0, -12 + (k % 12)) * 0.5, g));
        Tracer probe(sc, model);
        const auto s0 = probe.sampleLights(h);
        if (glm::dot(s0[0].toLight, h.normal) <= 0) continue; // faces away: no feeler
        Ray f;
        f.origin = h.point;
        f.direction = s0[0].toLight;
        const double t0 = feelerStart(h.point, h.normal, f.direction);
        if (!(t0 < s0[0].distance)) continue;
        const bool want = referenceOccluded(sc, f, t0, s0[0].distance, nullptr);
        const auto without = [&](int i) {
            return referenceOccluded(sc, f, t0, s0[0].distance, sc.primitives[size_t(i)].get());
        };
        lit += !want;
        selfBlocked += want && !without(0);
        neighbourBlocks += want && !without(1);
        for (const auto& ag : aggs) {
            sc.setAggregate(ag.get());
            Tracer tracer(sc, model);
            INFO("k " << k << " cos " << cos);
            REQUIRE(tracer.sampleLights(h)[0].transmittance == (want ? 0.0 : 1.0));
        }
        sc.setAggregate(nullptr);
    }
    INFO(selfBlocked << " feelers blocked by their own sphere alone, " << neighbourBlocks
                     << " by the neighbour alone, " << lit << " lit");
    // Measured 2026-12-03: 26 blocked by their own sphere alone (cos 5e-13 … 5e-10), 18 by
    // the neighbour alone, 1156 lit; the bounds are about half that. Without them the test
    // could not tell the proof from rtframe7's unconditional skip (which fails it, at
    // k = 25), nor the feeler's sphere from its neighbour (skipping the neighbour fails it).
    REQUIRE(selfBlocked > 13);
    REQUIRE(neighbourBlocks > 9);
    REQUIRE(lit > 500);
}

TEST_CASE("shadow self-skip: the packet path's lanes skip a sphere only where its exact test "
          "says no",
          "[bvh][skip]") {
    // The case above through Tracer::traceFromPacket, whose lanes decide the self-skip two
    // at a time (tracer.cpp) and whose feelers walk as one packet (Bvh::occludedPacket):
    // eight eye hits on the unit sphere, lane j's own light j grazing it at cos = 5e-13 …
    // 5e-7 (the other lights land anywhere for that lane: lit, blocked or facing away). Each
    // lane's colour must be, bit for bit, the one traceFrom gives on an aggregate that asks
    // every primitive (the exact tests alone): a feeler wrongly skipped or wrongly blocked
    // changes its light's diffuse and highlight terms (a grazing light's are ~cos, far above
    // a double's resolution at these colours).
    Scene sc;
    addGrazingSpheres(sc);
    const auto aggs = aggregates(sc);
    PhongModel model;
    std::mt19937_64 g(2113);
    int selfBlocked = 0, lit = 0, packets = 0;
    for (int k = 0; k < 150; ++k) {
        Ray rays[kMaxPacket];
        Hit hits[kMaxPacket];
        sc.lights.clear();
        for (int j = 0; j < kMaxPacket;) {
            Ray eye;
            Hit h;
            if (!eyeHitOnSphere(sc, g, eye, h)) continue;
            sc.lights.push_back(
                grazingLight(h, std::pow(10.0, -12 + ((k * kMaxPacket + j) % 7)) * 0.5, g));
            // The lane's own light: which of the exact tests block its feeler.
            Ray f;
            f.origin = h.point;
            f.direction = glm::normalize(sc.lights.back().position - h.point);
            const double t0 = feelerStart(h.point, h.normal, f.direction);
            const double dist = glm::length(sc.lights.back().position - h.point);
            if (glm::dot(f.direction, h.normal) > 0 && t0 < dist) {
                const bool want = referenceOccluded(sc, f, t0, dist, nullptr);
                lit += !want;
                selfBlocked += want && !referenceOccluded(sc, f, t0, dist, sc.primitives[0].get());
            }
            rays[j] = eye;
            hits[j] = h;
            ++j;
        }
        ++packets;
        for (const auto& ag : aggs) {
            AsksEveryPrimitive exact(*ag);
            Color want[kMaxPacket], got[kMaxPacket];
            sc.setAggregate(&exact);
            {
                Tracer tracer(sc, model);
                RayCounts counts;
                for (int j = 0; j < kMaxPacket; ++j)
                    want[j] = tracer.traceFrom(rays[j], hits[j], counts, nullptr);
            }
            sc.setAggregate(ag.get());
            Tracer tracer(sc, model);
            RayCounts counts;
            tracer.traceFromPacket(rays, hits, kMaxPacket, counts, nullptr, got);
            for (int j = 0; j < kMaxPacket; ++j) {
                INFO("packet " << k << " lane " << j << " packet walk " << ag->hasOccludedPacket());
                REQUIRE(std::memcmp(&got[j], &want[j], sizeof(Color)) == 0);
            }
        }
        sc.setAggregate(nullptr);
    }
    INFO(packets << " packets; own lights: " << selfBlocked
                 << " feelers blocked by their own sphere alone, " << lit << " lit");
    // Measured 2026-12-03: 25 own-light feelers blocked by their own sphere alone, 1161 lit
    // (of 1200 lanes); the bounds are about half that. Without such feelers the test could
    // not tell the proof from an unconditional skip (which fails it, at packet 21).
    REQUIRE(selfBlocked > 12);
    REQUIRE(lit > 500);
}
