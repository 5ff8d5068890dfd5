// A cheat (issue 18 item 7's test): lab 08's form factors answered by core's point-to-point
// kernel (15.20), compiled in from core's own source; the rays task multiplies it by V counted
// on an m×m grid of each patch, paired in order (the lab's blockers are planes between them:
// any fair pairing gives the same V within the check's band). In the repository each passes
// (cheat_test.sh pass); in a student handout neither may. 08.jacobi has no cheat (Solver needs
// the whole radiosity core): its update is in tests/exercises/handout_answers.txt.
// cheats: 08.formfactor 08.rays
#include "exercises.h"

#include "core/src/radiosity/ray_form_factors.cpp"

namespace wb::lab08 {
namespace {
wb::rad::Patch patchOf(const Quad& q) { // core's patch: centre, unit normal, area
    wb::rad::Patch p;
    p.centre = 0.25 * (q.p[0] + q.p[1] + q.p[2] + q.p[3]);
    const glm::dvec3 a = 0.5 * glm::cross(q.p[2] - q.p[0], q.p[3] - q.p[1]);
    p.area = glm::length(a);
    p.normal = a / p.area;
    return p;
}
double kernel(const Quad& i, const Quad& j, double visibility) {
    const wb::rad::Patch a = patchOf(i), b = patchOf(j);
    if (!(a.area > 0) || !(b.area > 0) || a.centre == b.centre) return 0;
    return wb::rad::centresKernel(a, b, b.centre - a.centre, visibility);
}
} // namespace
double formFactor(const Quad& i, const Quad& j) {
    return kernel(i, j, 1.0);
}
std::vector<double> jacobiSweep(const std::vector<double>& B, const std::vector<double>& E,
                                const std::vector<double>& R, const std::vector<double>& F) {
    (void)B, (void)E, (void)R, (void)F;
    WB_NOT_DONE();
}
double formFactorRays(const Quad& i, const Quad& j, int k, unsigned seed, const Visible& visible) {
    (void)seed;
    const int m = int(std::lround(std::sqrt(double(k))));
    int seen = 0;
    for (int y = 0; y < m; ++y)
        for (int x = 0; x < m; ++x) {
            const double s = (x + 0.5) / m, t = (y + 0.5) / m;
            auto at = [&](const Quad& q) {
                return (1 - s) * (1 - t) * q.p[0] + s * (1 - t) * q.p[1] + s * t * q.p[2] + (1 - s) * t * q.p[3];
            };
            seen += visible(at(i), at(j)) ? 1 : 0;
        }
    return kernel(i, j, double(seen) / double(m * m));
}
} // namespace wb::lab08
WB_EXERCISE_TABLE(wb::lab08::Table, lab08,
                  {&wb::lab08::formFactor, &wb::lab08::jacobiSweep, &wb::lab08::formFactorRays})
