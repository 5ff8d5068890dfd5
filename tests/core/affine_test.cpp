// Practical 1: mirror and shadow matrices. References are independent: exact rationals
// for exercise 1.1, the course's own formulas written out literally, and long double
// ray/plane intersections for the random property tests.
#include "core/affine.h"
#include "core/homogeneous.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace wb;

namespace {

constexpr double kEps = 2.220446049250313e-16; // DBL_EPSILON

// Entries of the 3D/2D products below go through at most ~10 roundings each with
// magnitudes up to the stated scale, so 64 ulps of the scale is a generous bound
// that still fails for any wrong formula (those are off by O(1)).
bool near(double a, double b, double scale) {
    return std::abs(a - b) <= 64 * kEps * scale;
}

template <typename M> bool matNear(const M& a, const M& b, double scale) {
    for (int c = 0; c < M::length(); ++c)
        for (int r = 0; r < M::length(); ++r)
            if (!near(a[c][r], b[c][r], scale)) return false;
    return true;
}

struct Rng {
    std::mt19937_64 gen{20261121};
    double uni(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    glm::dvec3 vec3(double r) { return {uni(-r, r), uni(-r, r), uni(-r, r)}; }
    glm::dvec2 vec2(double r) { return {uni(-r, r), uni(-r, r)}; }
};

} // namespace

TEST_CASE("exercise 1.1: mirror in 3x-2y+1=0, closed form equals the exact answer") {
    const glm::dmat3 m = mirrorLine({3, -2, 1});
    // Exact: n=(3,-2), |n|²=13; 1-2A²/13 = -5/13, -2AB/13 = 12/13, -2AC/13 = -6/13,
    // 1-2B²/13 = 5/13, -2BC/13 = 4/13.
    const double exact[3][3] = {
        {-5.0 / 13, 12.0 / 13, -6.0 / 13}, {12.0 / 13, 5.0 / 13, 4.0 / 13}, {0, 0, 1}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            INFO("row " << r << " col " << c);
            CHECK(near(m[c][r], exact[r][c], 1.0));
        }
}

TEST_CASE("exercise 1.1: composite T R Mx R^-1 T^-1 equals the closed form") {
    CHECK(matNear(mirrorLineComposite({3, -2, 1}), mirrorLine({3, -2, 1}), 1.0));
    // The course's own factors: T(0,1/2) R(φ) Mx R(-φ) T(0,-1/2), φ = atan(3/2).
    const double phi = std::atan(1.5);
    const glm::dmat3 course = translation2({0, 0.5}) * rotation2(phi) * mirrorX2() *
                              rotation2(-phi) * translation2({0, -0.5});
    CHECK(matNear(course, mirrorLine({3, -2, 1}), 1.0));
    Rng rng;
    for (int i = 0; i < 1000; ++i) {
        Line2 line{rng.uni(-5, 5), rng.uni(-5, 5), rng.uni(-5, 5)};
        if (i % 10 == 0) line.a = 0; // horizontal and vertical lines take the other branch
        if (i % 10 == 1) line.b = 0;
        // The composite divides c by a or b (|·| ≥ |n|/√2), so the translation entries
        // grow to ~|c|/|n|; the scale covers that.
        const double scale = 1.0 + 4.0 * std::abs(line.c) / std::hypot(line.a, line.b);
        INFO("line " << line.a << " " << line.b << " " << line.c);
        CHECK(matNear(mirrorLineComposite(line), mirrorLine(line), scale));
    }
}

TEST_CASE("2D mirror: twice is the identity, fixes the line, midpoint on the line") {
    Rng rng;
    for (int i = 0; i < 2000; ++i) {
        const Line2 line = lineThrough(rng.vec2(10), rng.vec2(10));
        const glm::dmat3 m = mirrorLine(line);
        const double nn = std::hypot(line.a, line.b);
        CHECK(matNear(m * m, glm::dmat3(1.0), 1.0 + 4 * std::abs(line.c) / nn));
        const glm::dvec2 p = rng.vec2(10);
        const glm::dvec3 q = m * glm::dvec3(p, 1);
        REQUIRE(q.z == 1.0); // affine: the last row is exactly (0,0,1)
        // Reference in long double: signed distances of P and Q are opposite.
        const long double dp =
            ((long double)line.a * p.x + (long double)line.b * p.y + line.c) / nn;
        const long double dq =
            ((long double)line.a * q.x + (long double)line.b * q.y + line.c) / nn;
        CHECK(std::abs((double)(dp + dq)) <= 64 * kEps * 30);
        // PQ is parallel to n: cross(PQ, n) = 0.
        const double cross = (q.x - p.x) * line.b - (q.y - p.y) * line.a;
        CHECK(std::abs(cross) <= 64 * kEps * 30 * nn);
    }
}

TEST_CASE("3D mirror: twice is the identity, points of the plane are fixed, det = -1") {
    Rng rng;
    for (int i = 0; i < 2000; ++i) {
        const Plane pl{rng.vec3(3), rng.uni(-5, 5)};
        if (glm::dot(pl.n, pl.n) < 1e-6) continue;
        const glm::dmat4 m = mirrorPlane(pl);
        const double scale = 1.0 + 4 * std::abs(pl.d) / glm::length(pl.n);
        CHECK(matNear(m * m, glm::dmat4(1.0), scale));
        CHECK(near(glm::determinant(m), -1.0, scale * scale));
        // A point of the plane: P - ((n,P)+d)/(n,n) n.
        glm::dvec3 p = rng.vec3(5);
        p -= (glm::dot(pl.n, p) + pl.d) / glm::dot(pl.n, pl.n) * pl.n;
        const glm::dvec4 q = m * glm::dvec4(p, 1);
        CHECK(glm::length(glm::dvec3(q) - p) <= 64 * kEps * 20 * scale);
    }
}

// Long double reference for a shadow: the intersection of the line from `from` along
// `dir` with the plane, by the parametric formula t = -(pi·from)/(n·dir).
static glm::dvec3 intersectLD(const Plane& pl, const glm::dvec3& from, const glm::dvec3& dir) {
    long double num = pl.d, den = 0;
    for (int k = 0; k < 3; ++k) {
        num += (long double)pl.n[k] * from[k];
        den += (long double)pl.n[k] * dir[k];
    }
    const long double t = -num / den;
    return {double(from.x + t * dir.x), double(from.y + t * dir.y), double(from.z + t * dir.z)};
}

TEST_CASE("3D point-light shadow lands on the plane and on the line SP (random)") {
    Rng rng;
    int checked = 0;
    for (int i = 0; i < 5000; ++i) {
        const Plane pl{glm::normalize(rng.vec3(1)), rng.uni(-2, 2)};
        const glm::dvec3 s = rng.vec3(10), p = rng.vec3(10);
        const double ns = glm::dot(pl.n, s) + pl.d, np = glm::dot(pl.n, p) + pl.d;
        // Stay away from P level with S (shadow at infinity, tested separately): the
        // relative conditioning is |ns|/|ns-np|, keep it below 100.
        if (std::abs(ns - np) < 0.01 * std::abs(ns) || std::abs(ns) < 1e-3) continue;
        const glm::dvec4 qh = shadowPoint(pl, s) * glm::dvec4(p, 1);
        REQUIRE(qh.w != 0.0);
        const glm::dvec3 q = glm::dvec3(qh) / qh.w;
        const glm::dvec3 ref = intersectLD(pl, s, p - s);
        // |q| can be up to ~100·20 here; the error is ~cond · eps · |q|.
        const double tol = 1e-10 * (1.0 + glm::length(ref));
        CHECK(glm::length(q - ref) <= tol);
        CHECK(std::abs(glm::dot(pl.n, q) + pl.d) <= tol);
        // On the line through S and P: (Q-S) x (P-S) = 0.
        CHECK(glm::length(glm::cross(q - s, p - s)) <= tol * glm::length(p - s));
        // Between the light and the plane (same side, P nearer the plane) => w > 0, as
        // OpenGL needs (see affine.h).
        if (ns * np > 0 && std::abs(np) < std::abs(ns)) CHECK(qh.w > 0);
        ++checked;
    }
    CHECK(checked > 4000);
}

TEST_CASE("3D point-light shadow is -sign(pi.S) times the course's matrix of practical 1.3") {
    const Plane pl{{1, 2, -2}, 3};
    const glm::dvec3 s{4, -1, 7};
    const double a = pl.n.x, b = pl.n.y, c = pl.n.z, d = pl.d;
    const double ns = glm::dot(pl.n, s);
    // Written out as in the seed, rows top to bottom.
    const double course[4][4] = {{a * s.x - d - ns, b * s.x, c * s.x, d * s.x},
                                 {a * s.y, b * s.y - d - ns, c * s.y, d * s.y},
                                 {a * s.z, b * s.z, c * s.z - d - ns, d * s.z},
                                 {a, b, c, -ns}};
    const glm::dmat4 m = shadowPoint(pl, s);
    REQUIRE(ns + d == -9.0); // light on the negative side: the course's sign is kept
    for (int r = 0; r < 4; ++r)
        for (int col = 0; col < 4; ++col)
            CHECK(m[col][r] == course[r][col]); // small integers: exact
    // Flip the plane's orientation: the course's matrix changes sign (it is linear in
    // A..D), ours does not, so w stays positive between the light and the plane.
    const glm::dmat4 f = shadowPoint({-pl.n, -pl.d}, s);
    for (int r = 0; r < 4; ++r)
        for (int col = 0; col < 4; ++col)
            CHECK(f[col][r] == m[col][r]);
    // Light on the positive side: minus the course's matrix.
    const glm::dvec3 s2{0, 0, -5}; // (n,s2)+d = 10+3 > 0
    const double ns2 = glm::dot(pl.n, s2);
    const glm::dmat4 m2 = shadowPoint(pl, s2);
    CHECK(m2[0][0] == -(a * s2.x - d - ns2));
    CHECK(m2[3][3] == ns2);
    CHECK(m2[2][3] == -c);
    CHECK(m2[3][2] == -d * s2.z);
}

TEST_CASE("3D directional shadow equals the course's matrix of practical 1.2 and lands right") {
    const Plane pl{{0, 1, 0}, 0.5};
    const glm::dvec3 l{1, -2, 0.5};
    const glm::dmat4 m = shadowDirectional(pl, l);
    // Practical 1.2 written out: entries 1 - A l_x/(n,l), -B l_x/(n,l), ... with (n,l) = -2.
    CHECK(m[0][0] == 1.0);
    CHECK(m[1][0] == 0.5);  // -B lx/(n,l) = -1*1/(-2)
    CHECK(m[1][1] == 0.0);  // 1 - B ly/(n,l) = 1 - (-2)/(-2)
    CHECK(m[1][2] == 0.25); // -B lz/(n,l)
    CHECK(m[3][1] == -0.5); // -D ly/(n,l) = -0.5*(-2)/(-2)
    CHECK(m[3][0] == 0.25); // -D lx/(n,l)
    CHECK(m[3][3] == 1.0);
    Rng rng;
    for (int i = 0; i < 5000; ++i) {
        const Plane p2{glm::normalize(rng.vec3(1)), rng.uni(-2, 2)};
        const glm::dvec3 dir = glm::normalize(rng.vec3(1)), p = rng.vec3(10);
        if (std::abs(glm::dot(p2.n, dir)) < 0.01) continue; // grazing: cond > 100
        const glm::dvec4 qh = shadowDirectional(p2, dir) * glm::dvec4(p, 1);
        REQUIRE(qh.w == 1.0);
        const glm::dvec3 q(qh);
        const glm::dvec3 ref = intersectLD(p2, p, dir);
        const double tol = 1e-11 * (1.0 + glm::length(ref));
        CHECK(glm::length(q - ref) <= tol);
        CHECK(std::abs(glm::dot(p2.n, q) + p2.d) <= tol);
        CHECK(glm::length(glm::cross(q - p, dir)) <= tol);
    }
}

TEST_CASE("hard case: point light ON the shadow plane collapses the shadow into the light") {
    const Plane pl{{0, 0, 2}, -4}; // z = 2
    const glm::dvec3 s{1, -3, 2};  // on the plane
    const glm::dmat4 m = shadowPoint(pl, s);
    Rng rng;
    for (int i = 0; i < 1000; ++i) {
        glm::dvec3 p = rng.vec3(10);
        if (std::abs(p.z - 2) < 1e-3) continue;
        const glm::dvec4 q = m * glm::dvec4(p, 1);
        REQUIRE(q.w != 0.0);
        // Reference: every ray from S meets the plane at S (t = 0), exactly.
        CHECK(glm::length(glm::dvec3(q) / q.w - s) <= 16 * kEps * 10);
    }
    // A point of the plane maps to the zero vector (no point), never to NaN.
    const glm::dvec4 z = m * glm::dvec4(5, 7, 2, 1);
    CHECK(z == glm::dvec4(0.0));
}

TEST_CASE("hard case: 2D point light ON the line collapses the shadow into the light") {
    const Line2 line = lineThrough({-1, -1}, {3, 1});
    const glm::dvec2 s{1, 0}; // on the line: exactly representable, pi·S = 0 exactly
    REQUIRE(line.a * s.x + line.b * s.y + line.c == 0.0);
    const ProjectedPoints<glm::dvec2> out =
        transformPoints(shadowLinePoint(line, s), {{0, 5}, {-3, 2}, {7, 4}, {4, -6}});
    for (std::size_t i = 0; i < 4; ++i) {
        REQUIRE(out.kinds[i] == PointKind::Finite);
        CHECK(glm::length(out.points[i] - s) <= 16 * kEps * 10);
    }
    // A point on the line itself: the zero vector, reported Undefined.
    const ProjectedPoints<glm::dvec2> on = transformPoints(shadowLinePoint(line, s), {{3, 1}});
    CHECK(on.kinds[0] == PointKind::Undefined);
}

TEST_CASE("hard case: P level with the light and light parallel to the plane give w = 0") {
    const Plane pl{{0, 1, 0}, 0};
    const glm::dvec4 q = shadowPoint(pl, {0, 3, 0}) * glm::dvec4(5, 3, -1, 1);
    CHECK(q.w == 0.0);
    CHECK(glm::length(glm::dvec3(q)) > 0);                 // a direction: the point at infinity
    const glm::dmat4 m = shadowDirectional(pl, {1, 0, 0}); // rays parallel to y = 0
    const glm::dvec4 r = m * glm::dvec4(2, 1, 3, 1);
    CHECK(r.w == 0.0);
    CHECK(r == glm::dvec4(1, 0, 0, 0)); // along l, scaled by (n,P)+d = 1
    const glm::dmat3 m2 = shadowLineDirectional({0, 1, 0}, {1, 0});
    CHECK((m2 * glm::dvec3(2, 3, 1)).z == 0.0);
}

TEST_CASE("2D shadows land on the line and on the line through the light (random)") {
    Rng rng;
    for (int i = 0; i < 5000; ++i) {
        const Line2 line = lineThrough(rng.vec2(5), rng.vec2(5));
        const double nn = std::hypot(line.a, line.b);
        if (nn < 0.1) continue;
        const glm::dvec2 s = rng.vec2(10), l = rng.vec2(1), p = rng.vec2(10);
        const double ls = line.a * s.x + line.b * s.y + line.c;
        const double lp = line.a * p.x + line.b * p.y + line.c;
        // Embed in 3D (z free) and reuse the long double reference: the line is the
        // plane a x + b y + c = 0.
        const Plane pl{{line.a, line.b, 0}, line.c};
        if (std::abs(ls - lp) > 0.01 * std::abs(ls) && std::abs(ls) > 1e-3 * nn) {
            const glm::dvec3 qh = shadowLinePoint(line, s) * glm::dvec3(p, 1);
            const glm::dvec2 q = glm::dvec2(qh) / qh.z;
            const glm::dvec3 ref = intersectLD(pl, {s, 0}, {p - s, 0});
            const double tol = 1e-10 * (1 + glm::length(ref));
            CHECK(glm::length(q - glm::dvec2(ref)) <= tol);
            // On Λ and on the line through S and P, checked directly as well.
            CHECK(std::abs(line.a * q.x + line.b * q.y + line.c) <= tol * nn);
            const glm::dvec2 sq = q - s, sp = p - s;
            CHECK(std::abs(sq.x * sp.y - sq.y * sp.x) <= tol * glm::length(sp));
        }
        if (std::abs(line.a * l.x + line.b * l.y) > 0.01 * nn * glm::length(l)) {
            const glm::dvec3 qh = shadowLineDirectional(line, l) * glm::dvec3(p, 1);
            REQUIRE(qh.z == 1.0);
            const glm::dvec3 ref = intersectLD(pl, {p, 0}, {l, 0});
            CHECK(glm::length(glm::dvec2(qh) - glm::dvec2(ref)) <= 1e-11 * (1 + glm::length(ref)));
        }
    }
}

TEST_CASE("bad input throws a clear error") {
    CHECK_THROWS_WITH(mirrorLine({0, 0, 1}),
                      Catch::Contains("mirrorLine") && Catch::Contains("normal"));
    CHECK_THROWS_AS(mirrorPlane({{0, 0, 0}, 1}), std::invalid_argument);
    CHECK_THROWS_AS(shadowPoint({{0, 0, 0}, 1}, {0, 1, 0}), std::invalid_argument);
    CHECK_THROWS_WITH(shadowDirectional({{0, 1, 0}, 0}, {0, 0, 0}), Catch::Contains("l is zero"));
    CHECK_THROWS_AS(shadowLineDirectional({1, 0, 0}, {0, 0}), std::invalid_argument);
    CHECK_THROWS_AS(mirrorLine({NAN, 1, 0}), std::invalid_argument);
    CHECK_THROWS_WITH(lineThrough({1, 2}, {1, 2}), Catch::Contains("coincide"));
}

TEST_CASE("batched transform: one 3xn product equals the point-by-point products") {
    Rng rng;
    std::vector<glm::dvec2> pts;
    for (int i = 0; i < 1000; ++i)
        pts.push_back(rng.vec2(10));
    const glm::dmat3 m = shadowLinePoint(lineThrough({-3, 1}, {4, -2}), {0.5, 6});
    const HomogeneousColumns<3> h = multiply(m, toHomogeneous(pts));
    REQUIRE(h.cols == pts.size());
    REQUIRE(h.data.size() == 3 * pts.size());
    const ProjectedPoints<glm::dvec2> out = transformPoints(m, pts);
    for (std::size_t j = 0; j < pts.size(); ++j) {
        const glm::dvec3 ref = m * glm::dvec3(pts[j], 1); // GLM's own product, the reference
        // Same three products and two sums per entry; only the summation order may
        // differ, so a few ulps of the largest term.
        const double scale = 4 * kEps * (1 + glm::length(ref) + 100);
        for (int r = 0; r < 3; ++r)
            CHECK(std::abs(h.at(r, j) - ref[r]) <= scale);
        if (ref.z != 0) {
            REQUIRE(out.kinds[j] == PointKind::Finite);
            CHECK(glm::length(out.points[j] - glm::dvec2(ref) / ref.z) <=
                  1e-12 * (1 + glm::length(glm::dvec2(ref) / ref.z)));
        }
    }
    CHECK(out.atInfinity == 0);
    CHECK(out.undefined == 0);
    // 4x4 version against GLM too.
    std::vector<glm::dvec3> p3;
    for (int i = 0; i < 100; ++i)
        p3.push_back(rng.vec3(5));
    const glm::dmat4 m4 = mirrorPlane({{1, 2, 3}, 4});
    const ProjectedPoints<glm::dvec3> o3 = transformPoints(m4, p3);
    for (std::size_t j = 0; j < p3.size(); ++j)
        CHECK(glm::length(o3.points[j] - glm::dvec3(m4 * glm::dvec4(p3[j], 1))) <= 64 * kEps * 20);
}

TEST_CASE("batched transform: w = 0 gives a direction, the zero vector Undefined, never NaN") {
    HomogeneousColumns<3> h;
    h.cols = 6;
    h.data = {3,     4,     0,      // w = 0: direction (0.6, 0.8)
              1,     1,     1e-320, // x/w overflows: at infinity along (1,1)/√2
              0,     0,     0,      // not a point
              2,     -4,    -2,     // w < 0 is an ordinary point: (-1, 2)
              NAN,   1,     1,      // bad input
              1e300, 1e300, 0};     // huge direction: normalised without overflow
    const ProjectedPoints<glm::dvec2> p = dehomogenize(h);
    REQUIRE(p.points.size() == 6);
    CHECK(p.kinds[0] == PointKind::AtInfinity);
    CHECK(glm::length(p.points[0] - glm::dvec2(0.6, 0.8)) <= 2 * kEps);
    CHECK(p.kinds[1] == PointKind::AtInfinity);
    CHECK(glm::length(p.points[1] - glm::dvec2(1, 1) / std::sqrt(2.0)) <= 2 * kEps);
    CHECK(p.kinds[2] == PointKind::Undefined);
    CHECK(p.points[2] == glm::dvec2(0, 0));
    CHECK(p.kinds[3] == PointKind::Finite);
    CHECK(p.points[3] == glm::dvec2(-1, 2));
    CHECK(p.kinds[4] == PointKind::Undefined);
    CHECK(p.kinds[5] == PointKind::AtInfinity);
    CHECK(glm::length(p.points[5] - glm::dvec2(1, 1) / std::sqrt(2.0)) <= 2 * kEps);
    CHECK(p.atInfinity == 3);
    CHECK(p.undefined == 2);
    for (const glm::dvec2& v : p.points)
        CHECK((std::isfinite(v.x) && std::isfinite(v.y)));
}

TEST_CASE("batched transform of a shadow with the light on the plane: S or Undefined") {
    const Plane pl{{0, 1, 0}, 0};
    const glm::dvec3 s{2, 0, -1};
    const std::vector<glm::dvec3> pts{{0, 1, 0}, {3, 2, 1}, {5, 0, 5}, {1, -1, 1}};
    const ProjectedPoints<glm::dvec3> out = transformPoints(shadowPoint(pl, s), pts);
    CHECK(out.kinds[0] == PointKind::Finite);
    CHECK(out.points[0] == s);
    CHECK(out.points[1] == s);
    CHECK(out.kinds[2] == PointKind::Undefined); // on the plane: the zero vector
    CHECK(out.points[3] == s);                   // below the plane: also S
    CHECK(out.undefined == 1);
}
