// Lab 08 - your answers. Replace each WB_NOT_DONE(); with your code and save: the running
// lab rebuilds this file; `./wb check lab08` grades it. The tasks are described in
// exercises.h.
#include "exercises.h"

#include <algorithm>
#include <random>

namespace wb::lab08 {

double formFactor(const Quad& i, const Quad& j) {
    (void)i, (void)j;
    WB_NOT_DONE();
}

std::vector<double> jacobiSweep(const std::vector<double>& B, const std::vector<double>& E,
                                const std::vector<double>& R, const std::vector<double>& F) {
    (void)B, (void)E, (void)R, (void)F;
    WB_NOT_DONE();
}

double formFactorRays(const Quad& i, const Quad& j, int k, unsigned seed, const Visible& visible) {
    (void)i, (void)j, (void)k, (void)seed, (void)visible;
    WB_NOT_DONE();
}

} // namespace wb::lab08

WB_EXERCISE_TABLE(wb::lab08::Table, lab08,
                  {&wb::lab08::formFactor, &wb::lab08::jacobiSweep, &wb::lab08::formFactorRays})
