#pragma once
// Lab 6's shapes made of Bezier pieces — a circle from cubic arcs and a sphere from
// two bicubic patches — and how far they and their tessellations are from the true
// circle and sphere (radial error), for the lab's panel and the speed-against-error bench.
#include "core/bezier.h"

#include <vector>

namespace wb {

// The handle length of a cubic arc of angle θ = 2π/nArcs on the unit circle that
// makes the arc's midpoint lie on the circle: k = 4/3·tan(θ/4) (4/3 for a half circle).
double circleHandle(int nArcs);

// nArcs cubic arcs around the circle of `radius` about the origin in the z = 0 plane,
// starting at angle `startAngle` (radians), counter-clockwise; each arc's inner control
// points sit k·radius along the tangents. Throws std::invalid_argument for nArcs < 2,
// radius <= 0 or k <= 0.
std::vector<BezierCurve> circleArcs(int nArcs, double k, double radius = 1.0,
                                    double startAngle = 0.0);

// The handle k that minimises the maximum radial error of nArcs arcs (the error
// equioscillates: the curve dips inside and bulges outside by the same amount).
double fitCircleHandle(int nArcs);

// The spread of distances |q - centre| of a shape from the origin.
struct RadialError {
    double minRadius = 0.0; // smallest distance found
    double maxRadius = 0.0; // largest distance found
    double radius = 0.0;    // the true radius compared against
    double maxError = 0.0;  // max |distance - radius|
    double relative() const { return radius > 0.0 ? maxError / radius : 0.0; }
};

// Radial error of the exact curves against the circle of `radius` about the origin,
// from `samples` evenly spaced parameters per curve (the error is smooth in u, so the
// sampled maximum is low by O(1/samples²) of its size).
RadialError curvesRadialError(const std::vector<BezierCurve>& curves, double radius,
                              int samples = 4096);
// The same for the line strip glMapGrid1(n) + glEvalMesh1(GL_LINE) draws: n segments per
// curve with vertices at u = i/n. Exact: a segment is farthest from the origin at an end
// and nearest at the foot of the perpendicular.
RadialError polylineRadialError(const std::vector<BezierCurve>& curves, double radius, int n);

// The sphere of lab 6: the course's 4×4 control net (upper half, z >= 0) and its mirror
// image in z = 0 with the row order reversed, so both patches' du × dv point outwards.
BezierPatch labHemisphereNet();
std::vector<BezierPatch> sphereFromNet(const BezierPatch& upper);

// A hemisphere net of the course's shape with its free coordinates fitted: corners
// fixed at (±2, ±2, 0), edge handles (±a, ±b, 0)/(±b, ±a, 0), inner points (±p, ±q, h)
// with the x/y roles as in the course's net. Minimises the maximum relative radial
// error against the best sphere about the origin (Nelder–Mead from the course's values).
BezierPatch fitHemisphereNet();

// Radial error of the exact patches, from (samples+1)² parameter pairs per patch. With
// radius <= 0 the true sphere is the one that minimises the maximum error,
// radius = (min + max)/2: the course's net does not say which sphere it means.
RadialError patchesRadialError(const std::vector<BezierPatch>& patches, double radius,
                               int samples = 256);
// The same for the triangles glMapGrid2(n, n) + glEvalMesh2(GL_FILL) draws (each grid
// quad as two triangles). Exact for those triangles: farthest at a vertex, nearest at
// the closest point of the triangle to the origin.
RadialError meshRadialError(const std::vector<BezierPatch>& patches, double radius, int n);

// Points and unit normals of an (n+1)×(n+1) grid on a patch, what glEvalMesh2 computes
// (the CPU cost of one mesh, for the bench). Index (i, j) is at [j·(n+1) + i].
void tessellatePatch(const BezierPatch& patch, int n, std::vector<glm::dvec3>& points,
                     std::vector<glm::dvec3>& normals);

} // namespace wb
