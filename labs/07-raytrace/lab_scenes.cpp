#include "lab_scenes.h"

#include "core/raytrace/box.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/scene_file.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/spd.h"
#include "core/raytrace/sphere.h"
#include "core/teapot.h"

#include "core/i18n.h"
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace wb {

namespace {

using glm::dvec3;
using rt::Light;
using rt::Material;

Material phongMaterial(const dvec3& colour, double kr = 0.0) {
    Material m;
    m.colour = colour;
    m.ka = 0.3;
    m.kd = 0.7;
    m.ks = 0.4;
    m.phongExp = 30;
    m.kr = kr;
    return m;
}

// The lab's timing experiment (lab 7, task 5): one sphere, then two, over a floor.
void buildSpheres(LabScene& s, int count) {
    rt::Scene& sc = *s.scene;
    sc.lights.push_back(Light::point({3, 4, 5}));
    const int floor = sc.addMaterial(phongMaterial({0.8, 0.8, 0.8}));
    sc.add(rt::Rectangle({-4, -1, 4}, {4, -1, 4}, {-4, -1, -4}), floor);
    sc.add(rt::Sphere({0, 0, 0}, 1.0), sc.addMaterial(phongMaterial({0.9, 0.2, 0.2})));
    if (count > 1)
        sc.add(rt::Sphere({1.7, -0.4, -1.2}, 0.6), sc.addMaterial(phongMaterial({0.2, 0.3, 0.9})));
    s.camera.eye = {0, 1.5, 6};
    s.camera.target = {0, 0, 0};
    s.camera.fovY = 45;
    s.model = ModelKind::Phong;
    s.about = count == 1 ? N_("one sphere over a floor (the lab's timing experiment)")
                         : N_("two spheres over a floor (the lab's timing experiment)");
}

// Diffuse spheres lit from the eye (so no shadow is visible): the scene on which the
// per-fragment GLSL raster and the phong tracer must agree up to tessellation.
void buildDiffuse(LabScene& s) {
    rt::Scene& sc = *s.scene;
    s.camera.eye = {0, 1.5, 6};
    s.camera.target = {0, 0, 0};
    s.camera.fovY = 45;
    sc.lights.push_back(Light::point(s.camera.eye));
    Material m = phongMaterial({0.9, 0.3, 0.2});
    m.ks = 0;
    sc.add(rt::Sphere({0, 0, 0}, 1.0), sc.addMaterial(m));
    m.colour = {0.2, 0.8, 0.3};
    sc.add(rt::Sphere({-1.6, -0.3, -1}, 0.7), sc.addMaterial(m));
    m.colour = {0.3, 0.4, 0.9};
    sc.add(rt::Sphere({1.5, 0.4, -0.5}, 0.5), sc.addMaterial(m));
    s.model = ModelKind::Phong;
    s.about = N_("diffuse spheres lit from the eye: raster and trace should agree");
}

Material seedMaterial(const dvec3& colour255, double kr) {
    Material m;
    m.colour = colour255 / 255.0;
    m.ka = m.kd = m.ks = 0.5;
    m.phongExp = 3;
    m.kr = kr;
    return m;
}

// Seed 000's camera: eye (0, 0, 100) looking down −z at the screen z = 0 (Dist = 100),
// one world unit per pixel, pixel (xx, yy) -> screen point (xx − W/2, H/2 − yy).
void seedCamera(LabScene& s) {
    s.camera.eye = {0, 0, 100};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.camera.screenPixel = 1.0;
    s.camera.pixelCorners = true;
    s.model = ModelKind::Course;
}

// Seed 000 part 1: red 20×20 rectangle at height 40 over a green 50×50 one at 20, light
// at (0, 0, 60): pixel P(50, 0) sees the green one in the red one's shadow.
void buildSeedPart1(LabScene& s, bool withRect1) {
    rt::Scene& sc = *s.scene;
    sc.lights.push_back(Light::point({0, 0, 60}));
    sc.ambient = dvec3(1.0);
    sc.distScale = 30;
    const int red = sc.addMaterial(seedMaterial({234, 21, 21}, 0));
    const int green = sc.addMaterial(seedMaterial({21, 234, 21}, 0));
    if (withRect1) sc.add(rt::Rectangle({0, 0, 40}, {20, 0, 40}, {0, 20, 40}), red);
    sc.add(rt::Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), green);
    seedCamera(s);
    // Framed: at the seed's 1 unit per pixel the 62-pixel rectangles were a dot in the
    // upper right of the window. A quarter unit per pixel (exact in binary) makes them
    // 250 pixels, and the seed's screen points stay pixel corners: P(xs, ys) is pixel
    // (W/2 + 4·xs, H/2 − 4·ys), so P(50, 0) is traced with the seed's very ray.
    s.camera.screenPixel = 0.25;
    s.about = withRect1 ? N_("seed 000 part 1: P(50,0) (pixel W/2+200, H/2) in the red "
                             "rectangle's shadow: (10,117,10)")
                        : N_("seed 000 part 1, red rectangle removed: P(50,0) (pixel W/2+200, "
                             "H/2) lit: (50,197,50)");
}

// Seed 000 part 2: the green rectangle (kr 0.5) reflects the red one standing in x = 50.
void buildSeedPart2(LabScene& s) {
    rt::Scene& sc = *s.scene;
    sc.lights.push_back(Light::point({0, 0, 60}));
    sc.ambient = dvec3(1.0);
    sc.distScale = 30;
    const int red = sc.addMaterial(seedMaterial({234, 21, 21}, 0));
    const int green = sc.addMaterial(seedMaterial({21, 234, 21}, 0.5));
    sc.add(rt::Rectangle({50, 0, 20}, {50, 0, 70}, {50, 50, 20}), red);
    sc.add(rt::Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), green);
    seedCamera(s);
    s.about = N_("seed 000 part 2: P(50,0) with the reflected ray (168,233,86)");
}

// Seed 000, figure 10: a glass cube (kr = kt = 0.3, index 1.5) over a mirror-ish rectangle.
void buildGlassCube(LabScene& s) {
    rt::Scene& sc = *s.scene;
    sc.distScale = 30;
    sc.lights.push_back(Light::point({-22, -22, 45}));
    Material floor = seedMaterial({21, 234, 21}, 0.3);
    Material glass = seedMaterial({234, 21, 21}, 0.3);
    glass.ka = 0.2;
    glass.kd = 0.3;
    glass.ks = 0.5;
    glass.phongExp = 20;
    glass.kt = 0.3;
    glass.medium.refract = 1.5;
    sc.add(rt::Rectangle({-50, -50, 0}, {50, -50, 0}, {-50, 50, 0}), sc.addMaterial(floor));
    sc.add(rt::Box({-15, -15, 10}, {30, 0, 0}, {0, 30, 0}, {0, 0, 30}), sc.addMaterial(glass));
    s.camera.eye = {70, -110, 80};
    s.camera.target = {0, 0, 15};
    s.camera.up = {0, 0, 1};
    s.camera.fovY = 40;
    s.model = ModelKind::Course;
    s.about = N_("seed 000 figure 10: glass cube (kr = kt = 0.3, n = 1.5) over a rectangle");
}

// Seed 001's scene: a table (box top, cylinder legs) with a glass (paraboloid cut by two
// planes, transparent) and an ellipsoid on it, over an infinite floor plane. z is up.
void buildTable(LabScene& s) {
    rt::Scene& sc = *s.scene;
    sc.lights.push_back(Light::point({2, -2, 3}));
    sc.add(rt::Plane({0, 0, 0}, {0, 0, 1}), sc.addMaterial(phongMaterial({0.6, 0.6, 0.55})));
    const int wood = sc.addMaterial(phongMaterial({0.55, 0.33, 0.15}));
    sc.add(rt::Box::axisAligned({-1.2, -0.8, 0.75}, {1.2, 0.8, 0.8}), wood);
    for (double x : {-1.1, 1.1})
        for (double y : {-0.7, 0.7})
            sc.add(rt::makeCylinder({x, y, 0}, {x, y, 0.75}, 0.05), wood);
    Material glass = phongMaterial({0.7, 0.85, 1.0}, 0.1);
    glass.kd = 0.2;
    glass.ks = 0.8;
    glass.phongExp = 80;
    glass.kt = 0.7;
    glass.medium.refract = 1.5;
    sc.add(rt::Quadric(rt::Quadric::Kind::Paraboloid, {0, 0, 0.8}, {0.15, 0.15, 0.3}, 0.8, 1.1),
           sc.addMaterial(glass));
    sc.add(rt::Quadric(rt::Quadric::Kind::Ellipsoid, {0.55, 0.25, 0.9}, {0.1, 0.1, 0.1}),
           sc.addMaterial(phongMaterial({1.0, 0.55, 0.1})));
    s.camera.eye = {2.5, -3.0, 2.0};
    s.camera.target = {0, 0, 0.8};
    s.camera.up = {0, 0, 1};
    s.camera.fovY = 40;
    s.model = ModelKind::Phong;
    s.about = N_("seed 001: table and glass (cut paraboloid, ellipsoid, cylinders, plane)");
}

// The Utah teapot (core/teapot: Newell's 32 Bezier patches) as 12×12-cell grids per patch,
// 9,120 smooth triangles with core's normals (the poles' limit normals included), on a
// floor. z is up. The pot is open (spout, lid gap), so its triangles bound no body.
void buildTeapot(LabScene& s) {
    rt::Scene& sc = *s.scene;
    sc.lights.push_back(Light::point({4, -3, 8}));
    sc.add(rt::Rectangle({-6, -6, 0}, {6, -6, 0}, {-6, 6, 0}),
           sc.addMaterial(phongMaterial({0.6, 0.6, 0.55})));
    Material china = phongMaterial({0.85, 0.85, 0.8}, 0.1);
    china.ks = 0.6;
    china.phongExp = 60;
    const int pot = sc.addMaterial(china);
    const Mesh m = teapotMesh(12);
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
        sc.add(rt::SmoothTriangle(m.positions[a], m.positions[b], m.positions[c], m.normals[a],
                                  m.normals[b], m.normals[c]),
               pot);
    }
    s.camera.eye = {5.5, -7.5, 5.0};
    s.camera.target = {0.25, 0, 1.3};
    s.camera.up = {0, 0, 1};
    s.camera.fovY = 38;
    s.model = ModelKind::Phong;
    // Translated when the scene is built (the count is in it): it keeps that language.
    s.about = trf("the Utah teapot: Newell's 32 Bezier patches as %zu smooth triangles "
                  "(core/teapot)",
                  m.indices.size() / 3);
}

// A scene of issue 6's readers and generators (phong model, the file's view).
void fromSceneFile(LabScene& s, rt::SceneFile&& f, const std::string& about) {
    s.scene = std::move(f.scene);
    s.camera.eye = f.view.from;
    s.camera.target = f.view.at;
    s.camera.up = f.view.up;
    s.camera.fovY = f.view.angle;
    s.camera.hither = f.view.hither; // as rt_render's SceneFile::camera()
    s.model = ModelKind::Phong;
    s.about = about;
    s.warnings = std::move(f.warnings);
    s.warningCount = f.warningCount;
}

// "balls:3" -> 3 when the prefix matches and N is 1..5.
bool sizeFactor(const std::string& name, const std::string& prefix, int& n) {
    if (name.compare(0, prefix.size(), prefix) != 0) return false;
    const std::string tail = name.substr(prefix.size());
    if (tail.size() != 1 || tail[0] < '1' || tail[0] > '5') return false;
    n = tail[0] - '0';
    return true;
}

bool hasExtension(const std::string& name, const std::string& ext) {
    if (name.size() <= ext.size()) return false;
    std::string tail = name.substr(name.size() - ext.size());
    std::transform(tail.begin(), tail.end(), tail.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return tail == ext;
}

} // namespace

std::vector<std::string> builtinSceneNames() {
    return {"one-sphere",        "two-spheres",   "diffuse-spheres", "seed000-part1",
            "seed000-part1-lit", "seed000-part2", "glass-cube",      "seed001-table",
            "balls:1",           "balls:2",       "balls:3",         "balls:4",
            "jacks:1",           "jacks:2",       "jacks:3",         "teapot"};
}

std::vector<std::string> warningLines(const LabScene& s) {
    std::vector<std::string> out;
    if (s.warningCount == 0) return out;
    out.push_back(s.warningCount == 1 ? trf("%zu warning:", size_t(s.warningCount))
                                      : trf("%zu warnings:", size_t(s.warningCount)));
    for (const std::string& w : s.warnings)
        out.push_back("  " + w);
    if (s.warningCount > s.warnings.size())
        out.push_back(trf("  ... and %zu more", size_t(s.warningCount - s.warnings.size())));
    return out;
}

bool loadLabScene(const std::string& name, LabScene& out, std::string& error) {
    const auto t0 = std::chrono::steady_clock::now();
    LabScene s;
    s.name = name;
    s.scene = std::make_unique<rt::Scene>();
    try {
        if (name == "one-sphere")
            buildSpheres(s, 1);
        else if (name == "two-spheres")
            buildSpheres(s, 2);
        else if (name == "diffuse-spheres")
            buildDiffuse(s);
        else if (name == "seed000-part1")
            buildSeedPart1(s, true);
        else if (name == "seed000-part1-lit")
            buildSeedPart1(s, false);
        else if (name == "seed000-part2")
            buildSeedPart2(s);
        else if (name == "glass-cube")
            buildGlassCube(s);
        else if (name == "seed001-table")
            buildTable(s);
        else if (name == "teapot")
            buildTeapot(s);
        else if (int n = 0; sizeFactor(name, "balls:", n))
            fromSceneFile(s, rt::toScene(rt::spdBalls(n)),
                          trf("SPD balls (sphereflake) size %d: %lld spheres", n,
                              (long long)rt::spdBallsSpheres(n)));
        else if (int m = 0; sizeFactor(name, "jacks:", m))
            fromSceneFile(s, rt::toScene(rt::spdJacks(m)),
                          trf("SPD jacks size %d: %lld jacks", m, (long long)rt::spdJacksCount(m)));
        else if (hasExtension(name, ".nff") || hasExtension(name, ".obj"))
            fromSceneFile(s, rt::loadSceneFile(name), trf("file %s", name.c_str()));
        else {
            std::string known;
            for (const auto& k : builtinSceneNames())
                known += " " + k;
            error =
                trf("unknown scene '%s' (one of:%s, balls:N, jacks:N with N = 1..5, or a .nff / "
                    ".obj file)",
                    name.c_str(), known.c_str());
            return false;
        }
    } catch (const std::exception& e) {
        error = name + ": " + e.what();
        return false;
    }
    s.loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out = std::move(s);
    return true;
}

bool setAccel(LabScene& s, bool on) {
    if (!on) {
        s.scene->setAggregate(nullptr);
        s.accel.reset();
        s.accelSeconds = 0;
        return true;
    }
    // Issue 6's binned-SAH BVH; below its measured crossover (a handful of objects) the
    // brute-force loop is as fast and makeAggregate returns null.
    const auto t0 = std::chrono::steady_clock::now();
    s.scene->setAggregate(nullptr);
    std::unique_ptr<rt::Bvh> bvh;
    try {
        bvh = rt::makeAggregate(*s.scene);
    } catch (const std::exception& e) {
        // The BVH refused to build (bad options, memory): said, and traced with the plain
        // loop (the same pictures, slower) rather than ending the lab.
        std::fprintf(stderr, tr("lab07: no BVH: %s; tracing with the plain loop\n"), e.what());
        s.accel.reset();
        s.accelSeconds = 0;
        return false;
    }
    s.accelSeconds =
        bvh ? std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() : 0.0;
    s.scene->setAggregate(bvh.get());
    s.accel = std::move(bvh);
    return true;
}

} // namespace wb
