#pragma once
// Lab 02's graded tasks (course §2.2): the two cubes' vertices and normals (③) and the
// normal at a grid point of a face blended from the corner normals (⑤, §1.4). See
// exercises.cpp for each task in the course's terms.
#include "common/exercise.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace wb::lab02 {

// A cube as the lab draws it with GL_QUADS: 6 faces x 4 vertices, one normal per vertex.
struct Cube {
    std::vector<glm::dvec3> vertices; // 24: face after face, each face's 4 corners
    std::vector<glm::dvec3> normals;  // 24: the normal given with glNormal3d before each vertex
};

// ③ Normals perpendicular to the faces (fig. 2.2 a).
Cube cubeWithFaceNormals(glm::dvec3 centre, double half);
// ③ Normals from the centre of the cube through the vertex (fig. 2.2 b).
Cube cubeWithCentreNormals(glm::dvec3 centre, double half);
// ⑤ The normal at point p of the face A B C D blended from the corner normals.
glm::dvec3 gridNormal(const std::array<glm::dvec3, 4>& corners,
                      const std::array<glm::dvec3, 4>& cornerNormals, glm::dvec3 p);

// The table the lab and wb-check reach your functions through (task order).
struct Table {
    Cube (*faceNormals)(glm::dvec3, double);
    Cube (*centreNormals)(glm::dvec3, double);
    glm::dvec3 (*gridNormal)(const std::array<glm::dvec3, 4>&, const std::array<glm::dvec3, 4>&,
                             glm::dvec3);
};

} // namespace wb::lab02
