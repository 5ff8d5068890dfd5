#pragma once
// Lab 03's exercise mode in the window (issue 18): with `e` on the lab projects with your
// glFrustum for gluPerspective (03.frustum), moves the camera with your moveCamera on z / x
// (03.camera) and mirrors the classroom through your glTranslatef/glScalef calls
// (03.mirror), the reference's mirrored room drawn over it as a ghost wireframe. An answer
// is used once its check lets it be called; otherwise the lab's own code runs.
#include "common/exercise_mode.h"

#include <glm/glm.hpp>

#include <optional>

namespace wb {

// glFrustum from your perspectiveAsFrustum; false (nothing issued) when not callable.
bool exerciseProjection(const ex::ExerciseMode& mode, double fovy, double aspect, double zNear,
                        double zFar);
// The eye's new distance from the centre after your moveCamera by `step` (world units of the
// lab's distance); nullopt when not callable.
std::optional<double> exerciseCameraStep(const ex::ExerciseMode& mode, double distance,
                                         double step);
// Your mirrorInWall(wallZ) on the current matrix; its glFrontFace mode, nullopt (and no
// calls made) when not callable.
std::optional<unsigned> exerciseMirror(const ex::ExerciseMode& mode, float wallZ);

} // namespace wb
