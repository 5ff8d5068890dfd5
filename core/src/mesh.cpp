#include "core/mesh.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wb {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Index of grid vertex (i, j) in a grid with `columns` + 1 vertices per row.
uint32_t gridIndex(int i, int j, int columns) {
    return uint32_t(j * (columns + 1) + i);
}

// Two triangles of grid cell (i, j); at a pole row (southPole: row j, northPole: row j+1)
// one triangle whose pole vertex is the copy of column i, whose s is the cell's middle.
void addQuad(Mesh& m, int i, int j, int columns, bool southPole, bool northPole) {
    const uint32_t a = gridIndex(i, j, columns), b = gridIndex(i + 1, j, columns),
                   c = gridIndex(i + 1, j + 1, columns), d = gridIndex(i, j + 1, columns);
    if (southPole) { // stacks >= 2, so a cell is never at both poles
        m.indices.insert(m.indices.end(), {a, c, d});
    } else if (northPole) {
        m.indices.insert(m.indices.end(), {a, b, d});
    } else {
        m.indices.insert(m.indices.end(), {a, b, c});
        m.indices.insert(m.indices.end(), {a, c, d});
    }
}
} // namespace

Mesh makeSphere(double radius, int slices, int stacks) {
    if (!(radius > 0.0) || !std::isfinite(radius) || slices < 3 || stacks < 2)
        throw std::invalid_argument("makeSphere: need radius > 0 (got " + std::to_string(radius) +
                                    "), slices >= 3 (got " + std::to_string(slices) +
                                    "), stacks >= 2 (got " + std::to_string(stacks) + ")");
    Mesh m;
    for (int j = 0; j <= stacks; ++j) {
        const double t = double(j) / stacks, lat = kPi * (t - 0.5);
        const bool pole = j == 0 || j == stacks;
        for (int i = 0; i <= slices; ++i) {
            // At a pole every vertex is the same point; s at the slice middle (see mesh.h).
            const double s = pole ? std::min(1.0, (i + 0.5) / slices) : double(i) / slices;
            const double phi = 2.0 * kPi * s;
            // sin/cos of ±π/2 are not exactly 1/0: snap the poles so they are one point.
            const double cl = pole ? 0.0 : std::cos(lat),
                         sl = pole ? (j == 0 ? -1.0 : 1.0) : std::sin(lat);
            const glm::dvec3 n(cl * std::sin(phi), sl, cl * std::cos(phi));
            m.positions.push_back(radius * n);
            m.normals.push_back(n);
            m.tangents.push_back(glm::dvec3(std::cos(phi), 0.0, -std::sin(phi)));
            m.texCoords.push_back({s, t});
        }
    }
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i)
            addQuad(m, i, j, slices, j == 0, j == stacks - 1);
    return m;
}

Mesh makeTorus(double majorRadius, double minorRadius, int rings, int sides) {
    if (!(minorRadius > 0.0) || !(majorRadius > minorRadius) || !std::isfinite(majorRadius) ||
        rings < 3 || sides < 3)
        throw std::invalid_argument(
            "makeTorus: need 0 < minorRadius < majorRadius (got " + std::to_string(minorRadius) +
            ", " + std::to_string(majorRadius) + "), rings >= 3 (got " + std::to_string(rings) +
            "), sides >= 3 (got " + std::to_string(sides) + ")");
    Mesh m;
    for (int j = 0; j <= sides; ++j) {
        const double t = double(j) / sides, theta = 2.0 * kPi * t;
        for (int i = 0; i <= rings; ++i) {
            const double s = double(i) / rings, phi = 2.0 * kPi * s;
            const glm::dvec3 centre(majorRadius * std::sin(phi), 0.0, majorRadius * std::cos(phi));
            const glm::dvec3 n(std::cos(theta) * std::sin(phi), std::sin(theta),
                               std::cos(theta) * std::cos(phi));
            m.positions.push_back(centre + minorRadius * n);
            m.normals.push_back(n);
            m.tangents.push_back(glm::dvec3(std::cos(phi), 0.0, -std::sin(phi)));
            m.texCoords.push_back({s, t});
        }
    }
    for (int j = 0; j < sides; ++j)
        for (int i = 0; i < rings; ++i)
            addQuad(m, i, j, rings, false, false);
    return m;
}

} // namespace wb
