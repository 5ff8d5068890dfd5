// Form factors by rays (§1.15.1) and by the CPU hemicube (§1.15.2) against closed forms, and
// their properties on every scene: F_ii = 0, reciprocity, rows of a closed room summing to 1.
#include "ff_common.h"

#include "core/radiosity/closed_forms.h"

#include <catch2/catch.hpp>

using namespace wb::rad;
using namespace wb::rad::test;

namespace {
FormFactorConfig rays(int k, RayKernel kernel) {
    FormFactorConfig c;
    c.method = FormFactorMethod::Rays;
    c.rays.samples = k;
    c.rays.kernel = kernel;
    return c;
}
FormFactorConfig cube(int res) {
    FormFactorConfig c;
    c.method = FormFactorMethod::Hemicube;
    c.hemicubeResolution = res;
    return c;
}
} // namespace

TEST_CASE("plate-to-plate F from patches against the closed forms") {
    const PatchMesh par = meshScene(parallelPlates(1, 1, 1), {0.25});       // 16 + 16 patches
    const PatchMesh per = meshScene(perpendicularPlates(1, 1, 1), {0.25});
    const double exPar = parallelRectangles(1, 1, 1), exPer = perpendicularRectangles(1, 1, 1);
    struct Case { const char* name; FormFactorConfig cfg; double tolPar, tolPer; };
    // Tolerances (relative), each at least 2× the measured error (parallel / perpendicular):
    //  - rays, exact point-to-polygon term, k = 16: 5.6e-4 / 2.6e-4 (sampling of P_i only);
    //  - rays auto, k = 16: 2.7e-3 / 1.7e-3 (far pairs use (15.20) at the centres);
    //  - hemicube 128²: 9.6e-3 / 1.0e-3 — not a resolution error (9.6e-3 at 64² and 256² too):
    //    a hemicube measures F from the centre of each patch, i.e. the midpoint rule over P_i.
    const Case cases[] = {
        {"rays k=16 point-to-polygon", rays(16, RayKernel::PointToPolygon), 2e-3, 1e-3},
        {"rays k=16 auto", rays(16, RayKernel::Auto), 6e-3, 4e-3},
        {"hemicube 128", cube(128), 2e-2, 3e-3},
    };
    for (const Case& c : cases) {
        FormFactors a(par, c.cfg), b(per, c.cfg);
        const double fPar = surfaceFF(par, a, 0, 1), fPer = surfaceFF(per, b, 0, 1);
        INFO(c.name << ": parallel " << fPar << " vs " << exPar << ", perpendicular " << fPer << " vs " << exPer);
        CHECK(std::abs(fPar - exPar) / exPar < c.tolPar);
        CHECK(std::abs(fPer - exPer) / exPer < c.tolPer);
    }
    // The course's (15.20) at the centres is far off for touching patches: +16.5% here.
    FormFactors cen(per, rays(16, RayKernel::Centres));
    CHECK(std::abs(surfaceFF(per, cen, 0, 1) - exPer) / exPer > 0.1);
}

TEST_CASE("F_ii = 0, reciprocity and row sums on a closed room with an occluder") {
    const PatchMesh m = meshScene(boxInRoom(), {0.25}); // 120 patches
    struct Case { const char* name; FormFactorConfig cfg; double recip, rowMax; };
    // Tolerances: measured on this mesh and rounded up ~1.5× (rays are seeded, so the figures
    // are reproducible; the hemicube's are exact functions of the resolution).
    //  - rays auto: near pairs use the exact point-to-polygon term sampled at k points of P_i,
    //    far pairs (15.20) at the centres; rows sum to 1 up to those two errors.
    //  - rays point pairs: (15.20) per ray pair is symmetric in i and j, so reciprocity holds
    //    to float storage (1e-7); its rows are far off for touching patches (1/r² singular).
    //  - hemicube: rows sum to the delta table's sum exactly when every pixel sees a front side
    //    (1 + 0.54/res², checked separately); reciprocity is the method's weak point: it is a
    //    point method from the patch centre, so near pairs are not reciprocal at any resolution.
    std::vector<Case> cases = {
        {"rays k=16 auto", rays(16, RayKernel::Auto), 0.08, 0.08},
        {"rays k=16 point pairs", rays(16, RayKernel::PointPairs), 1e-6, 1.0},
        {"hemicube 16", cube(16), 0.45, 0.6 / (16 * 16)},
        {"hemicube 64", cube(64), 0.2, 0.6 / (64 * 64)},
    };
#ifndef WB_SANITIZED
    cases.push_back({"hemicube 128", cube(128), 0.15, 0.6 / (128 * 128)});
#endif
    for (const Case& c : cases) {
        FormFactors ff(m, c.cfg);
        const FfStats s = stats(m, ff);
        INFO(c.name << ": diag " << s.maxDiag << " reciprocity " << s.reciprocity << " row error max "
                    << s.maxRowError << " mean " << s.meanRowError << " rows " << s.minRow << ".." << s.maxRow);
        CHECK(s.maxDiag == 0.0);
        CHECK(s.reciprocity < c.recip);
        CHECK(s.maxRowError < c.rowMax);
    }
}

TEST_CASE("F_ii = 0 and reciprocity on the lab's scenes (hemicube 32)") {
    for (const Scene& sc : {cornellBox(), classroom(), floorLamp()}) {
        const double edge = sc.name == "Cornell box" ? 0.15 : 1.0;
        const PatchMesh m = meshScene(sc, {edge});
        FormFactors ff(m, cube(32));
        const FfStats s = stats(m, ff);
        INFO(sc.name << ": n " << m.patches.size() << " reciprocity " << s.reciprocity << " rows " << s.minRow << ".." << s.maxRow);
        CHECK(s.maxDiag == 0.0);
        // Coarse patches and a 32² hemicube: measured 0.15–0.25, bound 0.35 (the bench reports
        // the default settings' figure).
        CHECK(s.reciprocity < 0.35);
        // No row exceeds the table's sum (1 + 0.54/32²): nothing is counted twice. Rows < 1
        // are patches that see the open front of the Cornell box or the inside of a body.
        CHECK(s.maxRow <= deltaFormFactors(32).sum + 1e-6);
    }
}

TEST_CASE("F_ii = 0 and reciprocity on the lab's scenes (rays, k = 4)") {
    for (const Scene& sc : {cornellBox(), classroom(), floorLamp()}) {
        const double edge = sc.name == "Cornell box" ? 0.15 : 1.0;
        const PatchMesh m = meshScene(sc, {edge});
        FormFactors ff(m, rays(4, RayKernel::Auto));
        const FfStats s = stats(m, ff);
        INFO(sc.name << ": n " << m.patches.size() << " reciprocity " << s.reciprocity << " rows " << s.minRow << ".." << s.maxRow);
        CHECK(s.maxDiag == 0.0);
        // Measured 0.10–0.14 with 4 rays per pair on these coarse meshes (the near term samples
        // P_i at 4 points, differently for F_ij and F_ji); bound 0.2.
        CHECK(s.reciprocity < 0.2);
        // Rows may exceed 1 by what (15.20) overestimates just beyond the near distance (7% at
        // 3 patch sizes, §2.2 of docs/radiosity-core.md): measured 1.063; bound 1.1.
        CHECK(s.maxRow < 1.1);
    }
}

TEST_CASE("the floor lamp lights the room only through the ceiling") {
    const PatchMesh m = meshScene(floorLamp(), {0.5});
    FormFactors ff(m, cube(64));
    std::vector<float> scratch;
    double toCeiling = 0.0;
    for (int i = 0; i < ff.size(); ++i) {
        if (m.patches[static_cast<std::size_t>(i)].emission.x == 0.0) continue;
        const float* row = ff.row(i, scratch);
        for (int j = 0; j < ff.size(); ++j) {
            if (row[j] == 0.0f) continue;
            const std::string& name = m.surfaces[static_cast<std::size_t>(m.patches[static_cast<std::size_t>(j)].surface)].name;
            INFO("the bulb sees " << name);
            CHECK((name == "ceiling" || name.rfind("shade inside", 0) == 0));
            if (name == "ceiling") toCeiling += row[j];
        }
    }
    CHECK(toCeiling > 0.0);
}

TEST_CASE("rows on demand equal stored rows") {
    const PatchMesh m = meshScene(cornellBox(), {0.15});
    FormFactorConfig c = cube(32);
    FormFactors stored(m, c);
    c.maxStoredPatches = 0;
    FormFactors onDemand(m, c);
    CHECK(stored.stored());
    CHECK(!onDemand.stored());
    std::vector<float> a, b;
    for (int i : {0, 7, 33}) {
        const float* ra = stored.row(i, a);
        const float* rb = onDemand.row(i, b);
        for (int j = 0; j < stored.size(); ++j) CHECK(ra[j] == rb[j]);
    }
    CHECK_THROWS_AS(onDemand.at(0, 1), std::logic_error);
}

TEST_CASE("external rows (the lab's GL hemicube path) go through the same accumulate") {
    const PatchMesh m = meshScene(cornellBox(), {0.15});
    FormFactorConfig c = cube(32);
    FormFactors cpu(m, c);
    c.method = FormFactorMethod::External;
    c.rowProvider = [&](int i, std::vector<float>& out) {
        ItemBuffer items;
        castItemBuffer(cpu.bvh(), hemicubeFrame(m, i), 32, items, false);
        accumulate(items, cpu.deltaTable(), static_cast<int>(m.patches.size()), i, out);
    };
    FormFactors ext(m, c);
    std::vector<float> a, b;
    const float* ra = cpu.row(3, a);
    const float* rb = ext.row(3, b);
    for (int j = 0; j < cpu.size(); ++j) CHECK(ra[j] == rb[j]);
}

namespace {
// A 1×1 wall standing on a 2×2 floor that extends behind it (the configuration of
// closed_forms_test's straddling case): the floor straddles the wall's plane.
Scene wallOnFloor() {
    Scene s;
    s.name = "wall on floor";
    auto facing = [](std::vector<glm::dvec3> poly, glm::dvec3 n) {
        if (glm::dot(polygonNormal(poly), n) < 0) std::reverse(poly.begin(), poly.end());
        return poly;
    };
    s.surfaces.push_back(Surface{facing({{0.5, 0, 0}, {1.5, 0, 0}, {1.5, 0, 1}, {0.5, 0, 1}}, {0, 1, 0}),
                                 glm::dvec3(0.5), glm::dvec3(1.0), "wall"});
    s.surfaces.push_back(Surface{facing({{0, -1, 0}, {2, -1, 0}, {2, 1, 0}, {0, 1, 0}}, {0, 0, 1}),
                                 glm::dvec3(0.5), glm::dvec3(0.0), "floor"});
    return s;
}
} // namespace

TEST_CASE("rays: a receiver straddling the emitter's plane is not clipped twice") {
    // Exact F(wall → floor) = 0.26383 (superposition of Howell C-14, closed_forms_test).
    const double exact = perpendicularRectangles(1.5, 1, 1) * 1.5 - perpendicularRectangles(0.5, 1, 1) * 0.5;
    // One patch each (the floor patch straddles the wall's plane), and a 0.3 m grid (7 × 7 on
    // the floor: the middle row of floor patches straddles it).
    for (double edge : {2.0, 0.3}) {
        const PatchMesh m = meshScene(wallOnFloor(), {edge});
        for (RayKernel kernel : {RayKernel::PointToPolygon, RayKernel::Auto}) {
            FormFactors ff(m, rays(64, kernel));
            const double f = surfaceFF(m, ff, 0, 1);
            INFO("edge " << edge << " kernel " << static_cast<int>(kernel) << ": F = " << f << " exact " << exact);
            // Point-to-polygon with 64 samples of the wall: the exact term at each sample, so the
            // error is the sampling of P_i (~1e-3 for touching plates, the test above) plus, for a
            // straddling P_j, the visibility rays' estimate of the front part (unoccluded here:
            // all rays reach it). Measured 9.3e-4 (one patch each), 5.9e-4 / 2.8e-4 (0.3 m grid,
            // point-to-polygon / Auto); bound 3e-3. Before the fix the front fraction was applied
            // twice: 0.1218 (−54%) with one patch each, 0.2332 (−12%) on the 0.3 m grid.
            CHECK(std::abs(f - exact) / exact < 3e-3);
        }
    }
}

TEST_CASE("rays: a floor partly under a box (fitted patches) gets the right F from the box's side") {
    // A 1 m box without bottom on a 3 × 3 m floor; the floor's 0.375 m patches straddle the
    // footprint, so meshing fits them (exposed area and centroid). F(front face → floor) is
    // F to the 3 × 1 m strip in front of it (the rest is behind the face's plane): by
    // superposition of Howell C-14, S(2) − S(1) with S(l) = l·C14(l; 1, 1) = 0.2812.
    Scene s;
    s.name = "box on floor";
    auto facing = [](std::vector<glm::dvec3> poly, glm::dvec3 n) {
        if (glm::dot(polygonNormal(poly), n) < 0) std::reverse(poly.begin(), poly.end());
        return poly;
    };
    s.surfaces.push_back(Surface{facing({{0, -1, 0}, {3, -1, 0}, {3, 2, 0}, {0, 2, 0}}, {0, 0, 1}), glm::dvec3(0.5), glm::dvec3(0.0), "floor"});
    s.surfaces.push_back(Surface{facing({{1, 1, 0}, {2, 1, 0}, {2, 1, 1}, {1, 1, 1}}, {0, 1, 0}), glm::dvec3(0.5), glm::dvec3(1.0), "front"});
    s.surfaces.push_back(Surface{facing({{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}}, {0, -1, 0}), glm::dvec3(0.5), glm::dvec3(0.0), "back"});
    s.surfaces.push_back(Surface{facing({{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}, {-1, 0, 0}), glm::dvec3(0.5), glm::dvec3(0.0), "left"});
    s.surfaces.push_back(Surface{facing({{2, 0, 0}, {2, 1, 0}, {2, 1, 1}, {2, 0, 1}}, {1, 0, 0}), glm::dvec3(0.5), glm::dvec3(0.0), "right"});
    s.surfaces.push_back(Surface{facing({{1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}}, {0, 0, 1}), glm::dvec3(0.5), glm::dvec3(0.0), "top"});
    const double exact = 2 * perpendicularRectangles(2, 1, 1) - perpendicularRectangles(1, 1, 1);
    const PatchMesh m = meshScene(s, {0.375});
    int fittedPatches = 0;
    for (std::size_t i = 0; i < m.patches.size(); ++i)
        fittedPatches += m.patches[i].area < polygonArea(m.cornersOf(static_cast<int>(i))) * (1 - 1e-9);
    REQUIRE(fittedPatches > 0);
    for (RayKernel kernel : {RayKernel::PointToPolygon, RayKernel::Auto}) {
        FormFactors ff(m, rays(64, kernel));
        const double fFace = surfaceFF(m, ff, 1, 0);
        // And back: A_floor F(floor → face) / A_face by reciprocity of the surface totals.
        double num = 0.0;
        std::vector<float> scratch;
        for (int i = 0; i < ff.size(); ++i) {
            if (m.patches[static_cast<std::size_t>(i)].surface != 0) continue;
            const float* row = ff.row(i, scratch);
            for (int j = 0; j < ff.size(); ++j)
                if (m.patches[static_cast<std::size_t>(j)].surface == 1) num += m.patches[static_cast<std::size_t>(i)].area * row[j];
        }
        const double fBack = num / 1.0;
        INFO("kernel " << static_cast<int>(kernel) << ": F(face→floor) " << fFace << ", A F(floor→face)/A_face " << fBack << ", exact " << exact);
        // Measured −0.13% / −1.8% (both kernels); bound 3%.
        // Before the fitted patches' covered samples were left out, F(floor → face) was low by
        // the covered fraction of the fitted floor patches next to the face.
        CHECK(std::abs(fFace - exact) / exact < 0.03);
        CHECK(std::abs(fBack - exact) / exact < 0.03);
    }
}
