// Tests of core/mesh: the hand-made sphere and torus (lab 4). Every property is checked
// against a second formula: the sphere's normal is p/r, the torus's is (p - c)/r with c
// the nearest point of the tube's centre circle; triangle winding against those normals.
#include "core/mesh.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using glm::dvec2;
using glm::dvec3;

namespace {
constexpr double kPi = 3.14159265358979323846;

void checkCommon(const wb::Mesh& m, int columns, int rows) {
    REQUIRE(m.positions.size() == m.normals.size());
    REQUIRE(m.positions.size() == m.tangents.size());
    REQUIRE(m.positions.size() == m.texCoords.size());
    REQUIRE(m.indices.size() % 3 == 0);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        INFO("vertex " << i);
        CHECK(glm::length(m.normals[i]) == Approx(1.0).margin(1e-14)); // a few ulps
        CHECK(glm::length(m.tangents[i]) == Approx(1.0).margin(1e-14));
        CHECK(std::abs(glm::dot(m.normals[i], m.tangents[i])) < 1e-14);
        CHECK(m.texCoords[i].x >= 0.0);
        CHECK(m.texCoords[i].x <= 1.0);
        CHECK(m.texCoords[i].y >= 0.0);
        CHECK(m.texCoords[i].y <= 1.0);
    }
    // Continuity: no triangle spans more than one grid cell in s or t. A triangle that
    // wrapped across the seam would span |Δs| ≈ 1 and smear the texture into a column.
    const double ds = 1.0 / columns + 1e-12, dt = 1.0 / rows + 1e-12;
    for (size_t k = 0; k < m.indices.size(); k += 3) {
        INFO("triangle " << k / 3);
        for (int e = 0; e < 3; ++e) {
            dvec2 a = m.texCoords[m.indices[k + size_t(e)]];
            dvec2 b = m.texCoords[m.indices[k + size_t((e + 1) % 3)]];
            CHECK(std::abs(a.x - b.x) <= ds);
            CHECK(std::abs(a.y - b.y) <= dt);
        }
        // Counter-clockwise from outside: the face normal agrees with the vertex normals.
        dvec3 p0 = m.positions[m.indices[k]], p1 = m.positions[m.indices[k + 1]],
              p2 = m.positions[m.indices[k + 2]];
        dvec3 face = glm::cross(p1 - p0, p2 - p0);
        REQUIRE(glm::length(face) > 0.0); // no degenerate triangle, poles included
        dvec3 avg =
            m.normals[m.indices[k]] + m.normals[m.indices[k + 1]] + m.normals[m.indices[k + 2]];
        CHECK(glm::dot(face, avg) > 0.0);
    }
}

// The seam: vertices with s = 0 have a twin with s = 1 at the same position and normal.
int checkSeamTwins(const wb::Mesh& m) {
    int twins = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        if (m.texCoords[i].x != 0.0) continue;
        bool found = false;
        for (size_t j = 0; j < m.positions.size(); ++j)
            if (m.texCoords[j].x == 1.0 && m.texCoords[j].y == m.texCoords[i].y &&
                glm::length(m.positions[j] - m.positions[i]) < 1e-12 &&
                glm::length(m.normals[j] - m.normals[i]) < 1e-12)
                found = true;
        CHECK(found);
        ++twins;
    }
    return twins;
}
} // namespace

TEST_CASE("sphere: normals are p/r, texcoords continuous, seam and poles as declared", "[mesh]") {
    const int slices = 24, stacks = 12;
    const double r = 1.7;
    wb::Mesh m = wb::makeSphere(r, slices, stacks);
    checkCommon(m, slices, stacks);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        CHECK(glm::length(m.positions[i]) == Approx(r).margin(1e-14));
        CHECK(glm::length(m.normals[i] - m.positions[i] / r) <
              1e-14); // outward, the second formula
        // t is latitude: y = -r cos(π t), an exact relation independent of the mesh code's lat.
        CHECK(m.positions[i].y == Approx(-r * std::cos(kPi * m.texCoords[i].y)).margin(1e-14));
    }
    CHECK(checkSeamTwins(m) == stacks - 1); // every non-pole row has its twin
    // Poles: one triangle per slice on each cap, 2 per quad elsewhere.
    CHECK(m.indices.size() == size_t(3 * (2 * slices + 2 * slices * (stacks - 2))));
    // Pole vertices: s at the middle of their slice.
    CHECK(m.texCoords[0] == dvec2(0.5 / slices, 0.0));
    CHECK(m.positions[0] == dvec3(0, -r, 0));
}

TEST_CASE("torus: normals are (p - c)/r, texcoords continuous with two seams", "[mesh]") {
    const int rings = 32, sides = 16;
    const double big = 2.0, small = 0.6;
    wb::Mesh m = wb::makeTorus(big, small, rings, sides);
    checkCommon(m, rings, sides);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        dvec3 p = m.positions[i];
        dvec3 c = big * glm::normalize(dvec3(p.x, 0, p.z)); // nearest point of the centre circle
        CHECK(glm::length(p - c) == Approx(small).margin(1e-14));
        CHECK(glm::length(m.normals[i] - (p - c) / small) < 1e-13);
    }
    CHECK(checkSeamTwins(m) == sides + 1);
    // Second seam: t = 0 and t = 1 rows coincide.
    for (int i = 0; i <= rings; ++i)
        CHECK(glm::length(m.positions[size_t(i)] - m.positions[size_t(sides * (rings + 1) + i)]) <
              1e-14);
    CHECK(m.indices.size() == size_t(6 * rings * sides));
}

TEST_CASE("meshes reject bad parameters with a message", "[mesh]") {
    CHECK_THROWS_AS(wb::makeSphere(0.0, 8, 4), std::invalid_argument);
    CHECK_THROWS_AS(wb::makeSphere(NAN, 8, 4), std::invalid_argument);
    CHECK_THROWS_AS(wb::makeSphere(1.0, 2, 4), std::invalid_argument);
    CHECK_THROWS_AS(wb::makeSphere(1.0, 8, 1), std::invalid_argument);
    CHECK_THROWS_WITH(wb::makeTorus(1.0, 1.0, 8, 8), Catch::Contains("minorRadius < majorRadius"));
    CHECK_THROWS_AS(wb::makeTorus(1.0, 0.0, 8, 8), std::invalid_argument);
    CHECK_THROWS_AS(wb::makeTorus(1.0, 0.5, 2, 8), std::invalid_argument);
    // Smallest valid meshes still pass the common checks.
    checkCommon(wb::makeSphere(1.0, 3, 2), 3, 2);
    checkCommon(wb::makeTorus(1.0, 0.5, 3, 3), 3, 3);
}
