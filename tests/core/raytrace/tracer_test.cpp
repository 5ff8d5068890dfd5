// The Whitted recursion's rules (seed 000 part 2, practical 12, seed 003): shadow
// feelers multiply the kt of every blocker, opaque blockers (kt < 0.01) block fully,
// blockers beyond the light do not count; recursion stops at maxDepth and when the
// weight falls below 0.01; colour is attenuated by exp(−atten·t) in a medium.
#include "core/raytrace/box.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/sphere.h"
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
