// Lab 02's reference answers (not shipped in a handout), and the typical mistakes CI plants
// one at a time behind WB_MUTANT(n) (listed in exercise_checks.cpp).
#include "exercises.h"

#include <utility>

namespace wb::lab02 {
namespace {

// The unit cube's faces: outward axis and the corners counter-clockwise seen from outside.
struct UnitFace {
    glm::dvec3 n;
    glm::dvec3 c[4];
};
const UnitFace kUnitFaces[6] = {
    {{0, 0, 1}, {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}},
    {{0, 0, -1}, {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}},
    {{1, 0, 0}, {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}}},
    {{-1, 0, 0}, {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}},
    {{0, 1, 0}, {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}}},
    {{0, -1, 0}, {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}},
};

Cube cube(glm::dvec3 centre, double half, bool centreNormals) {
    Cube c;
    const int faces = (WB_MUTANT(32) && !centreNormals) ? 5 : 6; // a face missing
    for (int f = 0; f < faces; ++f) {
        const UnitFace& u = kUnitFaces[f];
        for (int k = 0; k < 4; ++k) {
            // Mutant 33: the first face wound clockwise (corners in the other order).
            const int i = (WB_MUTANT(33) && !centreNormals && f == 0) ? 3 - k : k;
            c.vertices.push_back(centre + half * u.c[i]);
            glm::dvec3 n = u.n;
            if (WB_MUTANT(34) && !centreNormals) n = {u.n.y, u.n.x, u.n.z}; // x, y mixed up
            if (centreNormals) {
                n = WB_MUTANT(44) ? u.n : glm::normalize(u.c[i]);
                if (WB_MUTANT(41)) n = half * u.c[i];                          // not normalised
                if (WB_MUTANT(42)) n = glm::normalize(centre + half * u.c[i]); // from the origin
            }
            if (WB_MUTANT(31) && !centreNormals) n = -n; // inward
            if (WB_MUTANT(43) && centreNormals) n = -n;  // inward
            c.normals.push_back(n);
        }
    }
    return c;
}

} // namespace

Cube cubeWithFaceNormals(glm::dvec3 centre, double half) {
    return cube(centre, half, false);
}

Cube cubeWithCentreNormals(glm::dvec3 centre, double half) {
    return cube(centre, half, true);
}

glm::dvec3 gridNormal(const std::array<glm::dvec3, 4>& corners,
                      const std::array<glm::dvec3, 4>& cornerNormals, glm::dvec3 p) {
    // P = A + u (B - A) + v (D - A) on the square face: u, v by projection on its edges.
    const glm::dvec3 e1 = corners[1] - corners[0], e2 = corners[3] - corners[0];
    double u = glm::dot(p - corners[0], e1) / glm::dot(e1, e1);
    double v = glm::dot(p - corners[0], e2) / glm::dot(e2, e2);
    if (WB_MUTANT(52)) std::swap(u, v);
    double w[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
    if (WB_MUTANT(53)) w[0] = w[1] = w[2] = w[3] = 0.25;        // no weights: the plain average
    if (WB_MUTANT(54)) w[0] = 1 - u, w[1] = u, w[2] = w[3] = 0; // u only, the edge AB
    glm::dvec3 n(0.0);
    for (int k = 0; k < 4; ++k)
        n += w[k] * cornerNormals[size_t(k)];
    if (WB_MUTANT(51)) return n; // not normalised
    return glm::normalize(n);
}

} // namespace wb::lab02

WB_EXERCISE_TABLE(wb::lab02::Table, lab02,
                  {&wb::lab02::cubeWithFaceNormals, &wb::lab02::cubeWithCentreNormals,
                   &wb::lab02::gridNormal})
