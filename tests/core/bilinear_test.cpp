// Practical 4.2/4.3: bilinear interpolation and its inversion. References: exact
// rationals (exercise 4.5), and a long double Newton solve of P(α,β) = u that never
// uses the quadratic (4.9).
#include "core/bilinear.h"
#include "rational.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wb;
using wb::test::Rational;

namespace {

constexpr double kEps = 2.220446049250313e-16;

struct Quad {
    glm::dvec2 a, b, c, d;
};

// Newton on F(α,β) = P(α,β) − u in long double, from a start near the answer.
// Returns false when the Jacobian is singular.
bool newtonLD(const Quad& q, const glm::dvec2& u, long double& al, long double& be) {
    for (int it = 0; it < 50; ++it) {
        long double f[2], ja[2], jb[2];
        for (int k = 0; k < 2; ++k) {
            const long double A = q.a[k], B = q.b[k], C = q.c[k], D = q.d[k];
            f[k] = (1 - al) * (1 - be) * A + al * (1 - be) * B + al * be * C + (1 - al) * be * D -
                   u[k];
            ja[k] = (1 - be) * (B - A) + be * (C - D);
            jb[k] = (1 - al) * (D - A) + al * (C - B);
        }
        const long double det = ja[0] * jb[1] - ja[1] * jb[0];
        if (det == 0) return false;
        const long double da = (f[0] * jb[1] - f[1] * jb[0]) / det;
        const long double db = (ja[0] * f[1] - ja[1] * f[0]) / det;
        al -= da, be -= db;
        if (std::abs(da) + std::abs(db) < 1e-19L) break;
    }
    return true;
}

// Error bound for (α, β): the inversion is backward stable to a few ulps of the quad's
// size L, and the forward error is that times the Jacobian inverse's norm; 64 ulps
// covers the coefficient products (each a few roundings of size L²..L³).
double tolerance(const Quad& q, double al, double be) {
    const glm::dvec2 ja = (1 - be) * (q.b - q.a) + be * (q.c - q.d);
    const glm::dvec2 jb = (1 - al) * (q.d - q.a) + al * (q.c - q.b);
    const double det = std::abs(ja.x * jb.y - ja.y * jb.x);
    const double size = std::max(
        {glm::length(q.b - q.a), glm::length(q.c - q.a), glm::length(q.d - q.a), glm::length(q.a)});
    const double invNorm = (glm::length(ja) + glm::length(jb)) / det; // ≥ ‖J⁻¹‖
    return 64 * kEps * size * invNorm;
}

void checkInverse(const Quad& q, double al, double be) {
    const glm::dvec2 u = bilinear(q.a, q.b, q.c, q.d, al, be);
    long double ral = al, rbe = be;
    REQUIRE(newtonLD(q, u, ral, rbe));
    const auto got = invertBilinear(u, q.a, q.b, q.c, q.d);
    INFO("quad " << q.a.x << "," << q.a.y << " " << q.b.x << "," << q.b.y << " " << q.c.x << ","
                 << q.c.y << " " << q.d.x << "," << q.d.y << "  alpha " << al << " beta " << be);
    REQUIRE(got);
    const double tol = tolerance(q, al, be);
    CHECK(std::abs(got->x - double(ral)) <= tol);
    CHECK(std::abs(got->y - double(rbe)) <= tol);
}

} // namespace

TEST_CASE("exercise 4.5: A(0,0) B(4,0) C(5,3) D(0,2), exact answers") {
    struct Case {
        Rational al, be, x, y; // x, y worked by hand
    };
    const Case cases[] = {
        {1, 0, 4, 0},                                                      // a) = B
        {Rational(1, 3), 1, Rational(5, 3), Rational(7, 3)},               // b) on DC
        {Rational(1, 2), Rational(1, 4), Rational(17, 8), Rational(5, 8)}, // c)
        {Rational(2, 3), Rational(1, 3), Rational(26, 9), Rational(8, 9)}, // d)
    };
    const Rational ax = 0, ay = 0, bx = 4, by = 0, cx = 5, cy = 3, dx = 0, dy = 2;
    for (const Case& k : cases) {
        const Rational one = 1;
        const Rational wa = (one - k.al) * (one - k.be), wb = k.al * (one - k.be), wc = k.al * k.be,
                       wd = (one - k.al) * k.be;
        CHECK(wa * ax + wb * bx + wc * cx + wd * dx == k.x); // the hand answer is right
        CHECK(wa * ay + wb * by + wc * cy + wd * dy == k.y);
        const glm::dvec2 p =
            bilinear({0, 0}, {4, 0}, {5, 3}, {0, 2}, k.al.toDouble(), k.be.toDouble());
        CHECK(std::abs(p.x - k.x.toDouble()) <= 8 * kEps * 5); // O(1) weights of entries ≤ 5
        CHECK(std::abs(p.y - k.y.toDouble()) <= 8 * kEps * 5);
        const auto inv = invertBilinear(p, {0, 0}, {4, 0}, {5, 3}, {0, 2});
        REQUIRE(inv);
        CHECK(std::abs(inv->x - k.al.toDouble()) <=
              1e-14); // tolerance(): ~64 eps · 5 · |J⁻¹| ≈ 1e-14
        CHECK(std::abs(inv->y - k.be.toDouble()) <= 1e-14);
    }
    // The three forms of (4.8) agree (value version too).
    CHECK(bilinear(1.0, 2.0, 4.0, 8.0, 0.25, 0.5) == 0.375 * 1 + 0.125 * 2 + 0.125 * 4 + 0.375 * 8);
}

TEST_CASE("random convex quads: inversion matches long double Newton") {
    std::mt19937_64 gen(4403);
    std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
    for (int i = 0; i < 5000; ++i) {
        // A perturbed square keeps the quad convex (perturbation < 0.35 of the side).
        const double s = 0.3;
        Quad q{{0 + s * u(gen), 0 + s * u(gen)},
               {1 + s * u(gen), 0 + s * u(gen)},
               {1 + s * u(gen), 1 + s * u(gen)},
               {0 + s * u(gen), 1 + s * u(gen)}};
        if (i % 2) std::swap(q.b, q.d); // clockwise order: the orientation by n handles it
        const double scale = std::pow(10.0, u(gen) * 3);
        const glm::dvec2 shift{u(gen) * 10, u(gen) * 10};
        for (glm::dvec2* v : {&q.a, &q.b, &q.c, &q.d})
            *v = *v * scale + shift * scale;
        checkInverse(q, w(gen), w(gen));
    }
}

TEST_CASE("hard case: parallelograms (Aq = 0) and rectangles") {
    std::mt19937_64 gen(4404);
    std::uniform_real_distribution<double> u(-3, 3), w(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec2 a{u(gen), u(gen)}, e1{u(gen), u(gen)}, e2{u(gen), u(gen)};
        if (std::abs(e1.x * e2.y - e1.y * e2.x) < 0.1) continue;
        const Quad q{a, a + e1, a + e1 + e2, a + e2};
        checkInverse(q, w(gen), w(gen));
    }
    // Integer parallelogram, dyadic parameters: every step is exact, so is the answer.
    const Quad p{{0, 0}, {4, 1}, {6, 5}, {2, 4}};
    const auto got = invertBilinear(bilinear(p.a, p.b, p.c, p.d, 0.25, 0.75), p.a, p.b, p.c, p.d);
    REQUIRE(got);
    CHECK(*got == glm::dvec2(0.25, 0.75));
    // The linear branch directly: Aq = 0, Bq < 0 gives −Cq/Bq; Bq > 0 as well.
    CHECK(*bilinearBeta(0, -4, 1) == 0.25);
    CHECK(*bilinearBeta(0, 4, -1) == 0.25);
}

TEST_CASE("hard case: near-parallelograms, where (4.10) cancels and (4.11) does not") {
    // D moved by δ off the parallelogram: Aq ~ δ, so (4.10) subtracts two numbers ~|Bq|
    // and divides by 2Aq: its error grows like eps·|Bq|/|Aq|.
    double worstNaive = 0;
    for (double delta : {1e-4, 1e-7, 1e-10, 1e-13}) {
        const Quad q{{0, 0}, {3, 0.5}, {4, 3.5}, {1 + delta, 3}};
        for (double al : {0.0, 0.1, 0.5, 0.9, 1.0})
            for (double be : {0.0, 0.3, 0.7, 1.0}) {
                checkInverse(q, al, be);
                // (4.10) as printed, for comparison.
                const glm::dvec2 u = bilinear(q.a, q.b, q.c, q.d, al, be);
                auto cr = [](glm::dvec2 x, glm::dvec2 y) { return x.x * y.y - x.y * y.x; };
                const double A = cr(q.d - q.a, q.c - q.b);
                const double B = cr(q.c - q.b, u - q.a) - cr(q.d - q.a, u - q.b);
                const double C = cr(u - q.a, u - q.b);
                const double naive = (-B - std::sqrt(B * B - 4 * A * C)) / (2 * A);
                if (std::isfinite(naive)) worstNaive = std::max(worstNaive, std::abs(naive - be));
            }
    }
    INFO("worst beta error of (4.10) as printed: " << worstNaive);
    CHECK(worstNaive > 1e-6); // documents why bilinear.cpp takes the (4.11) branch
}

TEST_CASE("hard case: near-degenerate quads (thin, nearly a triangle)") {
    for (double h : {1e-3, 1e-6, 1e-9}) {
        // Thin: height h, length 1.
        checkInverse({{0, 0}, {1, 0}, {1.1, h}, {0.05, h}}, 0.3, 0.6);
        checkInverse({{0, 0}, {1, 0}, {1.1, h}, {0.05, h}}, 0.95, 0.05);
        // Nearly a triangle: C and D a distance h apart.
        const Quad t{{0, 0}, {2, 0}, {1 + h, 2}, {1, 2}};
        checkInverse(t, 0.4, 0.5);
        checkInverse(t, 0.7, 0.9);
    }
    // Exactly a triangle (C = D): at the apex every α fits, 0.5 is returned.
    const auto apex = invertBilinear(glm::dvec2(1, 2), {0, 0}, {2, 0}, {1, 2}, {1, 2});
    REQUIRE(apex);
    CHECK(apex->y == Approx(1.0).margin(1e-15));
    CHECK(apex->x == 0.5);
}

TEST_CASE("hard case: points on the four edges") {
    const Quad q{{0.5, -0.25}, {4.25, 0.5}, {5, 3}, {-0.5, 2.25}};
    for (int i = 0; i <= 16; ++i) {
        const double s = i / 16.0;
        checkInverse(q, s, 0); // AB
        checkInverse(q, s, 1); // DC
        checkInverse(q, 0, s); // AD
        checkInverse(q, 1, s); // BC
    }
    // On AB, Cq = (u−A)×(u−B) is ~0 and (4.11) returns 2Cq/(...) ≈ 0 with no cancellation.
    const auto ab = invertBilinear(bilinear(q.a, q.b, q.c, q.d, 0.5, 0), q.a, q.b, q.c, q.d);
    REQUIRE(ab);
    CHECK(std::abs(ab->y) <= 1e-15);
}

TEST_CASE("3D: planar quads in space agree with the 2D answer") {
    std::mt19937_64 gen(4405);
    std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const Quad q{{0.2 * u(gen), 0.2 * u(gen)},
                     {1 + 0.2 * u(gen), 0.2 * u(gen)},
                     {1 + 0.2 * u(gen), 1 + 0.2 * u(gen)},
                     {0.2 * u(gen), 1 + 0.2 * u(gen)}};
        // An orthonormal frame (e1, e2) in space and an origin.
        const glm::dvec3 e1 = glm::normalize(glm::dvec3(u(gen), u(gen), u(gen)));
        const glm::dvec3 e2 = glm::normalize(glm::cross(e1, glm::dvec3(u(gen), u(gen), u(gen))));
        const glm::dvec3 o{u(gen) * 5, u(gen) * 5, u(gen) * 5};
        auto lift = [&](glm::dvec2 v) { return o + v.x * e1 + v.y * e2; };
        const double al = w(gen), be = w(gen);
        const glm::dvec2 p = bilinear(q.a, q.b, q.c, q.d, al, be);
        const auto g2 = invertBilinear(p, q.a, q.b, q.c, q.d);
        const auto g3 = invertBilinear(lift(p), lift(q.a), lift(q.b), lift(q.c), lift(q.d));
        REQUIRE((g2 && g3));
        // Lifting rounds every coordinate once more (|o| ≤ 9): 10× the 2D bound.
        const double tol = 10 * tolerance(q, al, be) * (1 + glm::length(o));
        CHECK(std::abs(g2->x - g3->x) <= tol);
        CHECK(std::abs(g2->y - g3->y) <= tol);
    }
}

TEST_CASE("no solution and bad input give nothing, never NaN") {
    // (−5,−5) lies beyond the fold of exercise 4.5's quad: discriminant −96 < 0.
    CHECK_FALSE(invertBilinear(glm::dvec2(-5, -5), {0, 0}, {4, 0}, {5, 3}, {0, 2}).has_value());
    // Collinear vertices: every coefficient vanishes.
    CHECK_FALSE(invertBilinear(glm::dvec2(1, 1), {0, 0}, {1, 1}, {2, 2}, {3, 3}).has_value());
    CHECK_FALSE(invertBilinear(glm::dvec2(NAN, 0), {0, 0}, {1, 0}, {1, 1}, {0, 1}).has_value());
    CHECK_FALSE(
        invertBilinear(glm::dvec3(0, 0, 0), {0, 0, 0}, {1, 0, 0}, {1, INFINITY, 0}, {0, 1, 0})
            .has_value());
    CHECK_FALSE(bilinearBeta(1, 0, 1).has_value()); // disc = −4
    CHECK_FALSE(bilinearBeta(0, 0, 1).has_value()); // 1 = 0: no equation to solve
    CHECK(*bilinearBeta(1, 0, 0) == 0.0);           // double root at 0
    // A discriminant negative only by rounding is taken as zero (a tangent root).
    CHECK(bilinearBeta(1, -2, 1 + 1e-16).has_value());
}

TEST_CASE("3D: points on a twisted (non-planar) quad's surface give back their (alpha, beta)") {
    // At the true β, s1(β), u and s2(β) are collinear, so their cross product is the zero
    // vector and stays zero after the dot with n: the course's 3D algorithm is exact on
    // the bilinear surface even when the quad is not planar.
    const glm::dvec3 a{0, 0, 0}, b{1, 0, 0}, c{1, 1, 1}, d{0, 1, 0}; // z = αβ
    std::mt19937_64 gen(4406);
    std::uniform_real_distribution<double> w(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const double al = w(gen), be = w(gen);
        const auto got = invertBilinear(bilinear(a, b, c, d, al, be), a, b, c, d);
        REQUIRE(got);
        // Unit quad, |J⁻¹| ≤ ~2: the 64-ulp bound of tolerance() with size 1.
        CHECK(std::abs(got->x - al) <= 64 * kEps * 4);
        CHECK(std::abs(got->y - be) <= 64 * kEps * 4);
    }
}
