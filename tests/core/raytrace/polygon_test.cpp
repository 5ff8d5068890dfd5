// Triangulation of NFF polygons (issue 12, speckles in SPD gears): concave faces must be
// covered exactly once; convex ones keep the fan from vertex 0 bit for bit.
#include "core/raytrace/nff.h"
#include "core/raytrace/polygon.h"
#include "core/raytrace/spd.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wb::rt;

namespace {

using P2 = glm::dvec2;

// Independent reference: even–odd crossing test (a horizontal ray to +x).
bool insidePolygon(const std::vector<P2>& poly, const P2& q) {
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const P2 &a = poly[i], &b = poly[j];
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

// Strictly inside the triangle (either winding), with long double edge functions.
bool insideTriangle(const P2& a, const P2& b, const P2& c, const P2& q) {
    using LD = long double;
    const auto e = [](const P2& p0, const P2& p1, const P2& p) {
        return (LD(p1.x) - p0.x) * (LD(p.y) - p0.y) - (LD(p1.y) - p0.y) * (LD(p.x) - p0.x);
    };
    const LD u = e(a, b, q), v = e(b, c, q), w = e(c, a, q);
    return (u > 0 && v > 0 && w > 0) || (u < 0 && v < 0 && w < 0);
}

double distToSegment(const P2& a, const P2& b, const P2& q) {
    const P2 ab = b - a;
    const double t = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(a + t * ab - q);
}

double shoelace(const std::vector<P2>& p) {
    long double s = 0;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
        s += (long double)(p[j].x) * p[i].y - (long double)(p[i].x) * p[j].y;
    return double(s / 2);
}

std::vector<P2> xy(const std::vector<glm::dvec3>& v) {
    std::vector<P2> out;
    for (const auto& p : v)
        out.push_back({p.x, p.y});
    return out;
}

// Every triangle's winding agrees with the polygon's; areas add up; every sample point
// (not within 1e-9 of an edge) is in exactly as many triangles as the crossing test says.
void checkCoverage(const std::vector<glm::dvec3>& v, int samples) {
    const auto tris = triangulatePolygon(v);
    REQUIRE(tris.size() == v.size() - 2);
    const std::vector<P2> p = xy(v);
    const double area = shoelace(p);
    long double sum = 0;
    for (const auto& t : tris) {
        const double a = shoelace({p[size_t(t[0])], p[size_t(t[1])], p[size_t(t[2])]});
        CHECK(a * area >= 0); // same winding as the polygon (0: a dropped straight corner)
        sum += a;
    }
    // The triangles' areas are sums of products of coordinates of size ~1: their rounding
    // is ~1e-16 each, so 1e-12 relative leaves room for 10^4 triangles.
    CHECK(std::abs(double(sum) - area) <= 1e-12 * std::abs(area));
    P2 lo(1e300), hi(-1e300);
    for (const P2& q : p) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> ux(lo.x, hi.x), uy(lo.y, hi.y);
    int inside = 0, checked = 0;
    for (int i = 0; i < samples; ++i) {
        const P2 q(ux(rng), uy(rng));
        bool nearEdge = false;
        for (size_t k = 0, j = p.size() - 1; k < p.size() && !nearEdge; j = k++)
            nearEdge = distToSegment(p[j], p[k], q) < 1e-9;
        for (const auto& t : tris) // and near the triangles' own (inner) edges
            for (int e = 0; e < 3 && !nearEdge; ++e)
                nearEdge = distToSegment(p[size_t(t[size_t(e)])], p[size_t(t[size_t((e + 1) % 3)])],
                                         q) < 1e-9;
        if (nearEdge) continue;
        int cover = 0;
        for (const auto& t : tris)
            cover += insideTriangle(p[size_t(t[0])], p[size_t(t[1])], p[size_t(t[2])], q);
        const bool in = insidePolygon(p, q);
        INFO("point " << q.x << ", " << q.y);
        REQUIRE(cover == (in ? 1 : 0));
        inside += in;
        ++checked;
    }
    CHECK(inside > checked / 10); // the samples did land inside, and outside
    CHECK(inside < checked);
}

} // namespace

TEST_CASE("convex polygons keep the fan from vertex 0", "[raytrace][polygon]") {
    const std::vector<glm::dvec3> square = {{2, 2, 0}, {-2, 2, 0}, {-2, -2, 0}, {2, -2, 0}};
    const auto t = triangulatePolygon(square);
    REQUIRE(t.size() == 2);
    CHECK(t[0] == std::array<int, 3>{0, 1, 2});
    CHECK(t[1] == std::array<int, 3>{0, 2, 3});
    // A regular 12-gon (clockwise) and one with collinear points: fans as well.
    std::vector<glm::dvec3> ring;
    for (int i = 0; i < 12; ++i)
        ring.push_back({std::cos(-i * 0.5236), std::sin(-i * 0.5236), 3.0});
    const auto r = triangulatePolygon(ring);
    REQUIRE(r.size() == 10);
    for (int i = 0; i < 10; ++i)
        CHECK(r[size_t(i)] == std::array<int, 3>{0, i + 1, i + 2});
    CHECK(triangulatePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}}).size() == 2);
    CHECK(triangulatePolygon({{0, 0, 0}, {1, 0, 0}}).empty());
}

TEST_CASE("concave polygons are covered exactly once", "[raytrace][polygon]") {
    SECTION("an L") {
        checkCoverage({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, 20000);
    }
    SECTION("a comb, clockwise, reflex vertex 0") {
        std::vector<glm::dvec3> comb;
        for (int i = 0; i < 10; ++i) {
            comb.push_back({i, 3, 1});
            comb.push_back({i + 0.5, 1, 1});
        }
        comb.push_back({10, 0, 1});
        comb.push_back({0, 0, 1});
        std::reverse(comb.begin(), comb.end());
        std::rotate(comb.begin(), comb.begin() + 3, comb.end());
        checkCoverage(comb, 20000);
    }
    SECTION("every face of SPD gears 1 (144-gons)") {
        const NffDocument gears = spdGears(1);
        int faces = 0;
        for (const NffObject& o : gears.objects)
            if (o.vertices.size() == 144) {
                checkCoverage(o.vertices, 20000);
                ++faces;
            }
        CHECK(faces == 2); // top and bottom of the one gear
    }
}

TEST_CASE("self-intersecting polygons still give n - 2 triangles", "[raytrace][polygon]") {
    // A bow tie and a pentagram: no triangulation covers them; the reader must not hang.
    CHECK(triangulatePolygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}).size() == 2);
    std::vector<glm::dvec3> star;
    for (int i = 0; i < 5; ++i)
        star.push_back(
            {std::cos(i * 4 * 3.14159265358979 / 5), std::sin(i * 4 * 3.14159265358979 / 5), 0});
    CHECK(triangulatePolygon(star).size() == 3);
}

TEST_CASE("a gear face traced: rays between the teeth miss it", "[raytrace][polygon]") {
    // The fan from vertex 0 covered the gaps next to vertex 0 (white pixels where two
    // gears mesh in SPD gears 2). Shoot straight down at points of the top face's plane.
    NffDocument doc = spdGears(1);
    NffObject top;
    for (const NffObject& o : doc.objects)
        if (o.vertices.size() == 144) {
            top = o;
            break;
        }
    doc.objects = {top};
    const SceneFile sf = toScene(doc);
    const std::vector<P2> poly = xy(top.vertices);
    const double z = top.vertices[0].z;
    int hits = 0, tested = 0;
    for (int i = 0; i < 200; ++i)
        for (int j = 0; j < 200; ++j) {
            const P2 q(-1.0 + 2.0 * (i + 0.37) / 200, -1.0 + 2.0 * (j + 0.61) / 200);
            bool nearEdge = false;
            for (size_t k = 0, m = poly.size() - 1; k < poly.size() && !nearEdge; m = k++)
                nearEdge = distToSegment(poly[m], poly[k], q) < 1e-9;
            if (nearEdge) continue;
            Ray r;
            r.origin = {q.x, q.y, z + 1};
            r.direction = {0, 0, -1};
            Hit h;
            const bool hit = sf.scene->intersect(r, 0, 10, h);
            REQUIRE(hit == insidePolygon(poly, q));
            hits += hit;
            ++tested;
        }
    CHECK(hits > 0);
    CHECK(hits < tested);
}
