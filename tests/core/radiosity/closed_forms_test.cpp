// Closed-form form factors against an independent route: the contour integral from each point
// (pointToPolygon) integrated over the emitter by Gauss–Legendre, and published table values.
// Also: how far the course's centre-to-centre (15.20) is off for near pairs.
#include "core/radiosity/closed_forms.h"
#include "gauss_legendre.h"

#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

using namespace wb::rad;

namespace {

std::vector<double> uniform(double a, int n) {
    std::vector<double> v;
    for (int i = 0; i <= n; ++i) v.push_back(a * i / n);
    return v;
}

// Cells shrinking geometrically towards 0 (the singular edge of touching rectangles).
std::vector<double> graded(double a, int n) {
    std::vector<double> v = {0.0};
    for (int i = n; i >= 0; --i) v.push_back(a * std::pow(0.5, i));
    return v;
}

} // namespace

TEST_CASE("edgeAngle: atan2 of a non-negative sine within 2 ulp of std::atan2") {
    // The contour integral's angles (pointToPolygon, the near field's shared edges) use
    // Cephes' rational atan instead of libm's atan2. Bound: 2 ulp of std::atan2's value
    // (Cephes documents 2.2e-16 relative; glibc's atan2 is within 1 ulp, measured max here
    // 2.0 ulp). Inputs: the ratio y/|x| over 10^±8 on both sides of x = 0, every branch of the
    // range reduction (tan 3π/8 = 2.414, 0.66) and its ends, and the special values.
    auto ulps = [](double got, double want) {
        const double ulp = std::nextafter(std::abs(want), 10.0) - std::abs(want);
        return std::abs(got - want) / ulp;
    };
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> exponent(-8.0, 8.0), mantissa(0.5, 1.0);
    double worst = 0.0;
    int count = 0;
    for (int i = 0; i < 200000; ++i) {
        const double y = mantissa(rng) * std::pow(10.0, exponent(rng));
        const double x = (i % 2 ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, exponent(rng));
        worst = std::max(worst, ulps(edgeAngle(y, x), std::atan2(y, x)));
        ++count;
    }
    for (double t : {0.66, std::nextafter(0.66, 1.0), 2.41421356237309504880,
                     std::nextafter(2.41421356237309504880, 3.0), 1.0, 1e-300, 1e300})
        for (double x : {1.0, -1.0, 3.7e-5, -2.2e8}) {
            const double y = t * std::abs(x);
            worst = std::max(worst, ulps(edgeAngle(y, x), std::atan2(y, x)));
            ++count;
        }
    INFO(count << " inputs, worst " << worst << " ulp");
    CHECK(worst <= 2.0);
    CHECK(edgeAngle(0.0, 1.0) == 0.0);
    CHECK(edgeAngle(0.0, -1.0) == std::atan2(0.0, -1.0));
    CHECK(edgeAngle(1.0, 0.0) == std::atan2(1.0, 0.0));
    CHECK(edgeAngle(1.0, -0.0) == std::atan2(1.0, -0.0));
    CHECK(edgeAngle(0.0, 0.0) == 0.0);
    CHECK(edgeAngle(1.0, 1e-320) == std::atan2(1.0, 1e-320)); // y/x overflows to +inf
    CHECK(std::isnan(edgeAngle(std::numeric_limits<double>::quiet_NaN(), 1.0)));
    CHECK(std::isnan(edgeAngle(1.0, std::numeric_limits<double>::quiet_NaN())));
}

TEST_CASE("parallel rectangles: Howell C-11 against the integrated contour formula") {
    // Published: unit squares one apart, F = 0.19982 (Howell's catalogue, 5 digits).
    CHECK(parallelRectangles(1, 1, 1) == Approx(0.19982).margin(5e-6));
    for (auto abc : {glm::dvec3(1, 1, 1), glm::dvec3(2, 0.5, 0.3), glm::dvec3(0.2, 3, 5)}) {
        const double a = abc.x, b = abc.y, c = abc.z;
        const std::vector<glm::dvec3> top = {{0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
        const auto f = [&](double x, double y) {
            return pointToPolygon({x, y, 0}, {0, 0, 1}, top);
        };
        const double num = test::gaussAverage(uniform(a, 6), uniform(b, 6), f);
        // The integrand is analytic on the closed rectangle: 8-point Gauss on 6×6 cells
        // converges far below 1e-10; the closed form is evaluated in double (~1e-15).
        CHECK(parallelRectangles(a, b, c) == Approx(num).epsilon(1e-10));
    }
}

TEST_CASE("perpendicular rectangles with a common edge: Howell C-14 against the contour formula") {
    // Published: W = H = 1, F = 0.20004 (Howell).
    CHECK(perpendicularRectangles(1, 1, 1) == Approx(0.20004).margin(5e-6));
    for (auto lw : {glm::dvec3(1, 1, 1), glm::dvec3(2, 0.5, 1.5), glm::dvec3(0.5, 2, 0.25)}) {
        const double l = lw.x, w1 = lw.y, w2 = lw.z;
        // Emitter in y = 0 (x along the edge, z from 0 to w1), receiver in z = 0 (y 0..w2).
        const std::vector<glm::dvec3> recv = {{0, 0, 0}, {l, 0, 0}, {l, w2, 0}, {0, w2, 0}};
        // Grade x towards both ends too: near the edge (z -> 0) the integrand changes
        // abruptly at the corners x = 0 and x = l.
        std::vector<double> xs = graded(0.5 * l, 40);
        for (int k = static_cast<int>(xs.size()) - 2; k >= 0; --k) xs.push_back(l - xs[static_cast<std::size_t>(k)]);
        const double num = test::gaussAverage(xs, graded(w1, 40), [&](double x, double z) {
            return pointToPolygon({x, 0, z}, {0, 1, 0}, recv);
        });
        // The integrand has a log-type kink at the common edge: geometric grading (40 halvings,
        // the last cell 1e-12 wide) keeps the quadrature error below ~1e-9.
        CHECK(perpendicularRectangles(l, w1, w2) == Approx(num).epsilon(1e-8));
    }
    // Reciprocity of the closed form itself: w1 F12 = w2 F21.
    CHECK(1.0 * perpendicularRectangles(2, 1, 3) == Approx(3.0 * perpendicularRectangles(2, 3, 1)).epsilon(1e-13));
}

TEST_CASE("differential area facing a coaxial disc: r²/(h²+r²) against a 4096-gon") {
    for (auto hr : {glm::dvec2(1, 1), glm::dvec2(0.01, 1), glm::dvec2(10, 0.5)}) {
        const double h = hr.x, r = hr.y;
        std::vector<glm::dvec3> ngon;
        const int n = 4096;
        for (int k = 0; k < n; ++k) {
            const double t = 2 * glm::pi<double>() * k / n;
            ngon.push_back({r * std::cos(t), r * std::sin(t), h});
        }
        // The inscribed n-gon's area is the disc's times sin(2π/n)/(2π/n) ≈ 1 − (2π/n)²/6
        // = 1 − 3.9e-7, and it misses the rim, where the weight is lowest: F is low by at most that.
        const double f = pointToPolygon({0, 0, 0}, {0, 0, 1}, ngon);
        CHECK(f <= pointToCoaxialDisc(h, r));
        CHECK(f == Approx(pointToCoaxialDisc(h, r)).epsilon(4e-7));
    }
}

TEST_CASE("pointToPolygon: hard cases") {
    const std::vector<glm::dvec3> sq = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    // Orientation does not matter.
    std::vector<glm::dvec3> rev(sq.rbegin(), sq.rend());
    CHECK(pointToPolygon({0, 0, 0}, {0, 0, 1}, sq) == Approx(pointToPolygon({0, 0, 0}, {0, 0, 1}, rev)).epsilon(1e-15));
    // Behind the point: 0. Half behind: the clipped half.
    CHECK(pointToPolygon({0, 0, 0}, {0, 0, -1}, sq) == 0.0);
    const std::vector<glm::dvec3> wall = {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
    const std::vector<glm::dvec3> upper = {{1, -1, 0}, {1, 1, 0}, {1, 1, 1}, {1, -1, 1}};
    CHECK(pointToPolygon({0, 0, 0}, {0, 0, 1}, wall) == Approx(pointToPolygon({0, 0, 0}, {0, 0, 1}, upper)).epsilon(1e-14));
    // Far away: tends to (15.20) A cos cos/(π d²); at d = 1e3 the difference is O((size/d)²).
    const double d = 1e3;
    const std::vector<glm::dvec3> far = {{-0.5, -0.5, d}, {0.5, -0.5, d}, {0.5, 0.5, d}, {-0.5, 0.5, d}};
    CHECK(pointToPolygon({0, 0, 0}, {0, 0, 1}, far) == Approx(1.0 / (glm::pi<double>() * d * d)).epsilon(1e-6));
    // Degenerate polygon: 0, no NaN.
    CHECK(pointToPolygon({0, 0, 0}, {0, 0, 1}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}) == 0.0);
    CHECK(pointToPolygon({0, 0, 0}, {0, 0, 1}, {}) == 0.0);
}

TEST_CASE("(15.20) centre to centre against the exact value for near pairs (how far off)") {
    // Unit squares facing each other at distance c: (15.20) gives 1/(π c²) from the centres.
    struct Row { double c, ratioAtLeast, ratioAtMost; };
    // The ratio (15.20)/exact (from the closed form): 1.007 at c = 10, 1.073 at c = 3,
    // 1.59 at c = 1, 6.1 at c = 0.3, 38 at c = 0.1 where (15.20) = 31.8 > 1 (impossible for a
    // form factor). Bounds around those values.
    for (const Row& r : {Row{10, 1.0, 1.01}, Row{1, 1.55, 1.65}, Row{0.1, 30.0, 60.0}}) {
        const double approx = 1.0 / (glm::pi<double>() * r.c * r.c);
        const double exact = parallelRectangles(1, 1, r.c);
        CHECK(approx / exact >= r.ratioAtLeast);
        CHECK(approx / exact <= r.ratioAtMost);
    }
}

namespace {
// A·F for a plate of length l and height 1 and a perpendicular plate of length l and depth 1
// sharing the whole edge (Howell C-14, W = H = 1/l).
double commonEdgeExchange(double l) { return l * perpendicularRectangles(l, 1, 1); }
} // namespace

TEST_CASE("a receiver straddling the emitter's plane: only its front part counts") {
    // A 1×1 wall (y = 0, x from 0.5 to 1.5, z from 0 to 1, facing +y) standing on a 2×2 floor
    // (z = 0, x from 0 to 2, y from −1 to 1, facing +z) that extends behind it: the floor
    // straddles the wall's plane and the wall sees only the floor's front half y > 0.
    // Independent reference, by superposition of Howell C-14 along the common line (strips of
    // equal height 1 and depth 1, so the exchange between a wall span U and a floor span V is
    // symmetric in U and V): A_w F(w→front) = S(1) + 2·(S(1.5) − S(1) − S(0.5))/2
    // = S(1.5) − S(0.5), with S(l) = l·C14(l; 1, 1).
    const double reference = commonEdgeExchange(1.5) - commonEdgeExchange(0.5);
    CHECK(reference == Approx(0.264).margin(5e-4)); // the "about 0.264"
    const std::vector<glm::dvec3> floor = {{0, -1, 0}, {2, -1, 0}, {2, 1, 0}, {0, 1, 0}};
    // The contour integral clips the floor to the wall's front half-space itself; integrated
    // over the wall, graded towards the common edge (log-type kink at z → 0, as for C-14).
    // The wall's side edges x = 0.5, 1.5 are no kink: the floor goes on beyond them.
    const double num = test::gaussAverage(uniform(1.0, 4), graded(1.0, 40), [&](double x, double z) {
        return pointToPolygon({0.5 + x, 0, z}, {0, 1, 0}, floor);
    });
    // Same quadrature error as the common-edge test above (~1e-9).
    CHECK(num == Approx(reference).epsilon(1e-8));
    // The behind part is not counted at all: the same integral over the front half alone.
    const std::vector<glm::dvec3> front = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    const double numFront = test::gaussAverage(uniform(1.0, 4), graded(1.0, 40), [&](double x, double z) {
        return pointToPolygon({0.5 + x, 0, z}, {0, 1, 0}, front);
    });
    CHECK(num == Approx(numFront).epsilon(1e-12));
}
