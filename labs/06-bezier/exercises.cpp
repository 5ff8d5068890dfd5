// Lab 06 - your answers. Replace each WB_NOT_DONE(); with your code and save: the running
// lab rebuilds this file and redraws within seconds; `./wb check lab06` grades it.
// The tasks are described in exercises.h.
#include "exercises.h"

namespace wb::lab06 {

glm::dvec3 bezierPoint(const Curve& p, double u) {
    (void)p, (void)u;
    WB_NOT_DONE();
}

std::vector<Curve> circleCurves(double radius) {
    (void)radius;
    WB_NOT_DONE();
}

std::vector<Patch> spherePatches() {
    WB_NOT_DONE();
}

} // namespace wb::lab06

WB_EXERCISE_TABLE(wb::lab06::Table, lab06,
                  {&wb::lab06::bezierPoint, &wb::lab06::circleCurves, &wb::lab06::spherePatches})
