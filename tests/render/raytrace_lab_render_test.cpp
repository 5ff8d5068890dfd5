// Lab 07 rendered headless: goldens of both modes, and the per-fragment GLSL raster
// against the "phong" tracer on a diffuse scene (they share the lighting equation of
// core/lighting.h, so what is left is tessellation and interpolation).
#include "render_check.h"

#include "lab_scenes.h"
#include "raster_mesh.h"
#include "raytrace_lab.h"
#include "view_camera.h"

#include "core/raytrace/spd.h"

#include <algorithm>
#include <cstdlib>

namespace {

wb::Image render(const std::string& scene, int w, int h, const std::string& keys) {
    auto lab = wb::makeRaytraceLab();
    std::string err;
    REQUIRE(lab->setOption("scene", scene, err));
    return wb::test::renderLab(*lab, w, h, keys);
}

bool isBackground(const uint8_t* p) { // the scenes' sky (128,207,255)
    return p[0] == 128 && p[1] == 207 && p[2] == 255;
}

// Which primitive each pixel's primary ray hits (-1: none), through the lab's own camera
// for orbit angles (yaw, pitch): the true outlines, independent of both renderers.
struct IdMap {
    int w, h;
    std::vector<int> id;
    int at(int x, int y) const { return id[size_t(y) * size_t(w) + size_t(x)]; }
    // No outline within r pixels: the (2r+1)² neighbours all see the same primitive.
    bool interior(int x, int y, int r = 1) const {
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
                if (at(xx, yy) != at(x, y)) return false;
            }
        return true;
    }
};

IdMap idMap(const std::string& scene, int w, int h, double yaw, double pitch) {
    wb::LabScene s;
    std::string err;
    REQUIRE(wb::loadLabScene(scene, s, err));
    const wb::ViewCamera cam = wb::ViewCamera::make(s.camera, yaw, pitch, 1.0, w, h);
    IdMap m{w, h, std::vector<int>(size_t(w) * size_t(h), -1)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            wb::rt::Hit hit;
            if (s.scene->intersect(cam.pixelRay(x, y), 0, 1e300, hit))
                for (size_t i = 0; i < s.scene->primitives.size(); ++i)
                    if (s.scene->primitives[i].get() == hit.primitive)
                        m.id[size_t(y) * size_t(w) + size_t(x)] = int(i);
        }
    return m;
}

} // namespace

// Raster goldens (fixed function and GLSL): Mesa's rasterizer is deterministic on one
// machine; max 2 / mean 0.1 leaves room for another Mesa version's rounding of the
// lighting (float) and of edge coverage, as the other labs' goldens do.
// Traced goldens: double precision, one ray per pixel, no randomness; a different
// compiler or libm may move a colour across an 8-bit rounding boundary: max 1, mean 0.05.
TEST_CASE("lab 07 goldens: two spheres rasterized (fixed, GLSL) and traced", "[gl]") {
    wb::test::checkGolden(render("two-spheres", 120, 90, "g"), "lab07-two-spheres-g", 2, 0.1);
    wb::test::checkGolden(render("two-spheres", 120, 90, "gf"), "lab07-two-spheres-glsl", 2, 0.1);
    const wb::Image traced = render("two-spheres", 120, 90, "G");
    wb::test::checkGolden(traced, "lab07-two-spheres-G", 1, 0.05);
}

TEST_CASE("lab 07 goldens: seed 000 glass cube and seed 001 table traced, rotated", "[gl]") {
    wb::test::checkGolden(render("glass-cube", 120, 90, "G"), "lab07-glass-cube-G", 1, 0.05);
    wb::test::checkGolden(render("seed001-table", 120, 90, "G{left}{left}{up}"),
                          "lab07-table-G-rotated", 1, 0.05);
    wb::test::checkGolden(render("seed001-table", 120, 90, "g{left}{left}{up}"),
                          "lab07-table-g-rotated", 2, 0.1);
}

TEST_CASE("lab 07: the traced view and the raster view share the camera (silhouettes agree)",
          "[gl]") {
    // Same scene, same camera: the set of sky pixels may differ only along silhouettes,
    // where the tessellated outline lies inside the true circle by at most 0.5 pixel
    // (raster_mesh.h), so a pixel centre can change side only within a pixel of it.
    // Left twice and down once: yaw −10°, pitch +5°.
    for (const char* keys : {"", "{left}{left}{down}"}) {
        const wb::Image g = render("diffuse-spheres", 160, 120, std::string("g") + keys);
        const wb::Image t = render("diffuse-spheres", 160, 120, std::string("G") + keys);
        const IdMap ids = idMap("diffuse-spheres", 160, 120, *keys ? -10 : 0, *keys ? 5 : 0);
        int differ = 0, outline = 0;
        for (int y = 1; y + 1 < g.height; ++y)
            for (int x = 1; x + 1 < g.width; ++x) {
                const bool edge = !ids.interior(x, y);
                outline += edge;
                // The traced image itself hits what the rays say.
                CHECK(isBackground(t.at(x, y)) == (ids.at(x, y) < 0));
                if (isBackground(g.at(x, y)) != isBackground(t.at(x, y))) {
                    ++differ;
                    INFO("pixel " << x << "," << y << " keys " << keys);
                    CHECK(edge);
                }
            }
        INFO("keys '" << keys << "': " << differ << " pixels differ in coverage, " << outline
                      << " outline pixels");
        CHECK(outline > 100); // the scene is in view
        CHECK(differ < outline / 2);
    }
}

TEST_CASE("lab 07: per-fragment GLSL Phong raster agrees with the phong tracer on a diffuse "
          "scene",
          "[gl]") {
    const wb::Image g = render("diffuse-spheres", 160, 120, "gf");
    const wb::Image t = render("diffuse-spheres", 160, 120, "G");
    const wb::ImageDiff all = wb::compareImages(g, t);
    REQUIRE(all.sameSize);
    const IdMap ids = idMap("diffuse-spheres", 160, 120, 0, 0);
    // Inside the objects the shader evaluates the same equation per fragment in float,
    // with the normal interpolated between the facets of the tessellated sphere and the
    // eye-space position on the facet, which lies up to 0.5 px (the outline bound of
    // raster_mesh.h) inside the true sphere. Deep inside (no outline within 4 px) the
    // diffuse term changes slowly and what is left is float rounding (1 level) and the
    // normal interpolation across facets of ~12° (the big sphere has 30 segments): the
    // normalised blend of two vertex normals runs up to ~0.5° off the true normal at the
    // pixel's point, i.e. 0.7·0.9·255·sin θ·0.009 ≈ 1.5 levels: measured max 3, bound 4. Near the
    // limb the diffuse term falls to 0 within a few pixels (up to ~40 levels per pixel on these
    // spheres), so the fragment's normal standing for a point ~1/4 px away costs up to ~10 levels:
    // measured max 8 there, bound 12, mean over all interior pixels 0.62, bound 1.
    int inside = 0, maxInside = 0, deep = 0, maxDeep = 0;
    double sumInside = 0;
    for (int y = 1; y + 1 < g.height; ++y)
        for (int x = 1; x + 1 < g.width; ++x) {
            if (ids.at(x, y) < 0 || !ids.interior(x, y)) continue;
            ++inside;
            const bool isDeep = ids.interior(x, y, 4);
            deep += isDeep;
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(g.at(x, y)[c]) - int(t.at(x, y)[c]));
                maxInside = std::max(maxInside, d);
                if (isDeep) maxDeep = std::max(maxDeep, d);
                sumInside += d;
            }
        }
    const double meanInside = sumInside / (3.0 * inside);
    INFO("inside " << inside << " px: max " << maxInside << " mean " << meanInside << "; deep "
                   << deep << " px: max " << maxDeep << "; whole image max " << all.maxDiff
                   << " mean " << all.meanDiff);
    CHECK(inside > 2000);
    CHECK(deep > 1000);
    CHECK(maxDeep <= 4);
    CHECK(maxInside <= 12);
    CHECK(meanInside <= 1.0);
    // The whole image: silhouette pixels (sky on one side, sphere on the other) differ by
    // up to the full contrast, but there are few of them: mean below 1 level.
    CHECK(all.meanDiff <= 1.0);
    // Control: the same measure on a raster with the wrong lighting equation (the course
    // model's GL set-up: global ambient 1, attenuation 1/distScale) must fail the bound,
    // or this test could not tell a broken shader from a working one.
    const wb::Image wrong = render("diffuse-spheres", 160, 120, "gfm");
    CHECK(wb::compareImages(wrong, t).meanDiff > 5.0);
}

TEST_CASE("lab 07 options: --scene, --threads, --depth, --model, --inspect reject bad values",
          "[gl]") {
    auto lab = wb::makeRaytraceLab();
    std::string err;
    CHECK_FALSE(lab->setOption("scene", "no-such-scene", err));
    CHECK(err.find("no-such-scene") != std::string::npos);
    CHECK_FALSE(lab->setOption("scene", "balls:9", err));
    CHECK_FALSE(lab->setOption("scene", "/nonexistent/x.nff", err));
    CHECK(err.find("x.nff") != std::string::npos); // the reader names the file
    CHECK_FALSE(lab->setOption("depth", "21", err));
    CHECK_FALSE(lab->setOption("depth", "3x", err));
    CHECK_FALSE(lab->setOption("threads", "-1", err));
    CHECK_FALSE(lab->setOption("model", "gouraud", err));
    CHECK_FALSE(lab->setOption("inspect", "3", err));
    CHECK(lab->setOption("scene", "jacks:2", err));
    CHECK(lab->setOption("depth", "0", err));
    CHECK(lab->setOption("threads", "1", err));
    CHECK(lab->setOption("model", "course", err));
    CHECK(wb::raytraceState(*lab).maxDepth == 0);
    CHECK(wb::raytraceState(*lab).threads == 1);
    CHECK(wb::raytraceState(*lab).sceneName == "jacks:2");
}

TEST_CASE("lab 07: an NFF file written from the generator traces to the same picture", "[gl]") {
    // balls:2 from code and the same document through writeNff / --scene file.nff: the
    // reader's round trip is exact (17 digits), so the traced images must be identical.
    const std::string path = std::string(WB_TEST_OUT_DIR) + "/lab07-balls2.nff";
    wb::rt::writeNffFile(path, wb::rt::spdBalls(2));
    const wb::Image fromCode = render("balls:2", 96, 72, "G");
    const wb::Image fromFile = render(path, 96, 72, "G");
    const wb::ImageDiff d = wb::compareImages(fromCode, fromFile);
    REQUIRE(d.sameSize);
    CHECK(d.maxDiff == 0);
}

TEST_CASE("lab 07: the rasterizer draws every primitive of every scene", "[gl]") {
    // No primitive kind is silently left out of `g` (tessellate counts what it skips),
    // and the level follows the screen: a 4× larger view gives more triangles.
    for (const std::string& name : wb::builtinSceneNames()) {
        wb::LabScene s;
        std::string err;
        REQUIRE(wb::loadLabScene(name, s, err));
        const auto small = wb::ViewCamera::make(s.camera, 0, 0, 1, 160, 120);
        const auto large = wb::ViewCamera::make(s.camera, 0, 0, 1, 640, 480);
        wb::TessellationStats a, b;
        // No triangle budget here: this is about coverage and refinement (balls 4 at
        // 640×480 needs more than the default; raytrace_lab_mesh_test tests the budget).
        wb::TessellationOptions unlimited;
        unlimited.maxTriangles = 1LL << 40;
        wb::tessellate(*s.scene, small, unlimited, &a);
        wb::tessellate(*s.scene, large, unlimited, &b);
        INFO(name << ": " << a.triangles << " / " << b.triangles << " triangles");
        CHECK(a.skipped == 0);
        CHECK(a.triangles >= (long long)s.scene->primitives.size());
        CHECK(b.triangles >= a.triangles);
        if (name == "one-sphere" || name == "seed001-table") CHECK(b.triangles > a.triangles);
    }
}
