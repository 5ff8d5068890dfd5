// A cheat (issue 18 item 7's test): lab 07's sphere, normal and reflection answered by core's
// sphere test (sphere.cpp's nearest<true>, what Sphere::intersect and the BVH's exact
// confirmation call) and reflectDir (tracer.cpp), compiled in from core's own sources. In the
// repository each passes (cheat_test.sh pass); in a student handout none may (the bodies are
// cut). 07.shade has its own cheat (lab07_shade.cpp: core's lighting is another source).
// cheats: 07.intersect 07.normal 07.reflect
#include "exercises.h"

#include "core/src/raytrace/ray.cpp"
#include "core/src/raytrace/sphere.cpp"
#include "core/src/raytrace/tracer.cpp"
#include <cfloat>

namespace wb::lab07 {
bool intersectSphere(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r, double& t) {
    wb::rt::Ray ray;
    ray.origin = o;
    ray.direction = d;
    glm::dvec3 n;
    return wb::rt::nearest<true>(c, r, ray, 0.0, DBL_MAX, t, n);
}
// The normal as nearest<true> gives it at the point, for a ray from outside straight at it.
glm::dvec3 sphereNormal(const glm::dvec3& p, const glm::dvec3& c, double r) {
    wb::rt::Ray ray;
    ray.origin = p + (p - c);
    ray.direction = glm::normalize(c - p);
    double t;
    glm::dvec3 n(0.0);
    if (!wb::rt::nearest<true>(c, r, ray, 0.0, DBL_MAX, t, n)) return glm::dvec3(0.0);
    return n;
}
glm::dvec3 shade(const ShadeInput& in, const Feeler& feeler) {
    (void)in, (void)feeler;
    WB_NOT_DONE();
}
glm::dvec3 reflectDirection(const glm::dvec3& d, const glm::dvec3& n) {
    return wb::rt::reflectDir(d, n);
}
} // namespace wb::lab07
WB_EXERCISE_TABLE(wb::lab07::Table, lab07,
                  {&wb::lab07::intersectSphere, &wb::lab07::sphereNormal, &wb::lab07::shade,
                   &wb::lab07::reflectDirection})
