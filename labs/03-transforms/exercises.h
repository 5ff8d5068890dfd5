#pragma once
// Lab 03 - transforms and projection (§2.3) as graded tasks: the camera moved in and out
// through gluLookAt's parameters (④) and the classroom mirrored in the blackboard wall with
// OpenGL's matrix functions (⑤). You write the bodies in exercises.cpp; with `e` on the lab
// moves its camera with your function (keys z and x) and draws the mirrored room through
// your calls, the reference's as a ghost; `./wb check lab03` grades them, the mirror by
// reading the modelview matrix back from OpenGL after your calls.
#include "common/exercise.h"

#include <glm/glm.hpp>

namespace wb::lab03 {

// glFrustum's six parameters.
struct Frustum {
    double left = -1, right = 1, bottom = -1, top = 1, zNear = 1, zFar = 10;
};

// ③ (§2.3 task ③ (second list): glOrtho, gluPerspective and glFrustum) The glFrustum that
// gives the same projection as gluPerspective(fovy, aspect, zNear, zFar): fovy is the
// vertical field of view in DEGREES (1..179), aspect = width/height (0.1..10),
// 0 < zNear < zFar. The near rectangle is centred: top = zNear·tan(fovy/2), right =
// top·aspect, left = -right, bottom = -top.
Frustum perspectiveAsFrustum(double fovy, double aspect, double zNear, double zFar);

// gluLookAt's nine parameters: the eye, the point looked at, the up direction.
struct LookAt {
    glm::dvec3 eye{0, 0, 10};
    glm::dvec3 centre{0.0};
    glm::dvec3 up{0, 1, 0};
};

// The lab keeps the eye this far from the centre, at least and at most (its distance slider).
constexpr double kMinDistance = 1.0, kMaxDistance = 60.0;

// ④ (§2.3 task ④) The camera moved in (step > 0) or out (step < 0) by |step| along the line
// of sight: the eye moves towards / away from the centre, the centre and the up vector stay.
// The distance |eye - centre| after the move is kept within [kMinDistance, kMaxDistance]
// (the eye never reaches or passes the centre: gluLookAt with eye = centre has no view
// direction). Inputs: |eye - centre| in [1, 60], |step| <= 100, up not along the line of
// sight.
LookAt moveCamera(const LookAt& camera, double step);

// ⑤ (§2.3 task ⑤) The mirror image of the classroom in the blackboard wall, the plane
// z = wallZ (-100..100): call glTranslatef / glScalef / glRotatef (only those; no
// glLoadMatrix, glMultMatrix or glLoadIdentity) so that they multiply the CURRENT modelview
// matrix (the camera's) by the reflection (x, y, z) -> (x, y, 2·wallZ - z); the lab then
// draws the room again. Return the glFrontFace mode the mirrored room needs (GL_CCW =
// 0x0901 or GL_CW = 0x0900): a reflection turns counter-clockwise triangles clockwise.
unsigned mirrorInWall(float wallZ);

// The exercise table, in task order.
struct Table {
    Frustum (*perspectiveAsFrustum)(double, double, double, double);
    LookAt (*moveCamera)(const LookAt&, double);
    unsigned (*mirrorInWall)(float);
};

} // namespace wb::lab03
