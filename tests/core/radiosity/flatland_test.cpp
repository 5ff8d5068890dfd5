// The course's 2D example (15.22): γ(q)/π integrated over P_i, with and without an occluder
// (γ1 + γ2), against Hottel's crossed strings.
#include "core/radiosity/flatland.h"

#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

using namespace wb::rad;

TEST_CASE("crossed strings against the cosine-weighted integral, no occluder") {
    const Segment2 pi{{0, 0}, {1, 0}}; // emits upwards (left normal of a -> b)
    // Each P_j wholly in front of P_i and P_i wholly on one side of P_j's line.
    for (const Segment2& pj : {Segment2{{0, 1}, {1, 1}}, Segment2{{1.5, 0.5}, {0.5, 1.5}},
                               Segment2{{-1, 2}, {0.2, 1.2}}}) {
        const double exact = crossedStrings(pi, pj);
        // (sin φ2 − sin φ1)/2 is smooth in q for a segment wholly in front: 5-point Gauss on
        // 64 cells is exact to ~1e-14.
        CHECK(course2D(pi, pj, {}, 64, true) == Approx(exact).epsilon(1e-11));
    }
    // Perpendicular, sharing an end point: F = (1 + 1 − √2)/2.
    CHECK(crossedStrings(pi, Segment2{{0, 0}, {0, 1}}) == Approx((2 - std::sqrt(2.0)) / 2).epsilon(1e-15));
}

TEST_CASE("the course's uniform-angle γ/π is not the diffuse form factor") {
    // Parallel unit segments one apart: γ(x) = atan(x) + atan(1 − x), so
    // (1/π)∫γ = 1/2 − ln 2/π = 0.2794, while crossed strings give √2 − 1 = 0.4142.
    const Segment2 pi{{0, 0}, {1, 0}}, pj{{0, 1}, {1, 1}};
    const double course = course2D(pi, pj, {}, 64, false);
    CHECK(course == Approx(0.5 - std::log(2.0) / glm::pi<double>()).epsilon(1e-12));
    CHECK(crossedStrings(pi, pj) == Approx(std::sqrt(2.0) - 1).epsilon(1e-15));
    // 33% low: the course's formula counts directions uniformly, a Lambertian emitter sends
    // more light along the normal (cosine law), where P_j is.
    CHECK(course / crossedStrings(pi, pj) == Approx(0.6745).margin(1e-3));
}

TEST_CASE("with an occluder (γ1 + γ2): crossed strings around it against the integral") {
    const Segment2 pi{{0, 0}, {1, 0}}, pj{{0, 1}, {1, 1}};
    for (const Segment2& occ : {Segment2{{0.4, 0.5}, {0.6, 0.5}}, Segment2{{0.2, 0.3}, {0.5, 0.6}},
                                Segment2{{-0.5, 0.5}, {0.3, 0.5}}, Segment2{{0.7, 0.2}, {0.9, 0.8}}}) {
        const double exact = crossedStringsOccluded(pi, pj, {occ});
        // The visible angle has kinks where an occluder end crosses P_j's end: Gauss–Legendre
        // falls to O(h²) there; 4000 cells give ~1e-8.
        const double lambert = course2D(pi, pj, {occ}, 4000, true);
        CHECK(lambert == Approx(exact).epsilon(1e-6));
        CHECK(exact < crossedStrings(pi, pj)); // the occluder takes something away
        const double course = course2D(pi, pj, {occ}, 4000, false);
        CHECK(course < course2D(pi, pj, {}, 64, false));
        CHECK(std::isfinite(course));
    }
    // An occluder wider than the view hides everything.
    CHECK(crossedStringsOccluded(pi, pj, {Segment2{{-5, 0.5}, {6, 0.5}}}) == Approx(0.0).margin(1e-15));
    CHECK(course2D(pi, pj, {Segment2{{-5, 0.5}, {6, 0.5}}}, 100, true) == Approx(0.0).margin(1e-15));
}
