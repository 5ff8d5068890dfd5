// Rows of shooting groups by rays at the receivers (point_rays.h, lab 08's key 1): against
// the exact parallel-plates form factor, row sums in a closed cube, and the group outline
// (hull) covering exactly its members (a dropped corner made one row sum 1.29).
#include "core/radiosity/closed_forms.h"
#include "core/radiosity/mesh.h"
#include "core/radiosity/patch_bvh.h"
#include "core/radiosity/point_rays.h"
#include "core/radiosity/scenes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wb::rad;

namespace {

// The shoelace area (own copy: an independent check of the hull).
double areaOf(const std::vector<glm::dvec3>& p) {
    glm::dvec3 a(0.0);
    for (size_t i = 0; i < p.size(); ++i)
        a += glm::cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * glm::length(a);
}

} // namespace

TEST_CASE("group rays: two parallel unit plates 1 apart give the exact F", "[radiosity]") {
    Scene s;
    s.name = "plates";
    s.surfaces.push_back(Surface{
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, glm::dvec3(0.5), glm::dvec3(1.0), "A"});
    s.surfaces.push_back(Surface{
        {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}, glm::dvec3(0.5), glm::dvec3(0.0), "B"});
    const PatchMesh m = meshScene(s, MeshConfig{0.125, 1.0}); // 8×8 patches, one group a plate
    const PatchBvh bvh(m);
    int ga = -1;
    for (size_t g = 0; g < m.groups.size(); ++g)
        if (m.groups[g].surface == 0) ga = int(g);
    REQUIRE(ga >= 0);
    REQUIRE(m.groups[size_t(ga)].members.size() == 64);
    std::vector<float> row;
    groupGatherRow(m, bvh, ga, 4, row);
    double sum = 0;
    for (size_t j = 0; j < row.size(); ++j) {
        if (m.patches[j].surface == 0) CHECK(row[j] == 0.0f); // its own plane: nothing
        sum += row[j];
    }
    // Exact 0.19982 (Howell C-11). Each receiver's F(dA → A) is exact; the row is their
    // midpoint rule over 8×8 cells of B: 0.2003 measured (+0.24%). 0.5% bounds it with room
    // for a different BVH's visibility decisions at the plates' edges (none block here).
    CHECK(sum == Approx(parallelRectangles(1, 1, 1)).epsilon(0.005));
}

TEST_CASE("group rays: rows of a closed cube sum to 1; the hull is the group", "[radiosity]") {
    const PatchMesh m = meshScene(furnace(0.5, 1.0), MeshConfig{0.1, 0.35});
    const PatchBvh bvh(m);
    REQUIRE(m.groups.size() > 6);
    std::vector<float> row;
    for (size_t g = 0; g < m.groups.size(); ++g) {
        INFO("group " << g);
        CHECK(areaOf(groupHull(m, int(g))) == Approx(m.groups[g].area).epsilon(1e-9));
        groupGatherRow(m, bvh, int(g), 4, row);
        double sum = 0;
        for (float f : row)
            sum += double(f);
        // Closed: every direction above the group meets a wall. Measured 0.9964..1.0026: the
        // quadrature over the receivers (4×4 points for the cells next to G's plane, their
        // centre elsewhere); without the 4×4 points it was 0.965..0.979. Bound 1%.
        CHECK(sum == Approx(1.0).epsilon(0.01));
    }
    // The Cornell box's groups (the ceiling's pieces around the light are where a corner was
    // lost): hull area = members' area for every group.
    const PatchMesh c = meshScene(sceneByName("cornell"), MeshConfig{0.05, 0.311});
    for (size_t g = 0; g < c.groups.size(); ++g)
        CHECK(areaOf(groupHull(c, int(g))) == Approx(c.groups[g].area).epsilon(1e-9));
}
