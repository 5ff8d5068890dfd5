#pragma once
// Bezier curves and tensor-product patches of practical 10 (§1.10): Bernstein
// evaluation, de Casteljau, subdivision at any u0, degree elevation, derivatives,
// and patch points with normals that stay defined at degenerate corners and poles.
//
// A curve of degree k is its k+1 control points p[0..k], parameter u in [0, 1]
// (values outside extrapolate the polynomial). Bad input (no control points, a
// NaN parameter, a patch whose point count does not match its orders) throws
// std::invalid_argument with a message saying what is wrong.
#include <glm/glm.hpp>

#include <utility>
#include <vector>

namespace wb {

using BezierCurve = std::vector<glm::dvec3>; // control points p[0..k], degree k = size() - 1

// Binomial coefficient C(n, i) as a double (exact for n <= 50); 0 when i is outside [0, n].
double binomial(int n, int i);
// Bernstein polynomial B_i^k(u) = C(k, i) u^i (1-u)^(k-i); 0 when i is outside [0, k].
double bernstein(int k, int i, double u);

// q(u) = sum B_i^k(u) p_i, the direct Bernstein sum.
glm::dvec3 evalBernstein(const BezierCurve& p, double u);
// q(u) by de Casteljau's repeated linear interpolation (Theorem 0.4); the stable way.
glm::dvec3 evalDeCasteljau(const BezierCurve& p, double u);

// Splits q at u0 (Theorem 0.5): left(u) = q(u0·u), right(u) = q(u0 + (1-u0)·u),
// both of the same degree as q.
std::pair<BezierCurve, BezierCurve> subdivide(const BezierCurve& p, double u0);

// The same curve as a Bezier curve of degree k+1 (§1.10.3).
BezierCurve elevateDegree(const BezierCurve& p);

// Control points of q' (Theorem 0.2): k·(p_{i+1} - p_i), degree k-1. A degree-0
// curve gives one zero point (its derivative is the zero polynomial).
BezierCurve derivativeCurve(const BezierCurve& p);
// The order-th derivative of q at u (order 0 is q itself); zero above the degree.
glm::dvec3 evalDerivative(const BezierCurve& p, double u, int order = 1);

// A tensor-product patch q(u,v) = sum_i sum_j B_i(u) B_j(v) p_ij. The layout is
// the one glMap2f reads with u stride 3 and v stride 3·orderU, as in the course:
// one row of the net per v index, so p_ij = points[j·orderU + i].
struct BezierPatch {
    int orderU = 0;                 // control points along u (degree in u + 1), >= 1
    int orderV = 0;                 // control points along v (degree in v + 1), >= 1
    std::vector<glm::dvec3> points; // orderU·orderV points, row j (fixed v index) after row j-1

    const glm::dvec3& at(int i, int j) const {
        return points[size_t(j) * size_t(orderU) + size_t(i)];
    }
    glm::dvec3& at(int i, int j) { return points[size_t(j) * size_t(orderU) + size_t(i)]; }
};

// Throws std::invalid_argument when the orders and the point count disagree.
void checkPatch(const BezierPatch& patch);

struct PatchSample {
    glm::dvec3 point{0.0};  // q(u, v)
    glm::dvec3 du{0.0};     // ∂q/∂u
    glm::dvec3 dv{0.0};     // ∂q/∂v
    glm::dvec3 normal{0.0}; // unit normal along du × dv (the GL_AUTO_NORMAL direction)
    // How the normal was found: 0 = du × dv; 1 = its limit from inside the patch
    // (a pole or a collapsed edge where du or dv vanish or are parallel);
    // 2 = no direction exists (all control points coincide), normal is (0, 0, 1).
    int normalKind = 0;
};

// Point, first partial derivatives and unit normal at (u, v).
PatchSample evalPatch(const BezierPatch& patch, double u, double v);

} // namespace wb
