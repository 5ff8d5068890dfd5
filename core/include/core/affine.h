#pragma once
// Affine and projective maps of practical 1 as homogeneous matrices:
// mirror images and shadows in 2D (3×3) and 3D (4×4, column-major like OpenGL,
// so glMultMatrixd(glm::value_ptr(m)) applies them).
//
// Conventions shared by the shadow matrices:
// - Invalid input (zero normal, zero light direction, non-finite normal) throws
//   std::invalid_argument naming the function.
// - Point light S: M = σ·((pi·S)·I − S·piᵀ) with pi = (n, d), S = (s, 1) and
//   σ = sign(pi·S) (+1 when pi·S = 0). This is the course's matrix of practical 1.3
//   times −σ, the same projective map. With that sign w = |pi·S| − σ(pi·P) > 0 for
//   every point P between the light and the plane, whichever way n points; OpenGL
//   needs that (a vertex with clip w < 0 is clipped away, so with the course's sign
//   the shadow may not be drawn at all). Points level with the light
//   ((n,P) = (n,S)) go to w = 0, the point at infinity.
// - Light ON the plane (pi·S = 0): M = −S·piᵀ has rank 1 and sends every point off the
//   plane to S itself (the whole shadow collapses into the light), and points on the
//   plane to the zero vector, which is no point at all; transformPoints() in
//   homogeneous.h reports those as PointKind::Undefined. No NaN is produced.
// - Directional light along l (the direction the rays travel): exactly the course's
//   affine matrix M = I − l·piᵀ/(n,l) of practical 1.2 (w stays 1). When (n,l) = 0 the
//   rays never reach the plane; M = l·piᵀ (the limit of the projectively equal
//   −(n,l)·I + l·piᵀ) sends every point to the point at infinity along l (w = 0) and
//   points on the plane to the zero vector.
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

// The line through two distinct points (throws std::invalid_argument if k == l).
Line2 lineThrough(const glm::dvec2& k, const glm::dvec2& l);

// 2D (practical 1.1 and lab 1).
glm::dmat3 mirrorLine(const Line2& line); // closed form, solution (2) of exercise 1.1
glm::dmat3 shadowLineDirectional(const Line2& line,
                                 const glm::dvec2& l);              // light at infinity along l
glm::dmat3 shadowLinePoint(const Line2& line, const glm::dvec2& s); // point light at s

// Elementary 2D maps in homogeneous coordinates, for solution (1) of exercise 1.1.
glm::dmat3 translation2(const glm::dvec2& v);
glm::dmat3 rotation2(double radians); // counter-clockwise about the origin
glm::dmat3 mirrorX2();                // y -> -y
// Solution (1) of exercise 1.1: T(p0)·R(φ)·Mx·R(−φ)·T(−p0), where p0 is a point of the
// line ((0, −c/b) as the course takes it, or (−c/a, 0) when |a| > |b|) and φ the angle
// of its direction (−b, a). Equal to mirrorLine() up to rounding.
glm::dmat3 mirrorLineComposite(const Line2& line);

// 3D (practicals 1.2, 1.3).
glm::dmat4 mirrorPlane(const Plane& plane);
glm::dmat4 shadowDirectional(const Plane& plane, const glm::dvec3& l); // light at infinity along l
glm::dmat4 shadowPoint(const Plane& plane, const glm::dvec3& s);       // point light at s

} // namespace wb
