// Lab 03 - your answers. Replace each WB_NOT_DONE(); with your code and save: the running
// lab rebuilds this file and redraws within seconds; `./wb check lab03` grades it.
// The tasks are described in exercises.h.
#include "exercises.h"

#include <GL/gl.h>

#include <cmath>

namespace wb::lab03 {

Frustum perspectiveAsFrustum(double fovy, double aspect, double zNear, double zFar) {
    (void)fovy, (void)aspect, (void)zNear, (void)zFar;
    WB_NOT_DONE();
}

LookAt moveCamera(const LookAt& camera, double step) {
    (void)camera, (void)step;
    WB_NOT_DONE();
}

unsigned mirrorInWall(float wallZ) {
    (void)wallZ;
    WB_NOT_DONE();
}

} // namespace wb::lab03

WB_EXERCISE_TABLE(wb::lab03::Table, lab03,
                  {&wb::lab03::perspectiveAsFrustum, &wb::lab03::moveCamera,
                   &wb::lab03::mirrorInWall})
