// Lab 07 - your answers. Replace each WB_NOT_DONE(); with your code and save: the running
// lab rebuilds this file and redraws within seconds; `./wb check lab07` grades it.
// The tasks are described in exercises.h.
#include "exercises.h"

namespace wb::lab07 {

bool intersectSphere(const glm::dvec3& origin, const glm::dvec3& direction,
                     const glm::dvec3& centre, double radius, double& t) {
    (void)origin, (void)direction, (void)centre, (void)radius, (void)t;
    WB_NOT_DONE();
}

glm::dvec3 sphereNormal(const glm::dvec3& point, const glm::dvec3& centre, double radius) {
    (void)point, (void)centre, (void)radius;
    WB_NOT_DONE();
}

glm::dvec3 shade(const ShadeInput& in, const Feeler& feeler) {
    (void)in, (void)feeler;
    WB_NOT_DONE();
}

glm::dvec3 reflectDirection(const glm::dvec3& d, const glm::dvec3& n) {
    (void)d, (void)n;
    WB_NOT_DONE();
}

} // namespace wb::lab07

WB_EXERCISE_TABLE(wb::lab07::Table, lab07,
                  {&wb::lab07::intersectSphere, &wb::lab07::sphereNormal, &wb::lab07::shade,
                   &wb::lab07::reflectDirection})
