#pragma once
// Affine and projective maps of practical 1 as homogeneous matrices:
// mirror images and shadows in 2D (3×3) and 3D (4×4, column-major like OpenGL,
// so glMultMatrixd(glm::value_ptr(m)) applies them).
#include <glm/glm.hpp>

#include <vector>

namespace wb {

// A line a·x + b·y + c = 0 in the plane; (a, b) need not be unit length but must not be zero.
struct Line2 {
    double a = 0, b = 1, c = 0;
};
// A plane A·x + B·y + C·z + D = 0; n = (A, B, C) need not be unit length but must not be zero.
struct Plane {
    glm::dvec3 n{0, 1, 0};
    double d = 0;
};

// 2D (practical 1.1 and lab 1).
glm::dmat3 mirrorLine(const Line2& line);
glm::dmat3 shadowLineDirectional(const Line2& line, const glm::dvec2& l); // light at infinity along l
glm::dmat3 shadowLinePoint(const Line2& line, const glm::dvec2& s);       // point light at s

// 3D (practicals 1.2, 1.3).
glm::dmat4 mirrorPlane(const Plane& plane);
glm::dmat4 shadowDirectional(const Plane& plane, const glm::dvec3& l); // light at infinity along l
glm::dmat4 shadowPoint(const Plane& plane, const glm::dvec3& s);       // point light at s

} // namespace wb
