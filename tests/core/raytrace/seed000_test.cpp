// Seed 000's worked example, to the unit: every figure the seed prints for pixel P(50, 0).
// The seed prints vectors and factors with 3 decimals (sometimes rounded, sometimes
// truncated), distances with 2: a printed figure x is checked as |value − x| <= 1 unit
// of its last printed digit. Colours are checked exactly.
#include "core/raytrace/camera.h"
#include "core/raytrace/course_model.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/render.h"
#include "core/raytrace/scene.h"
#include "core/raytrace/tracer.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace wb::rt;

namespace {

const glm::dvec3 kRed = glm::dvec3(234, 21, 21) / 255.0;
const glm::dvec3 kGreen = glm::dvec3(21, 234, 21) / 255.0;

void checkPrinted(double value, double printed, double unit) {
    INFO("value " << value << " printed " << printed);
    CHECK(std::fabs(value - printed) <= unit * (1 + 1e-9));
}
void checkPrinted(const glm::dvec3& v, const glm::dvec3& printed, double unit) {
    for (int i = 0; i < 3; ++i)
        checkPrinted(v[i], printed[i], unit);
}
void checkColour(const Color& c, int r, int g, int b) {
    INFO("colour (" << c.x << ", " << c.y << ", " << c.z << ") expected (" << r << ", " << g << ", "
                    << b << ")");
    CHECK(c.x == r);
    CHECK(c.y == g);
    CHECK(c.z == b);
}

Material seedMaterial(const glm::dvec3& colour, double kr = 0) {
    Material m;
    m.colour = colour;
    m.ka = m.kd = m.ks = 0.5;
    m.phongExp = 3;
    m.kr = kr;
    return m;
}

// Part 1: red 20×20 rectangle at height 40, green 50×50 at height 20, light at 60.
void buildPart1(Scene& s, bool withRect1) {
    s.lights.push_back(Light::point({0, 0, 60}));
    s.ambient = glm::dvec3(1.0); // BA = (255,255,255)
    s.distScale = 30;
    const int red = s.addMaterial(seedMaterial(kRed));
    const int green = s.addMaterial(seedMaterial(kGreen));
    if (withRect1) s.add(Rectangle({0, 0, 40}, {20, 0, 40}, {0, 20, 40}), red);
    s.add(Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), green);
}

} // namespace

TEST_CASE("seed 000: rectangle parameters", "[raytrace][seed000]") {
    const Rectangle r1({0, 0, 40}, {20, 0, 40}, {0, 20, 40});
    CHECK(r1.loc == glm::dvec3(0, 0, 40));
    CHECK(r1.e1 == glm::dvec3(20, 0, 0));
    CHECK(r1.e2 == glm::dvec3(0, 20, 0));
    CHECK(r1.normal == glm::dvec3(0, 0, 1));
    CHECK(r1.ku == glm::dvec3(0.05, 0, 0)); // 20·400/160000, exact in binary? close enough:
    CHECK(r1.kv == glm::dvec3(0, 0.05, 0));
    CHECK(r1.u0 == 0);
    CHECK(r1.v0 == 0);
    const Rectangle r2({0, 0, 20}, {50, 0, 20}, {0, 50, 20});
    CHECK(r2.normal == glm::dvec3(0, 0, 1));
    CHECK(r2.ku == glm::dvec3(0.02, 0, 0));
    CHECK(r2.kv == glm::dvec3(0, 0.02, 0));
    CHECK(r2.u0 == 0);
    CHECK(r2.v0 == 0);
    // Part 2's red rectangle in the plane x = 50.
    const Rectangle r3({50, 0, 20}, {50, 0, 70}, {50, 50, 20});
    CHECK(r3.normal == glm::dvec3(-1, 0, 0));
    CHECK(r3.loc == glm::dvec3(50, 0, 20));
    checkPrinted(r3.ku, {0, 0, 0.02}, 1e-15);
    checkPrinted(r3.kv, {0, 0.02, 0}, 1e-15);
    checkPrinted(r3.u0, 0.4, 1e-15);
    CHECK(r3.v0 == 0);
}

TEST_CASE("seed 000: primary ray through P(50,0) and its intersections", "[raytrace][seed000]") {
    const ScreenCamera cam = ScreenCamera::seed000();
    const Ray ray = cam.rayThroughScreen(50, 0);
    CHECK(ray.origin == glm::dvec3(0, 0, 100));
    checkPrinted(ray.direction, {0.447, 0, -0.894}, 1e-3);
    // The same ray from the pixel grid of an image whose centre is (homeX, homeY).
    const Ray pix = cam.primaryRay(40 + 50, 40, 80, 80);
    CHECK(glm::length(pix.direction - ray.direction) == 0.0);

    const Rectangle r1({0, 0, 40}, {20, 0, 40}, {0, 20, 40});
    const Rectangle r2({0, 0, 20}, {50, 0, 20}, {0, 50, 20});
    // Rectangle 1: the plane is met at T = 67.082, P = (30,0,40), u = 1.5 > 1: no hit.
    const double vd1 = glm::dot(r1.normal, ray.direction);
    checkPrinted(vd1, -0.894, 1e-3);
    const double t1 = glm::dot(r1.loc - ray.origin, r1.normal) / vd1;
    checkPrinted(t1, 67.082, 1e-3);
    checkPrinted(ray.at(t1), {30, 0, 40}, 1e-9);
    checkPrinted(r1.uvOf(ray.at(t1)).x, 1.5, 1e-12);
    checkPrinted(r1.uvOf(ray.at(t1)).y, 0.0, 1e-12);
    Hit h;
    CHECK_FALSE(r1.intersect(ray, 0, 1e30, h));
    // Rectangle 2: T = 89.443, P2 = (40,0,20), u = 0.8, v = 0: hit.
    REQUIRE(r2.intersect(ray, 0, 1e30, h));
    checkPrinted(h.t, 89.443, 1e-3);
    checkPrinted(h.point, {40, 0, 20}, 1e-12);
    checkPrinted(h.uv.x, 0.8, 1e-12);
    checkPrinted(h.uv.y, 0.0, 1e-12);
    checkPrinted(h.cosVN, -0.894, 1e-3);
    CHECK_FALSE(h.entering); // a rectangle has no inside (seed 000)
}

TEST_CASE("seed 000 part 1: P2 in the shadow of rectangle 1 is (10,117,10)",
          "[raytrace][seed000]") {
    Scene s;
    buildPart1(s, true);
    const Ray ray = ScreenCamera::seed000().rayThroughScreen(50, 0);
    Hit hit;
    REQUIRE(s.intersect(ray, 0, 1e30, hit));
    checkPrinted(hit.point, {40, 0, 20}, 1e-12);

    // The feeler: L = (−0.707, 0, 0.707), Dist = 56.57, sh = 30/Dist = 0.530.
    const glm::dvec3 toLight = glm::dvec3(0, 0, 60) - hit.point;
    const double dist = glm::length(toLight);
    checkPrinted(dist, 56.57, 1e-2);
    checkPrinted(toLight / dist, {-0.707, 0, 0.707}, 1e-3);
    checkPrinted(30 / dist, 0.530, 1e-3);
    // It meets rectangle 1 at T = 28.28, p1 = (20,0,40), u = 1, v = 0 (on its border),
    // nearer than the light.
    Ray feeler;
    feeler.origin = hit.point;
    feeler.direction = toLight / dist;
    Hit block;
    REQUIRE(s.primitives[0]->intersect(feeler, 0, dist, block));
    checkPrinted(block.t, 28.28, 1e-2);
    checkPrinted(block.point, {20, 0, 40}, 1e-12);
    checkPrinted(block.uv.x, 1.0, 1e-12);
    checkPrinted(block.uv.y, 0.0, 1e-12);
    CHECK(block.t < dist);

    const CourseModel model;
    const Tracer tracer(s, model);
    const auto samples = tracer.sampleLights(hit);
    REQUIRE(samples.size() == 1);
    CHECK(samples[0].transmittance == 0.0); // kt of rectangle 1 is 0: full shadow
    checkColour(tracer.trace(ray), 10, 117, 10);
}

TEST_CASE("seed 000 part 1: P2 lit (rectangle 1 removed) is (50,197,50)", "[raytrace][seed000]") {
    Scene s;
    buildPart1(s, false);
    const Ray ray = ScreenCamera::seed000().rayThroughScreen(50, 0);
    Hit hit;
    REQUIRE(s.intersect(ray, 0, 1e30, hit));
    CourseModel model;
    CourseModel::Trace tr;
    model.trace = &tr;
    const Tracer tracer(s, model);
    const auto samples = tracer.sampleLights(hit);
    REQUIRE(samples.size() == 1);
    CHECK(samples[0].transmittance == 1.0);
    const Color c = model.direct(s, ray, hit, s.materials[size_t(hit.material)], kGreen, samples);
    checkColour(tr.ambient, 10, 117, 10);        // (255,255,255)·(21,234,21)·0.5
    checkPrinted(tr.sh, 0.530, 1e-3);            // 30/56.57
    checkPrinted(tr.ln, 0.707, 1e-3);            // L·N
    checkPrinted(tr.diffuseFactor, 0.187, 1e-3); // SH·LN·KD
    checkColour(CourseModel::mul(glm::dvec3(255), CourseModel::fromUnit(kGreen)), 21, 234, 21);
    checkColour(tr.diffuse, 4, 44, 4); // (21,234,21)·0.187
    checkColour(tr.afterDiffuse, 14, 161, 14);
    const glm::dvec3 hv = samples[0].toLight - ray.direction;
    checkPrinted(hv, {-1.154, 0, 1.601}, 1e-3);            // L − Ray.Direction
    checkPrinted(tr.halfVector, {-0.584, 0, 0.811}, 1e-3); // normalised
    checkPrinted(tr.nn, 0.811, 1e-3);
    checkPrinted(tr.nnp, 0.533, 1e-3);            // 0.811³
    checkPrinted(tr.specularFactor, 0.142, 1e-3); // SH·KS·NNP
    checkColour(tr.specular, 36, 36, 36);         // (255,255,255)·0.142
    checkColour(tr.afterSpecular, 50, 197, 50);
    checkColour(c, 50, 197, 50);
    model.trace = nullptr;
    checkColour(Tracer(s, model).trace(ray), 50, 197, 50);
}

TEST_CASE("seed 000 part 2: reflected ray gives (236,73,73) at Q and (168,233,86) at P",
          "[raytrace][seed000]") {
    Scene s;
    s.lights.push_back(Light::point({0, 0, 60}));
    s.distScale = 30;
    // The red rectangle's kr must be 0 for the printed (236,73,73): the seed says so at
    // the end of the computation (its earlier "KR of the first rectangle = 0.5" means the
    // green one, whose reflected ray is traced at P2).
    const int red = s.addMaterial(seedMaterial(kRed, 0.0));
    const int green = s.addMaterial(seedMaterial(kGreen, 0.5));
    s.add(Rectangle({50, 0, 20}, {50, 0, 70}, {50, 50, 20}), red);
    s.add(Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), green);

    const Ray view = ScreenCamera::seed000().rayThroughScreen(50, 0);
    Hit p2;
    REQUIRE(s.intersect(view, 0, 1e30, p2));
    checkPrinted(p2.point, {40, 0, 20}, 1e-12);
    // R.Origin = (40,0,20), weight 1·0.5, VN = −0.894, R.Direction = (0.447, 0, 0.894).
    checkPrinted(p2.cosVN, -0.894, 1e-3);
    Ray r;
    r.origin = p2.point;
    r.direction = reflectDir(view.direction, p2.normal);
    r.weight = view.weight * 0.5;
    r.depth = 1;
    checkPrinted(r.direction, {0.447, 0, 0.894}, 1e-3);
    // It meets the red rectangle: VD = −0.447, T = 22.36, Q = (50,0,40), U = 0.4, V = 0.
    Hit q;
    REQUIRE(s.intersect(r, 0, 1e30, q));
    CHECK(q.primitive == s.primitives[0].get());
    checkPrinted(q.cosVN, -0.447, 1e-3);
    checkPrinted(q.t, 22.36, 1e-2);
    checkPrinted(q.point, {50, 0, 40}, 1e-12);
    // U = P·KU − U0 with P = Q: 40·0.02 − 0.4 = 0.4.
    checkPrinted(q.uv.x, 0.4, 1e-12);
    checkPrinted(q.uv.y, 0.0, 1e-12);

    CourseModel model;
    CourseModel::Trace tr;
    model.trace = &tr;
    const Tracer tracer(s, model);
    const auto samples = tracer.sampleLights(q);
    REQUIRE(samples.size() == 1);
    checkPrinted(samples[0].toLight, {-0.928, 0, 0.371}, 1e-3);
    checkPrinted(samples[0].distance, 53.85, 1e-2);
    CHECK(samples[0].transmittance == 1.0); // nothing between Q and the light
    const Color bq = model.direct(s, r, q, s.materials[size_t(red)], kRed, samples);
    checkColour(tr.ambient, 117, 10, 10);
    checkPrinted(tr.sh, 0.557, 1e-3);
    checkPrinted(tr.ln, 0.928, 1e-3);
    checkPrinted(tr.diffuseFactor, 0.259, 1e-3);
    checkColour(tr.diffuse, 61, 5, 5);
    checkColour(tr.afterDiffuse, 178, 15, 15);
    checkPrinted(samples[0].toLight - r.direction, {-1.375, 0, -0.523}, 1e-3);
    checkPrinted(tr.halfVector, {-0.935, 0, -0.355}, 1e-3);
    checkPrinted(tr.nn, 0.935, 1e-3);
    checkPrinted(tr.nnp, 0.817, 1e-3);
    checkPrinted(tr.specularFactor, 0.227, 1e-3);
    checkColour(tr.specular, 58, 58, 58);
    checkColour(tr.afterSpecular, 236, 73, 73);
    checkColour(bq, 236, 73, 73);
    // Weighted by KR = 0.5: (118, 36.5, 36.5) -> (118, 36, 36), ties to even.
    checkColour(CourseModel::mulBy(bq, 0.5), 118, 36, 36);
    model.trace = nullptr;
    const Tracer full(s, model);
    checkColour(full.trace(r), 236, 73, 73); // red kr = 0: the recursion stops at Q
    checkColour(full.trace(view), 168, 233, 86);
}

TEST_CASE("seed 000: colour arithmetic rounds ties to even", "[raytrace][seed000]") {
    CHECK(CourseModel::roundEven(10.5) == 10);
    CHECK(CourseModel::roundEven(36.5) == 36);
    CHECK(CourseModel::roundEven(11.5) == 12);
    CHECK(CourseModel::roundEven(3.9375) == 4);
    CHECK(CourseModel::roundEven(-0.5) == 0);
    checkColour(CourseModel::add({200, 100, 0}, {100, 100, 0}), 255, 200, 0); // clamped
    checkColour(CourseModel::mulBy({100, 100, 100}, -1), 0, 0, 0);
    checkColour(CourseModel::mulBy({100, 100, 100}, std::nan("")), 0, 0, 0);
}

TEST_CASE("seed 000 part 2: the rendered image has (168,233,86) at pixel P(50,0)",
          "[raytrace][seed000]") {
    Scene s;
    s.lights.push_back(Light::point({0, 0, 60}));
    s.distScale = 30;
    const int red = s.addMaterial(seedMaterial(kRed, 0.0));
    const int green = s.addMaterial(seedMaterial(kGreen, 0.5));
    s.add(Rectangle({50, 0, 20}, {50, 0, 70}, {50, 50, 20}), red);
    s.add(Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), green);
    const CourseModel model;
    RenderStats st;
    // 160×160 pixels of one world unit: homeX = homeY = 80, so P(50, 0) is pixel (130, 80).
    const wb::Image img = render(s, ScreenCamera::seed000(), model, 160, 160, {}, &st);
    CHECK(st.nonFinitePixels == 0);
    CHECK(int(img.at(130, 80)[0]) == 168);
    CHECK(int(img.at(130, 80)[1]) == 233);
    CHECK(int(img.at(130, 80)[2]) == 86);
    CHECK(int(img.at(0, 0)[0]) == 128); // background (128,207,255) outside the rectangles
    CHECK(int(img.at(0, 0)[1]) == 207);
    CHECK(int(img.at(0, 0)[2]) == 255);
    CHECK(wb::writePng(std::string(WB_TEST_OUT_DIR) + "/seed000_part2.png", img));
}
