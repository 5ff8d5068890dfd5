// Tests of core/sphere_map: the formula of section 1.5.3 against a second derivation
// (the mirror sphere's geometry) and against exact values, plus degenerate input.
// The comparison with GL's own texgen is a render test (tests/render/textures_spheremap_test.cpp).
#include "core/sphere_map.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using glm::dvec2;
using glm::dvec3;

TEST_CASE("sphere map: exact values for a viewer looking at the mirror", "[sphere_map]") {
    // Normal facing the viewer: f = (0,0,1), m = 2·√4 = 4, (s,t) = (½,½) exactly.
    dvec2 c = wb::sphereMapCoord({0, 0, -5}, {0, 0, 1});
    CHECK(c.x == 0.5);
    CHECK(c.y == 0.5);
    // Normal at 45° towards +x: u = (0,0,-1), n = (1,0,1)/√2, f = u - 2n(n·u) = (1,0,0),
    // m = 2√2, s = 1/(2√2) + ½.
    c = wb::sphereMapCoord({0, 0, -1}, {1, 0, 1});
    CHECK(c.x == Approx(0.5 + 1.0 / (2.0 * std::sqrt(2.0))).epsilon(1e-15));
    CHECK(c.y == Approx(0.5).margin(1e-15));
}

TEST_CASE("sphere map: the formula and its geometric inverse agree", "[sphere_map]") {
    // Independent derivation: a unit mirror sphere seen from far along +z shows direction f
    // at disc point (x,y) with normal N = (x,y,√(1-x²-y²)). Feeding that N with u = (0,0,-1)
    // to the formula must give s = (x+1)/2, t = (y+1)/2. Tolerance: a few ulps of the
    // square roots and divisions, 1e-12 is far above them and far below a texel (1/4096).
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    int n = 0;
    while (n < 2000) {
        double x = d(rng), y = d(rng);
        if (x * x + y * y > 0.999) continue;
        ++n;
        dvec3 normal(x, y, std::sqrt(1 - x * x - y * y));
        dvec2 st = wb::sphereMapCoord({0, 0, -3}, normal);
        CHECK(st.x == Approx((x + 1) / 2).margin(1e-12));
        CHECK(st.y == Approx((y + 1) / 2).margin(1e-12));
        dvec3 f;
        REQUIRE(wb::sphereMapDirection(st.x, st.y, f));
        // f is the reflection of u about n (long double reference of the formula's first step).
        long double nl = std::sqrt((long double)(normal.x * normal.x) + normal.y * normal.y +
                                   (long double)normal.z * normal.z);
        long double nx = normal.x / nl, ny = normal.y / nl, nz = normal.z / nl;
        long double dot = -nz; // n·u with u = (0,0,-1)
        CHECK(double(f.x) == Approx(double(-2 * nx * dot)).margin(1e-12));
        CHECK(double(f.y) == Approx(double(-2 * ny * dot)).margin(1e-12));
        CHECK(double(f.z) == Approx(double(-1 - 2 * nz * dot)).margin(1e-12));
        CHECK(glm::length(f) == Approx(1.0).margin(1e-12));
    }
}

TEST_CASE("sphere map: round trip direction -> (s,t) -> direction", "[sphere_map]") {
    // Any unit reflection direction f except the blind spot (0,0,-1) round-trips: choose
    // n as the half vector between -u and f so that reflecting u about n gives f.
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    for (int k = 0; k < 2000; ++k) {
        dvec3 f = glm::normalize(dvec3(g(rng), g(rng), g(rng)));
        if (f.z < -0.99) continue; // near the blind spot m → 0 and s,t lose all precision
        dvec3 u(0, 0, -1);
        dvec3 n = glm::normalize(f - u);
        dvec2 st = wb::sphereMapCoord(2.5 * u, n);
        REQUIRE(st.x >= 0.0);
        REQUIRE(st.x <= 1.0);
        dvec3 back;
        REQUIRE(wb::sphereMapDirection(st.x, st.y, back));
        // Error grows like 1/m ~ 1/√(1+fz); with fz ≥ -0.99 that is ≤ 10× the 1e-13 base.
        CHECK(glm::length(back - f) < 1e-11);
    }
}

TEST_CASE("sphere map: degenerate input stays finite", "[sphere_map]") {
    dvec2 c = wb::sphereMapCoord({0, 0, 0}, {0, 0, 1});
    CHECK(c == dvec2(0.5, 0.5));
    c = wb::sphereMapCoord({0, 0, -1}, {0, 0, 0});
    CHECK(c == dvec2(0.5, 0.5));
    // Grazing: u along -z, n perpendicular to it → f = u = (0,0,-1), the blind spot.
    c = wb::sphereMapCoord({0, 0, -1}, {1, 0, 0});
    CHECK(c == dvec2(1.0, 0.5));
    c = wb::sphereMapCoord({NAN, 0, -1}, {0, 0, 1});
    CHECK(std::isfinite(c.x));
    CHECK(std::isfinite(c.y));
    dvec3 f(7, 7, 7);
    CHECK_FALSE(wb::sphereMapDirection(1.0, 1.0, f)); // corner of the texture: outside the disc
    CHECK(f == dvec3(7, 7, 7));
    CHECK_FALSE(wb::sphereMapDirection(NAN, 0.5, f));
    REQUIRE(wb::sphereMapDirection(1.0, 0.5, f)); // rim: the blind spot
    CHECK(f.z == Approx(-1.0));
}
