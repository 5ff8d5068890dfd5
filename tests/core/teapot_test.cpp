// The Utah teapot of core/teapot: the published data's shape (counts, mirror symmetry),
// patches that meet without cracks, normals at the lid's and the bottom's poles against
// their exact value and a limit, and outward orientation checked edge by edge.
#include "core/teapot.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <stdexcept>

using namespace wb;
using glm::dvec3;

namespace {

// Edge e (0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0) of a patch at parameter t along it,
// t running counter-clockwise around the (u, v) square, as a mesh face walks its border.
dvec3 edgePoint(const BezierPatch& p, int e, double t) {
    switch (e) {
    case 0:
        return evalPatch(p, t, 0).point;
    case 1:
        return evalPatch(p, 1, t).point;
    case 2:
        return evalPatch(p, 1 - t, 1).point;
    default:
        return evalPatch(p, 0, 1 - t).point;
    }
}

// Exactly equal decimal data run through the same de Casteljau steps in a different
// order of control points: the sums may round differently by a few ulps of 3.15.
constexpr double kSameTol = 1e-13;

} // namespace

TEST_CASE("teapot data: 306 points, 32 patches, mirror symmetric in y = 0") {
    const auto& pts = teapotControlPoints();
    const auto& idx = teapotPatchIndices();
    REQUIRE(pts.size() == 306);
    REQUIRE(idx.size() == 32);
    std::set<int> used;
    for (const auto& patch : idx)
        for (int k : patch) {
            REQUIRE(k >= 1);
            REQUIRE(k <= 306);
            used.insert(k);
        }
    // All but the four near-pole points 205, 206, 216, 223 that no patch uses.
    CHECK(used.size() == 302);
    for (int k : {205, 206, 216, 223})
        CHECK(used.count(k) == 0);
    // Every used point's mirror image (x, -y, z) is a used point too: a typo in one
    // coordinate of one point breaks this (the data are exact decimals; tolerance 1e-12
    // is far below the data's 0.001 resolution).
    for (int k : used) {
        const dvec3 m = pts[size_t(k - 1)] * dvec3(1, -1, 1);
        bool found = false;
        for (int j : used)
            found = found || glm::length(pts[size_t(j - 1)] - m) < 1e-12;
        INFO("point " << k);
        CHECK(found);
    }
    double zMin = 1e9, zMax = -1e9;
    for (int k : used)
        zMin = std::min(zMin, pts[size_t(k - 1)].z), zMax = std::max(zMax, pts[size_t(k - 1)].z);
    CHECK(zMin == 0.0);
    CHECK(zMax == kTeapotHeight);
}

TEST_CASE("teapot patches meet without cracks and are oriented consistently") {
    const auto& ps = teapotPatches();
    REQUIRE(ps.size() == 32);
    // Pairs of boundary edges whose end points coincide; on each such pair the two
    // patches' own evaluations must agree all along (no crack), and consistent
    // orientation means the two faces walk the shared edge in opposite directions.
    int shared = 0, reversed = 0;
    std::vector<int> perPatch(32, 0);
    for (int a = 0; a < 32; ++a)
        for (int ea = 0; ea < 4; ++ea) {
            const dvec3 a0 = edgePoint(ps[size_t(a)], ea, 0), a1 = edgePoint(ps[size_t(a)], ea, 1);
            if (glm::length(a1 - a0) < 1e-9) continue; // an edge collapsed to a pole
            for (int b = a + 1; b < 32; ++b)
                for (int eb = 0; eb < 4; ++eb) {
                    const dvec3 b0 = edgePoint(ps[size_t(b)], eb, 0),
                                b1 = edgePoint(ps[size_t(b)], eb, 1);
                    // Meant to be one edge: the ends coincide and the middles are close (0.05,
                    // so that a mistyped inner control point still counts here and fails
                    // the gap below; the two halves of a tube's end circle share only ends).
                    const dvec3 am = edgePoint(ps[size_t(a)], ea, 0.5);
                    const bool same = glm::length(a0 - b0) < kSameTol &&
                                      glm::length(a1 - b1) < kSameTol &&
                                      glm::length(am - edgePoint(ps[size_t(b)], eb, 0.5)) < 0.05;
                    const bool opposite =
                        glm::length(a0 - b1) < kSameTol && glm::length(a1 - b0) < kSameTol &&
                        glm::length(am - edgePoint(ps[size_t(b)], eb, 0.5)) < 0.05;
                    if (!same && !opposite) continue;
                    ++shared, ++perPatch[size_t(a)], ++perPatch[size_t(b)];
                    reversed += opposite;
                    double gap = 0;
                    for (int i = 0; i <= 64; ++i) {
                        const double t = i / 64.0;
                        const dvec3 q = edgePoint(ps[size_t(b)], eb, opposite ? 1 - t : t);
                        gap = std::max(gap, glm::length(edgePoint(ps[size_t(a)], ea, t) - q));
                    }
                    INFO("patches " << a << " edge " << ea << " and " << b << " edge " << eb);
                    CHECK(gap < kSameTol);
                }
        }
    // The seams of the data: rim 4 sides + 4 to the body; body 8 sides + 4 between its
    // rows + 4 to the bottom; bottom 4 sides; lid 8 sides + 4 between rows; handle and
    // spout 6 each (two half tubes of two segments). The handle and the spout end on the
    // body without sharing an edge, and the lid rests on the rim.
    CHECK(shared == 4 + 4 + 8 + 4 + 4 + 4 + 8 + 4 + 6 + 6);
    CHECK(reversed == shared); // every shared edge is walked both ways: one orientation
    for (int p = 0; p < 32; ++p) {
        INFO("patch " << p << " (" << teapotPart(p) << ")");
        CHECK(perPatch[size_t(p)] >= 3);
    }
}

TEST_CASE("teapot normals point outwards") {
    const auto& ps = teapotPatches();
    // One patch per connected part, against a direction that is outward without doubt;
    // the edge test above carries the orientation to the rest of each part.
    const PatchSample bottom = evalPatch(ps[28], 0.5, 0.5); // the base faces down
    CHECK(bottom.normal.z < -0.9);
    const PatchSample lid = evalPatch(ps[24], 0.5, 0.5); // the lid's slope faces up
    CHECK(lid.normal.z > 0.5);
    // The handle's farthest point from the pot (x most negative) faces -x.
    double xMin = 1e9;
    dvec3 nAtMin(0);
    for (int p = 12; p < 16; ++p)
        for (int i = 0; i <= 32; ++i)
            for (int j = 0; j <= 32; ++j) {
                const PatchSample s = evalPatch(ps[size_t(p)], i / 32.0, j / 32.0);
                if (s.point.x < xMin) xMin = s.point.x, nAtMin = s.normal;
            }
    CHECK(nAtMin.x < -0.9);
    // The spout's highest point (its lip) faces up.
    double zMax = -1e9;
    dvec3 nAtMax(0);
    for (int p = 16; p < 20; ++p)
        for (int i = 0; i <= 32; ++i)
            for (int j = 0; j <= 32; ++j) {
                const PatchSample s = evalPatch(ps[size_t(p)], i / 32.0, j / 32.0);
                if (s.point.z > zMax) zMax = s.point.z, nAtMax = s.normal;
            }
    CHECK(nAtMax.z > 0.5);
}

TEST_CASE("teapot normals are defined at the lid's and the bottom's poles") {
    const auto& ps = teapotPatches();
    struct Pole {
        int first;   // first of the four patches around it
        dvec3 point; // the pole
        dvec3 n;     // its normal: ±z by the pot's symmetry about the z axis
    };
    for (const Pole& pole :
         {Pole{20, {0, 0, kTeapotHeight}, {0, 0, 1}}, Pole{28, {0, 0, 0}, {0, 0, -1}}}) {
        for (int p = pole.first; p < pole.first + 4; ++p) {
            const BezierPatch& b = ps[size_t(p)];
            INFO("patch " << p << " (" << teapotPart(p) << ")");
            for (double u : {0.0, 0.3, 0.5, 1.0}) {
                const PatchSample s = evalPatch(b, u, 0.0); // the published first row is the pole
                REQUIRE(glm::length(s.point - pole.point) < 1e-15);
                CHECK(glm::length(glm::cross(s.du, s.dv)) == 0.0); // du vanishes: no du × dv
                CHECK(s.normalKind == 1);                          // evalPatch took the limit
                // Exact value, to rounding (double; the limit is a normalised cross product).
                CHECK(glm::length(s.normal - pole.n) < 1e-12);
                // A second formula: du × dv just inside the patch tends to the pole's normal
                // as O(h) (the surface is smooth there), so at h = 1e-4 within 1e-3.
                const PatchSample in = evalPatch(b, u, 1e-4);
                REQUIRE(in.normalKind == 0);
                CHECK(glm::length(glm::normalize(glm::cross(in.du, in.dv)) - pole.n) < 1e-3);
            }
        }
    }
    // The mesh keeps one normal per pole vertex and drops the collapsed triangles.
    const Mesh m = teapotMesh(8);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        REQUIRE(std::isfinite(m.normals[i].x + m.normals[i].y + m.normals[i].z));
        CHECK(std::abs(glm::length(m.normals[i]) - 1.0) < 1e-12);
    }
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const dvec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                    c = m.positions[m.indices[t + 2]];
        CHECK(glm::length(glm::cross(b - a, c - a)) > 1e-12);
    }
    // 32 patches × 8² cells × 2, less one triangle per pole cell (8 patches × 8 cells).
    CHECK(m.indices.size() / 3 == size_t(32 * 64 * 2 - 8 * 8));
    CHECK_THROWS_AS(teapotMesh(0), std::invalid_argument);
}
