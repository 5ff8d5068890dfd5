// Lab 04 - the reference answers and, behind WB_MUTANT(n), the typical mistakes CI checks
// the grading against (listed with their ids in exercise_checks.cpp).
#include "exercises.h"

#include <algorithm>
#include <cmath>

namespace wb::lab04 {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Grid cells (i, j), i < columns, j < rows, of a vertex grid with `stride` vertices per
// row, two triangles each, counter-clockwise when s grows to the right and t upwards as
// seen from outside.
void cells(Mesh& m, int columns, int rows, int stride, bool clockwise) {
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const unsigned a = unsigned(j * stride + i), b = a + 1,
                           d = unsigned((j + 1) * stride + i), c = d + 1;
            if (clockwise)
                m.indices.insert(m.indices.end(), {a, c, b, a, d, c});
            else
                m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
}
} // namespace

int texelIndex(double s, int size, bool repeat) {
    if (repeat && !WB_MUTANT(32)) { // 32: GL_REPEAT treated as clamping
        // 31: std::fmod keeps the sign (-0.25 -> -0.25).
        const double f = WB_MUTANT(31) ? std::fmod(s, 1.0) : s - std::floor(s);
        const int i = int(std::floor(f * size));
        return std::min(i, size - 1); // f·size rounds up to size when f is just below 1
    }
    const int i = int(std::floor(s * size));
    if (WB_MUTANT(33)) return std::max(0, std::min(i, size)); // 33: clamped one past the end
    return std::max(0, std::min(i, size - 1));
}

Mesh sphereMesh(double radius, int slices, int stacks) {
    Mesh m;
    for (int j = 0; j <= stacks; ++j) {
        const double t = double(j) / stacks, lat = kPi * (t - 0.5);
        const bool pole = j == 0 || j == stacks;
        for (int i = 0; i <= slices; ++i) {
            // The seam: column `slices` is s = 1 (mutant 1: wrapped back to s = 0).
            const double s = WB_MUTANT(1) && i == slices ? 0.0 : double(i) / slices;
            const double phi = 2 * kPi * s;
            const double cl = pole ? 0.0 : std::cos(lat),
                         sl = pole ? (j == 0 ? -1.0 : 1.0) : std::sin(lat);
            const glm::dvec3 n(cl * std::sin(phi), sl, cl * std::cos(phi));
            m.positions.push_back(radius * n);
            m.normals.push_back(WB_MUTANT(3) ? radius * n : n);   // 3: not normalised
            m.texCoords.push_back({s, WB_MUTANT(5) ? 1 - t : t}); // 5: t from the north pole
        }
    }
    // 2: a slice short (the loop to slices - 1), 4: clockwise triangles.
    cells(m, WB_MUTANT(2) ? slices - 1 : slices, stacks, slices + 1, WB_MUTANT(4));
    return m;
}

Mesh torusMesh(double R, double r, int rings, int sides) {
    Mesh m;
    for (int j = 0; j <= sides; ++j) {
        // The t seam: row `sides` is t = 1 (mutant 11: wrapped back to t = 0).
        const double t = WB_MUTANT(11) && j == sides ? 0.0 : double(j) / sides;
        const double theta = 2 * kPi * t;
        for (int i = 0; i <= rings; ++i) {
            const double s = double(i) / rings, phi = 2 * kPi * s;
            const glm::dvec3 c(R * std::sin(phi), 0, R * std::cos(phi));
            const glm::dvec3 n(std::cos(theta) * std::sin(phi), std::sin(theta),
                               std::cos(theta) * std::cos(phi));
            const glm::dvec3 p = c + r * n;
            m.positions.push_back(p);
            m.normals.push_back(WB_MUTANT(12) ? glm::normalize(p) : n); // 12: a sphere's normal
            m.texCoords.push_back({s, t});
        }
    }
    cells(m, rings, WB_MUTANT(13) ? sides - 1 : sides, rings + 1, false); // 13: a row short
    return m;
}

glm::dvec2 sphereMap(const glm::dvec3& eyePos, const glm::dvec3& n) {
    const double len = glm::length(eyePos);
    const glm::dvec3 u = WB_MUTANT(21) ? eyePos : eyePos / len;       // 21: u not normalised
    const glm::dvec3 f = WB_MUTANT(22) ? u + 2.0 * n * glm::dot(n, u) // 22: sign of the reflection
                                       : u - 2.0 * n * glm::dot(n, u);
    const double fz1 = WB_MUTANT(23) ? f.z : f.z + 1; // 23: the +1 forgotten
    const double m = 2 * std::sqrt(f.x * f.x + f.y * f.y + fz1 * fz1);
    if (!(m > 0)) return {1.0, 0.5}; // the blind spot: a point of the rim
    return {f.x / m + 0.5, f.y / m + 0.5};
}

} // namespace wb::lab04

WB_EXERCISE_TABLE(wb::lab04::Table, lab04,
                  {&wb::lab04::texelIndex, &wb::lab04::sphereMesh, &wb::lab04::torusMesh,
                   &wb::lab04::sphereMap})
