// Practical 4.1: barycentric coordinates with the precomputed u_beta/u_gamma.
// References: exact rationals (exercise 4.4) by Cramer's rule, and long double
// Cramer's rule for random triangles and slivers.
#include "core/barycentric.h"
#include "rational.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wb;
using wb::test::Rational;

namespace {

constexpr double kEps = 2.220446049250313e-16;

// Cramer's rule on P − A = β e1 + γ e2, exactly.
struct ExactBary {
    Rational alpha, beta, gamma;
};
ExactBary cramer(Rational ax, Rational ay, Rational bx, Rational by, Rational cx, Rational cy,
                 Rational px, Rational py) {
    const Rational e1x = bx - ax, e1y = by - ay, e2x = cx - ax, e2y = cy - ay;
    const Rational fx = px - ax, fy = py - ay;
    const Rational det = e1x * e2y - e1y * e2x;
    const Rational beta = (fx * e2y - fy * e2x) / det;
    const Rational gamma = (e1x * fy - e1y * fx) / det;
    return {Rational(1) - beta - gamma, beta, gamma};
}

// The same in long double from double input.
glm::dvec3 cramerLD(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                    const glm::dvec2& p) {
    const long double e1x = (long double)b.x - a.x, e1y = (long double)b.y - a.y;
    const long double e2x = (long double)c.x - a.x, e2y = (long double)c.y - a.y;
    const long double fx = (long double)p.x - a.x, fy = (long double)p.y - a.y;
    const long double det = e1x * e2y - e1y * e2x;
    const long double beta = (fx * e2y - fy * e2x) / det, gamma = (e1x * fy - e1y * fx) / det;
    return {double(1 - beta - gamma), double(beta), double(gamma)};
}

// (4.6) exactly as printed, in double: the textbook form the class improves on.
glm::dvec3 literal46(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                     const glm::dvec2& p) {
    const glm::dvec2 e1 = b - a, e2 = c - a, f = p - a;
    const double e11 = glm::dot(e1, e1), e22 = glm::dot(e2, e2), e12 = glm::dot(e1, e2);
    const double den = e11 * e22 - e12 * e12;
    const glm::dvec2 ub = (e22 * e1 - e12 * e2) / den, ug = (e11 * e2 - e12 * e1) / den;
    const double beta = glm::dot(ub, f), gamma = glm::dot(ug, f);
    return {1 - beta - gamma, beta, gamma};
}

// First-order rounding bound. The computed coordinates are exact for vertices and P
// moved by ~eps·(their size); β = (f×e2)/(e1×e2) then moves by at most
// (|e1|+|e2|)/|e1×e2| · (that move) · (1 + |α| + |β| + |γ|). 8 ulps of slack on top covers
// the few roundings of each step. Thin triangles and far points legitimately get more.
double tolerance(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p,
                 const glm::dvec3& ref) {
    const glm::dvec2 e1 = b - a, e2 = c - a, f = p - a;
    const double k = std::abs(e1.x * e2.y - e1.y * e2.x);
    const double move = glm::length(e1) + glm::length(e2) + glm::length(f) + glm::length(a);
    const double size = std::abs(ref.x) + std::abs(ref.y) + std::abs(ref.z);
    return 8 * kEps * (glm::length(e1) + glm::length(e2)) / k * move * (1 + size);
}

} // namespace

TEST_CASE("exercise 4.4: A(0,0) B(2,3) C(3,1), exact answers") {
    const BarycentricFrame2 t({0, 0}, {2, 3}, {3, 1});
    REQUIRE(t.valid());
    struct Case {
        Rational px, py;
        Rational alpha, beta, gamma; // worked by hand, checked by cramer() below
    };
    const Case cases[] = {
        {2, 3, 0, 1, 0},                                        // a) P = B
        {Rational(4, 3), 2, Rational(1, 3), Rational(2, 3), 0}, // b) on edge AB
        {Rational(3, 2), Rational(3, 2), Rational(5, 14), Rational(3, 7),
         Rational(3, 14)},                                       // c) inside
        {1, 0, Rational(5, 7), Rational(-1, 7), Rational(3, 7)}, // d) outside (β < 0)
    };
    for (const Case& k : cases) {
        const ExactBary e = cramer(0, 0, 2, 3, 3, 1, k.px, k.py);
        CHECK(e.alpha == k.alpha);
        CHECK(e.beta == k.beta);
        CHECK(e.gamma == k.gamma);
        const auto got = t.coords({k.px.toDouble(), k.py.toDouble()});
        REQUIRE(got);
        INFO("P = (" << k.px.toDouble() << ", " << k.py.toDouble() << ")");
        // Entries O(1) and a handful of roundings: 8 ulps.
        CHECK(std::abs(got->x - k.alpha.toDouble()) <= 8 * kEps);
        CHECK(std::abs(got->y - k.beta.toDouble()) <= 8 * kEps);
        CHECK(std::abs(got->z - k.gamma.toDouble()) <= 8 * kEps);
    }
}

TEST_CASE("random triangles: coordinates match long double Cramer and rebuild P") {
    std::mt19937_64 gen(4401);
    std::uniform_real_distribution<double> u(-10, 10);
    int n = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec2 a{u(gen), u(gen)}, b{u(gen), u(gen)}, c{u(gen), u(gen)}, p{u(gen), u(gen)};
        const BarycentricFrame2 t(a, b, c);
        if (!t.valid()) continue;
        const auto got = t.coords(p);
        REQUIRE(got);
        const glm::dvec3 ref = cramerLD(a, b, c, p);
        const double tol = tolerance(a, b, c, p, ref);
        CHECK(std::abs(got->x - ref.x) <= tol);
        CHECK(std::abs(got->y - ref.y) <= tol);
        CHECK(std::abs(got->z - ref.z) <= tol);
        CHECK(got->x + got->y + got->z == Approx(1.0).margin(4 * kEps));
        ++n;
    }
    CHECK(n == 20000);
}

TEST_CASE("hard case: points on edges and vertices get a zero coordinate") {
    const glm::dvec2 a{0.1, 0.2}, b{7.3, -1.9}, c{2.2, 5.5};
    const BarycentricFrame2 t(a, b, c);
    for (int i = 0; i <= 64; ++i) {
        const double s = i / 64.0; // dyadic, so the edge points below are exact up to one rounding
        const glm::dvec2 onAB = a + s * (b - a), onAC = a + s * (c - a), onBC = b + s * (c - b);
        const auto ab = t.coords(onAB), ac = t.coords(onAC), bc = t.coords(onBC);
        REQUIRE((ab && ac && bc));
        CHECK(std::abs(ab->z) <= tolerance(a, b, c, onAB, *ab)); // γ = 0 on AB
        CHECK(std::abs(ab->y - s) <= tolerance(a, b, c, onAB, *ab));
        CHECK(std::abs(ac->y) <= tolerance(a, b, c, onAC, *ac)); // β = 0 on AC
        CHECK(std::abs(bc->x) <= tolerance(a, b, c, onBC, *bc)); // α = 0 on BC
    }
    const auto atB = t.coords(b);
    CHECK(std::abs(atB->y - 1) <= tolerance(a, b, c, b, *atB));
    const auto atA = t.coords(a);
    CHECK(*atA == glm::dvec3(1, 0, 0)); // f = 0: exact
}

TEST_CASE("hard case: slivers against long double, where (4.6) as printed loses digits") {
    // A 10-long sliver of height h: the (4.6) denominator |e1|²|e2|² − (e1·e2)² subtracts
    // two numbers ~1e4 to get ~1e2·h², so it keeps only ~eps·1e4/(1e2 h²) relative accuracy.
    double worstOurs = 0, worstLiteral = 0;
    for (double h : {1e-3, 1e-5, 1e-6, 1e-7}) {
        const glm::dvec2 a{0, 0}, b{10, 0.3}, c{4.9, 0.147 + h};
        const BarycentricFrame2 t(a, b, c);
        REQUIRE(t.valid());
        std::mt19937_64 gen(7);
        std::uniform_real_distribution<double> w(0, 1);
        for (int i = 0; i < 500; ++i) {
            double bb = w(gen), cc = w(gen);
            if (bb + cc > 1) bb = 1 - bb, cc = 1 - cc;
            const glm::dvec2 p = a + bb * (b - a) + cc * (c - a);
            const glm::dvec3 ref = cramerLD(a, b, c, p);
            const auto got = t.coords(p);
            REQUIRE(got);
            const double tol = tolerance(a, b, c, p, ref);
            const double errOurs = glm::length(*got - ref);
            CHECK(errOurs <= tol);
            worstOurs = std::max(worstOurs, errOurs / tol);
            worstLiteral = std::max(worstLiteral, glm::length(literal46(a, b, c, p) - ref) / tol);
        }
    }
    INFO("worst error / tolerance: ours " << worstOurs << ", (4.6) as printed " << worstLiteral);
    CHECK(worstOurs <= 1.0);
    CHECK(worstLiteral > 100.0); // documents why barycentric.cpp uses the cross-product form
}

TEST_CASE("degenerate triangles are rejected, not divided by zero") {
    CHECK_FALSE(BarycentricFrame2({0, 0}, {1, 1}, {2, 2}).valid());
    CHECK_FALSE(BarycentricFrame2({1, 1}, {1, 1}, {3, 0}).valid());
    CHECK_FALSE(BarycentricFrame2({0, 0}, {NAN, 1}, {3, 0}).valid());
    CHECK_FALSE(BarycentricFrame2({0, 0}, {1, 0}, {0, 1}).coords({NAN, 0}).has_value());
    CHECK_FALSE(
        BarycentricFrame3({0, 0, 0}, {1, 0, 0}, {0, 1, 0}).coords({0, INFINITY, 0}).has_value());
    CHECK_FALSE(BarycentricFrame3({0, 0, 0}, {1, 1, 1}, {2, 2, 2}).valid());
    CHECK_FALSE(BarycentricFrame2({0, 0}, {1, 1}, {2, 2}).coords({0, 0}).has_value());
}

TEST_CASE("3D: agrees with 2D in the plane, off-plane points project orthogonally") {
    std::mt19937_64 gen(4403);
    std::uniform_real_distribution<double> u(-5, 5);
    for (int i = 0; i < 5000; ++i) {
        const glm::dvec2 a{u(gen), u(gen)}, b{u(gen), u(gen)}, c{u(gen), u(gen)}, p{u(gen), u(gen)};
        const BarycentricFrame2 t2(a, b, c);
        if (!t2.valid()) continue;
        // Embed z = 0, then lift p off the plane: same coordinates expected.
        const BarycentricFrame3 t3({a, 0}, {b, 0}, {c, 0});
        REQUIRE(t3.valid());
        const auto g2 = t2.coords(p), g3 = t3.coords({p, u(gen)});
        REQUIRE((g2 && g3));
        CHECK(glm::length(*g2 - *g3) <= 2 * tolerance(a, b, c, p, *g2));
        // And in a general plane: rebuild P from the coordinates.
        const glm::dvec3 A{u(gen), u(gen), u(gen)}, B{u(gen), u(gen), u(gen)},
            C{u(gen), u(gen), u(gen)};
        const BarycentricFrame3 t(A, B, C);
        if (!t.valid()) continue;
        const double bb = u(gen) / 5, cc = u(gen) / 5;
        const glm::dvec3 P = A + bb * (B - A) + cc * (C - A);
        const auto g = t.coords(P);
        REQUIRE(g);
        const double tol =
            16 * kEps *
            (1 + std::max(glm::length(t.uBeta()), glm::length(t.uGamma())) * glm::length(P - A));
        CHECK(std::abs(g->y - bb) <= tol);
        CHECK(std::abs(g->z - cc) <= tol);
    }
}
