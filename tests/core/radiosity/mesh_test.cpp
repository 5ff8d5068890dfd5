// Meshing, adaptive refinement with T-vertices, conforming display triangles and smoothing
// that never mixes surfaces.
#include "core/radiosity/mesh.h"
#include "core/radiosity/scenes.h"
#include "core/radiosity/smoothing.h"

#include <catch2/catch.hpp>

#include <map>
#include <set>

using namespace wb::rad;

TEST_CASE("meshing: edge lengths, areas, normals") {
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        const double maxEdge = s.name == "Cornell box" ? 0.05 : 0.4;
        const PatchMesh m = meshScene(s, {maxEdge});
        std::vector<double> area(s.surfaces.size(), 0.0);
        for (std::size_t i = 0; i < m.patches.size(); ++i) {
            const auto c = m.cornersOf(static_cast<int>(i));
            for (std::size_t k = 0; k < c.size(); ++k)
                CHECK(glm::length(c[(k + 1) % c.size()] - c[k]) <= maxEdge * (1 + 1e-12));
            area[static_cast<std::size_t>(m.patches[i].surface)] += m.patches[i].area;
            // Same side as the surface: the normal of the patch's own corners agrees.
            CHECK(glm::dot(polygonNormal(c), m.patches[i].normal) == Approx(1.0).epsilon(1e-9));
        }
        // Patches tile their surface: areas add up (rounding of ~1e4 additions: 1e-12).
        for (std::size_t k = 0; k < s.surfaces.size(); ++k)
            CHECK(area[k] == Approx(polygonArea(s.surfaces[k].vertices)).epsilon(1e-12));
    }
}

namespace {
// Every display-triangle edge inside a surface is shared by exactly two triangles (no crack
// at a T-vertex); edges used once lie on the surface's boundary (lattice border).
void checkConforming(const PatchMesh& m) {
    std::vector<int> patchOf;
    const auto tris = displayTriangles(m, &patchOf);
    std::map<std::pair<int, int>, int> uses;
    std::vector<double> area(m.patches.size(), 0.0);
    for (std::size_t t = 0; t < tris.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            int a = tris[t][static_cast<std::size_t>(k)], b = tris[t][static_cast<std::size_t>((k + 1) % 3)];
            if (a > b) std::swap(a, b);
            ++uses[{a, b}];
        }
        const glm::dvec3 p0 = m.vertices[static_cast<std::size_t>(tris[t][0])],
                         p1 = m.vertices[static_cast<std::size_t>(tris[t][1])],
                         p2 = m.vertices[static_cast<std::size_t>(tris[t][2])];
        area[static_cast<std::size_t>(patchOf[t])] += 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    }
    for (std::size_t i = 0; i < m.patches.size(); ++i)
        CHECK(area[i] == Approx(m.patches[i].area).epsilon(1e-12));
    int boundary = 0;
    for (const auto& [e, n] : uses) {
        CHECK(n <= 2);
        if (n == 1) {
            const int s = m.vertexSurface[static_cast<std::size_t>(e.first)];
            const glm::dvec2 a = m.vertexLattice[static_cast<std::size_t>(e.first)];
            const glm::dvec2 b = m.vertexLattice[static_cast<std::size_t>(e.second)];
            const glm::ivec2 g = m.grid[static_cast<std::size_t>(s)];
            const double U = g.x * kLatticeScale, W = g.y * kLatticeScale;
            const bool tri = m.surfaces[static_cast<std::size_t>(s)].vertices.size() == 3;
            const bool onBorder =
                tri ? ((a.x == 0 && b.x == 0) || (a.y == 0 && b.y == 0) ||
                       (a.x + a.y == U && b.x + b.y == U))
                    : ((a.x == 0 && b.x == 0) || (a.y == 0 && b.y == 0) || (a.x == U && b.x == U) ||
                       (a.y == W && b.y == W));
            CHECK(onBorder);
            ++boundary;
        }
    }
    CHECK(boundary > 0);
}
} // namespace

TEST_CASE("adaptive refinement: T-vertices handled, display mesh conforming") {
    PatchMesh m = meshScene(cornellBox(), {0.1});
    const std::size_t n0 = m.patches.size();
    // A sharp step in B across the floor makes the patches along it split.
    std::vector<glm::dvec3> B(n0);
    for (std::size_t i = 0; i < n0; ++i) B[i] = glm::dvec3(m.patches[i].centre.x < 0.26 ? 1.0 : 0.1);
    std::vector<int> parent;
    const int split = refineAdaptive(m, B, {0.05, 3, 0.001, 100000}, &parent);
    CHECK(split > 0);
    CHECK(m.patches.size() == n0 + 3 * static_cast<std::size_t>(split));
    CHECK(parent.size() == m.patches.size());
    int withT = 0;
    for (const Patch& p : m.patches) withT += p.outline.size() > static_cast<std::size_t>(p.cornerCount);
    CHECK(withT > 0); // unsplit neighbours of split patches carry T-vertices
    checkConforming(m);
    // Twice more (levels 2, 3), still conforming.
    for (int round = 0; round < 2; ++round) {
        std::vector<glm::dvec3> b2(m.patches.size());
        for (std::size_t i = 0; i < m.patches.size(); ++i) b2[i] = glm::dvec3(m.patches[i].centre.x < 0.26 ? 1.0 : 0.1);
        refineAdaptive(m, b2, {0.05, 3, 0.001, 100000}, nullptr);
    }
    checkConforming(m);
    int maxLevel = 0;
    for (const Patch& p : m.patches) maxLevel = std::max(maxLevel, p.level);
    CHECK(maxLevel == 3);
    // Triangles split too (the red wall is two triangles).
    checkConforming(meshScene(cornellBox(), {0.05}));
}

TEST_CASE("smoothing: constant stays constant, surfaces never mix (no light leaks)") {
    PatchMesh m = meshScene(cornellBox(), {0.1});
    std::vector<glm::dvec3> B(m.patches.size());
    for (std::size_t i = 0; i < B.size(); ++i) B[i] = glm::dvec3(m.patches[i].centre.x < 0.26 ? 1.0 : 0.1);
    refineAdaptive(m, B, {0.05, 2, 0.001, 100000}, nullptr);
    // Value = surface index: every vertex must get exactly its own surface's index.
    std::vector<glm::dvec3> S(m.patches.size());
    for (std::size_t i = 0; i < S.size(); ++i) S[i] = glm::dvec3(m.patches[i].surface);
    const auto v = vertexRadiosity(m, S);
    // (a mean of equal values: exact up to a few ulps)
    for (std::size_t k = 0; k < v.size(); ++k) CHECK(v[k].x == Approx(double(m.vertexSurface[k])).epsilon(1e-14));
    // A linear function of position is reproduced exactly in the interior only up to the
    // averaging; a constant exactly.
    const auto c = vertexRadiosity(m, std::vector<glm::dvec3>(m.patches.size(), glm::dvec3(0.25, 0.5, 0.75)));
    for (const auto& x : c) {
        // Σ A·c / Σ A rounds to c within a few ulps.
        CHECK(x.x == Approx(0.25).epsilon(1e-14));
        CHECK(x.z == Approx(0.75).epsilon(1e-14));
    }
}

TEST_CASE("adaptive refinement ignores the emitters' brightness for its threshold") {
    // Cornell box: B = E on the light (17), walls lit ~1: a 0.05 threshold relative to the
    // light would split nothing; relative to the brightest wall it splits at the step.
    PatchMesh m = meshScene(cornellBox(), {0.1});
    std::vector<glm::dvec3> B(m.patches.size());
    for (std::size_t i = 0; i < B.size(); ++i)
        B[i] = m.patches[i].emission.x > 0 ? m.patches[i].emission
                                           : glm::dvec3(m.patches[i].centre.x < 0.26 ? 1.0 : 0.5);
    CHECK(refineAdaptive(m, B, {0.05, 1, 0.001, 100000}, nullptr) > 0);
}

TEST_CASE("meshing: bounded aspect ratio on every scene") {
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        const bool box = s.name == "Cornell box";
        for (double edge : box ? std::vector<double>{0.02, 0.035, 0.05, 0.1, 0.2} : std::vector<double>{0.1, 0.2, 0.4, 0.8}) {
            const PatchMesh m = meshScene(s, {edge});
            double worst = 0.0;
            int at = -1;
            for (std::size_t i = 0; i < m.patches.size(); ++i) {
                const double a = patchAspect(m, static_cast<int>(i));
                if (a > worst) { worst = a; at = static_cast<int>(i); }
            }
            INFO(s.name << " edge " << edge << ": " << m.patches.size() << " patches, worst aspect " << worst
                        << " on " << m.surfaces[static_cast<std::size_t>(m.patches[static_cast<std::size_t>(at)].surface)].name);
            // Before issue 19 item 10: 3.3 (edge 0.1) to 20 (edge 0.8) on the tables' 3 cm top
            // edges; the bound is mesh.h's kMaxAspect (measured 2.15, the shade rim's end cells).
            CHECK(worst <= kMaxAspect);
        }
    }
}
