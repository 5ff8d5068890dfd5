// A cheat (issue 18 item 7's test): lab 05's matrices answered by calling core's 3D mirror and
// shadow maps, compiled in from core's own source. In the repository each passes
// (cheat_test.sh pass: the cheat is a real one); in a student handout, where their bodies
// are cut, neither may (cheat_test.sh fail). The ellipse has no core function (the lab's
// own outline is cut from a handout; tests/exercises/handout_test.sh greps for it).
// cheats: 05.reflection 05.shadow
#include "exercises.h"

#include "core/src/affine.cpp"

namespace wb::lab05 {

glm::dmat4 reflectionMatrix(const glm::dvec4& plane) {
    return wb::mirrorPlane({glm::dvec3(plane), plane.w});
}

glm::dmat4 shadowMatrix(const glm::dvec4& plane, const glm::dvec4& light) {
    const wb::Plane p{glm::dvec3(plane), plane.w};
    if (light.w != 0) return wb::shadowPoint(p, glm::dvec3(light) / light.w);
    // A light at infinity towards (x, y, z): core's rays run along -(x, y, z), its matrix is
    // the course's divided by π·L (the sign OpenGL needs comes back with the factor).
    const double pl = glm::dot(plane, light);
    const glm::dmat4 m = wb::shadowDirectional(p, -glm::dvec3(light));
    return pl != 0 ? pl * m : -m;
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
