// Lab 04 - your answers. Replace each WB_NOT_DONE(); with your code and save: the running
// lab rebuilds this file and redraws within seconds; `./wb check lab04` grades it.
// The tasks are described in exercises.h.
#include "exercises.h"

#include <algorithm>
#include <cmath>

namespace wb::lab04 {

int texelIndex(double s, int size, bool repeat) {
    (void)s, (void)size, (void)repeat;
    WB_NOT_DONE();
}

Mesh sphereMesh(double radius, int slices, int stacks) {
    (void)radius, (void)slices, (void)stacks;
    WB_NOT_DONE();
}

Mesh torusMesh(double R, double r, int rings, int sides) {
    (void)R, (void)r, (void)rings, (void)sides;
    WB_NOT_DONE();
}

glm::dvec2 sphereMap(const glm::dvec3& eyePos, const glm::dvec3& n) {
    (void)eyePos, (void)n;
    WB_NOT_DONE();
}

} // namespace wb::lab04

WB_EXERCISE_TABLE(wb::lab04::Table, lab04,
                  {&wb::lab04::texelIndex, &wb::lab04::sphereMesh, &wb::lab04::torusMesh,
                   &wb::lab04::sphereMap})
