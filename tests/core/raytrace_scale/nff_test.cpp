// NFF reader and writer, the SPD generators and the OBJ loader:
//  - generator counts against the SPD formulas, and the first sphereflake child against
//    the published balls.nff line "s 0.272166 0.272166 0.544331 0.166667";
//  - read(write(doc)) == doc exactly, and writing twice gives the same text;
//  - every command, both forms of `c`, optional light colour, comments;
//  - malformed files: each error names the file, the line and the problem;
//  - OBJ: negative indices, polygons, materials, vertex normals, a missing .mtl, bad input.
#include "core/raytrace/nff.h"
#include "core/raytrace/obj_file.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/spd.h"
#include "core/raytrace/sphere.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace wb::rt;

namespace {

NffDocument parse(const std::string& text) {
    std::istringstream in(text);
    return readNff(in, "test.nff");
}

std::string write(const NffDocument& d) {
    std::ostringstream out;
    writeNff(out, d);
    return out.str();
}

int count(const NffDocument& d, NffObject::Kind k) {
    int n = 0;
    for (const auto& o : d.objects)
        n += o.kind == k;
    return n;
}

void requireEqual(const NffDocument& a, const NffDocument& b) {
    REQUIRE(a.hasView == b.hasView);
    REQUIRE(a.view.from == b.view.from);
    REQUIRE(a.view.at == b.view.at);
    REQUIRE(a.view.up == b.view.up);
    REQUIRE(a.view.angle == b.view.angle);
    REQUIRE(a.view.hither == b.view.hither);
    REQUIRE(a.view.width == b.view.width);
    REQUIRE(a.view.height == b.view.height);
    REQUIRE(a.hasBackground == b.hasBackground);
    REQUIRE(a.background == b.background);
    REQUIRE(a.lights.size() == b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        REQUIRE(a.lights[i].position == b.lights[i].position);
        REQUIRE(a.lights[i].hasColour == b.lights[i].hasColour);
        if (a.lights[i].hasColour) REQUIRE(a.lights[i].colour == b.lights[i].colour);
    }
    REQUIRE(a.surfaces.size() == b.surfaces.size());
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
        const auto &x = a.surfaces[i], &y = b.surfaces[i];
        REQUIRE((x.colour == y.colour && x.kd == y.kd && x.ks == y.ks && x.shine == y.shine &&
                 x.t == y.t && x.ior == y.ior));
    }
    REQUIRE(a.objects.size() == b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const auto &x = a.objects[i], &y = b.objects[i];
        REQUIRE(x.kind == y.kind);
        REQUIRE(x.surface == y.surface);
        REQUIRE(x.centre == y.centre);
        REQUIRE(x.radius == y.radius);
        REQUIRE(x.base == y.base);
        REQUIRE(x.apex == y.apex);
        REQUIRE(x.baseRadius == y.baseRadius);
        REQUIRE(x.apexRadius == y.apexRadius);
        REQUIRE(x.coneOneLine == y.coneOneLine);
        REQUIRE(x.vertices == y.vertices);
        REQUIRE(x.normals == y.normals);
    }
}

std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const SceneFileError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string tempPath(const std::string& name) {
    return std::string(WB_TEST_TMP) + "/" + name;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

} // namespace

TEST_CASE("rt_spd: balls and jacks primitive counts follow the SPD formulas", "[raytrace][nff]") {
    const long long balls[] = {10, 91, 820, 7381}; // the table in balls.c
    for (int sf = 1; sf <= 4; ++sf) {
        INFO("size factor " << sf);
        CHECK(spdBallsSpheres(sf) == balls[sf - 1]);
        const NffDocument b = spdBalls(sf);
        CHECK(count(b, NffObject::Kind::Sphere) == balls[sf - 1]);
        CHECK(count(b, NffObject::Kind::Polygon) == 1);
        CHECK(b.lights.size() == 3);
        const NffDocument j = spdJacks(sf);
        const long long jacks = spdJacksCount(sf);
        CHECK(jacks == (sf == 1 ? 1 : sf == 2 ? 9 : sf == 3 ? 73 : 585));
        CHECK(count(j, NffObject::Kind::Cone) == 3 * jacks);
        CHECK(count(j, NffObject::Kind::Sphere) == 6 * jacks);
    }
    CHECK(spdBallsSpheres(5) == 66430);
    CHECK_THROWS_AS(spdBalls(0), std::invalid_argument);
    CHECK_THROWS_AS(spdJacks(7), std::invalid_argument);
}

TEST_CASE("rt_spd: sphereflake geometry matches the published balls.nff", "[raytrace][nff]") {
    const NffDocument b = spdBalls(1);
    // balls.nff (SPD 3.x): "s 0 0 0 0.5" then "s 0.272166 0.272166 0.544331 0.166667";
    // the file prints 6 digits, so 5e-7 is its rounding.
    REQUIRE(b.objects[1].kind == NffObject::Kind::Sphere);
    CHECK(b.objects[1].radius == Approx(0.5).margin(5e-7));
    const NffObject& c = b.objects[2];
    CHECK(c.centre.x == Approx(0.272166).margin(5e-7));
    CHECK(c.centre.y == Approx(0.272166).margin(5e-7));
    CHECK(c.centre.z == Approx(0.544331).margin(5e-7));
    CHECK(c.radius == Approx(0.166667).margin(5e-7));
    // Every child touches its parent: |c − p| = r_p + r_c (tangent spheres), to rounding.
    CHECK(glm::length(c.centre) == Approx(0.5 + 0.5 / 3).epsilon(1e-14));
    // The spheres' Phong exponent printed in balls.nff: "f 1 0.9 0.7 0.5 0.5 3.0827 0 1".
    CHECK(b.surfaces[1].shine == Approx(3.0827).margin(5e-5));
}

TEST_CASE("rt_nff: write then read gives the same document for balls and jacks",
          "[raytrace][nff]") {
    for (const NffDocument& d : {spdBalls(2), spdJacks(2), twoSpheresScene()}) {
        const std::string text = write(d);
        const NffDocument back = parse(text);
        requireEqual(d, back);
        CHECK(write(back) == text);
    }
}

TEST_CASE("rt_nff: every command is read", "[raytrace][nff]") {
    const std::string text = "# a comment line\n"
                             "v\nfrom 1 2 3\nat 0 0 0\nup 0 0 1\nangle 30\nhither 0.5\n"
                             "resolution 64 48\n"
                             "b 0.1 0.2 0.3   # trailing comment\n"
                             "l 1 1 1\n"
                             "l 2 2 2 0.5 0.25 1\n"
                             "s 0 0 0 1\n" // before any f: default surface
                             "f 1 0 0 0.6 0.4 20 0.1 1.5\n"
                             "c 0 0 0 1 0 0 1 0.5\n"
                             "c\n0 0 0 1\n0 0 2 1\n"
                             "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                             "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0.1 0 1\n";
    const NffDocument d = parse(text);
    CHECK(d.hasView);
    CHECK(d.view.from == glm::dvec3(1, 2, 3));
    CHECK(d.view.angle == 30);
    CHECK(d.view.hither == 0.5);
    CHECK(d.view.width == 64);
    CHECK(d.view.height == 48);
    CHECK(d.background == glm::dvec3(0.1, 0.2, 0.3));
    REQUIRE(d.lights.size() == 2);
    CHECK_FALSE(d.lights[0].hasColour);
    CHECK(d.lights[1].hasColour);
    CHECK(d.lights[1].colour == glm::dvec3(0.5, 0.25, 1));
    REQUIRE(d.objects.size() == 5);
    CHECK(d.objects[0].surface == -1);
    CHECK(d.objects[1].coneOneLine);
    CHECK_FALSE(d.objects[2].coneOneLine);
    CHECK(d.objects[2].apex == glm::dvec3(0, 0, 2));
    CHECK(d.objects[3].vertices.size() == 4);
    CHECK(d.objects[4].normals[2] == glm::dvec3(0.1, 0, 1));
    CHECK(d.objects[4].line == 23);
    // Both forms of `c` survive a round trip in their own form.
    const std::string again = write(d);
    CHECK(again.find("c 0 0 0 1 0 0 1 0.5\n") != std::string::npos);
    CHECK(again.find("c\n0 0 0 1\n0 0 2 1\n") != std::string::npos);
    requireEqual(d, parse(again));

    // The scene: NFF's mapping onto the phong model.
    const SceneFile sf = toScene(d);
    CHECK(sf.scene->primitives.size() == 1 + 2 + 2 + 1);
    const Material& m = sf.scene->materials[size_t(sf.scene->primitives[1]->material)];
    CHECK(m.kd == 0.6);
    CHECK(m.ks == 0.4);
    CHECK(m.kr == 0.4); // Ks is also the mirror reflectance
    CHECK(m.kt == 0.1);
    CHECK(m.medium.refract == 1.5);
    CHECK(m.phongExp == 20);
    CHECK(sf.scene->lights[0].colour == glm::dvec3(1 / std::sqrt(2.0)));
    CHECK(sf.scene->lights[1].colour == glm::dvec3(0.5, 0.25, 1));
    CHECK(dynamic_cast<const SmoothTriangle*>(sf.scene->primitives.back().get()) != nullptr);
}

TEST_CASE("rt_nff: pp shading normals are interpolated", "[raytrace][nff]") {
    const NffDocument d = parse("pp 3\n0 0 0 -1 0 1\n1 0 0 1 0 1\n0 1 0 0 0 1\n");
    const SceneFile sf = toScene(d);
    Ray ray;
    ray.origin = {0.25, 0.25, 1};
    ray.direction = {0, 0, -1};
    Hit h;
    REQUIRE(sf.scene->intersect(ray, 0, 10, h));
    // Barycentrics (0.5, 0.25, 0.25) of the unit vertex normals.
    const double r = 1 / std::sqrt(2.0);
    const glm::dvec3 expect = glm::normalize(
        0.5 * glm::dvec3(-r, 0, r) + 0.25 * glm::dvec3(r, 0, r) + 0.25 * glm::dvec3(0, 0, 1));
    CHECK(h.normal.x == Approx(expect.x).margin(1e-12));
    CHECK(h.normal.z == Approx(expect.z).margin(1e-12));
}

TEST_CASE("rt_nff: malformed files name the file and the line and the problem", "[raytrace][nff]") {
    struct Case {
        const char* text;
        const char* expect;
    };
    const Case cases[] = {
        {"s 0 0 0 1\ns 0 0 x 1\n", "test.nff:2: expected a number"},
        {"p 100000000\n0 0 0\n", "test.nff:1: polygon with 100000000 vertices (limit"},
        {"p 2\n0 0 0\n1 1 1\n", "test.nff:1: polygon with 2 vertices"},
        {"p -5\n", "test.nff:1: polygon with -5 vertices"},
        {"p 3\n0 0 0\n1 0 0\n", "test.nff:1: unexpected end of file"},
        {"p 99999999999999999999999\n",
         "test.nff:1: integer '99999999999999999999999' (number of vertices) out of range"},
        {"v\nfrom 0 0 1\nat 0 0 0\nangle 30\n", "test.nff:4: expected 'up'"},
        {"v\nfrom 0 0 1\n", "test.nff:1: unexpected end of file in the v block"},
        {"v\nfrom 0 0 0\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\nresolution 8 8\n",
         "test.nff:1: bad view"},
        {"v\nfrom 0 0 1\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\nresolution 0 8\n",
         "test.nff:7: resolution"},
        {"s nan 0 0 1\n", "test.nff:1: non-finite number"},
        {"s 1e999 0 0 1\n", "test.nff:1: number '1e999' for sphere centre is beyond the range"},
        {"s 0 0 0 -1\n", "test.nff:1: negative sphere radius"},
        {"c 0 0 0 1 0 0 0 1\n", "test.nff:1: cone base and apex coincide"},
        {"c 0 0 0 0 1 0 0 0\n", "test.nff:1: cone with both radii 0"},
        {"\n\nz 1 2 3\n", "test.nff:3: unknown command 'z'"},
        {"f 1 1 1 1 1\n", "test.nff:1: unexpected end of file"},
        {"l 1 2\n", "test.nff:1: unexpected end of file"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK_THAT(errorOf(c.text), Catch::Matchers::StartsWith(c.expect));
    }
}

TEST_CASE("rt_nff: files on disk and unknown formats", "[raytrace][nff]") {
    const std::string p = tempPath("rt_nff_balls2.nff");
    writeNffFile(p, spdBalls(2));
    const SceneFile sf = loadSceneFile(p);
    CHECK(sf.hasView);
    CHECK(sf.scene->primitives.size() == 91 + 2);
    CHECK_THROWS_WITH(loadSceneFile(tempPath("missing.nff")),
                      Catch::Matchers::Contains("missing.nff:0: cannot open"));
    CHECK_THROWS_WITH(loadSceneFile(tempPath("x.ply")),
                      Catch::Matchers::Contains("unknown scene format"));
    std::remove(p.c_str());
}

TEST_CASE("rt_obj: faces of any size and negative indices and materials and normals",
          "[raytrace][obj]") {
    const std::string mtl = tempPath("rt_obj_a.mtl");
    writeText(mtl, "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 30\nNi 1.4\nd 0.25\n");
    const std::string obj = tempPath("rt_obj_a.obj");
    writeText(obj, "mtllib rt_obj_a.mtl\n"
                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                   "vn 0 0 1\n"
                   "usemtl red\n"
                   "f -4 -3 -2 -1\n"    // a quad by negative indices: 2 triangles
                   "f 1//1 2//1 3//1\n" // with normals: smooth
                   "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nv 0.5 1.5 1\n"
                   "f 5 6 7 9 8\n"); // a pentagon: 3 triangles
    ObjLoadReport rep;
    const SceneFile sf = loadObjFile(obj, &rep);
    CHECK(rep.triangles == 2 + 1 + 3);
    REQUIRE(sf.scene->primitives.size() == 6);
    CHECK_FALSE(sf.hasView);
    CHECK(sf.scene->lights.size() == 1); // default light
    const Material& m = sf.scene->materials[size_t(sf.scene->primitives[0]->material)];
    CHECK(m.colour == glm::dvec3(1, 0, 0));
    CHECK(m.ks == Approx(0.5));
    CHECK(m.phongExp == 30);
    CHECK(m.medium.refract == Approx(1.4));
    CHECK(m.kt == Approx(0.75));
    CHECK(dynamic_cast<const SmoothTriangle*>(sf.scene->primitives[2].get()) != nullptr);
    // The default view sees the model: the centre ray hits it.
    const LookAtCamera cam = sf.camera();
    Hit h;
    CHECK(sf.scene->intersect(cam.rayAt(32, 32, 64, 64), 0, 1e9, h));
}

TEST_CASE("rt_obj: a missing mtl is repaired and bad files are named", "[raytrace][obj]") {
    const std::string obj = tempPath("rt_obj_b.obj");
    writeText(obj, "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
    ObjLoadReport rep;
    const SceneFile sf = loadObjFile(obj, &rep);
    CHECK(sf.scene->primitives.size() == 1);
    CHECK_FALSE(rep.warnings.empty());

    writeText(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    CHECK_THROWS_WITH(loadObjFile(obj), Catch::Matchers::Contains("rt_obj_b.obj:"));
    writeText(obj, "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK_THROWS_WITH(loadObjFile(obj), Catch::Matchers::Contains("rt_obj_b.obj:2: non-finite"));
    writeText(obj, "v 0 0 0\nv 1 0 0\nf 1 2\n");
    ObjLoadReport rep2;
    try {
        const SceneFile s2 = loadObjFile(obj, &rep2);
        CHECK(s2.scene->primitives.empty()); // a 2-vertex face is dropped with a warning
    } catch (const SceneFileError& e) {
        CHECK_THAT(e.what(), Catch::Matchers::Contains("rt_obj_b.obj:"));
    }
    CHECK_THROWS_WITH(loadObjFile(tempPath("none.obj")), Catch::Matchers::Contains("none.obj:0"));
}
