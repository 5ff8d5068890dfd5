// Lab 03 - the reference answers and, behind WB_MUTANT(n), the typical mistakes CI checks
// the grading against (listed with their ids in exercise_checks.cpp).
#include "exercises.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace wb::lab03 {

Frustum perspectiveAsFrustum(double fovy, double aspect, double zNear, double zFar) {
    constexpr double kPi = 3.14159265358979323846;
    const double half = WB_MUTANT(21) ? fovy * kPi / 180 : fovy * kPi / 360; // 21: not halved
    const double top = zNear * std::tan(WB_MUTANT(22) ? fovy / 2 : half);    // 22: degrees
    const double right = WB_MUTANT(23) ? top / aspect : top * aspect;        // 23: aspect inverted
    return {-right, right, -top, top, zNear, zFar};
}

LookAt moveCamera(const LookAt& camera, double step) {
    const glm::dvec3 toEye = camera.eye - camera.centre;
    const double dist = glm::length(toEye);
    double next = dist - (WB_MUTANT(2) ? -step : step);                     // 2: in and out swapped
    if (!WB_MUTANT(4)) next = std::clamp(next, kMinDistance, kMaxDistance); // 4: no limit
    LookAt out = camera;
    if (WB_MUTANT(1)) { // 1: the unnormalised line of sight: moves step·dist
        out.eye = camera.eye - step * (toEye);
        return out;
    }
    out.eye = camera.centre + toEye * (next / dist);
    if (WB_MUTANT(3)) out.centre = camera.centre + (out.eye - camera.eye); // 3: centre moved too
    return out;
}

unsigned mirrorInWall(float wallZ) {
    if (WB_MUTANT(15)) glLoadIdentity(); // 15: the camera's matrix thrown away
    if (WB_MUTANT(16)) { // 16: the right matrix, but by glMultMatrixd (the task forbids it)
        const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 2.0 * wallZ, 1};
        glMultMatrixd(m);
    } else if (WB_MUTANT(12)) { // 12: the translations in the wrong order
        glTranslatef(0, 0, -wallZ);
        glScalef(1, 1, -1);
        glTranslatef(0, 0, wallZ);
    } else if (WB_MUTANT(11)) { // 11: one translation: mirrored in z = 0, then moved
        glTranslatef(0, 0, wallZ);
        glScalef(1, 1, -1);
    } else {
        // Move the wall to z = 0, flip z, move it back: T(wallZ)·S(1,1,-1)·T(-wallZ).
        glTranslatef(0, 0, wallZ);
        glScalef(WB_MUTANT(13) ? -1.0f : 1.0f, 1, WB_MUTANT(13) ? 1.0f : -1.0f); // 13: x flipped
        glTranslatef(0, 0, -wallZ);
    }
    return WB_MUTANT(14) ? GL_CCW : GL_CW; // 14: the front faces not turned
}

} // namespace wb::lab03

WB_EXERCISE_TABLE(wb::lab03::Table, lab03,
                  {&wb::lab03::perspectiveAsFrustum, &wb::lab03::moveCamera,
                   &wb::lab03::mirrorInWall})
