// Bad input gives a clear message naming the surface and the problem; nothing crashes or
// produces NaN.
#include "core/radiosity/form_factors.h"
#include "core/radiosity/scenes.h"
#include "core/radiosity/solver.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace wb::rad;

namespace {
Scene base() { return parallelPlates(1, 1, 1); }
} // namespace

TEST_CASE("bad scenes are refused with the surface and the reason") {
    {
        Scene s = base();
        s.surfaces[1].vertices = {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}}; // collinear: zero area
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("surface 1") && Catch::Contains("zero area"));
    }
    {
        Scene s = base();
        s.surfaces[0].reflectivity = glm::dvec3(0.5, 1.0, 0.5);
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("plate 1") && Catch::Contains("diverge"));
        s.surfaces[0].reflectivity = glm::dvec3(0.5, 1.5, -0.1);
        CHECK_THROWS_AS(meshScene(s, {0.5}), std::invalid_argument);
    }
    {
        Scene s = base();
        s.surfaces[0].emission = glm::dvec3(0.0);
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("no surface emits"));
    }
    {
        Scene s = base();
        s.surfaces[1].vertices[2].y = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("NaN") && Catch::Contains("vertex 2"));
        s = base();
        s.surfaces[1].vertices[0].x = std::numeric_limits<double>::infinity();
        CHECK_THROWS_AS(meshScene(s, {0.5}), std::invalid_argument);
    }
    {
        Scene s = base();
        s.surfaces[0].vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.9, 0.2, 0}}; // not convex
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("not convex"));
        s = base();
        s.surfaces[0].vertices[2].z = 0.1; // not planar
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("not planar"));
        s = base();
        s.surfaces[0].vertices.resize(2);
        CHECK_THROWS_WITH(meshScene(s, {0.5}), Catch::Contains("2 vertices"));
        s = base();
        s.surfaces[0].emission = glm::dvec3(std::numeric_limits<double>::quiet_NaN());
        CHECK_THROWS_AS(meshScene(s, {0.5}), std::invalid_argument);
    }
    CHECK_THROWS_WITH(meshScene(base(), {0.0}), Catch::Contains("maxEdge"));
    CHECK_THROWS_WITH(meshScene(base(), {std::numeric_limits<double>::quiet_NaN()}), Catch::Contains("maxEdge"));
    CHECK_THROWS_WITH(meshScene(base(), {1e-5}), Catch::Contains("4 million"));
    CHECK_THROWS_AS(sceneByName("nope"), std::invalid_argument);
}

TEST_CASE("bad configurations are refused") {
    const PatchMesh m = meshScene(base(), {0.5});
    FormFactorConfig c;
    c.hemicubeResolution = 7;
    CHECK_THROWS_WITH(FormFactors(m, c), Catch::Contains("even"));
    c.hemicubeResolution = 16;
    c.method = FormFactorMethod::Rays;
    c.rays.samples = 0;
    CHECK_THROWS_WITH(FormFactors(m, c), Catch::Contains("samples"));
    c.method = FormFactorMethod::External;
    CHECK_THROWS_WITH(FormFactors(m, c), Catch::Contains("rowProvider"));
    c.method = FormFactorMethod::Hemicube;
    FormFactors ff(m, c);
    std::vector<float> scratch;
    CHECK_THROWS_AS(ff.row(-1, scratch), std::out_of_range);
    CHECK_THROWS_AS(ff.row(ff.size(), scratch), std::out_of_range);
    PatchMesh mm = m;
    CHECK_THROWS_AS(refineAdaptive(mm, {}, {}), std::invalid_argument);
    std::vector<glm::dvec3> nanB(m.patches.size(), glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
    CHECK_THROWS_AS(refineAdaptive(mm, nanB, {}), std::invalid_argument);
}

TEST_CASE("a black but valid scene (E > 0, R = 0) solves to finite values") {
    Scene s = base();
    for (auto& f : s.surfaces) f.reflectivity = glm::dvec3(0.0);
    const PatchMesh m = meshScene(s, {0.5});
    FormFactors ff(m, {});
    Solver sol(m, ff, {});
    sol.run();
    for (const auto& b : sol.displayRadiosity()) {
        CHECK(std::isfinite(b.x));
        CHECK(std::isfinite(b.y));
    }
}
