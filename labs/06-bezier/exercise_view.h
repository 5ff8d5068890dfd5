#pragma once
// Lab 06's exercise mode in the window (issue 18): the student's circle and sphere drawn
// with GL's evaluators as the lab draws its own, the reference's over them as a ghost.
#include "common/exercise_mode.h"

namespace wb {

// The circle of radius 1 from the student's two curves (06.circle) in the arc colours, with
// their control polygons when `control`; the reference's curves as a ghost. True when the
// student's curves were drawn (false: not done / failing, only the ghost is shown).
bool drawCircleExercise(const ex::ExerciseMode& mode, int grid, bool control);
// The student's two patches (06.sphere), lit (GL_AUTO_NORMAL) or as a wireframe, with their
// nets when `control`; the reference's patches as a ghost wireframe.
bool drawSphereExercise(const ex::ExerciseMode& mode, int grid, bool wireframe, bool control);

} // namespace wb
