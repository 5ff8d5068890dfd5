#pragma once
// Lab 06 - the course's graded tasks (§2.6, practical 10 = §1.10). You write the bodies in
// exercises.cpp; the lab draws your curves and patches with glMap1f/glMap2f over the
// reference (ghost) when `e` is on, and `./wb check lab06` grades them.
#include "common/exercise.h"

#include <glm/glm.hpp>

#include <vector>

namespace wb::lab06 {

// A Bezier curve: its control points p0..pk (degree k = size() - 1), what glMap1f reads.
using Curve = std::vector<glm::dvec3>;

// A tensor-product Bezier patch in glMap2f's layout (u stride 3, v stride 3·orderU):
// p_ij = points[j·orderU + i], i = 0..orderU-1 along u, j = 0..orderV-1 along v.
// GL_AUTO_NORMAL takes the normal along ∂q/∂u × ∂q/∂v: make it point OUT of the sphere.
struct Patch {
    int orderU = 4, orderV = 4;
    std::vector<glm::dvec3> points;
};

// ③ (§1.10, Theorem 0.4; practical 10, which §2.6 sends you to) A point of a Bezier curve.
// q(u) = Σ B_i^k(u) p_i for the control points p0..pk (1 <= k+1 <= 30), u in [0, 1], by
// de Casteljau: repeat p_i <- (1 - u)·p_i + u·p_{i+1} on the list until one point is left
// (k rounds). q(0) = p0 and q(1) = pk exactly. This is what glEvalCoord1 computes for a
// glMap1f curve, and what the two tasks below are drawn with.
glm::dvec3 bezierPoint(const Curve& p, double u);

// ④ (§2.6 task ④, §1.10) A circle from two Bezier curves.
// The circle of radius `radius` (0.1 .. 10) about the origin in the plane z = 0, drawn as
// TWO Bezier curves (glMap1f + glEvalMesh1): the first ends where the second begins and
// the second ends where the first begins, together once around the circle (either way).
// A cubic arc over half the circle from a to b has its inner points on the tangents at a
// and b, at k·radius from them; choose k so the arc stays close to the circle
// (at u = ½ the cubic is (p0 + 3p1 + 3p2 + p3)/8 - put that point on the circle).
// Graded by the largest radial error |q(u)| - radius over both curves, relative to the
// radius: the best two cubics reach 1.32 %, so 2 % passes (see exercise_checks.cpp).
std::vector<Curve> circleCurves(double radius);

// ⑤ (§2.6 task ⑤, §1.10.4) A sphere from two Bezier patches.
// Two patches (glMap2f + glEvalMesh2 with GL_AUTO_NORMAL) that together close around a
// sphere about the origin: for instance the course's 4×4 net of §2.6 for the upper half
// (z >= 0) and its mirror image in z = 0 for the lower half. Mirroring turns the patch
// inside out: reverse the order of its rows (or columns) so ∂q/∂u × ∂q/∂v points outwards
// on both, or the lower half is lit from inside. Any orders (2..8, GL's limit) are allowed.
// Graded by the radial error against the sphere about the origin that fits best (the
// course's net says no radius): the course's own net reaches 4.6 %, so 5 % passes.
std::vector<Patch> spherePatches();

// The exercise table, in task order.
struct Table {
    glm::dvec3 (*bezierPoint)(const Curve& p, double u);
    std::vector<Curve> (*circleCurves)(double radius);
    std::vector<Patch> (*spherePatches)();
};

} // namespace wb::lab06
