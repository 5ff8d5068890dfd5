// A cheat (issue 18 item 7's test): lab 06's tasks answered by calling core's Bezier code,
// compiled in from core's own sources. In the repository each task passes (cheat_test.sh
// pass: the cheat is a real one); in a student handout 06.circle and 06.sphere may not.
// cheats: 06.point 06.circle 06.sphere
// accepted: 06.point (core's Bezier evaluator stays in a handout: the teapot and the checks of
// 06.circle/06.sphere need one; docs/exercises.md, "Labs 06-08 in a handout")
#include "exercises.h"

#include "core/src/bezier.cpp"
#include "core/src/bezier_shapes.cpp"

namespace wb::lab06 {
glm::dvec3 bezierPoint(const Curve& p, double u) {
    return wb::evalDeCasteljau(p, u);
}
std::vector<Curve> circleCurves(double radius) {
    return wb::circleArcs(2, wb::circleHandle(2), radius);
}
std::vector<Patch> spherePatches() {
    std::vector<Patch> out;
    for (const auto& b : wb::sphereFromNet(wb::labHemisphereNet()))
        out.push_back(Patch{b.orderU, b.orderV, b.points});
    return out;
}
} // namespace wb::lab06
WB_EXERCISE_TABLE(wb::lab06::Table, lab06,
                  {&wb::lab06::bezierPoint, &wb::lab06::circleCurves, &wb::lab06::spherePatches})
