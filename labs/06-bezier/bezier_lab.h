#pragma once
// Lab 06: a circle from Bezier curves (glMap1f + glMapGrid1f/glEvalMesh1) and a
// sphere from two Bezier patches (glMap2f + glMapGrid2f/glEvalMesh2, GL_AUTO_NORMAL),
// with the control polygon/net, the grid resolution, and better control points.
#include "common/lab.h"
#include "core/bezier_shapes.h"

#include <memory>
#include <string>
#include <vector>

namespace wb {

// The lab's plain state; the keys and the panel change it.
struct BezierLabState {
    int shape = 0; // 0 = circle from curves (1), 1 = sphere from patches (2), 2 = Utah teapot (3)
    bool showControl = false; // c: control polygon (circle) / control net (sphere)
    int grid = 16;            // glMapGrid segments per curve or per patch side, 2..256 ([ and ])
    int circleVariant = 0;    // index into bezierCircleVariants(); 0 = the course's two arcs
    int sphereVariant = 0;    // index into bezierSphereVariants(); 0 = the course's net
    bool wireframe = false;   // w: glEvalMesh2(GL_LINE) instead of GL_FILL
    bool showTrue = false;    // t: the true circle / sphere in grey for comparison
    // n: draw the sphere's grid from core's evalPatch normals (defined at the patch corners,
    // where du ∥ dv) instead of glEvalMesh2 + GL_AUTO_NORMAL (zero normal there).
    bool coreNormals = false;
    // z: an inset magnifying where GL_AUTO_NORMAL has no normal - a corner of the sphere's
    // patches (du ∥ dv), the teapot lid's pole (du = 0) - with a marker around that spot.
    bool zoomInset = true;
    double shownMs = -1.0; // the GL time per mesh the panel last showed (-1: none; for tests)
};

// One way of building the circle: its arcs (unit radius) and their radial error.
struct CircleVariant {
    std::string name;              // as listed in the panel
    std::vector<BezierCurve> arcs; // cubic arcs of the unit circle, counter-clockwise
    RadialError error;             // of the exact curves against the unit circle
};

// One way of building the sphere: two patches and their radial error.
struct SphereVariant {
    std::string name;                 // as listed in the panel
    std::vector<BezierPatch> patches; // upper and lower half
    RadialError error;                // against the minimax sphere about the origin
};

// The approximations the lab offers, the course's first; computed once per process.
const std::vector<CircleVariant>& bezierCircleVariants();
const std::vector<SphereVariant>& bezierSphereVariants();

// World size of the drawn circle (the arcs are built on the unit circle and scaled).
constexpr double kBezierCircleRadius = 2.5;
// Half the height of the orthographic view at zoom 1, world units: the circle view,
// and the sphere view (wider so that the tilted control net, up to z = ±5, fits).
constexpr double kBezierViewHalfHeight = 3.6;
constexpr double kBezierSphereViewHalfHeight = 6.0;
// The sphere is tilted by this many degrees about x so that both patches show.
constexpr double kBezierSphereTilt = -60.0;
// The teapot view: orthographic half height, looked at from this many degrees above
// and turned this many degrees about the vertical so that spout, handle and lid show.
constexpr double kBezierTeapotViewHalfHeight = 2.4;
constexpr double kBezierTeapotTilt = 25.0, kBezierTeapotTurn = -30.0;
// The inset: half the side of the magnified square in scene units (1/20 of the sphere
// view's height, so 30× there) and its side as a fraction of the view's smaller side.
constexpr double kBezierInsetHalfSize = 0.2;
constexpr double kBezierInsetFraction = 0.42;
// Where the inset looks, in the shape's own coordinates: the front corner (2, -2, 0) of
// the sphere's patches, the teapot's knob top (0, 0, 3.15).
glm::dvec3 bezierInsetFocus(int shape);

// GL's evaluator against core on the teapot's 32 patches at grid n (GL_FEEDBACK: the
// points, and GL_AUTO_NORMAL's normals read back through lighting).
struct TeapotGlComparison {
    double maxPointError = 0.0;  // max |p_GL - p_core| over all grid vertices (float vs double)
    double maxNormalAngle = 0.0; // degrees, max angle between the normals where GL has one
    int noNormal = 0;            // grid vertices where GL_AUTO_NORMAL gives none (du × dv = 0)
    int coreLimit = 0;           // grid vertices where core took the limit (normalKind 1)
    int vertices = 0;            // all grid vertices compared
};
// Needs a current GL context; leaves the GL state as it found it.
TeapotGlComparison compareTeapotWithGl(int n);

std::unique_ptr<Lab> makeBezierLab();
// `observe` is the state the lab uses (tests read and set it).
std::unique_ptr<Lab> makeBezierLab(BezierLabState* observe);

} // namespace wb
