// Reflection and refraction directions (seed 000 formula (7), practical 12.6):
// unit length, Snell's law, coplanarity, total internal reflection exactly past the
// critical angle, and a glass slab that returns a ray parallel to how it entered.
// Tolerances: the directions are computed from unit vectors with a handful of
// operations, so each identity holds to a few ULPs of 1; 1e-14 (~45 ULPs) is used.
#include "core/raytrace/box.h"
#include "core/raytrace/tracer.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wb::rt;

namespace {
constexpr double kTol = 1e-14;
}

TEST_CASE("reflection: unit, angle of incidence = angle of reflection", "[raytrace][refraction]") {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g;
    for (int i = 0; i < 10000; ++i) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        glm::dvec3 v = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        if (glm::dot(v, n) > 0) v = -v;
        const glm::dvec3 r = reflectDir(v, n);
        CHECK(std::fabs(glm::length(r) - 1) <= kTol);
        CHECK(std::fabs(glm::dot(r, n) + glm::dot(v, n)) <= kTol);
        CHECK(std::fabs(glm::dot(r, glm::cross(v, n))) <= kTol); // coplanar
    }
}

TEST_CASE("refraction: Snell's law, unit direction, coplanar", "[raytrace][refraction]") {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> etaDist(0.5, 2.0);
    int refracted = 0, tir = 0;
    for (int i = 0; i < 10000; ++i) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        glm::dvec3 v = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        if (glm::dot(v, n) > 0) v = -v;
        const double eta = etaDist(rng);
        const double sinV = glm::length(glm::cross(v, n));
        const auto t = refractDir(v, n, eta);
        if (eta * sinV > 1 + 1e-12) {
            CHECK_FALSE(t.has_value());
            ++tir;
            continue;
        }
        if (eta * sinV > 1 - 1e-12) continue; // within rounding of the critical angle
        REQUIRE(t.has_value());
        ++refracted;
        CHECK(std::fabs(glm::length(*t) - 1) <= kTol);
        CHECK(glm::dot(*t, n) < 0); // goes through the surface
        // n_v sin θv = n_t sin θt with η = n_v/n_t; the error of sin θt is ~ eps/cos θt.
        const double sinT = glm::length(glm::cross(*t, n));
        CHECK(std::fabs(sinT - eta * sinV) <= kTol / std::max(1e-3, -glm::dot(*t, n)));
        CHECK(std::fabs(glm::dot(*t, glm::cross(v, n))) <= kTol);
    }
    CHECK(refracted > 1000);
    CHECK(tir > 1000);
}

TEST_CASE("refraction: total internal reflection exactly past the critical angle",
          "[raytrace][refraction]") {
    const glm::dvec3 n(0, 0, 1);
    const double eta = 1.5; // glass -> air: sin θc = 1/1.5
    const double sc = 1 / eta;
    for (double rel : {1 - 1e-6, 1 - 1e-9}) {
        const double s = sc * rel;
        const auto t = refractDir(glm::dvec3(s, 0, -std::sqrt(1 - s * s)), n, eta);
        REQUIRE(t.has_value()); // just inside: refracts, nearly along the surface
        CHECK(t->z < 0);
        CHECK(std::fabs(t->x - eta * s) <= kTol);
    }
    for (double rel : {1 + 1e-9, 1 + 1e-6, 1.2}) {
        const double s = sc * rel;
        CHECK_FALSE(refractDir(glm::dvec3(s, 0, -std::sqrt(1 - s * s)), n, eta).has_value());
    }
    // Normal incidence passes straight; η = 1 changes nothing.
    CHECK(glm::length(*refractDir({0, 0, -1}, n, eta) - glm::dvec3(0, 0, -1)) <= kTol);
    const glm::dvec3 v = glm::normalize(glm::dvec3(1, 2, -3));
    CHECK(glm::length(*refractDir(v, n, 1.0) - v) <= kTol);
}

TEST_CASE("refraction: a ray through a glass slab leaves parallel to how it entered",
          "[raytrace][refraction]") {
    const Box slab = Box::axisAligned({-10, -10, 0}, {10, 10, 1});
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> ang(0.0, 1.4); // up to 80 degrees
    for (int i = 0; i < 1000; ++i) {
        const double th = ang(rng), ph = 6.283185307179586 * (i / 1000.0);
        Ray r;
        r.direction = {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), -std::cos(th)};
        r.origin = glm::dvec3(0, 0, 1) - 2.0 * r.direction; // enters at the top's centre
        Hit in;
        REQUIRE(slab.intersect(r, 0, 1e30, in));
        REQUIRE(in.entering);
        const auto t1 = refractDir(r.direction, in.normal, 1.0 / 1.5);
        REQUIRE(t1.has_value());
        Ray inside;
        inside.origin = offsetRayOrigin(in.point, -in.normal);
        inside.direction = *t1;
        Hit out;
        REQUIRE(slab.intersect(inside, 0, 1e30, out));
        REQUIRE_FALSE(out.entering);
        CHECK(out.point.z == Approx(0).margin(1e-12)); // leaves through the bottom
        const auto t2 = refractDir(inside.direction, out.normal, 1.5 / 1.0);
        REQUIRE(t2.has_value());
        CHECK(glm::length(*t2 - r.direction) <= 4 * kTol);
        // The lateral shift of a slab of thickness 1: sin(θ−θt)/cos θt.
        const double tt = std::asin(std::sin(th) / 1.5);
        // (margin: the inner ray starts 2^20 ULPs, ~2e-10, off the top face.)
        const double shift = glm::length(glm::cross(out.point - in.point, r.direction));
        CHECK(shift == Approx(std::sin(th - tt) / std::cos(tt)).margin(1e-9));
    }
}
