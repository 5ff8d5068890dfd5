// Lab 06 - the reference answers and, behind WB_MUTANT(n), the typical mistakes CI checks
// the grading against (listed with their ids in exercise_checks.cpp).
#include "exercises.h"

#include <utility>

namespace wb::lab06 {

glm::dvec3 bezierPoint(const Curve& p, double u) {
    if (WB_MUTANT(21)) u = 1 - u; // 21: the curve run backwards (u and 1 - u swapped)
    Curve q = p;
    const size_t rounds =
        WB_MUTANT(22) ? (q.size() > 1 ? q.size() - 2 : 0) : q.size() - 1; // 22: one round short
    for (size_t r = 0; r < rounds; ++r)
        for (size_t i = 0; i + 1 < q.size() - r; ++i)
            q[i] = WB_MUTANT(23) ? 0.5 * (q[i] + q[i + 1])
                                 : (1 - u) * q[i] + u * q[i + 1]; // 23: midpoints
    return q.empty() ? glm::dvec3(0.0) : q[0];
}

std::vector<Curve> circleCurves(double radius) {
    // Half circles: the arc's midpoint (p0 + 3p1 + 3p2 + p3)/8 lies on the circle when
    // the handle is k = 4/3·tan(θ/4) = 4/3 for θ = π.
    double k = 4.0 / 3.0;
    if (WB_MUTANT(1)) k = 0.5523; // the quarter-circle handle used for half circles
    const double h = WB_MUTANT(3) ? k : k * radius; // handle not scaled with the radius
    const double r = radius;
    Curve upper = {{r, 0, 0}, {r, h, 0}, {-r, h, 0}, {-r, 0, 0}};
    Curve lower = {{-r, 0, 0}, {-r, -h, 0}, {r, -h, 0}, {r, 0, 0}};
    if (WB_MUTANT(2)) lower = {{-r, 0, 0}, {-r, h, 0}, {r, h, 0}, {r, 0, 0}}; // sign of y
    if (WB_MUTANT(4)) std::swap(upper[1], upper[2]); // inner points in the wrong order
    return {upper, lower};
}

std::vector<Patch> spherePatches() {
    // The course's net (§2.6), one row per line of the table: p_ij = points[j·4 + i].
    Patch upper;
    upper.points = {{2, -2, 0},  {3, -1, 0},  {3, 1, 0},  {2, 2, 0},  //
                    {1, -3, 0},  {2, -3, 5},  {2, 3, 5},  {1, 3, 0},  //
                    {-1, -3, 0}, {-2, -3, 5}, {-2, 3, 5}, {-1, 3, 0}, //
                    {-2, -2, 0}, {-3, -1, 0}, {-3, 1, 0}, {-2, 2, 0}};
    if (WB_MUTANT(13)) // the net transposed: p_ij and p_ji swapped, so du × dv turns inwards
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j)
                std::swap(upper.points[size_t(j * 4 + i)], upper.points[size_t(i * 4 + j)]);
    Patch lower = upper;
    for (auto& p : lower.points)
        p.z = WB_MUTANT(12) ? p.z : -p.z; // 12: forgot to mirror: the upper half twice
    if (!WB_MUTANT(11)) {                 // 11: mirrored without reversing the rows: lit inside
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 4; ++i)
                std::swap(lower.points[size_t(j * 4 + i)], lower.points[size_t((3 - j) * 4 + i)]);
    }
    return {upper, lower};
}

} // namespace wb::lab06

WB_EXERCISE_TABLE(wb::lab06::Table, lab06,
                  {&wb::lab06::bezierPoint, &wb::lab06::circleCurves, &wb::lab06::spherePatches})
