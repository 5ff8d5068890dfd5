#pragma once
// Lab 03: modelling transforms and projections (lab 3). A table, a book, a pen and a
// teapot drawn at the origin by the lab's own functions; a classroom of 3 rows × 4
// tables with objects at seeded random places; glOrtho / gluPerspective / glFrustum with
// visible near/far clipping; gluLookAt moved in and out; the classroom mirrored in the
// blackboard wall with the matrix functions alone.
#include "common/lab.h"

#include <memory>
#include <vector>

namespace wb {

enum class Projection { Ortho, Perspective, Frustum };

// Everything the lab shows; plain data so tests can set it and read it.
struct TransformsState {
    unsigned seed = 1;     // object placement on the tables; `r` reseeds
    bool classroom = true; // false: the single-table scene at the origin
    Projection projection = Projection::Perspective;
    float fovy = 50.0f;           // gluPerspective field of view, degrees
    float orthoHalfHeight = 6.0f; // glOrtho: top = −bottom, right = −left = top·aspect
    float frustum[4] = {-0.6f, 0.6f, -0.3f, 0.5f}; // glFrustum left, right, bottom, top at zNear
    float zNear = 1.0f;                            // near clipping plane distance (all three)
    float zFar = 60.0f;                            // far clipping plane distance (all three)
    float distance = 15.0f;      // gluLookAt: eye distance from the look-at centre
    float elevation = 25.0f;     // degrees the eye is raised above the horizontal
    bool mirror = true;          // draw the mirror image in the blackboard wall
    bool mirrorFrontFace = true; // glFrontFace(GL_CW) for the mirror image
    bool mirrorLight = true;     // re-send the light position under the mirror
    bool topView = false;        // look straight down at the wall (mirror test)
    float topViewHeight = 30.0f; // eye height of the top view
};

// The room: the blackboard wall is the plane z = kWallZ; the room lies at z > kWallZ.
constexpr float kWallZ = -6.0f;
constexpr float kRoomBack = 4.5f; // back wall plane z
constexpr float kRoomHalfWidth = 7.0f;

// Object placement on one table, in the table top's coordinates (x across, z deep, metres).
struct TableObjects {
    float bookX, bookZ, bookAngle;
    float penX, penZ, penAngle;
    float potX, potZ, potAngle;
};
// Near and far plane keys step through fixed grids so that every state can be reached
// and a value comes back exactly after n then N: near = k·kNearStep (with 0.1 and 0.25
// below the first step), far = k·kFarStep. Steps are small enough to stop with the
// plane inside the back row of tables (~11.1 to 12 units deep from the default eye).
constexpr float kNearStep = 0.5f; // n N: 0.1, 0.25, 0.5, 1.0, 1.5, ... (k·0.5 is exact in float)
constexpr float kFarStep = 2.0f;  // b B: 2, 4, ..., 200
constexpr float kNearMax = 30.0f, kFarMax = 200.0f;
// The grids, ascending: near 0.1, 0.25, 0.5, 1.0, ..., 30; far 2, 4, ..., 200.
const std::vector<float>& nearSteps();
const std::vector<float>& farSteps();
// The next grid value after `zNear` (dir = +1) or before it (dir = -1), kept at least
// kNearStep in front of `zFar`; a value between grid points (dragged in the panel) goes
// to its neighbour; at the end of the grid the value stays.
float stepNear(float zNear, float zFar, int dir);
// The same for the far plane, kept at least kNearStep behind `zNear`.
float stepFar(float zFar, float zNear, int dir);

// 12 tables' placements from `seed` (row-major, front row first); the same seed, the same room.
std::vector<TableObjects> placeObjects(unsigned seed);

std::unique_ptr<Lab> makeTransformsLab();
// The lab working on `observe` (owned by the caller), so tests can set and read its state.
std::unique_ptr<Lab> makeTransformsLab(TransformsState* observe);

} // namespace wb
