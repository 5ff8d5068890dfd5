#pragma once
// Lab 07's exercise mode in the window (issue 18): a small scene of three spheres under one
// point light traced with YOUR functions (exercises.cpp: intersection, normal, lighting with
// the shadow feeler, the reflected ray), the same scene traced with the reference's laid
// over it as a ghost. A step the student has not done yet falls back to the reference's
// (so the picture grows task by task) and the panel says which.
#include "common/exercise_mode.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wb {

struct ExerciseTrace {
    int width = 0, height = 0;
    std::vector<uint8_t> mine, reference; // RGB, bottom row first (glDrawPixels)
    std::string usedYours;                // which of your functions the picture used
};

// Traces both pictures at width × height (small: every pixel calls through the table).
ExerciseTrace traceExercise(const ex::ExerciseMode& mode, int width, int height);
// Draws the trace filling the viewport: yours, then the reference's blended at the ghost's
// alpha.
void drawExerciseTrace(const ExerciseTrace& t, int viewWidth, int viewHeight);

} // namespace wb
