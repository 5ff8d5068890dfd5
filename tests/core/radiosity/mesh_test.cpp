// Meshing, adaptive refinement with T-vertices, conforming display triangles and smoothing
// that never mixes surfaces.
#include "core/radiosity/mesh.h"
#include "core/radiosity/patch_bvh.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/triangle.h"
#include "core/radiosity/scenes.h"
#include "core/radiosity/smoothing.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

using namespace wb::rad;

namespace {
// These tests are of the conforming mesh (issue 19 item 10, MeshConfig::conforming; off in the
// labs until it holds the Cycles bar: mesh.h).
MeshConfig conforming(double maxEdge) {
    MeshConfig c{maxEdge, 0.0};
    c.conforming = true;
    return c;
}
} // namespace

namespace {
// The test's own "inside a body": the first surface is met from behind along the normal and
// along 64 seeded directions uniform over the hemisphere (mesh.cpp looks along two fixed rings
// instead). A panel hanging just off a surface is no body: from a ceiling above a panel 2 cm
// under it (the classroom's lamps until the fifth session; now the test below), directions
// more than ~82° from the normal (14% of the hemisphere) leave through the gap.
bool metFromBehind(const PatchBvh& bvh, const glm::dvec3& o, const glm::dvec3& d) {
    return bvh.nearestPatch(o, d, 0.0, 1e4) < 0 && !bvh.visible(o, o + 1e4 * d);
}

// Under a body's top: the first surface along the normal is met from behind. The edge checks
// below use this one: their points lie within 1e-3 of an edge from a footprint's border,
// where a grazing direction can leave past the body's side.
bool underBody(const PatchBvh& bvh, const glm::dvec3& p, const glm::dvec3& n) {
    return metFromBehind(bvh, p + 1e-7 * (1.0 + glm::length(p)) * n, n);
}

bool coveredPoint(const PatchBvh& bvh, const glm::dvec3& p, const glm::dvec3& n) {
    const glm::dvec3 o = p + 1e-7 * (1.0 + glm::length(p)) * n;
    auto behind = [&](const glm::dvec3& d) { return metFromBehind(bvh, o, d); };
    if (!behind(n)) return false;
    const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t1 = glm::normalize(glm::cross(n, a)), t2 = glm::cross(n, t1);
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int k = 0; k < 64; ++k) {
        const double c = u01(rng), s = std::sqrt(std::max(0.0, 1.0 - c * c)),
                     phi = 2.0 * 3.14159265358979323846 * u01(rng);
        if (!behind(c * n + s * (std::cos(phi) * t1 + std::sin(phi) * t2))) return false;
    }
    return true;
}
} // namespace

TEST_CASE("meshing: edge lengths, areas, normals") {
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        const double maxEdge = s.name == "Cornell box" ? 0.05 : 0.4;
        const PatchMesh m = meshScene(s, conforming(maxEdge));
        std::vector<double> area(s.surfaces.size(), 0.0);
        for (std::size_t i = 0; i < m.patches.size(); ++i) {
            const auto c = m.cornersOf(static_cast<int>(i));
            for (std::size_t k = 0; k < c.size(); ++k)
                CHECK(glm::length(c[(k + 1) % c.size()] - c[k]) <= maxEdge * (1 + 1e-12));
            area[static_cast<std::size_t>(m.patches[i].surface)] += m.patches[i].area;
            // Same side as the surface: the normal of the patch's own corners agrees.
            CHECK(glm::dot(polygonNormal(c), m.patches[i].normal) == Approx(1.0).epsilon(1e-9));
        }
        // Patches tile their surface: areas add up (rounding of ~1e4 additions: 1e-12), except
        // where a body covers the surface (buildFitted counts only the exposed part, sampled
        // 8×8 per patch): the Cornell floor under the blocks, the sliver of its back wall behind
        // the red wall, the classroom's floor under the red box (its ceiling is whole: the lamps are
        // set into it, in holes),
        // the floor lamp's floor under its pole, the classroom's floor under the table panels
        // and the tops' undersides over them (a panel is closed by the top's underside).
        for (std::size_t k = 0; k < s.surfaces.size(); ++k) {
            const double full = polygonArea(s.surfaces[k].vertices);
            const std::string& name = s.surfaces[k].name;
            INFO(s.name << ": " << name << " " << area[k] << " of " << full);
            CHECK(area[k] <= full * (1 + 1e-12));
            if (s.name == "Cornell box" && name == "floor") {
                // Minus the two footprints (the blocks' tops): measured +0.2%; bound 0.5%.
                double feet = 0.0;
                for (const Surface& f : s.surfaces)
                    if (f.name == "short block 0" || f.name == "tall block 0") feet += polygonArea(f.vertices);
                CHECK(area[k] == Approx(full - feet).epsilon(5e-3));
            } else if (s.name == "Cornell box" && name == "back wall") {
                CHECK(area[k] == Approx(full).epsilon(3e-3)); // the sliver is 8.8e-4 m² of 0.303
            } else if (s.name == "classroom" && name == "floor") {
                // The 0.6 × 0.6 m box, and at most the 12 table panels' 2 × 50 cm footprints
                // (bodies closed by the top's underside: mesh.cpp covered(); sampled 8×8, so
                // partly: measured 2.4e-4 m² of 0.12 at 0.4 m).
                CHECK(area[k] <= full - 0.36 + 1e-9);
                CHECK(area[k] >= full - 0.36 - 12 * 0.02 * 0.5);
            } else if (name.find("top bottom") != std::string::npos) {
                // The underside over its two panels' 2 × 50 cm tops (measured 4e-5 m²).
                CHECK(area[k] <= full * (1 + 1e-12));
                CHECK(area[k] >= full - 2 * 0.02 * 0.5);
            } else if (s.name == "floor lamp" && name == "floor") {
                // The lamp's 4 cm pole, and at most its table's two panel footprints.
                CHECK(area[k] <= full - 0.04 * 0.04 + 1e-9);
                CHECK(area[k] >= full - 0.04 * 0.04 - 2 * 0.02 * 0.5);
            } else {
                CHECK(area[k] == Approx(full).epsilon(1e-12));
            }
        }
    }
}

TEST_CASE("meshing: no patch is seen from inside a body (no black blotches at the blocks' feet)") {
    // Before issue 19 item 10 the Cornell floor at 0.05 m had patches straddling the blocks'
    // footprints whose centre (the hemicube's eye) lay under a block: B = 0, drawn black where
    // the patch showed, and 22 whole patches under the blocks that nobody sees.
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        for (double edge : s.name == "Cornell box" ? std::vector<double>{0.03, 0.05, 0.1} : std::vector<double>{0.2, 0.4}) {
            const PatchMesh m = meshScene(s, conforming(edge));
            const PatchBvh bvh(m);
            int inside = 0;
            for (const Patch& p : m.patches) inside += coveredPoint(bvh, p.centre, p.normal) ? 1 : 0;
            INFO(s.name << " edge " << edge);
            CHECK(inside == 0);
        }
    }
}

TEST_CASE("meshing: no patch centre inside a table's side panel (the classroom's grid mesh)") {
    // A table's side panel is a 2 cm slab closed at the top by the table top's underside, which
    // faces down into it: from inside, the normal ray meets a front face, so 'inside a body'
    // along the normal (and the test's own coveredPoint) says no. At the lab's edge (0.2877 m,
    // 3,814 patches, the fifth session's classroom) four floor patches had their centre 7 mm
    // inside a panel, between their 8×8 exposure samples: their hemicube / rays looked at the
    // panel's inside and flat mode drew them black beside two tables. Checked geometrically
    // here for the floor's patches: the slab between each panel's (-x) and (+x) faces.
    const Scene s = classroom();
    struct Slab {
        glm::dvec3 lo, hi;
    };
    std::vector<Slab> slabs;
    for (std::size_t k = 0; k < s.surfaces.size(); ++k) {
        const std::string& name = s.surfaces[k].name;
        if (name.size() < 4 || name.compare(name.size() - 4, 4, "(-x)") != 0 || name.find("panel") == std::string::npos)
            continue;
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const std::string& side : {std::string("(-x)"), std::string("(+x)")})
            for (const Surface& f : s.surfaces)
                if (f.name == name.substr(0, name.size() - 4) + side)
                    for (const glm::dvec3& v : f.vertices) {
                        lo = glm::min(lo, v);
                        hi = glm::max(hi, v);
                    }
        slabs.push_back({lo, hi});
    }
    REQUIRE(slabs.size() == 12); // 6 tables × 2 panels
    for (double edge : {0.2, 0.28765, 0.4}) {
        const PatchMesh m = meshScene(s, {edge, 4.25 * edge});
        int inside = 0;
        for (const Patch& p : m.patches)
            for (const Slab& b : slabs)
                if (m.surfaces[static_cast<std::size_t>(p.surface)].name == "floor" && p.centre.x > b.lo.x && p.centre.x < b.hi.x && p.centre.z > b.lo.z && p.centre.z < b.hi.z &&
                    p.centre.y < b.hi.y) {
                    ++inside;
                    UNSCOPED_INFO(m.surfaces[static_cast<std::size_t>(p.surface)].name << " patch at " << p.centre.x << ", " << p.centre.y << ", " << p.centre.z);
                }
        INFO("classroom, grid mesh, edge " << edge << ": " << m.patches.size() << " patches");
        CHECK(inside == 0);
    }
}

TEST_CASE("meshing: a ceiling over a panel hanging 2 cm below it keeps its area") {
    // The rule in mesh.cpp covered() for a panel hanging just off a surface (no body: the
    // ceiling over it is seen through the gap), kept since the classroom's lamps were set into
    // its ceiling (fifth session): a 2 m room with a 0.6 × 0.3 m emitting panel 2 cm under the
    // ceiling, facing down. Tested along the normal only, the ceiling over the panel was
    // dropped (the classroom's 852 px crack).
    Scene s;
    s.name = "hanging panel";
    s.closed = true;
    const glm::dvec3 c(1.0);
    auto quad = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 cc, glm::dvec3 d, const std::string& name, glm::dvec3 e,
                    glm::dvec3 toward) {
        std::vector<glm::dvec3> v{a, b, cc, d};
        if (glm::dot(polygonNormal(v), toward - 0.25 * (a + b + cc + d)) < 0) std::reverse(v.begin(), v.end());
        s.surfaces.push_back({v, glm::dvec3(0.5), e, name});
    };
    quad({0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}, "floor", glm::dvec3(0), c);
    quad({0, 2, 0}, {2, 2, 0}, {2, 2, 2}, {0, 2, 2}, "ceiling", glm::dvec3(0), c);
    quad({0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, "wall z0", glm::dvec3(0), c);
    quad({0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}, "wall z2", glm::dvec3(0), c);
    quad({0, 0, 0}, {0, 2, 0}, {0, 2, 2}, {0, 0, 2}, "wall x0", glm::dvec3(0), c);
    quad({2, 0, 0}, {2, 2, 0}, {2, 2, 2}, {2, 0, 2}, "wall x2", glm::dvec3(0), c);
    quad({0.7, 1.98, 0.85}, {1.3, 1.98, 0.85}, {1.3, 1.98, 1.15}, {0.7, 1.98, 1.15}, "panel", glm::dvec3(10),
         glm::dvec3(1, 0, 1));
    const PatchMesh m = meshScene(s, {0.1, 0.0});
    double ceiling = 0.0;
    for (const Patch& p : m.patches)
        if (m.surfaces[static_cast<std::size_t>(p.surface)].name == "ceiling") ceiling += p.area;
    CHECK(ceiling == Approx(4.0).epsilon(1e-12));
}

TEST_CASE("meshing: a ray census finds no crack between patches that share an edge") {
    // Every edge shared by two display triangles (within a surface, T-vertices included) and
    // every patch corner: rays from in front of the surface aimed at points on the edge must hit
    // the surface there, never pass through to what lies behind (a crack). Watertight
    // triangles (core/raytrace) make a shared edge hit exactly once; a crack is a miss.
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        PatchMesh m = meshScene(s, conforming(s.name == "Cornell box" ? 0.1 : 0.8));
        // Refine once so T-vertices are in the census.
        std::vector<glm::dvec3> B(m.patches.size());
        for (std::size_t i = 0; i < B.size(); ++i) B[i] = glm::dvec3(m.patches[i].centre.x < 0.3 * m.patches[i].centre.x + 0.2 ? 1.0 : 0.0);
        refineAdaptive(m, B, {0.05, 1, 0.001, 100000}, nullptr);
        std::vector<int> patchOf;
        const auto tris = displayTriangles(m, &patchOf);
        std::vector<std::unique_ptr<wb::rt::Primitive>> prims;
        for (std::size_t t = 0; t < tris.size(); ++t) {
            auto tri = std::make_unique<wb::rt::Triangle>(m.vertices[static_cast<std::size_t>(tris[t][0])],
                                                          m.vertices[static_cast<std::size_t>(tris[t][1])],
                                                          m.vertices[static_cast<std::size_t>(tris[t][2])]);
            tri->material = patchOf[t];
            prims.push_back(std::move(tri));
        }
        const wb::rt::Bvh bvh(prims);
        const PatchBvh pbvh(m);
        int rays = 0, misses = 0;
        for (const auto& t : tris)
            for (int k = 0; k < 3; ++k) {
            const int ia = t[static_cast<std::size_t>(k)], ib = t[static_cast<std::size_t>((k + 1) % 3)];
            // Edges on the surface's border (its lattice's outline) have one patch only: skipped.
            const int surface = m.vertexSurface[static_cast<std::size_t>(ia)];
            const glm::dvec2 la = m.vertexLattice[static_cast<std::size_t>(ia)], lb = m.vertexLattice[static_cast<std::size_t>(ib)];
            const glm::ivec2 g = m.grid[static_cast<std::size_t>(surface)];
            const double U = g.x * kLatticeScale, W = g.y * kLatticeScale;
            const bool tri = m.surfaces[static_cast<std::size_t>(surface)].vertices.size() == 3;
            const bool border = tri ? ((la.x == 0 && lb.x == 0) || (la.y == 0 && lb.y == 0) || (la.x + la.y == U && lb.x + lb.y == U))
                                    : ((la.x == 0 && lb.x == 0) || (la.y == 0 && lb.y == 0) || (la.x == U && lb.x == U) || (la.y == W && lb.y == W));
            if (border) continue;
            const glm::dvec3 a = m.vertices[static_cast<std::size_t>(ia)], b = m.vertices[static_cast<std::size_t>(ib)];
            const glm::dvec3 normal = polygonNormal(m.surfaces[static_cast<std::size_t>(surface)].vertices);
            const glm::dvec3 side = glm::normalize(glm::cross(normal, b - a));
            // The rim of a hole left under a body (patches dropped there) is no crack.
            const glm::dvec3 mid = 0.5 * (a + b);
            const double h = 1e-3 * glm::length(b - a);
            if (underBody(pbvh, mid + h * side, normal) || underBody(pbvh, mid - h * side, normal)) continue;
            for (double f : {0.25, 0.5, 0.75}) {
                const glm::dvec3 target = a + f * (b - a);
                // From a point in front, slightly off the normal (no ray exactly along the edge).
                const glm::dvec3 from = target + 0.05 * normal + 0.01 * side;
                const glm::dvec3 dir = glm::normalize(target - from);
                wb::rt::Ray ray;
                ray.origin = from;
                ray.direction = dir;
                wb::rt::Hit hit;
                const double d = glm::length(target - from);
                const bool any = bvh.intersect(ray, 0.0, 2.0 * d, hit);
                if (any && hit.t < d - 1e-9 * (1 + d)) continue; // something else in front: no census
                ++rays;
                if (!any || hit.t > d + 1e-9 * (1 + d)) ++misses; // through the edge: a crack
            }
        }
        INFO(s.name << ": " << rays << " rays, " << misses << " through a crack");
        CHECK(rays > 1000);
        CHECK(misses == 0);
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
    // The triangles cover the patch's polygon (its area may be less: the exposed part), up to
    // two moves of a few µm: a triangle patch on a trapezoid surface (the Cornell floor, 552.8
    // / 549.6 mm) gets its finer neighbour's T-vertex at the lattice midpoint of an edge not
    // along the lattice, which the bilinear map puts off the straight edge; stitching gives
    // vertices within 1e-5 m of each other on two surfaces one position (the Cornell red wall
    // meets the back wall 10-20 µm off its plane). Measured 1.4e-4 of a patch's area at worst.
    double worstRel = 0.0;
    for (std::size_t i = 0; i < m.patches.size(); ++i)
        worstRel = std::max(worstRel, std::abs(area[i] / polygonArea(m.cornersOf(static_cast<int>(i))) - 1.0));
    INFO("worst relative area of a display fan against its patch " << worstRel);
    CHECK(worstRel <= 1e-3);
    const PatchBvh bvh(m);
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
            if (!onBorder) {
                // Else the edge borders a patch dropped under a body: a point just beyond it
                // (in the surface, away from the kept patch) is covered.
                const glm::dvec3 pa = m.vertices[static_cast<std::size_t>(e.first)], pb = m.vertices[static_cast<std::size_t>(e.second)];
                const glm::dvec3 nrm = polygonNormal(m.surfaces[static_cast<std::size_t>(s)].vertices);
                const glm::dvec3 mid = 0.5 * (pa + pb), side = glm::normalize(glm::cross(nrm, pb - pa));
                const double h = 1e-3 * glm::length(pb - pa);
                CHECK((underBody(bvh, mid + h * side, nrm) || underBody(bvh, mid - h * side, nrm)));
            }
            ++boundary;
        }
    }
    CHECK(boundary > 0);
}
} // namespace

TEST_CASE("adaptive refinement: T-vertices handled, display mesh conforming") {
    PatchMesh m = meshScene(cornellBox(), conforming(0.1));
    const std::size_t n0 = m.patches.size();
    // A sharp step in B across the floor makes the patches along it split.
    std::vector<glm::dvec3> B(n0);
    for (std::size_t i = 0; i < n0; ++i) B[i] = glm::dvec3(m.patches[i].centre.x < 0.26 ? 1.0 : 0.1);
    std::vector<int> parent;
    const int split = refineAdaptive(m, B, {0.05, 3, 0.001, 100000}, &parent);
    CHECK(split > 0);
    // Children wholly under a block are dropped (meshing: no patch is seen from inside a body).
    CHECK(m.patches.size() <= n0 + 3 * static_cast<std::size_t>(split));
    CHECK(m.patches.size() > n0 + 2 * static_cast<std::size_t>(split));
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
    checkConforming(meshScene(cornellBox(), conforming(0.05)));
    // Triangles split too.
    Scene tri = perpendicularPlates(1, 1, 1);
    tri.surfaces[1].vertices.pop_back();
    PatchMesh t = meshScene(tri, conforming(0.25));
    std::vector<glm::dvec3> bt(t.patches.size());
    for (std::size_t i = 0; i < bt.size(); ++i) bt[i] = glm::dvec3(t.patches[i].centre.x < 0.5 ? 1.0 : 0.1);
    CHECK(refineAdaptive(t, bt, {0.05, 3, 0.001, 100000}, nullptr) > 0);
    checkConforming(t);
}

TEST_CASE("smoothing: constant stays constant, surfaces never mix (no light leaks)") {
    PatchMesh m = meshScene(cornellBox(), conforming(0.1));
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
    PatchMesh m = meshScene(cornellBox(), conforming(0.1));
    std::vector<glm::dvec3> B(m.patches.size());
    for (std::size_t i = 0; i < B.size(); ++i)
        B[i] = m.patches[i].emission.x > 0 ? m.patches[i].emission
                                           : glm::dvec3(m.patches[i].centre.x < 0.26 ? 1.0 : 0.5);
    CHECK(refineAdaptive(m, B, {0.05, 1, 0.001, 100000}, nullptr) > 0);
}

TEST_CASE("meshing: bounded aspect ratio on every scene") {
    // The bound stated in mesh.h: quads L²/A <= kMaxAspect, triangles every angle >=
    // kMinTriangleAngleDeg (so L²/(2A) <= kMaxTriangleAspect). Before issue 19 item 10: 3.3
    // (edge 0.1) to 20 (edge 0.8) on the tables' 3 cm top edges, and a floor patch partly
    // under a Cornell block drawn as its whole quad.
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        const bool box = s.name == "Cornell box";
        for (double edge : box ? std::vector<double>{0.02, 0.0236, 0.035, 0.05, 0.1, 0.2} : std::vector<double>{0.1, 0.2, 0.243, 0.4, 0.8}) {
            const PatchMesh m = meshScene(s, conforming(edge));
            double worstQuad = 0.0, worstTri = 0.0, minAngle = 180.0;
            int tris = 0;
            for (std::size_t i = 0; i < m.patches.size(); ++i) {
                const double a = patchAspect(m, static_cast<int>(i));
                if (m.patches[i].cornerCount == 4) {
                    worstQuad = std::max(worstQuad, a);
                    continue;
                }
                ++tris;
                worstTri = std::max(worstTri, a);
                const auto c = m.cornersOf(static_cast<int>(i));
                for (int k = 0; k < 3; ++k) {
                    const glm::dvec3 u = glm::normalize(c[static_cast<std::size_t>((k + 1) % 3)] - c[static_cast<std::size_t>(k)]);
                    const glm::dvec3 v = glm::normalize(c[static_cast<std::size_t>((k + 2) % 3)] - c[static_cast<std::size_t>(k)]);
                    minAngle = std::min(minAngle, glm::degrees(std::acos(std::clamp(glm::dot(u, v), -1.0, 1.0))));
                }
            }
            INFO(s.name << " edge " << edge << ": " << m.patches.size() << " patches (" << tris
                        << " triangles), worst quad " << worstQuad << ", worst triangle " << worstTri
                        << ", smallest angle " << minAngle << "°");
            CHECK(worstQuad <= kMaxAspect);
            CHECK(worstTri <= kMaxTriangleAspect);
            // The mesher's bound is on its 2D points; the lattice round trip moves a corner by
            // ~1e-16 of the surface: 1e-6° of slack.
            CHECK(minAngle >= kMinTriangleAngleDeg - 1e-6);
            CHECK(tris > 0); // every scene has a body standing on a surface
        }
    }
}

TEST_CASE("scenes: no two surfaces lie face to face in one plane (no depth ties)") {
    // The floor lamp's shade was two coincident faces per panel (inside, outside), the
    // classroom's table panels too: GL's depth test decides between them pixel by pixel, so
    // the bright inside showed through as a ragged rim and a 1-px crack (issue 19 item 10).
    auto inside = [](const glm::dvec3& q, const std::vector<glm::dvec3>& poly, const glm::dvec3& n) {
        for (std::size_t k = 0; k < poly.size(); ++k)
            if (glm::dot(glm::cross(poly[(k + 1) % poly.size()] - poly[k], q - poly[k]), n) <= 1e-12) return false;
        return true; // strictly inside the convex polygon
    };
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        int ties = 0;
        for (std::size_t a = 0; a < s.surfaces.size(); ++a)
            for (std::size_t b = a + 1; b < s.surfaces.size(); ++b) {
                const auto& A = s.surfaces[a].vertices;
                const auto& Bv = s.surfaces[b].vertices;
                const glm::dvec3 na = polygonNormal(A), nb = polygonNormal(Bv);
                if (std::abs(std::abs(glm::dot(na, nb)) - 1.0) > 1e-12) continue;
                if (std::abs(glm::dot(Bv[0] - A[0], na)) > 1e-9) continue; // parallel planes
                glm::dvec3 ca(0.0), cb(0.0);
                for (const auto& v : A) ca += v / double(A.size());
                for (const auto& v : Bv) cb += v / double(Bv.size());
                if (inside(ca, Bv, nb) || inside(cb, A, na)) {
                    ++ties;
                    UNSCOPED_INFO(s.name << ": " << s.surfaces[a].name << " and " << s.surfaces[b].name);
                }
            }
        CHECK(ties == 0);
    }
}

namespace {
// Display edges (exact endpoint positions, both orders alike) that lie on ANOTHER surface's
// polygon but have no twin there: a T-junction where two surfaces meet, which the rasteriser
// opens into a row of 1-px holes (the background or a body's inside shows through).
int openSeams(const PatchMesh& m, int* seamEdges) {
    using Key = std::array<double, 6>;
    std::map<Key, std::pair<int, int>> uses; // edge -> (count, surface of the first use)
    const auto tris = displayTriangles(m);
    for (const auto& t : tris)
        for (int k = 0; k < 3; ++k) {
            glm::dvec3 a = m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
            glm::dvec3 b = m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
            if (std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z)) std::swap(a, b);
            auto& u = uses[Key{a.x, a.y, a.z, b.x, b.y, b.z}];
            if (u.first++ == 0) u.second = m.vertexSurface[static_cast<std::size_t>(t[0])];
        }
    int open = 0;
    *seamEdges = 0;
    for (const auto& [e, u] : uses) {
        const glm::dvec3 a(e[0], e[1], e[2]), b(e[3], e[4], e[5]), mid = 0.5 * (a + b);
        for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
            if (static_cast<int>(s) == u.second) continue;
            const auto& d = m.surfaces[s].vertices;
            const glm::dvec3 n = polygonNormal(d);
            const double tol = 1e-9;
            if (std::abs(glm::dot(a - d[0], n)) > tol || std::abs(glm::dot(b - d[0], n)) > tol) continue;
            bool in = true;
            for (std::size_t k = 0; k < d.size(); ++k)
                in = in && glm::dot(glm::cross(d[(k + 1) % d.size()] - d[k], mid - d[k]), n) >= -tol;
            if (!in) continue;
            ++*seamEdges;
            // The other surface running on across the edge (a table panel standing on the
            // floor, open at the top: no hole under it) leaves nothing to crack.
            auto coveredBySurface = [&](const glm::dvec3& q) {
                for (const auto& t : tris) {
                    if (m.vertexSurface[static_cast<std::size_t>(t[0])] != static_cast<int>(s)) continue;
                    const glm::dvec3 p0 = m.vertices[static_cast<std::size_t>(t[0])], p1 = m.vertices[static_cast<std::size_t>(t[1])],
                                     p2 = m.vertices[static_cast<std::size_t>(t[2])];
                    const double area2 = glm::dot(glm::cross(p1 - p0, p2 - p0), n);
                    const double w0 = glm::dot(glm::cross(p2 - p1, q - p1), n) / area2, w1 = glm::dot(glm::cross(p0 - p2, q - p2), n) / area2;
                    if (w0 >= -1e-9 && w1 >= -1e-9 && 1.0 - w0 - w1 >= -1e-9) return true;
                }
                return false;
            };
            bool under = false;
            if (u.first == 1) {
                const glm::dvec3 side = glm::normalize(glm::cross(n, b - a)) * (1e-4 * glm::length(b - a));
                under = coveredBySurface(mid + side) && coveredBySurface(mid - side);
            }
            if (u.first == 1 && !under) {
                ++open;
                if (std::getenv("WB_DEBUG_SEAMS")) std::fprintf(stderr, "open %s | %s: %.6f %.6f %.6f - %.6f %.6f %.6f\n", m.surfaces[static_cast<std::size_t>(u.second)].name.c_str(), m.surfaces[s].name.c_str(), a.x, a.y, a.z, b.x, b.y, b.z);
            }
            break;
        }
    }
    return open;
}
} // namespace

TEST_CASE("meshing: conforming where surfaces meet (no T-junction at a seam)") {
    // Issue 19 item 10: the Cornell floor was a grid whose patches ran under the blocks, with
    // no vertex on the blocks' bottom edges; the walls' and the floor's grids met at the room's
    // corners with different vertices. Every display edge lying on another surface must have a
    // twin there, endpoint for endpoint (exact positions: GL's rasteriser shares an edge
    // without a gap only between identical vertices). At the lab's sizes and after refinement.
    for (const Scene& s : {cornellBox(), classroom(), floorLamp()}) {
        const bool box = s.name == "Cornell box";
        for (double edge : box ? std::vector<double>{0.0236, 0.05} : std::vector<double>{0.243, 0.4}) {
            PatchMesh m = meshScene(s, conforming(edge));
            int seams = 0;
            const int open = openSeams(m, &seams);
            INFO(s.name << " edge " << edge << ": " << seams << " display edges on another surface, " << open << " without a twin");
            CHECK(seams > 100);
            CHECK(open == 0);
            // A refinement step splits patches on one side of a seam only.
            std::vector<glm::dvec3> B(m.patches.size());
            for (std::size_t i = 0; i < B.size(); ++i)
                B[i] = glm::dvec3(std::fmod(std::floor(m.patches[i].centre.x / (3 * edge)) + std::floor(m.patches[i].centre.z / (3 * edge)), 2.0));
            CHECK(refineAdaptive(m, B, {0.05, 1, 0.001, 100000}, nullptr) > 0);
            const int openAfter = openSeams(m, &seams);
            INFO("after refinement: " << m.patches.size() << " patches, " << seams << " seam edges, " << openAfter << " open");
            CHECK(openAfter == 0);
        }
    }
}
