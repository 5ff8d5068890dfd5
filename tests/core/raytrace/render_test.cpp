// Closed-form renders (as pbrt's tests do) and degenerate scenes:
//  - a diffuse plane under a point light is Lambert's cos θ pixel by pixel;
//  - a sphere lit from the camera is brightest at its centre;
//  - no NaN/Inf reaches a pixel with zero-area triangles, zero-radius spheres, a
//    light inside a body, on a surface, or a zero-length directional light;
//  - seed 000's glass cube scene (its figures 10 and 11) renders; the PNG goes to
//    build/test-out/ and, with WB_UPDATE_SCREENSHOT=1, to docs/screenshots/glass_cube.png.
#include "core/raytrace/box.h"
#include "core/raytrace/course_model.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/polyhedron.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/render.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

using namespace wb::rt;

namespace {

void lambertScene(Scene& s) {
    s.background = glm::dvec3(0.0);
    s.globalAmbient = glm::dvec3(0.0);
    s.ambient = glm::dvec3(0.0);
    s.distScale = 0; // course model: SH = 1
    s.lights.push_back(Light::point({0, 0, 2}));
    Material m;
    m.colour = glm::dvec3(1.0);
    m.ka = 0;
    m.kd = 1;
    m.ks = 0;
    s.add(Plane({0, 0, 0}, {0, 0, 1}), s.addMaterial(m));
}

} // namespace

TEST_CASE("render: Lambert plane under a point light, pixel by pixel", "[raytrace][render]") {
    Scene s;
    lambertScene(s);
    const LookAtCamera cam({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 70);
    const int w = 61, h = 61;
    const PhongModel phong;
    const CourseModel course;
    RenderStats st;
    const wb::Image ip = render(s, cam, phong, w, h, {}, &st);
    CHECK(st.nonFinitePixels == 0);
    const wb::Image ic = render(s, cam, course, w, h, {}, &st);
    CHECK(st.nonFinitePixels == 0);
    int worst = 0, offByOne = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Closed form: the primary ray meets z = 0 at t = −o.z/d.z; cos θ = 2/|L − p|.
            const Ray r = cam.primaryRay(x, y, w, h);
            const glm::dvec3 p = r.origin + (-r.origin.z / r.direction.z) * r.direction;
            const double cosT = 2 / glm::length(glm::dvec3(0, 0, 2) - p);
            const int ep = int(std::lround(255 * cosT));            // phong: round(255·c)
            const int ec = int(CourseModel::roundEven(255 * cosT)); // course: (BL·C)·LN·KD
            const int dp = std::abs(ip.at(x, y)[0] - ep), dc = std::abs(ic.at(x, y)[0] - ec);
            worst = std::max({worst, dp, dc});
            offByOne += (dp > 0) + (dc > 0);
            CHECK(ip.at(x, y)[0] == ip.at(x, y)[1]); // white light, white plane: grey
        }
    // Equal except where 255·cos θ lies within rounding (~1e-13) of a .5 boundary.
    CHECK(worst <= 1);
    CHECK(offByOne <= 2);
    CHECK(ip.at(30, 30)[0] == 255); // straight under the light: cos = 1
}

TEST_CASE("render: a sphere lit from the camera is brightest at its centre", "[raytrace][render]") {
    Scene s;
    s.background = glm::dvec3(0.0);
    s.globalAmbient = glm::dvec3(0.0);
    s.lights.push_back(Light::point({0, 0, 5}));
    Material m;
    m.ka = 0;
    m.kd = 1;
    m.ks = 0.3;
    m.phongExp = 20;
    s.add(Sphere({0, 0, 0}, 1), s.addMaterial(m));
    const LookAtCamera cam({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    const PhongModel model;
    const Tracer tracer(s, model);
    const int w = 41, h = 41;
    double best = -1;
    int bx = -1, by = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Color c = tracer.trace(cam.primaryRay(x, y, w, h));
            if (c.x > best) best = c.x, bx = x, by = y;
        }
    CHECK(bx == 20);
    CHECK(by == 20);
    CHECK(best == Approx(1.3).epsilon(1e-12)); // kd·1 + ks·1: normal, light and eye aligned
}

TEST_CASE("render: degenerate scenes give no NaN or Inf", "[raytrace][render]") {
    Scene s;
    Material glass;
    glass.kr = 0.3;
    glass.kt = 0.7;
    glass.medium = {1.5, 0.1};
    const int g = s.addMaterial(glass);
    Material plain;
    plain.kr = 0.2;
    const int p = s.addMaterial(plain);
    s.add(Triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), g); // zero area
    s.add(Triangle({0, 0, 0}, {0, 0, 0}, {0, 0, 0}), g); // a point
    s.add(Sphere({0.5, 0, 0.5}, 0), g);                  // zero radius
    s.add(Sphere({0, 0, 1}, 1), g);                      // the light is inside
    s.add(Plane({0, 0, 0}, {0, 0, 1}), p);               // the light is on it below
    s.add(Box::axisAligned({1.5, -0.5, 0}, {2.5, 0.5, 1}), g);
    s.add(Cone({-2, 0, 0}, 0.5, {-2, 0, 1.5}, 0), g);
    s.add(Quadric(Quadric::Kind::Paraboloid, {2, 2, 0}, {0.5, 0.5, 1}, 0, 1), g);
    s.add(ConvexPolyhedron({{{0, 0, 1}, 3.0}, {{0, 0, -1}, -2.5}}), g); // unbounded slab
    s.lights.push_back(Light::point({0, 0, 1}));                        // inside the sphere
    s.lights.push_back(Light::point({3, 0, 0}));                        // on the plane
    s.lights.push_back(Light::directional({0, 0, 0}));                  // zero direction
    s.lights.push_back(Light::point({0, 0, 2}));                        // on the sphere
    const LookAtCamera cam({0, -6, 4}, {0, 0, 0.5}, {0, 0, 1}, 60);
    const PhongModel phong;
    const CourseModel course;
    TraceSettings ts;
    ts.maxDepth = 8;
    for (const ShadingModel* m :
         {static_cast<const ShadingModel*>(&phong), static_cast<const ShadingModel*>(&course)}) {
        RenderStats st;
        const wb::Image img = render(s, cam, *m, 48, 36, ts, &st);
        CHECK(st.nonFinitePixels == 0);
        CHECK(img.width == 48);
    }
    // The camera inside the glass sphere, too.
    const LookAtCamera inside({0, 0, 1.2}, {0, 1, 1.2}, {0, 0, 1}, 90);
    RenderStats st;
    render(s, inside, course, 24, 24, ts, &st);
    CHECK(st.nonFinitePixels == 0);
}

namespace {

// Seed 000, figures 10 and 11: a glass cube (kr = kt = 0.3) over a rectangle (kr = 0.3);
// the light near the cube's left vertex (10) or between the two objects (11).
wb::Image glassCube(const glm::dvec3& light, int w, int h, RenderStats& st) {
    Scene s;
    s.distScale = 30;
    s.lights.push_back(Light::point(light));
    Material floor;
    floor.colour = glm::dvec3(21, 234, 21) / 255.0;
    floor.kr = 0.3;
    Material glass;
    glass.colour = glm::dvec3(234, 21, 21) / 255.0;
    glass.ka = 0.2;
    glass.kd = 0.3;
    glass.ks = 0.5;
    glass.phongExp = 20;
    glass.kr = 0.3;
    glass.kt = 0.3;
    glass.medium.refract = 1.5;
    s.add(Rectangle({-50, -50, 0}, {50, -50, 0}, {-50, 50, 0}), s.addMaterial(floor));
    s.add(Box({-15, -15, 10}, {30, 0, 0}, {0, 30, 0}, {0, 0, 30}), s.addMaterial(glass));
    const LookAtCamera cam({70, -110, 80}, {0, 0, 15}, {0, 0, 1}, 40);
    const CourseModel model;
    return render(s, cam, model, w, h, {}, &st);
}

} // namespace

TEST_CASE("render: seed 000's glass cube scene (figures 10 and 11)", "[raytrace][render]") {
    const int w = 320, h = 240;
    RenderStats s10, s11;
    const wb::Image a = glassCube({-22, -22, 45}, w, h, s10); // near the cube's left top vertex
    const wb::Image b = glassCube({0, 0, 5}, w, h, s11);      // between the cube and the rectangle
    CHECK(s10.nonFinitePixels == 0);
    CHECK(s11.nonFinitePixels == 0);
    wb::Image both(2 * w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                both.at(x, y)[c] = a.at(x, y)[c];
                both.at(w + x, y)[c] = b.at(x, y)[c];
            }
    // The top left corner looks past the rectangle at the background (128,207,255).
    CHECK(a.at(0, 0)[0] == 128);
    CHECK(a.at(0, 0)[1] == 207);
    CHECK(a.at(0, 0)[2] == 255);
    // The image is not flat: cube, floor, shadow and background all differ.
    int distinct = 0;
    for (int x = 0; x < w; x += 8)
        distinct += a.at(x, h / 2)[1] != a.at(w / 2, h / 2)[1];
    CHECK(distinct > 0);
    std::string err;
    CHECK(wb::writePng(std::string(WB_TEST_OUT_DIR) + "/glass_cube.png", both, &err));
    if (const char* up = std::getenv("WB_UPDATE_SCREENSHOT"); up && std::string(up) == "1")
        CHECK(wb::writePng(std::string(WB_GOLDEN_DIR) + "/../../docs/screenshots/glass_cube.png",
                           both, &err));
    INFO(err);
}

TEST_CASE("render: every primitive in one scene (phong model)", "[raytrace][render]") {
    Scene s;
    s.background = {0.15, 0.15, 0.2};
    s.lights.push_back(Light::point({-4, -6, 8}));
    auto mat = [&](double r, double g, double b, double kr = 0, double kt = 0) {
        Material m;
        m.colour = {r, g, b};
        m.ka = 0.3;
        m.kd = 0.7;
        m.ks = 0.4;
        m.phongExp = 30;
        m.kr = kr;
        m.kt = kt;
        m.medium.refract = 1.5;
        return s.addMaterial(m);
    };
    Plane floor({0, 0, 0}, {0, 0, 1});
    s.add(floor, mat(0.8, 0.8, 0.8, 0.2));
    s.add(Sphere({-3, 0, 1}, 1), mat(0.9, 0.2, 0.2));
    s.add(Box({-0.8, -0.8, 0}, {1.6, 0, 0}, {0.4, 1.6, 0}, {0, 0, 1.6}), mat(0.2, 0.8, 0.2));
    s.add(makeCylinder({3, 0, 0}, {3, 0, 2}, 0.8), mat(0.2, 0.3, 0.9));
    s.add(Cone({-3, 3, 0}, 1, {-3, 3, 2}, 0.3), mat(0.9, 0.8, 0.2));
    s.add(Quadric(Quadric::Kind::Ellipsoid, {0, 3, 1}, {1.2, 0.7, 1}), mat(0.8, 0.3, 0.8, 0, 0.6));
    s.add(Quadric(Quadric::Kind::Paraboloid, {3, 3, 0.2}, {0.6, 0.6, 1}, 0, 1.8),
          mat(0.3, 0.8, 0.8));
    s.add(Quadric(Quadric::Kind::Hyperboloid, {3, -3, 1}, {0.5, 0.5, 0.6}, 0, 2),
          mat(0.9, 0.5, 0.2));
    // A pyramid from five half-spaces (normals left unnormalised on purpose).
    s.add(ConvexPolyhedron({{{0, 0, -1}, 0},
                            {{1, 0, 1}, 2.1},
                            {{-1, 0, 1}, -0.9},
                            {{0, 1, 1}, -1.4},
                            {{0, -1, 1}, 2.6}}),
          mat(0.6, 0.6, 0.3));
    s.add(Triangle({-1.5, -2, 0}, {-0.5, -2, 0}, {-1, -2, 1.5}), mat(0.9, 0.9, 0.9));
    s.add(Rectangle({-4.5, -4, 0.01}, {-2.5, -4, 0.01}, {-4.5, -2, 0.01}), mat(0.1, 0.1, 0.1, 0.6));
    const LookAtCamera cam({2, -11, 7}, {0, 0, 0.8}, {0, 0, 1}, 45);
    const PhongModel model;
    RenderStats st;
    const wb::Image img = render(s, cam, model, 320, 240, {}, &st);
    CHECK(st.nonFinitePixels == 0);
    CHECK(wb::writePng(std::string(WB_TEST_OUT_DIR) + "/primitives.png", img));
}
