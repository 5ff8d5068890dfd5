// Issue 19 item 10: "a test that ... looks for cracks (a ray-cast census of the background
// showing through between two patches that share an edge)". What a student sees as a crack is
// a pixel of the background inside the picture of a closed surface, so the census is taken
// the way the lab draws: every scene's mesh at the lab's default patch size is drawn as patch
// ids (PatchView::drawItems, the lab's item pass: unlit, flat, no dithering) at the lab's
// window size, 1280×800, from the scene's camera, and every background pixel that the
// background around the picture does not reach (4-connected flood fill from the image border)
// is counted. The rasteriser is the ray cast here: one sample at each pixel centre.
//
// The census is shown to fail on two deliberately cracked copies of the Cornell mesh:
//  - the floor moved 1 mm sideways (a gap at a wall's foot, ~1 px wide at this size);
//  - every patch drawn from its corners only (its T-vertices and seam vertices dropped): the
//    T-junctions the conforming mesh removes. This one is reported, not required red: whether
//    a T-junction opens a pixel depends on the rasteriser's snapping (a point on a long edge
//    is off it by rounding only), which is what the census measures.
#include "patch_view.h"

#include "common/headless_context.h"
#include "core/radiosity/scenes.h"

#include <GL/gl.h>
#include <GL/glu.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace wb::rad;

constexpr int kW = 1280, kH = 800; // the lab's window (README, lab08_window.sh)

// Lab 08's default patch edge (RadiosityLab::defaultPatchSize, as radiosity_reference copies
// it): e = √(A/3700), corrected twice by the count the mesher makes of it.
MeshConfig config(double e, bool conforming) {
    MeshConfig c{e, 0.0};
    c.conforming = conforming;
    return c;
}

double labPatch(const Scene& scene, bool conforming) {
    double area = 0;
    for (const Surface& sf : scene.surfaces)
        area += polygonArea(sf.vertices);
    double e = std::sqrt(area / 3700.0);
    for (int pass = 0; pass < 2; ++pass)
        e *= std::sqrt(double(meshScene(scene, config(e, conforming)).patches.size()) / 3700.0);
    return e;
}

struct Census {
    int background = 0; // background pixels in all
    int enclosed = 0;   // of them, not reached from the image border
    int firstX = -1, firstY = -1;
};

// Draws `mesh` as item ids from the scene's camera (the lab's setupCamera at yaw = pitch = 0:
// 40° vertically from outside the scene, ≥ 56° from inside) and counts the enclosed background.
// WB_CRACK_DUMP=DIR: also writes each picture as DIR/<tag>.ppm, the enclosed pixels in magenta
// (to look at where a crack is).
Census census(const Scene& scene, const PatchMesh& mesh, const std::string& tag) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& v : mesh.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    const double dist = glm::length(scene.eye - centre);
    double fovy = 40.0;
    if (dist < radius) {
        const double aspect = double(kW) / kH;
        fovy = std::clamp(std::max(56.0, 2.0 * glm::degrees(std::atan(std::tan(glm::radians(40.0)) / aspect))),
                          56.0, 100.0);
    }
    glViewport(0, 0, kW, kH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(fovy, double(kW) / kH, std::max(1e-3 * radius, (dist - radius) * 0.5), dist + 2 * radius);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(scene.eye.x, scene.eye.y, scene.eye.z, scene.target.x, scene.target.y, scene.target.z,
              scene.up.x, scene.up.y, scene.up.z);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE); // as the lab: patches are one-sided
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    wb::PatchView view;
    view.setMesh(mesh);
    view.drawItems();
    std::vector<uint8_t> rgb(size_t(kW) * kH * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kW, kH, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    auto bg = [&](int x, int y) {
        const uint8_t* p = &rgb[(size_t(y) * kW + size_t(x)) * 3];
        return p[0] == 0 && p[1] == 0 && p[2] == 0; // item 0: nothing drawn (ids are patch + 1)
    };
    std::vector<char> outside(size_t(kW) * kH, 0);
    std::vector<std::pair<int, int>> stack;
    auto push = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= kW || y >= kH) return;
        char& o = outside[size_t(y) * kW + size_t(x)];
        if (o || !bg(x, y)) return;
        o = 1;
        stack.emplace_back(x, y);
    };
    for (int x = 0; x < kW; ++x) {
        push(x, 0);
        push(x, kH - 1);
    }
    for (int y = 0; y < kH; ++y) {
        push(0, y);
        push(kW - 1, y);
    }
    while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        push(x + 1, y);
        push(x - 1, y);
        push(x, y + 1);
        push(x, y - 1);
    }
    Census c;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (!bg(x, y)) continue;
            ++c.background;
            if (outside[size_t(y) * kW + size_t(x)]) continue;
            if (c.enclosed++ == 0) {
                c.firstX = x;
                c.firstY = kH - 1 - y; // from the top, as in a screenshot
            }
        }
    if (const char* dir = std::getenv("WB_CRACK_DUMP")) {
        std::ofstream f(std::string(dir) + "/" + tag + ".ppm", std::ios::binary);
        f << "P6 " << kW << " " << kH << " 255\n";
        for (int y = kH - 1; y >= 0; --y)
            for (int x = 0; x < kW; ++x) {
                const uint8_t* p = &rgb[(size_t(y) * kW + size_t(x)) * 3];
                // Item ids spread over the colours (neighbouring ids differ visibly).
                const uint32_t id = uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2];
                uint8_t q[3] = {uint8_t(id * 97), uint8_t(id * 57), uint8_t(id * 23 + 64)};
                if (id == 0) q[0] = q[1] = q[2] = 0;
                if (bg(x, y) && !outside[size_t(y) * kW + size_t(x)]) q[0] = 255, q[1] = 0, q[2] = 255;
                f.write(reinterpret_cast<const char*>(q), 3);
            }
    }
    return c;
}

int surfaceNamed(const PatchMesh& mesh, const std::string& name) {
    for (size_t s = 0; s < mesh.surfaces.size(); ++s)
        if (mesh.surfaces[s].name == name) return int(s);
    return -1;
}

} // namespace

// Both meshes at the lab's default size for them (~3,700 patches). The conforming mesh
// (MeshConfig::conforming) must show no crack. The default grid mesh (the labs') showed two:
//  - the classroom a 1-2 px line along the ceiling above the lamps (852 px): a ceiling cell
//    over a lamp's back was dropped as "inside a body", and the 2 cm gap beside the lamp showed
//    the background through it. Mended (mesh.cpp covered(): grazing rays leave through the
//    gap); the census is 0 and this case is red without the mend.
//  - the Cornell box one pixel at the short block's right foot (846, ·): a floor cell whose
//    8×8 exposure samples all lay under the block was dropped, and the sliver of it outside
//    the footprint (narrower than the samples' 1/16 inset) left a 1 px hole. Mended
//    (mesh.cpp exposedSliver(): such a cell is kept when a corner is exposed, with the exact
//    area of its sliver); the census is 0 and this case is red (1 px) without the mend.
void noCracks(bool conforming) {
    wb::HeadlessContext ctx(kW, kH);
    REQUIRE(ctx.ok());
    const std::pair<const char*, Scene> scenes[] = {
        {"Cornell box", cornellBox()}, {"classroom", classroom()}, {"floor lamp", floorLamp()}};
    for (const auto& [name, scene] : scenes) {
        const PatchMesh mesh = meshScene(scene, config(labPatch(scene, conforming), conforming));
        const Census c = census(scene, mesh, std::string(name) + (conforming ? "-conforming" : "-grid"));
        INFO(name << ": " << mesh.patches.size() << " patches, background " << c.background
                  << " px, enclosed " << c.enclosed << " (first at " << c.firstX << ", " << c.firstY << ")");
        WARN(name << (conforming ? " (conforming)" : " (grid)") << ": " << mesh.patches.size() << " patches, "
                  << c.background << " background px, enclosed " << c.enclosed);
        CHECK(c.enclosed == 0);
    }
}

TEST_CASE("issue 19 item 10: no background shows between patches of the conforming mesh", "[gl]") {
    noCracks(true);
}

TEST_CASE("the default grid mesh's crack census: no background between patches in any scene", "[gl]") {
    noCracks(false);
}

TEST_CASE("the crack census fails on a cracked mesh", "[gl]") {
    wb::HeadlessContext ctx(kW, kH);
    REQUIRE(ctx.ok());
    const Scene scene = cornellBox();
    const PatchMesh mesh = meshScene(scene, config(labPatch(scene, true), true));
    SECTION("the floor 1 mm off a side wall") {
        PatchMesh cracked = mesh;
        const int floor = surfaceNamed(cracked, "floor");
        REQUIRE(floor >= 0);
        // The side walls stand at the floor's x ends (x = 0 and 0.556 m): the floor moved 1 mm
        // along x leaves a 1 mm slot at one wall's foot (about 1 px at 1280×800: the box's
        // 0.55 m spans ~700 px) and runs 1 mm under the other.
        for (size_t v = 0; v < cracked.vertices.size(); ++v)
            if (cracked.vertexSurface[v] == floor) cracked.vertices[v].x += 0.001;
        const Census c = census(scene, cracked, "cornell-floor-moved");
        WARN("floor moved 1 mm: enclosed background " << c.enclosed << " px (first at " << c.firstX << ", "
                                                     << c.firstY << ")");
        CHECK(c.enclosed > 50);
    }
    SECTION("T-junctions: patches drawn from their corners only") {
        PatchMesh tj = mesh;
        int dropped = 0;
        for (Patch& p : tj.patches) {
            dropped += int(p.outline.size()) - p.cornerCount;
            p.outline.assign(p.corners.begin(), p.corners.begin() + p.cornerCount);
            p.centreVertex = -1;
        }
        const Census c = census(scene, tj, "cornell-t-junctions");
        WARN("T-junctions (" << dropped << " outline vertices dropped): enclosed background " << c.enclosed
                             << " px (first at " << c.firstX << ", " << c.firstY << ")");
        CHECK(dropped > 0);
    }
}
