// Lab 05 - your answers. Replace each WB_NOT_DONE(); with your code and save: the running
// lab rebuilds this file and redraws within seconds; `./wb check lab05` grades it.
// The tasks are described in exercises.h.
#include "exercises.h"

#include <cmath>

namespace wb::lab05 {

glm::dmat4 reflectionMatrix(const glm::dvec4& plane) {
    (void)plane;
    WB_NOT_DONE();
}

glm::dmat4 shadowMatrix(const glm::dvec4& plane, const glm::dvec4& light) {
    (void)plane, (void)light;
    WB_NOT_DONE();
}

std::vector<glm::dvec3> ellipseOutline(const glm::dvec2& centre, double a, double b, double z,
                                       int n) {
    (void)centre, (void)a, (void)b, (void)z, (void)n;
    WB_NOT_DONE();
}

} // namespace wb::lab05

WB_EXERCISE_TABLE(wb::lab05::Table, lab05,
                  {&wb::lab05::reflectionMatrix, &wb::lab05::shadowMatrix,
                   &wb::lab05::ellipseOutline})
