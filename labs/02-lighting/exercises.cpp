// Lab 02 - lighting: YOUR answers (course §2.2). Edit the bodies; the running lab rebuilds
// this file when you save it (press `e` in the lab: your cubes are drawn, your normals as
// solid hairs, the reference's as a ghost), and `./wb check lab02` grades it.
#include "exercises.h"

namespace wb::lab02 {

// ③ "Draw two cubes giving the vertices and the normals" (§2.2, fig. 2.2 a): the cube with
// centre `centre` and half-size `half` (edge 2*half), as 6 faces of 4 vertices for GL_QUADS,
// each face's corners counter-clockwise seen from OUTSIDE (glFrontFace(GL_CCW): a face
// wound the other way is culled or lit from behind). In this first cube every vertex's
// normal is perpendicular to its face and points outwards, unit length (the lab lights
// without GL_NORMALIZE, and OpenGL uses the normal as given).
// Inputs: |centre| up to 1e3, half in [1e-3, 1e3]. Face order and the first corner of each
// face are yours to choose.
Cube cubeWithFaceNormals(glm::dvec3 centre, double half) {
    (void)centre, (void)half;
    WB_NOT_DONE();
}

// ③ The second cube (fig. 2.2 b): the same vertices, but each vertex's normal points from
// the centre of the cube to that vertex, unit length. (Gouraud shading then makes the cube
// look round.)
Cube cubeWithCentreNormals(glm::dvec3 centre, double half) {
    (void)centre, (void)half;
    WB_NOT_DONE();
}

// ⑤ The face split into a grid (fig. 2.3): at a grid point P the normal is
//   n_P = (a n_A + b n_B + c n_C + d n_D) / |a n_A + b n_B + c n_C + d n_D|,
// a, b, c, d the barycentric coordinates of P in the system of points A, B, C, D
// (§1.4; for the cube's square face, the bilinear weights: with P = A + u (B - A) + v (D - A),
// a = (1-u)(1-v), b = u(1-v), c = uv, d = (1-u)v).
// corners = A, B, C, D in order around the face (a square of any size and orientation);
// cornerNormals = their normals (unit, never summing to zero inside the face); P lies on
// the face, corners and edges included. Return a unit vector.
glm::dvec3 gridNormal(const std::array<glm::dvec3, 4>& corners,
                      const std::array<glm::dvec3, 4>& cornerNormals, glm::dvec3 p) {
    (void)corners, (void)cornerNormals, (void)p;
    WB_NOT_DONE();
}

} // namespace wb::lab02

WB_EXERCISE_TABLE(wb::lab02::Table, lab02,
                  {&wb::lab02::cubeWithFaceNormals, &wb::lab02::cubeWithCentreNormals,
                   &wb::lab02::gridNormal})
