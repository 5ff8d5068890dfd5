// Bezier maths of practical 10 against independent references: long double sums
// with a separately built Pascal triangle, finite differences of a long double
// evaluation, exact rational control points, and published circle-arc errors.
#include "core/bezier.h"
#include "core/bezier_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

using namespace wb;
using glm::dvec3;

namespace {

using LVec = std::array<long double, 3>;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Reference: the Bernstein sum in long double, binomials from Pascal's triangle
// (a different construction from core's multiplicative formula).
LVec refEval(const BezierCurve& p, long double u) {
    const int k = int(p.size()) - 1;
    std::vector<long double> row{1.0L};
    for (int n = 1; n <= k; ++n) {
        std::vector<long double> next(size_t(n) + 1, 1.0L);
        for (int i = 1; i < n; ++i)
            next[size_t(i)] = row[size_t(i) - 1] + row[size_t(i)];
        row = next;
    }
    LVec q{0, 0, 0};
    for (int i = 0; i <= k; ++i) {
        const long double b =
            row[size_t(i)] * std::pow(u, (long double)i) * std::pow(1.0L - u, (long double)(k - i));
        for (int c = 0; c < 3; ++c)
            q[size_t(c)] += b * (long double)p[size_t(i)][c];
    }
    return q;
}

double dist(const dvec3& a, const LVec& b) {
    long double s = 0;
    for (int c = 0; c < 3; ++c) {
        const long double d = (long double)a[c] - b[size_t(c)];
        s += d * d;
    }
    return double(std::sqrt(s));
}

double maxNorm(const BezierCurve& p) {
    double m = 0;
    for (const auto& q : p)
        m = std::max(m, glm::length(q));
    return m;
}

BezierCurve randomCurve(std::mt19937& rng, int degree) {
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    BezierCurve p(size_t(degree) + 1);
    for (auto& q : p)
        q = {d(rng), d(rng), d(rng)};
    return p;
}

} // namespace

TEST_CASE("Bernstein polynomials: Theorem 0.1 and exact values", "[bezier]") {
    CHECK(bernstein(3, 0, 0.0) == 1.0);
    CHECK(bernstein(3, 3, 1.0) == 1.0);
    CHECK(bernstein(3, 1, 0.0) == 0.0);
    CHECK(bernstein(3, 4, 0.5) == 0.0);
    CHECK(bernstein(4, 2, 0.5) == 6.0 / 16.0); // C(4,2)/2^4, exact in binary
    CHECK(binomial(20, 10) == 184756.0);
    CHECK(binomial(50, 25) == 126410606437752.0);
    for (int k = 1; k <= 20; ++k)
        for (double u : {0.0, 1e-12, 0.25, 0.5, 0.7, 1.0 - 1e-12, 1.0}) {
            double sum = 0;
            for (int i = 0; i <= k; ++i) {
                CHECK(bernstein(k, i, u) >= 0.0);
                sum += bernstein(k, i, u);
            }
            // k+1 terms, each with ~(k+3) roundings of relative size eps.
            CHECK(std::abs(sum - 1.0) <= double((k + 1) * (k + 3)) * kEps);
        }
}

TEST_CASE("Bernstein polynomials of very high degree stay finite", "[bezier]") {
    // C(2000, 1000) overflows a double; the central term is ~ sqrt(2/(π·2000)) by Stirling
    // (relative error 1/(8·1000) from the next Stirling term).
    CHECK(bernstein(2000, 1000, 0.5) == Approx(std::sqrt(2.0 / (M_PI * 2000.0))).epsilon(2e-4));
    for (double u : {0.0, 1e-12, 0.3, 1.0}) {
        double sum = 0.0;
        for (int i = 0; i <= 2000; ++i) {
            const double b = bernstein(2000, i, u);
            REQUIRE(std::isfinite(b));
            sum += b;
        }
        // lgamma and exp in double: relative ~1e-13 per term near the peak (log values ~1e4).
        CHECK(sum == Approx(1.0).epsilon(1e-9));
    }
    // Across the switch to logarithms (degree 500 -> 501) the values agree.
    CHECK(bernstein(501, 200, 0.4) ==
          Approx(bernstein(500, 200, 0.4) * 0.6 + bernstein(500, 199, 0.4) * 0.4).epsilon(1e-10));
    // Outside [0, 1] the polynomial keeps its sign pattern: B_1^3(-1) = 3·(-1)·4 = -12.
    CHECK(bernstein(3, 1, -1.0) == -12.0);
    CHECK(bernstein(600, 1, -1e-3) < 0.0);
}

TEST_CASE("Bezier at u = 0, 1 and 1e-12", "[bezier]") {
    const BezierCurve p{{0.3, -1.7, 2.0}, {4.0, 1.0, -2.0}, {-3.0, 2.5, 0.5}, {1.25, 1.5, -0.75}};
    for (auto eval : {evalBernstein, evalDeCasteljau}) {
        CHECK(eval(p, 0.0) == p.front()); // Theorem 0.1(a): the ends are interpolated exactly
        CHECK(eval(p, 1.0) == p.back());
        const dvec3 q = eval(p, 1e-12);
        // Independent: q(u) = p0 + u·3(p1-p0) + O(u²), so at u = 1e-12 the offset from p0
        // is 3e-12·(p1-p0) to relative 1e-12; the double result can only resolve it to eps·|p0|.
        const dvec3 expected = p[0] + 1e-12 * 3.0 * (p[1] - p[0]);
        CHECK(glm::length(q - expected) <= 4.0 * kEps * maxNorm(p));
        CHECK(dist(q, refEval(p, 1e-12L)) <= 4.0 * kEps * maxNorm(p));
        CHECK(q != p[0]); // the step is resolved, not lost
    }
}

TEST_CASE("de Casteljau against Bernstein up to degree 20, long double reference", "[bezier]") {
    std::mt19937 rng(20261121);
    std::uniform_real_distribution<double> ud(0.0, 1.0);
    for (int k = 1; k <= 20; ++k)
        for (int trial = 0; trial < 20; ++trial) {
            const BezierCurve p = randomCurve(rng, k);
            const double m = maxNorm(p);
            for (int s = 0; s < 25; ++s) {
                const double u =
                    s < 5 ? std::vector<double>{0.0, 1e-12, 0.5, 1.0 - 1e-12, 1.0}[size_t(s)]
                          : ud(rng);
                const LVec ref = refEval(p, (long double)u);
                // de Casteljau: k levels of convex combinations, each adding at most
                // ~2 eps·max|p| (a rounding in the product and one in the sum).
                CHECK(dist(evalDeCasteljau(p, u), ref) <= 2.0 * k * kEps * m + 1e-300);
                // Bernstein: each term carries ~(k+3) roundings (binomial, two pows, product)
                // and the B_i sum to 1, so the error is bounded by (k+4)·eps·max|p|.
                CHECK(dist(evalBernstein(p, u), ref) <= double(k + 4) * kEps * m + 1e-300);
            }
        }
}

TEST_CASE("Subdivision at any u0: the halves reproduce the curve", "[bezier]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ud(0.0, 1.0);
    for (int k = 1; k <= 12; ++k)
        for (double u0 : {0.5, 0.25, 0.9, 1e-12, 1.0 - 1e-9, 0.0, 1.0}) {
            const BezierCurve p = randomCurve(rng, k);
            const auto [left, right] = subdivide(p, u0);
            REQUIRE(left.size() == p.size());
            REQUIRE(right.size() == p.size());
            CHECK(left.front() == p.front());
            CHECK(right.back() == p.back());
            CHECK(glm::length(left.back() - right.front()) == 0.0); // both are p_0^k(u0)
            for (int s = 0; s <= 16; ++s) {
                const double t = s / 16.0;
                // Each side is k+1 de Casteljau levels away from the reference value:
                // 4k·eps·max|p| covers both evaluations.
                const double tol = 4.0 * k * kEps * maxNorm(p);
                CHECK(dist(evalDeCasteljau(left, t), refEval(p, (long double)u0 * t)) <= tol);
                CHECK(dist(evalDeCasteljau(right, t), refEval(p, u0 + (1.0L - u0) * t)) <= tol);
            }
        }
}

TEST_CASE("Degree elevation leaves the curve unchanged", "[bezier]") {
    // The seed's example: a quadratic with integer points elevated to a cubic,
    // p̂1 = p0/3 + 2p1/3, p̂2 = 2p1/3 + p2/3 (exact in thirds, checked to 1 ulp).
    const BezierCurve q{{0, 0, 0}, {3, 6, 0}, {6, 0, 3}};
    const BezierCurve c = elevateDegree(q);
    REQUIRE(c.size() == 4);
    CHECK(c[0] == q[0]);
    CHECK(c[3] == q[2]);
    CHECK(glm::length(c[1] - dvec3(2, 4, 0)) <= 8 * kEps);
    CHECK(glm::length(c[2] - dvec3(4, 4, 1)) <= 8 * kEps);

    std::mt19937 rng(11);
    for (int k = 0; k <= 15; ++k) {
        const BezierCurve p = randomCurve(rng, k);
        BezierCurve e = p;
        for (int times = 0; times < 5; ++times)
            e = elevateDegree(e);
        REQUIRE(e.size() == p.size() + 5);
        for (int s = 0; s <= 20; ++s) {
            const double u = s / 20.0;
            // Elevation is a convex combination per step (eps·max|p| each) plus the
            // evaluation of degree k+5: (2(k+5) + 10)·eps·max|p|.
            CHECK(dist(evalDeCasteljau(e, u), refEval(p, u)) <=
                  (2.0 * (k + 5) + 10.0) * kEps * maxNorm(p));
        }
    }
}

TEST_CASE("Derivatives against finite differences of a long double evaluation", "[bezier]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ud(0.0, 1.0);
    for (int k = 1; k <= 10; ++k)
        for (int trial = 0; trial < 10; ++trial) {
            const BezierCurve p = randomCurve(rng, k);
            // Corollary 0.3, exactly: q'(0) = k(p1 - p0), q'(1) = k(pk - pk-1).
            CHECK(evalDerivative(p, 0.0) == double(k) * (p[1] - p[0]));
            CHECK(evalDerivative(p, 1.0) == double(k) * (p[size_t(k)] - p[size_t(k) - 1]));
            const long double h = 1e-5L;
            for (double u : {0.0, 1e-12, 0.3, ud(rng), 1.0}) {
                const LVec a = refEval(p, u + h), b = refEval(p, u - h), c = refEval(p, u);
                LVec d1, d2;
                for (size_t i = 0; i < 3; ++i) {
                    d1[i] = (a[i] - b[i]) / (2 * h);
                    d2[i] = (a[i] - 2 * c[i] + b[i]) / (h * h);
                }
                // Central differences: truncation h²/6·|q'''| <= 1e-10·k³·2^k·max|p| (the
                // derivative bound), rounding 1e-19/h² = 1e-9 for the second one (long
                // double eps 1.1e-19); the limits below have a factor ~10 to spare.
                const double scale = std::pow(2.0, k) * k * k * k * maxNorm(p);
                CHECK(dist(evalDerivative(p, u, 1), d1) <= 1e-9 * scale);
                CHECK(dist(evalDerivative(p, u, 2), d2) <= 1e-6 * scale);
            }
            CHECK(evalDerivative(p, 0.4, k + 1) == dvec3(0.0)); // above the degree
        }
    // The hodograph of an elevated curve is the elevated hodograph.
    const BezierCurve p{{0, 0, 0}, {1, 2, 0}, {3, -1, 1}, {4, 0, 0}};
    for (double u : {0.1, 0.5, 0.8})
        CHECK(glm::length(evalDerivative(elevateDegree(p), u) - evalDerivative(p, u)) <= 1e-13);
}

TEST_CASE("Seeded random properties: convex hull, endpoints, symmetry", "[bezier]") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> ud(0.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
        const int k = 1 + int(rng() % 15);
        const BezierCurve p = randomCurve(rng, k);
        const double u = ud(rng);
        const dvec3 q = evalDeCasteljau(p, u);
        dvec3 lo(1e9), hi(-1e9);
        for (const auto& c : p)
            lo = glm::min(lo, c), hi = glm::max(hi, c);
        // Theorem 0.1 (b, c): a convex combination stays in the bounding box.
        CHECK(glm::all(glm::greaterThanEqual(q, lo - 1e-15)));
        CHECK(glm::all(glm::lessThanEqual(q, hi + 1e-15)));
        // Reversing the control points reverses the parameter.
        BezierCurve r(p.rbegin(), p.rend());
        CHECK(glm::length(evalDeCasteljau(r, 1.0 - u) - q) <= 4.0 * k * kEps * maxNorm(p));
        // Subdividing at u puts the split point on the curve.
        CHECK(glm::length(subdivide(p, u).first.back() - q) <= 4.0 * k * kEps * maxNorm(p));
    }
}

TEST_CASE("Patch evaluation: bilinear and planar patches, long double reference", "[bezier]") {
    // A 2×2 net is the bilinear patch; a flat net has the plane's normal everywhere.
    BezierPatch b{2, 2, {{0, 0, 0}, {2, 0, 1}, {0, 3, 0}, {2, 3, 4}}};
    const PatchSample s = evalPatch(b, 0.25, 0.5);
    const dvec3 bilinear = 0.75 * 0.5 * b.at(0, 0) + 0.25 * 0.5 * b.at(1, 0) +
                           0.75 * 0.5 * b.at(0, 1) + 0.25 * 0.5 * b.at(1, 1);
    CHECK(glm::length(s.point - bilinear) <= 1e-15);
    CHECK(glm::length(s.du - (0.5 * (b.at(1, 0) - b.at(0, 0)) + 0.5 * (b.at(1, 1) - b.at(0, 1)))) <=
          1e-15);

    BezierPatch flat{4, 3, {}};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i)
            flat.points.push_back({i * 1.0 + 0.1 * j * j, j * 2.0 - 0.3 * i, 5.0});
    for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.6, 1.0}) {
            const PatchSample f = evalPatch(flat, u, v);
            CHECK(f.normalKind == 0);
            CHECK(glm::length(f.normal - dvec3(0, 0, 1)) <= 1e-14);
        }

    // The lab's net against a long double double sum.
    const BezierPatch net = labHemisphereNet();
    for (double u : {0.0, 1e-12, 0.37, 0.5, 1.0})
        for (double v : {0.0, 0.81, 1.0}) {
            LVec ref{0, 0, 0};
            for (int j = 0; j < 4; ++j) {
                BezierCurve row;
                for (int i = 0; i < 4; ++i)
                    row.push_back(net.at(i, j));
                const LVec r = refEval(row, u);
                const long double bj = std::vector<long double>{1, 3, 3, 1}[size_t(j)] *
                                       std::pow((long double)v, j) * std::pow(1.0L - v, 3 - j);
                for (size_t c = 0; c < 3; ++c)
                    ref[c] += bj * r[c];
            }
            // Two nested cubic de Casteljau evaluations on coordinates <= 5: 12 eps·|p|·2.
            CHECK(dist(evalPatch(net, u, v).point, ref) <= 24 * kEps * 5.0 * std::sqrt(3.0));
        }
}

TEST_CASE("Patch partial derivatives against finite differences", "[bezier]") {
    const BezierPatch net = labHemisphereNet();
    const double h = 1e-6;
    for (double u : {0.1, 0.5, 0.77})
        for (double v : {0.2, 0.5, 0.9}) {
            const PatchSample s = evalPatch(net, u, v);
            const dvec3 fu =
                (evalPatch(net, u + h, v).point - evalPatch(net, u - h, v).point) / (2 * h);
            const dvec3 fv =
                (evalPatch(net, u, v + h).point - evalPatch(net, u, v - h).point) / (2 * h);
            // h² truncation (~1e-11 here) plus eps·|p|/h ≈ 1e-9 of rounding.
            CHECK(glm::length(s.du - fu) <= 1e-8);
            CHECK(glm::length(s.dv - fv) <= 1e-8);
            CHECK(std::abs(glm::length(s.normal) - 1.0) <= 1e-14);
        }
}

TEST_CASE("Patch normals stay defined at a pole and at tangent corners", "[bezier]") {
    // A cap: row 0 of the net collapses to the pole (0, 0, 1); du vanishes along v = 0.
    BezierPatch cap{4, 3, {}};
    const double pts[4][2] = {{1, 0}, {1, 1}, {-1, 1}, {-1, 0}};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            const double r = j * 0.5, z = 1.0 - 0.5 * j * j / 2.0;
            cap.points.push_back({r * pts[i][0], r * pts[i][1], z});
        }
    for (double u : {0.0, 0.2, 0.5, 1.0}) {
        const PatchSample pole = evalPatch(cap, u, 0.0);
        CHECK(glm::length(pole.du) == 0.0);
        CHECK(pole.normalKind == 1);
        CHECK(std::abs(glm::length(pole.normal) - 1.0) <= 1e-14);
        // The limit from inside: the normal a little way off the pole.
        const PatchSample near = evalPatch(cap, u, 1e-7);
        CHECK(near.normalKind == 0);
        CHECK(glm::length(pole.normal - near.normal) <= 1e-5);
    }
    // The same cap with u and v swapped: now a column collapses and dv vanishes along
    // u = 0. Swapping the parameters flips du × dv, so the normal must be the negated one.
    BezierPatch capT{3, 4, {}};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 3; ++i)
            capT.points.push_back(cap.at(j, i));
    for (double v : {0.0, 0.3, 1.0}) {
        const PatchSample pole = evalPatch(capT, 0.0, v);
        CHECK(glm::length(pole.dv) == 0.0);
        CHECK(pole.normalKind == 1);
        CHECK(glm::length(pole.normal + evalPatch(cap, v, 0.0).normal) <= 1e-14);
        CHECK(glm::length(pole.normal - evalPatch(capT, 1e-7, v).normal) <= 1e-5);
    }
    // The lab's hemisphere: at its corners the two boundary curves are tangent
    // (du ∥ dv), du × dv = 0, yet the normal must point out of the sphere, along (±1, ±1, 0).
    const BezierPatch net = labHemisphereNet();
    for (double u : {0.0, 1.0})
        for (double v : {0.0, 1.0}) {
            const PatchSample c = evalPatch(net, u, v);
            CHECK(glm::length(glm::cross(c.du, c.dv)) <= 1e-12);
            CHECK(c.normalKind == 1);
            CHECK(glm::dot(c.normal, glm::normalize(c.point)) > 0.9);
            CHECK(std::abs(c.normal.z) < 0.1);
        }
    // Everything in one point: no direction exists, but a defined one is returned.
    BezierPatch dot{3, 3, std::vector<dvec3>(9, dvec3(1, 2, 3))};
    const PatchSample d = evalPatch(dot, 0.5, 0.5);
    CHECK(d.normalKind == 2);
    CHECK(d.normal == dvec3(0, 0, 1));
}

TEST_CASE("Bad input gives clear errors", "[bezier]") {
    CHECK_THROWS_AS(evalDeCasteljau({}, 0.5), std::invalid_argument);
    CHECK_THROWS_AS(evalBernstein({}, 0.5), std::invalid_argument);
    CHECK_THROWS_WITH(evalDeCasteljau({{0, 0, 0}}, std::nan("")),
                      Catch::Contains("not a finite number"));
    CHECK_THROWS_AS(subdivide({{0, 0, 0}}, INFINITY), std::invalid_argument);
    CHECK_THROWS_AS(evalDerivative({{0, 0, 0}}, 0.5, -1), std::invalid_argument);
    CHECK_THROWS_WITH(evalPatch(BezierPatch{3, 3, {}}, 0.5, 0.5),
                      Catch::Contains("needs 9 points, got 0"));
    CHECK_THROWS_AS(evalPatch(BezierPatch{0, 3, {}}, 0.5, 0.5), std::invalid_argument);
    CHECK_THROWS_AS(circleArcs(1, 1.0), std::invalid_argument);
    CHECK_THROWS_AS(circleArcs(4, -1.0), std::invalid_argument);
    CHECK_THROWS_AS(meshRadialError({labHemisphereNet()}, 1.0, 0), std::invalid_argument);
    // A degree-0 curve is a point: defined value, zero derivative.
    CHECK(evalDeCasteljau({{1, 2, 3}}, 0.4) == dvec3(1, 2, 3));
    CHECK(evalDerivative({{1, 2, 3}}, 0.4) == dvec3(0.0));
}

TEST_CASE("Circle arcs: the published errors of the cubic approximation", "[bezier][shapes]") {
    CHECK(circleHandle(2) == Approx(4.0 / 3.0).epsilon(1e-15));
    CHECK(circleHandle(4) == Approx(0.5522847498307936).epsilon(1e-15)); // 4/3(√2 - 1)
    // Quarter arcs with k = 4/3·tan(π/8): max radial error 2.7253e-4 (the classic
    // figure, e.g. Riškus 2006 / Goldapp 1991), all outward; the arc ends and midpoint lie on the
    // circle.
    const RadialError q = curvesRadialError(circleArcs(4, circleHandle(4)), 1.0);
    CHECK(q.maxError == Approx(2.7253e-4).epsilon(1e-4));
    CHECK(q.minRadius == Approx(1.0).margin(1e-15));
    // The minimax handle for quarter arcs is 0.551915 with error 1.9608e-4 (same sources).
    const double kf = fitCircleHandle(4);
    CHECK(kf == Approx(0.551915).epsilon(2e-6));
    CHECK(curvesRadialError(circleArcs(4, kf), 1.0).maxError == Approx(1.9608e-4).epsilon(1e-3));
    // Error falls like θ⁶: halving the arc angle divides it by ~64.
    const double e2 = curvesRadialError(circleArcs(2, circleHandle(2)), 1.0).maxError;
    const double e8 = curvesRadialError(circleArcs(8, circleHandle(8)), 1.0).maxError;
    CHECK(e2 > q.maxError * 30);
    CHECK(q.maxError / e8 == Approx(64).epsilon(0.1));
}

TEST_CASE("Polyline and mesh radial errors are exact on simple shapes", "[bezier][shapes]") {
    // The segment from (1,0) to (0,1): nearest point to the origin is its midpoint, 1/√2.
    const std::vector<BezierCurve> line{{{1, 0, 0}, {0, 1, 0}}};
    const RadialError l = polylineRadialError(line, 1.0, 1);
    CHECK(l.minRadius == Approx(std::sqrt(0.5)).epsilon(1e-15));
    CHECK(l.maxRadius == 1.0);
    CHECK(l.maxError == Approx(1.0 - std::sqrt(0.5)).epsilon(1e-14));
    // A flat square at z = 1: nearest point (0,0,1), farthest the corners at √3.
    BezierPatch sq{2, 2, {{-1, -1, 1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, 1}}};
    const RadialError m = meshRadialError({sq}, 0.0, 3);
    CHECK(m.minRadius == Approx(1.0).epsilon(1e-14));
    CHECK(m.maxRadius == Approx(std::sqrt(3.0)).epsilon(1e-14));
    CHECK(m.radius == Approx(0.5 * (1.0 + std::sqrt(3.0))).epsilon(1e-14));
    // A fine polyline of the quarter-arc circle: chord sag 1 - cos(π/(4n)) dominates.
    const auto arcs = circleArcs(4, circleHandle(4));
    const RadialError p = polylineRadialError(arcs, 1.0, 8);
    CHECK(p.maxError == Approx(1.0 - std::cos(M_PI / 32)).epsilon(0.05));
    CHECK(polylineRadialError(arcs, 1.0, 256).maxError == Approx(2.7253e-4).epsilon(0.01));
}

TEST_CASE("Lab 6 sphere: course net, mirror patch and fitted net", "[bezier][shapes]") {
    const BezierPatch net = labHemisphereNet();
    CHECK(net.at(1, 1) == dvec3(2, -3, 5)); // the seed's table, row 2, column 2
    CHECK(net.at(0, 3) == dvec3(-2, -2, 0));
    const auto sphere = sphereFromNet(net);
    REQUIRE(sphere.size() == 2);
    for (const auto& p : sphere)
        for (double u : {0.2, 0.5, 0.9})
            for (double v : {0.1, 0.5, 0.7}) {
                const PatchSample s = evalPatch(p, u, v);
                CHECK(glm::dot(s.normal, s.point) > 0.0); // both patches face outwards
            }
    CHECK(evalPatch(sphere[1], 0.3, 0.4).point.z == -evalPatch(sphere[0], 0.3, 0.6).point.z);
    const RadialError course = patchesRadialError(sphere, 0.0);
    const RadialError fitted = patchesRadialError(sphereFromNet(fitHemisphereNet()), 0.0);
    CHECK(course.relative() > 0.01); // the course's net is a rough sphere
    CHECK(fitted.relative() < 0.5 * course.relative());
    // A fine mesh converges to the exact patches' error.
    CHECK(meshRadialError(sphere, course.radius, 128).maxError ==
          Approx(course.maxError).epsilon(0.01));
}
