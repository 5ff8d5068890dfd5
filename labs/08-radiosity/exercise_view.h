#pragma once
// Lab 08's exercise mode in the window (issue 18): two facing squares with a plate over half
// of the gap between them. Your formFactorRays (exercises.cpp) casts its rays through the
// lab's visibility test, and each ray is drawn (green: it got through, red: the plate stopped
// it), the reference's rays over them as a ghost; the panel lines compare your (15.20), your
// ray-cast F and your Jacobi sweeps with the reference and the closed form.
#include "common/exercise_mode.h"
#include "common/lab.h"

#include <string>
#include <vector>

namespace wb {

// Draws the scene and the rays (its own projection: the lab's orbit and zoom apply).
void drawRadiosityExercise(const ex::ExerciseMode& mode, const View& view);
// The panel lines: F by (15.20), by rays, and B after sweeps, yours against the reference.
std::vector<std::string> radiosityExerciseLines(const ex::ExerciseMode& mode);

} // namespace wb
