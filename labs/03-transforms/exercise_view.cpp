#include "exercise_view.h"

#include "common/gl.h"
#include "exercises.h"

namespace wb {

bool exerciseProjection(const ex::ExerciseMode& mode, double fovy, double aspect, double zNear,
                        double zFar) {
    const auto* t = mode.on() ? mode.studentTable<lab03::Table>() : nullptr;
    if (!t) return false;
    const auto f = mode.call(
        "03.frustum", [&] { return t->perspectiveAsFrustum(fovy, aspect, zNear, zFar); }, fovy,
        aspect, zNear, zFar);
    if (!f) return false;
    glFrustum(f->left, f->right, f->bottom, f->top, f->zNear, f->zFar);
    return true;
}

std::optional<double> exerciseCameraStep(const ex::ExerciseMode& mode, double distance,
                                         double step) {
    const auto* t = mode.on() ? mode.studentTable<lab03::Table>() : nullptr;
    if (!t) return std::nullopt;
    // The lab's camera looks at its centre from `distance` along some direction: the
    // distance is all that changes, so one line of sight stands for every orbit.
    const lab03::LookAt cam{{0, 0, distance}, {0, 0, 0}, {0, 1, 0}};
    const auto moved = mode.call(
        "03.camera", [&] { return t->moveCamera(cam, step); }, distance, step);
    if (!moved) return std::nullopt;
    const double d = glm::length(moved->eye - moved->centre);
    if (!(d > 0) || !(d < 1e6)) return std::nullopt;
    return d;
}

std::optional<unsigned> exerciseMirror(const ex::ExerciseMode& mode, float wallZ) {
    const auto* t = mode.on() ? mode.studentTable<lab03::Table>() : nullptr;
    if (!t) return std::nullopt;
    return mode.call(
        "03.mirror", [&] { return t->mirrorInWall(wallZ); }, wallZ);
}

} // namespace wb
