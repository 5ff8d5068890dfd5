// The Whitted recursion's rules (seed 000 part 2, practical 12, seed 003): shadow
// feelers multiply the kt of every blocker, opaque blockers (kt < 0.01) block fully,
// blockers beyond the light do not count; recursion stops at maxDepth and when the
// weight falls below 0.01; colour is attenuated by exp(−atten·t) in a medium.
#include "core/raytrace/box.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/texture.h"
#include "core/raytrace/tracer.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wb::rt;

namespace {
Ray down(const glm::dvec3& o) {
    Ray r;
    r.origin = o;
    r.direction = {0, 0, -1};
    return r;
}
} // namespace

TEST_CASE("tracer: shadow feelers multiply the kt of every blocker", "[raytrace][tracer]") {
    Scene s;
    s.lights.push_back(Light::point({0, 0, 10}));
    const int floorM = s.addMaterial(Material{});
    Material glassA, glassB, opaque;
    glassA.kt = 0.5;
    glassB.kt = 0.4;
    opaque.kt = 0.005; // below seed 000's 0.01: blocks fully
    s.add(Plane({0, 0, 0}, {0, 0, 1}), floorM);
    const int a = s.addMaterial(glassA), b = s.addMaterial(glassB);
    s.add(Rectangle({-1, -1, 2}, {1, -1, 2}, {-1, 1, 2}), a);
    s.add(Rectangle({-1, -1, 4}, {1, -1, 4}, {-1, 1, 4}), b);
    // A blocker beyond the light (z = 12) must not count.
    s.add(Rectangle({-1, -1, 12}, {1, -1, 12}, {-1, 1, 12}), s.addMaterial(opaque));
    const PhongModel model;
    const Tracer tracer(s, model);
    Hit hit;
    REQUIRE(s.intersect(down({0, 0, 1}), 0, 1e30, hit));
    CHECK(hit.point.z == 0);
    auto samples = tracer.sampleLights(hit);
    REQUIRE(samples.size() == 1);
    CHECK(samples[0].transmittance == Approx(0.2).epsilon(1e-15));
    // An opaque blocker between: 0.
    s.add(Rectangle({-1, -1, 6}, {1, -1, 6}, {-1, 1, 6}), s.addMaterial(opaque));
    samples = tracer.sampleLights(hit);
    CHECK(samples[0].transmittance == 0.0);
    // The feeler from under the floor: the light is behind the surface, no feeler.
    Hit under;
    Ray up;
    up.origin = {0, 0, -1};
    up.direction = {0, 0, 1};
    REQUIRE(s.intersect(up, 0, 1e30, under));
    CHECK(tracer.sampleLights(under)[0].transmittance == 0.0);
}

TEST_CASE("tracer: recursion stops at maxDepth and below weight 0.01", "[raytrace][tracer]") {
    // Two parallel mirrors: a ray bouncing between them forever unless stopped.
    auto run = [](double kr, int maxDepth) {
        Scene s;
        Material mirror;
        mirror.kr = kr;
        const int m = s.addMaterial(mirror);
        s.add(Plane({0, 0, 0}, {0, 0, 1}), m);
        s.add(Plane({0, 0, 10}, {0, 0, -1}), m);
        const PhongModel model;
        TraceSettings ts;
        ts.maxDepth = maxDepth;
        const Tracer tracer(s, model, ts);
        tracer.trace(down({0, 0, 5}));
        return tracer.secondaryRays.load();
    };
    CHECK(run(1.0, 7) == 7); // weight stays 1: depth stops it
    CHECK(run(1.0, 0) == 0);
    CHECK(run(0.5, 100) == 6); // 0.5^6 = 0.0156 >= 0.01 > 0.5^7
    CHECK(run(0.01, 100) == 1);
    CHECK(run(0.0099, 100) == 0);
}

TEST_CASE("tracer: attenuation exp(-atten*t) inside a medium", "[raytrace][tracer]") {
    Scene s;
    s.globalAmbient = glm::dvec3(1.0);
    Material m;
    m.ka = 1;
    m.kd = m.ks = 0;
    m.colour = glm::dvec3(0.8);
    s.add(Plane({0, 0, 0}, {0, 0, 1}), s.addMaterial(m));
    const PhongModel model;
    const Tracer tracer(s, model);
    Ray r = down({0, 0, 3});
    const Color clear = tracer.trace(r);
    CHECK(clear.x == Approx(0.8).epsilon(1e-15));
    r.medium.atten = 0.25;
    const Color murky = tracer.trace(r);
    CHECK(murky.x == Approx(0.8 * std::exp(-0.75)).epsilon(1e-14));
}

TEST_CASE("tracer: a ray entering and leaving a glass sphere uses both index ratios",
          "[raytrace][tracer]") {
    // A glass ball with kt = 1 and no local light in front of a black background: a ray
    // through its centre goes straight through; an off-centre ray is bent twice and
    // leaves towards the axis (a converging lens).
    Scene s;
    s.background = glm::dvec3(0.0);
    s.globalAmbient = glm::dvec3(0.0);
    Material glass;
    glass.ka = glass.kd = glass.ks = 0;
    glass.kt = 1;
    glass.medium.refract = 1.5;
    s.add(Sphere({0, 0, 0}, 1), s.addMaterial(glass));
    Hit in;
    Ray r = down({0.5, 0, 5});
    REQUIRE(s.intersect(r, 0, 1e30, in));
    REQUIRE(in.entering);
    const auto t1 = refractDir(r.direction, in.normal, 1.0 / 1.5);
    REQUIRE(t1);
    Ray inside;
    inside.origin = offsetRayOrigin(in.point, -in.normal);
    inside.direction = *t1;
    inside.medium.refract = 1.5;
    Hit out;
    REQUIRE(s.intersect(inside, 0, 1e30, out));
    REQUIRE_FALSE(out.entering);
    const auto t2 = refractDir(inside.direction, out.normal, 1.5);
    REQUIRE(t2);
    CHECK(t2->x < 0); // bent towards the axis
    // Symmetric path: the exit angle with the normal equals the entry angle (to 1e-9:
    // the inner ray starts 2^20 ULPs, ~2e-10, off the surface, which shifts the exit).
    CHECK(std::fabs(glm::dot(*t2, out.normal)) == Approx(std::fabs(in.cosVN)).epsilon(1e-9));
}

TEST_CASE("phong model: the GL lighting equation, by hand", "[raytrace][phong]") {
    // Plane z = 0 seen and lit straight from (0,0,5): n·L = 1, n·h = 1, d = 5.
    Scene s;
    s.globalAmbient = glm::dvec3(0.2);
    Light l = Light::point({0, 0, 5}, {1.0, 0.5, 0.25});
    l.ambient = glm::dvec3(0.1);
    l.constantAttenuation = 1;
    l.linearAttenuation = 0.1; // att = 1/(1 + 0.5)
    s.lights.push_back(l);
    Material m;
    m.colour = {0.5, 0.6, 0.7};
    m.ka = 0.4;
    m.kd = 0.8;
    m.ks = 0.3;
    m.phongExp = 10;
    m.emission = {0.05, 0, 0};
    s.add(Plane({0, 0, 0}, {0, 0, 1}), s.addMaterial(m));
    const PhongModel model;
    const Tracer tracer(s, model);
    const Color c = tracer.trace(down({0, 0, 5}));
    for (int i = 0; i < 3; ++i) {
        const double ma = 0.4 * m.colour[i], md = 0.8 * m.colour[i], ms = 0.3;
        const double expect =
            m.emission[i] + 0.2 * ma + (1 / 1.5) * (0.1 * ma + md * l.colour[i] + ms * l.colour[i]);
        CHECK(c[i] == Approx(expect).epsilon(1e-14));
    }
    // A spot pointing away (cutoff 30 degrees) leaves emission and global ambient only.
    s.lights[0].spotDirection = {1, 0, 0};
    s.lights[0].spotCutoff = 30;
    const Color spotOff = tracer.trace(down({0, 0, 5}));
    CHECK(spotOff.x == Approx(0.05 + 0.2 * 0.4 * 0.5).epsilon(1e-14));
    // A shadowing blocker removes diffuse and specular but not the light's ambient.
    s.lights[0].spotCutoff = 180;
    Material opaque;
    s.add(Rectangle({-1, -1, 2}, {1, -1, 2}, {-1, 1, 2}), s.addMaterial(opaque));
    Ray below = down({0, 0, 1});
    const Color shadowed = tracer.trace(below);
    CHECK(shadowed.y ==
          Approx(0.2 * 0.4 * 0.6 + (1 / (1 + 0.1 * 5)) * 0.1 * 0.4 * 0.6).epsilon(1e-12));
}

TEST_CASE("textures: a plane bound by three points, a box face, an ellipsoid",
          "[raytrace][texture]") {
    // A 2×2 texture: top row red, green; bottom row blue, white (v upwards).
    wb::Image tex(2, 2, 3);
    const uint8_t px[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
            tex.at(i % 2, i / 2)[c] = px[i][c];
    CHECK(sampleTexture(tex, {0.25, 0.75}) == glm::dvec3(1, 0, 0));
    CHECK(sampleTexture(tex, {0.75, 0.25}) == glm::dvec3(1, 1, 1));
    CHECK(sampleTexture(tex, {1.25, -0.75}) == glm::dvec3(0, 0, 1)); // repeats
    CHECK(sampleTexture(wb::Image{}, {0.5, 0.5}) == glm::dvec3(1));  // no texture: white

    Scene s;
    s.globalAmbient = glm::dvec3(1.0);
    Material m;
    m.ka = 1;
    m.kd = m.ks = 0;
    m.texture = &tex;
    Plane p({0, 0, 0}, {0, 0, 1});
    p.bindTexture({0, 0, 0}, {2, 0, 0}, {0, 2, 0}); // one tile per 2×2 units
    s.add(p, s.addMaterial(m));
    const PhongModel model;
    const Tracer tracer(s, model);
    CHECK(tracer.trace(down({0.5, 1.5, 1})) == glm::dvec3(1, 0, 0)); // u 0.25, v 0.75
    CHECK(tracer.trace(down({1.5, 1.5, 1})) == glm::dvec3(0, 1, 0));
    CHECK(tracer.trace(down({0.5, 0.5, 1})) == glm::dvec3(0, 0, 1));
    CHECK(tracer.trace(down({2.5, 0.5, 1})) == glm::dvec3(0, 0, 1)); // next tile

    Hit h;
    const Box b = Box::axisAligned({0, 0, 0}, {4, 2, 1});
    REQUIRE(b.intersect(down({1, 0.5, 3}), 0, 1e30, h)); // top face spans e1, e2
    CHECK(h.uv.x == Approx(0.25));
    CHECK(h.uv.y == Approx(0.25));
    const Quadric e(Quadric::Kind::Ellipsoid, {0, 0, 0}, {2, 1, 1});
    Ray side;
    side.origin = {0, -5, 0};
    side.direction = {0, 1, 0};
    REQUIRE(e.intersect(side, 0, 1e30, h)); // longitude −90°: u = 0.25, equator v = 0.5
    CHECK(e.textureCoords(h).x == Approx(0.25));
    CHECK(e.textureCoords(h).y == Approx(0.5));
    REQUIRE(e.intersect(down({0, 0, 5}), 0, 1e30, h)); // the pole: v = 1
    CHECK(e.textureCoords(h).y == Approx(1.0));
    // The sphere computes its uv on demand, from the outward normal; the tracer must ask
    // for them. From −y at height 0.5 the unit sphere is hit at longitude −90° (u = 0.25),
    // latitude asin(0.5) = 30° (v = 0.5 + 1/6): the red tile (u 0.25, v 0.75 above).
    Scene s2;
    s2.globalAmbient = glm::dvec3(1.0);
    const Sphere& sp = s2.add(Sphere({0, 0, 0}, 1), s2.addMaterial(m));
    Ray lat30;
    lat30.origin = {0, -5, 0.5};
    lat30.direction = {0, 1, 0};
    REQUIRE(sp.intersect(lat30, 0, 1e30, h));
    REQUIRE(h.hasUv);
    CHECK(sp.textureCoords(h).x == Approx(0.25));
    CHECK(sp.textureCoords(h).y == Approx(0.5 + 1.0 / 6));
    const Tracer tracer2(s2, model);
    CHECK(tracer2.trace(lat30) == glm::dvec3(1, 0, 0));
    lat30.origin.x = 0.5; // longitude atan2(−0.707, 0.5) ≈ −55°: u ≈ 0.35, still red
    CHECK(tracer2.trace(lat30) == glm::dvec3(1, 0, 0));
    lat30.origin = {0, 5, -0.5}; // from +y below the equator: u = 0.75, v = 1/3: white
    lat30.direction = {0, -1, 0};
    CHECK(tracer2.trace(lat30) == glm::dvec3(1, 1, 1));
}

TEST_CASE("tracer: the ray budget bounds a tree that kr + kt >= 1 does not", "[raytrace][tracer]") {
    // Issue 12 point 3: 30 stacked quads with kr = kt = 1 took 2^depth rays (depth 16
    // over 60 s at 160x120). Each hit spawns a reflected and a transmitted ray of weight
    // 1, so only the depth and the budget stop the tree.
    Scene s;
    Material both;
    both.kr = 1;
    both.kt = 1;
    const int m = s.addMaterial(both);
    for (int i = 0; i < 30; ++i) {
        const double z = -1.0 - i;
        s.add(Rectangle({-50, -50, z}, {50, -50, z}, {-50, 50, z}), m);
    }
    s.add(Rectangle({-50, -50, 1}, {-50, 50, 1}, {50, -50, 1}), m); // a lid: reflections come back
    const PhongModel model;
    auto rays = [&](int depth, long budget, double minWeight) {
        TraceSettings ts;
        ts.maxDepth = depth;
        ts.maxRaysPerSample = budget;
        ts.minWeight = minWeight;
        const Tracer tracer(s, model, ts);
        const Color c = tracer.trace(down({0.1, 0.2, 0}));
        CHECK(std::isfinite(c.x + c.y + c.z));
        return tracer.secondaryRays.load();
    };
    const long kNoBudget = 1L << 40;
    // Without the weight cut-off and the budget the tree grows by about 2x per level
    // (rays that leave the stack miss and end their branch): exponential, as reported.
    const long long unbounded12 = rays(12, kNoBudget, 0), unbounded16 = rays(16, kNoBudget, 0);
    CHECK(unbounded16 > 8 * unbounded12);
    CHECK(unbounded16 > 30000);
    // The weight cut-off holds: children get k / (kr + kt) = 1/2 of the weight, so a ray
    // of depth d has weight 2^-d and depth 7 (1/128 < 0.01) is never traced: at most
    // 2 + 4 + ... + 64 = 126 rays at any depth limit.
    CHECK(rays(16, kNoBudget, 0.01) <= 126);
    CHECK(rays(16, kNoBudget, 0.01) == rays(64, kNoBudget, 0.01));
    CHECK(rays(16, kNoBudget, 0.01) == rays(6, kNoBudget, 0.01));
    // The budget is the backstop when minWeight is 0: below it nothing changes, above it
    // the tree stops exactly at the budget.
    CHECK(rays(8, 4096, 0) == rays(8, kNoBudget, 0));
    CHECK(rays(16, 4096, 0) == 4096);
    CHECK(rays(16, TraceSettings{}.maxRaysPerSample, 0) == 4096);
    CHECK(rays(16, 10, 0) == 10);
    CHECK(rays(16, 0, 0) == 0);

    // The observer is told why a child was skipped.
    struct Count : TraceObserver {
        int budget = 0;
        void childSkipped(RayKind, SkipReason why) override {
            budget += why == SkipReason::RayBudget;
        }
    } obs;
    TraceSettings ts;
    ts.maxDepth = 16;
    ts.maxRaysPerSample = 10;
    ts.minWeight = 0;
    const Tracer tracer(s, model, ts);
    tracer.trace(down({0.1, 0.2, 0}), &obs);
    CHECK(obs.budget > 0);
}
