// Tracer::trace(ray, observer): the observer sees the recursion as it happens (seed 000
// part 2's tree, event by event), and observing never changes a colour.
#include "core/raytrace/box.h"
#include "core/raytrace/camera.h"
#include "core/raytrace/course_model.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/tracer.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace wb::rt;

namespace {

// Every event as one record, in order.
struct Event {
    std::string what;
    RayKind kind = RayKind::Primary;
    SkipReason why = SkipReason::DepthLimit;
    const Primitive* primitive = nullptr;
    double t = 0.0, k = 0.0;
    Color colour{0.0};
};
Event ev(const char* what, RayKind kind = RayKind::Primary) {
    Event e;
    e.what = what;
    e.kind = kind;
    return e;
}

struct Recorder : TraceObserver {
    std::vector<Event> events;
    void rayBegin(const Ray&, RayKind kind) override { events.push_back(ev("begin", kind)); }
    void missed(const Color& bg) override {
        Event e = ev("missed");
        e.colour = bg;
        events.push_back(e);
    }
    void hit(const Ray&, const Hit& h, const Material&, const glm::dvec3&,
             const std::vector<LightSample>&, const Color& direct) override {
        Event e = ev("hit");
        e.primitive = h.primitive;
        e.t = h.t;
        e.colour = direct;
        events.push_back(e);
    }
    void childSkipped(RayKind child, SkipReason why) override {
        Event e = ev("skipped", child);
        e.why = why;
        events.push_back(e);
    }
    void childResult(RayKind child, const Color& c, double k) override {
        Event e = ev("child", child);
        e.colour = c;
        e.k = k;
        events.push_back(e);
    }
    void attenuated(double factor) override {
        Event e = ev("attenuated");
        e.k = factor;
        events.push_back(e);
    }
    void rayEnd(const Color& c) override {
        Event e = ev("end");
        e.colour = c;
        events.push_back(e);
    }
};

void checkColour(const Color& c, int r, int g, int b) {
    INFO("colour (" << c.x << ", " << c.y << ", " << c.z << ") expected (" << r << ", " << g << ", "
                    << b << ")");
    CHECK(c.x == r);
    CHECK(c.y == g);
    CHECK(c.z == b);
}

// Seed 000 part 2 (as in seed000_test.cpp): red rectangle upright at x = 50 (kr 0),
// green one flat at height 20 (kr 0.5), light at 60.
void buildSeed000Part2(Scene& s) {
    s.lights.push_back(Light::point({0, 0, 60}));
    s.distScale = 30;
    Material red, green;
    red.colour = glm::dvec3(234, 21, 21) / 255.0;
    green.colour = glm::dvec3(21, 234, 21) / 255.0;
    red.ka = red.kd = red.ks = green.ka = green.kd = green.ks = 0.5;
    red.phongExp = green.phongExp = 3;
    green.kr = 0.5;
    s.add(Rectangle({50, 0, 20}, {50, 0, 70}, {50, 50, 20}), s.addMaterial(red));
    s.add(Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), s.addMaterial(green));
}

// Rebuilds every ray's colour from the events with the model's own arithmetic (direct,
// + k·child, × attenuation) and checks it against the ray's rayEnd: the events tell
// the whole colour. Counts the rare events so the test can ask that they happened.
struct Checker : TraceObserver {
    const ShadingModel& model;
    std::vector<Color> stack;
    std::vector<Color> finished;
    int rays = 0, badSums = 0, tir = 0, depthLimit = 0, belowWeight = 0, attenuations = 0;
    int misses = 0, maxStack = 0;
    explicit Checker(const ShadingModel& m) : model(m) {}
    void rayBegin(const Ray&, RayKind) override {
        ++rays;
        stack.emplace_back(0.0);
        maxStack = std::max(maxStack, int(stack.size()));
    }
    void missed(const Color& bg) override {
        ++misses;
        stack.back() = bg;
    }
    void hit(const Ray&, const Hit&, const Material&, const glm::dvec3&,
             const std::vector<LightSample>&, const Color& direct) override {
        stack.back() = direct;
    }
    void childSkipped(RayKind, SkipReason why) override {
        tir += why == SkipReason::TotalInternalReflection;
        depthLimit += why == SkipReason::DepthLimit;
        belowWeight += why == SkipReason::BelowWeight;
    }
    void childResult(RayKind, const Color& c, double k) override {
        badSums += c != finished.back();
        stack.back() = model.addScaled(stack.back(), c, k);
    }
    void attenuated(double factor) override {
        ++attenuations;
        stack.back() = model.scale(stack.back(), factor);
    }
    void rayEnd(const Color& c) override {
        badSums += c != stack.back();
        stack.pop_back();
        finished.push_back(c);
    }
};

} // namespace

TEST_CASE("tracer observer: sees seed 000 part 2's tree at P(50,0)", "[raytrace][seed000]") {
    Scene s;
    buildSeed000Part2(s);
    const CourseModel model;
    const Tracer tracer(s, model);
    const Ray view = ScreenCamera::seed000().rayThroughScreen(50, 0);
    Recorder rec;
    const Color c = tracer.trace(view, &rec);
    checkColour(c, 168, 233, 86);
    const std::vector<Event>& e = rec.events;
    REQUIRE(e.size() == 7);
    CHECK(e[0].what == "begin");
    CHECK(e[0].kind == RayKind::Primary);
    // The primary ray meets the green rectangle at (40,0,20): t = √(40² + 80²) = 89.443.
    CHECK(e[1].what == "hit");
    CHECK(e[1].primitive == s.primitives[1].get());
    CHECK(e[1].t == Approx(89.443).margin(1e-3)); // the seed prints 3 decimals
    CHECK(e[2].what == "begin");
    CHECK(e[2].kind == RayKind::Reflected);
    // The reflected ray meets the red one at Q = (50,0,40): T = √(10² + 20²) = 22.361, less
    // the origin's tiny normal offset (offsetRayOrigin: far below the printed 1e-3).
    CHECK(e[3].what == "hit");
    CHECK(e[3].primitive == s.primitives[0].get());
    CHECK(e[3].t == Approx(22.361).margin(1e-3));
    checkColour(e[3].colour, 236, 73, 73); // the red kr is 0: no child, nothing skipped
    CHECK(e[4].what == "end");
    checkColour(e[4].colour, 236, 73, 73);
    CHECK(e[5].what == "child");
    CHECK(e[5].kind == RayKind::Reflected);
    CHECK(e[5].k == 0.5);
    checkColour(e[5].colour, 236, 73, 73);
    CHECK(e[6].what == "end");
    checkColour(e[6].colour, 168, 233, 86);
    // The unobserved trace gives the same colour.
    CHECK(tracer.trace(view) == c);
}

TEST_CASE("tracer observer: skipped children say why", "[raytrace][tracer]") {
    Scene s;
    buildSeed000Part2(s);
    const CourseModel model;
    const Ray view = ScreenCamera::seed000().rayThroughScreen(50, 0);
    TraceSettings noDepth;
    noDepth.maxDepth = 0;
    TraceSettings heavy;
    heavy.minWeight = 0.6; // above the green kr 0.5
    for (const TraceSettings& settings : {noDepth, heavy}) {
        const Tracer tracer(s, model, settings);
        Recorder rec;
        const Color c = tracer.trace(view, &rec);
        REQUIRE(rec.events.size() == 4);
        CHECK(rec.events[1].what == "hit");
        CHECK(rec.events[2].what == "skipped");
        CHECK(rec.events[2].kind == RayKind::Reflected);
        CHECK(rec.events[2].why ==
              (settings.maxDepth == 0 ? SkipReason::DepthLimit : SkipReason::BelowWeight));
        CHECK(rec.events[3].what == "end");
        CHECK(c == rec.events[1].colour); // only the direct light
        CHECK(tracer.trace(view) == c);
    }
}

TEST_CASE("tracer observer: trace(ray) and trace(ray, &observer) agree on every pixel",
          "[raytrace][tracer]") {
    // Glass (refraction, total internal reflection, attenuation), a mirror floor and a
    // glass box, traced to depth 4 so the depth limit is met too.
    Scene s;
    s.lights.push_back(Light::point({4, 6, 5}));
    s.lights.push_back(Light::directional({-1, -2, -1}));
    Material floorM, mirror, glass, boxM;
    floorM.colour = {0.8, 0.8, 0.7};
    floorM.kr = 0.4;
    mirror.colour = {0.9, 0.9, 0.9};
    mirror.kr = 0.8;
    glass.colour = {0.6, 0.8, 1.0};
    glass.kr = 0.1;
    glass.kt = 0.85;
    glass.medium.refract = 1.5;
    glass.medium.atten = 0.2;
    boxM.colour = {1.0, 0.5, 0.2};
    boxM.kt = 0.5;
    boxM.medium.refract = 1.3;
    s.add(Plane({0, 0, 0}, {0, 1, 0}), s.addMaterial(floorM));
    s.add(Sphere({0, 1, 0}, 1.0), s.addMaterial(glass));
    s.add(Sphere({-2.2, 1, -1}, 1.0), s.addMaterial(mirror));
    s.add(Box({1.3, 0, -0.5}, {1, 0, 0}, {0, 1.2, 0}, {0, 0, 1}), s.addMaterial(boxM));
    TraceSettings settings;
    settings.maxDepth = 4;
    const LookAtCamera camera({0.5, 2.5, 6}, {0, 0.8, 0}, {0, 1, 0}, 50);
    const PhongModel phong;
    const CourseModel course;
    for (const ShadingModel* model :
         {static_cast<const ShadingModel*>(&phong), static_cast<const ShadingModel*>(&course)}) {
        const Tracer tracer(s, *model, settings);
        Checker check(*model);
        int differ = 0, rootsWrong = 0;
        constexpr int kW = 64, kH = 48;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const Ray ray = camera.primaryRay(x, y, kW, kH);
                const Color plain = tracer.trace(ray);
                const Color seen = tracer.trace(ray, &check);
                differ += plain != seen;
                rootsWrong += check.finished.back() != seen || !check.stack.empty();
            }
        INFO(check.rays << " rays, " << check.tir << " TIR, " << check.depthLimit
                        << " depth limits, " << check.belowWeight << " below weight, "
                        << check.attenuations << " attenuations, " << check.misses << " misses");
        CHECK(differ == 0);
        CHECK(rootsWrong == 0);
        CHECK(check.badSums == 0);
        // The scene exercises every kind of event (else the agreement says little).
        CHECK(check.tir > 0);
        CHECK(check.depthLimit > 0);
        CHECK(check.attenuations > 0);
        CHECK(check.misses > 0);
        CHECK(check.maxStack == settings.maxDepth + 1);
    }
}
