// The CPU hemicube: the delta form-factor table, the layout (pixel directions against the
// documented table), rows against closed forms, row sums in a closed room.
#include "core/radiosity/closed_forms.h"
#include "core/radiosity/hemicube.h"
#include "core/radiosity/scenes.h"

#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>

using namespace wb::rad;

TEST_CASE("delta form factors: sum, symmetry, exact pixels") {
    for (int res : {16, 64, 256, 1024}) {
        const DeltaFormFactors t = deltaFormFactors(res);
        // Midpoint rule over the hemisphere: the error is O(h²), h = 2/res, and the rule
        // overestimates (the weight is convex over most pixels); measured sum − 1 = 2.12e-3 at
        // 16², 1.32e-4 at 64², 8.27e-6 at 256², 5.17e-7 at 1024², i.e. 0.54/res²; bound 0.6/res².
        CHECK(t.sum > 1.0);
        CHECK(t.sum - 1.0 < 0.6 / (res * res));
        // The top face is symmetric in s and t.
        const auto& top = t.faces[0];
        CHECK(top[0] == top[static_cast<std::size_t>(res - 1)]);
        CHECK(top[0] == top[static_cast<std::size_t>(res) * static_cast<std::size_t>(res) - 1]);
        // All side faces carry the same weights.
        for (int f = 2; f < 5; ++f) CHECK(t.faces[static_cast<std::size_t>(f)] == t.faces[1]);
    }
    const DeltaFormFactors e = deltaFormFactors(32, true);
    // Exact pixel form factors tile the hemisphere: sum 1 up to rounding of 3·32² terms.
    CHECK(e.sum == Approx(1.0).epsilon(1e-12));
    CHECK_THROWS_AS(deltaFormFactors(15), std::invalid_argument);
    CHECK_THROWS_AS(deltaFormFactors(0), std::invalid_argument);
}

TEST_CASE("hemicube layout: pixel directions as documented") {
    HemicubeFrame fr; // u = x, v = y, n = z
    const int res = 8;
    // Top row 0 col 0 is at s = t = −1 + 1/8: direction (−7/8, −7/8, 1).
    CHECK(pixelDirection(fr, res, HemicubeFace::Top, 0, 0) == glm::dvec3(-0.875, -0.875, 1));
    // +U face: u − s·v + z·n; col 0 -> s = −7/8 -> +v side; row 0 -> z = 1/8.
    CHECK(pixelDirection(fr, res, HemicubeFace::PosU, 0, 0) == glm::dvec3(1, 0.875, 0.125));
    CHECK(pixelDirection(fr, res, HemicubeFace::NegU, 0, 0) == glm::dvec3(-1, -0.875, 0.125));
    CHECK(pixelDirection(fr, res, HemicubeFace::PosV, 0, 3) == glm::dvec3(-0.875, 1, 0.875));
    CHECK(pixelDirection(fr, res, HemicubeFace::NegV, 7, 0) == glm::dvec3(-0.875, -1, 0.125));
    // GL's right = look × up for the sides: +U looks along u with up n: right = −v.
    CHECK(glm::cross(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)) == glm::dvec3(0, -1, 0));
    CHECK(faceHeight(res, HemicubeFace::Top) == 8);
    CHECK(faceHeight(res, HemicubeFace::NegV) == 4);
}

TEST_CASE("hemicube row from a patch centre against the exact point-to-polygon value") {
    // Two unit squares one apart, each one patch: the hemicube measures F from the emitter's
    // centre point (it is a point method), so the reference is pointToPolygon from there.
    const PatchMesh m = meshScene(parallelPlates(1, 1, 1), {2.0});
    REQUIRE(m.patches.size() == 2);
    const PatchBvh bvh(m);
    const double exact = pointToPolygon(m.patches[0].centre, m.patches[0].normal, m.cornersOf(1));
    double last = 1.0;
    for (int res : {16, 64, 256, 1024}) {
        std::vector<float> row;
        hemicubeRow(m, bvh, deltaFormFactors(res), 0, row);
        const double err = std::abs(row[1] - exact) / exact;
        // The square's edges fall on pixel boundaries here (its edges project to s = ±1/2 on
        // the top face), so no pixel is cut and the error is the midpoint rule's alone:
        // measured 0.76/res² (3.0e-3 at 16², 1.9e-4 at 64², 7.0e-7 at 1024²); bound 1/res².
        CHECK(err < 1.0 / (res * res));
        CHECK(row[0] == 0.0f); // F_ii = 0
        last = err;
    }
    CHECK(last < 1e-5);
}

TEST_CASE("hemicube rows of a closed room sum to the table's sum") {
    const PatchMesh m = meshScene(furnace(0.5, 1.0), {0.25});
    const PatchBvh bvh(m);
    for (int res : {16, 64, 256}) {
        const DeltaFormFactors t = deltaFormFactors(res);
        for (int i : {0, 5, 37, 95}) {
            std::vector<float> row;
            hemicubeRow(m, bvh, t, i, row);
            double sum = 0.0;
            for (float f : row) sum += f;
            // Every pixel sees a wall (closed, convex room): the row sum is the table's sum up to
            // float storage of the row (96 entries × 6e-8).
            CHECK(sum == Approx(t.sum).epsilon(1e-6));
        }
    }
}

TEST_CASE("accumulate: GL-style item buffer, bad ids skipped, mismatched resolution refused") {
    const DeltaFormFactors t = deltaFormFactors(4);
    ItemBuffer items;
    items.resize(4);
    for (auto& f : items.faces) std::fill(f.begin(), f.end(), 1);
    items.faces[0][0] = 7;  // beyond patchCount: skipped
    items.faces[0][1] = -1; // nothing
    items.faces[1][0] = 0;  // self: forced to 0
    std::vector<float> row;
    accumulate(items, t, 3, 0, row);
    REQUIRE(row.size() == 3);
    CHECK(row[0] == 0.0f);
    CHECK(row[2] == 0.0f);
    CHECK(row[1] == Approx(t.sum - t.faces[0][0] - t.faces[0][1] - t.faces[1][0]).epsilon(1e-7));
    ItemBuffer other;
    other.resize(8);
    CHECK_THROWS_AS(accumulate(other, t, 3, 0, row), std::invalid_argument);
}

namespace {
// Every pixel's id in `items` is nearestPatch's for that pixel's ray alone (the packets' answer
// against one ray per pixel); counts the pixels and those that see a patch.
void requireItemsMatchRays(const PatchBvh& bvh, const HemicubeFrame& frame, int res,
                           const ItemBuffer& items, long& pixels, long& seen) {
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto face = static_cast<HemicubeFace>(f);
        for (int row = 0; row < faceHeight(res, face); ++row)
            for (int col = 0; col < faceWidth(res, face); ++col) {
                const glm::dvec3 d = glm::normalize(pixelDirection(frame, res, face, col, row));
                const int want =
                    bvh.nearestPatch(frame.origin, d, 0.0, std::numeric_limits<double>::infinity());
                const int got = items.faces[static_cast<std::size_t>(f)]
                                           [static_cast<std::size_t>(row * res + col)];
                INFO("res " << res << " face " << f << " col " << col << " row " << row
                            << " eye " << frame.origin.x << ' ' << frame.origin.y << ' '
                            << frame.origin.z << " n " << frame.n.x << ' ' << frame.n.y << ' '
                            << frame.n.z);
                REQUIRE(got == want);
                ++pixels;
                seen += want >= 0;
            }
    }
}
} // namespace

TEST_CASE("hemicube item buffer: packets of pixels give the ids of one ray per pixel") {
    // Issue 21: castItemBuffer traces each face row's neighbouring pixels as packets of up
    // to 8 rays; every id must be nearestPatch's for that pixel's ray alone (the Cornell
    // box: boxes' edges and corners, back sides, resolutions not a multiple of 8).
    const PatchMesh m = meshScene(cornellBox(), {0.15});
    const PatchBvh bvh(m);
    long pixels = 0, seen = 0;
    for (int res : {6, 20, 64}) {
        for (int i = 0; i < static_cast<int>(m.patches.size()); i += 7) {
            const HemicubeFrame frame = hemicubeFrame(m, i);
            for (HemicubeCast method : {HemicubeCast::Raster, HemicubeCast::Packets}) {
                ItemBuffer items;
                castItemBuffer(bvh, frame, res, items, false, method);
                requireItemsMatchRays(bvh, frame, res, items, pixels, seen);
            }
        }
    }
    REQUIRE(seen > pixels / 2);
}

TEST_CASE("hemicube item buffer: packets equal one ray per pixel from adversarial eyes") {
    // Issue 21: all rays of a hemicube share one origin; the packet walk must give the
    // per-ray answer where the float node and triangle tests are closest to wrong: the eye
    // exactly on a mesh vertex (a corner shared by several patches), on the midpoint of a
    // patch edge, on a corner of the box (three surfaces), and hemicubes lying in a wall's
    // plane (side faces' rays grazing it; rows of pixels exactly parallel to it).
    const PatchMesh m = meshScene(cornellBox(), {0.15});
    const PatchBvh bvh(m);
    std::vector<HemicubeFrame> frames;
    auto frameAt = [](glm::dvec3 o, glm::dvec3 n, glm::dvec3 u) {
        HemicubeFrame f;
        f.origin = o;
        f.n = glm::normalize(n);
        f.u = glm::normalize(u - glm::dot(u, f.n) * f.n);
        f.v = glm::cross(f.n, f.u);
        return f;
    };
    for (int i = 0; i < static_cast<int>(m.patches.size()); i += 13) {
        const Patch& p = m.patches[static_cast<std::size_t>(i)];
        const glm::dvec3 c0 = m.vertices[static_cast<std::size_t>(p.corners[0])];
        const glm::dvec3 c1 = m.vertices[static_cast<std::size_t>(p.corners[1])];
        const glm::dvec3 e = c1 - c0;
        // On a vertex and on an edge midpoint, looking off the surface and along it.
        frames.push_back(frameAt(c0, p.normal, e));
        frames.push_back(frameAt(0.5 * (c0 + c1), p.normal, e));
        frames.push_back(frameAt(c0, e, p.normal)); // n in the surface: grazing
        frames.push_back(frameAt(0.5 * (c0 + c1), glm::cross(p.normal, e), e)); // likewise
    }
    long pixels = 0, seen = 0;
    for (int res : {8, 30}) {
        for (const HemicubeFrame& frame : frames)
            for (HemicubeCast method : {HemicubeCast::Raster, HemicubeCast::Packets}) {
                ItemBuffer items, itemsParallel;
                castItemBuffer(bvh, frame, res, items, false, method);
                castItemBuffer(bvh, frame, res, itemsParallel, true, method);
                for (int f = 0; f < kHemicubeFaces; ++f)
                    REQUIRE(items.faces[static_cast<std::size_t>(f)] ==
                            itemsParallel.faces[static_cast<std::size_t>(f)]);
                requireItemsMatchRays(bvh, frame, res, items, pixels, seen);
            }
    }
    CHECK(frames.size() >= 40);
    REQUIRE(seen > pixels / 3); // most rays see a patch (the rest: back sides, the open side)
}

namespace {
Surface wall(glm::dvec3 o, glm::dvec3 a, glm::dvec3 b) {
    Surface s;
    s.vertices = {o, o + a, o + a + b, o + b};
    s.emission = glm::dvec3(1.0); // any: the scene must emit to be valid
    return s;
}

// The hemicube's own cube, [−1, 1]³ around `c` (normals inward), with a box floating inside
// (normals outward: its back sides are seen from outside it... and block).
Scene cubeRoom(glm::dvec3 c, bool box) {
    const glm::dvec3 X(2, 0, 0), Y(0, 2, 0), Z(0, 0, 2), lo = c - glm::dvec3(1.0);
    Scene sc;
    sc.closed = !box;
    sc.surfaces = {wall(lo, X, Y),     wall(lo + Z, Y, X), wall(lo, Z, X),
                   wall(lo + Y, X, Z), wall(lo, Y, Z),     wall(lo + X, Z, Y)};
    if (box) {
        // Corners on the 1/8 lattice too, so its edges also pass through pixel centres.
        const glm::dvec3 b0 = c + glm::dvec3(0.25, -0.5, 0.25), d(0.5, 0.25, 0.5);
        const glm::dvec3 dx(d.x, 0, 0), dy(0, d.y, 0), dz(0, 0, d.z);
        sc.surfaces.push_back(wall(b0, dx, dz));
        sc.surfaces.push_back(wall(b0 + dy, dz, dx));
        sc.surfaces.push_back(wall(b0, dz, dy));
        sc.surfaces.push_back(wall(b0 + dx, dy, dz));
        sc.surfaces.push_back(wall(b0, dy, dx));
        sc.surfaces.push_back(wall(b0 + dz, dx, dy));
    }
    return sc;
}
} // namespace

TEST_CASE("hemicube raster: the edge-plane filter never changes a pixel's id") {
    // Issue 21: the rasteriser decides most pixels from edge functions (the edge planes through
    // the eye) with a relative margin, without the watertight test. Its ids must be
    // nearestPatch's. Hardest cases, built exactly: the eye at the centre of the hemicube's own
    // cube, whose walls are meshed on a 1/4 grid (vertices at multiples of 1/4, exact), so at
    // 4² every pixel's ray passes exactly through a vertex shared by four patches, at 8²
    // through the middle of a patch (on both its diagonals' line, one of them the split of its
    // quad into triangles), at 16² through shared edges and diagonals; the walls meet at the
    // faces' borders (the cube's edges). Frames turned to every axis, the eye moved along the
    // lattice, on a wall (its surface through the eye: side rows graze it), the whole scene
    // shifted by exact and inexact offsets (rounded differences), a box with back sides.
    struct Case {
        glm::dvec3 centre;
        bool box;
    };
    const Case cases[] = {{glm::dvec3(0.0), false},
                          {glm::dvec3(0.0), true},
                          {glm::dvec3(3, 5, -7), true},
                          {glm::dvec3(1e6 + 0.1, -2e5 + 0.3, 7.7), true}};
    long pixels = 0, seen = 0;
    for (const Case& cs : cases) {
        const PatchMesh m = meshScene(cubeRoom(cs.centre, cs.box), {0.25});
        const PatchBvh bvh(m);
        std::vector<HemicubeFrame> frames;
        const glm::dvec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
        for (const glm::dvec3& n : axes)
            for (const glm::dvec3& u : axes) {
                if (glm::dot(n, u) != 0.0) continue;
                for (const glm::dvec3& shift :
                     {glm::dvec3(0.0), glm::dvec3(0.25, 0.5, -0.25), glm::dvec3(0.125, 0, 0)}) {
                    HemicubeFrame f;
                    f.origin = cs.centre + shift;
                    f.n = n;
                    f.u = u;
                    f.v = glm::cross(n, u);
                    frames.push_back(f);
                }
                // On the wall behind: its plane through the eye, at a lattice vertex.
                HemicubeFrame g;
                g.origin = cs.centre - n + 0.25 * u;
                g.n = n;
                g.u = u;
                g.v = glm::cross(n, u);
                frames.push_back(g);
            }
        // And the lab's own frames on some patches (offset origins).
        for (int i = 0; i < static_cast<int>(m.patches.size()); i += 37) frames.push_back(hemicubeFrame(m, i));
        for (int res : {4, 8, 16})
            for (const HemicubeFrame& frame : frames) {
                ItemBuffer items;
                castItemBuffer(bvh, frame, res, items, false, HemicubeCast::Raster);
                requireItemsMatchRays(bvh, frame, res, items, pixels, seen);
            }
    }
    REQUIRE(seen > pixels / 2);
}
