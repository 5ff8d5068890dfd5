#pragma once
// Lab 05 - the stencil buffer (§2.5) as graded tasks: the matrix that reflects the scene in
// the rectangular mirror's plane (③), the shadow matrix onto each plane of the staircase
// (④), and the elliptical mirror's outline that marks it in the stencil (⑤). You write the
// bodies in exercises.cpp; with `e` on the lab draws the reflection, the shadows and the
// mirror with your answers (the reference as a ghost) and `./wb check lab05` grades them.
// Matrices are OpenGL's: column-major, m[column][row], for glMultMatrixd(&m[0][0]);
// a plane is (A, B, C, D) for A·x + B·y + C·z + D = 0 with (A, B, C) != 0, not necessarily
// of unit length.
#include "common/exercise.h"

#include <glm/glm.hpp>

#include <vector>

namespace wb::lab05 {

// ③ (§2.5 task ③, practical 1.3) The mirror image in the plane: the 4×4 matrix that maps
// every point to its reflection in the plane (the scene drawn through it appears in the
// mirror). With n = (A, B, C)/|(A, B, C)| and d = D/|(A, B, C)|:  p' = p - 2(n·p + d)n.
// Any non-zero multiple of the matrix is the same map (homogeneous coordinates).
glm::dmat4 reflectionMatrix(const glm::dvec4& plane);

// ④ (§2.5 task ④, practicals 1.2-1.3) The shadow matrix: projects every point from the
// light L = (x, y, z, w) onto the plane π = (A, B, C, D) (w = 1: a point light; w = 0: a
// light at infinity in the direction (x, y, z) from the scene). With the dot product
// π·L = Ax + By + Cz + Dw:   M = (π·L)·I - L·πᵀ   (column-major: M[c][r] = (π·L)δ_rc - L_r π_c).
// Any non-zero multiple is the same map; for OpenGL take the sign that makes π·L > 0 (a
// vertex with clip w < 0 is clipped away: a matrix with the other sign shows no shadow).
// Degenerate: the light ON the plane (π·L = 0) gives M = -L·πᵀ (every point goes to the
// light: the shadow collapses to a point), never a zero matrix.
glm::dmat4 shadowMatrix(const glm::dvec4& plane, const glm::dvec4& light);

// ⑤ (§2.5 task ⑤) The elliptical mirror's outline for the stencil: n points (8..1024) of the
// ellipse (x - cx)²/a² + (y - cy)²/b² = 1 in the plane z = `z` (a semi-axis along x, b along
// y, both 0.01..100), drawn as one GL_POLYGON into the stencil. Counter-clockwise seen from
// +z (the side the mirror faces, so its front face is drawn), spread evenly in the
// parameter angle (point k at angle 2πk/n, any starting angle), each point once (do not
// repeat the first at the end).
std::vector<glm::dvec3> ellipseOutline(const glm::dvec2& centre, double a, double b, double z,
                                       int n);

// The exercise table, in task order.
struct Table {
    glm::dmat4 (*reflectionMatrix)(const glm::dvec4&);
    glm::dmat4 (*shadowMatrix)(const glm::dvec4&, const glm::dvec4&);
    std::vector<glm::dvec3> (*ellipseOutline)(const glm::dvec2&, double, double, double, int);
};

} // namespace wb::lab05
