#pragma once
// Lab 05's exercise mode in the window (issue 18): with it on (key E; e is the elliptical
// mirror here) the lab reflects, shadows and masks with YOUR matrices and outline
// (exercises.cpp), and draws the reference's shadow and mirror outlines over the picture
// as a ghost. Each answer is used once its check lets it be called, else the reference's
// (none in a student handout: nullopt / empty, and the lab leaves that part out).
#include "common/exercise_mode.h"
#include "core/affine.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace wb {

// The reflection in `plane`: yours (05.reflection) when on and callable, else `reference`.
std::optional<glm::dmat4> exerciseReflection(const ex::ExerciseMode& mode, const Plane& plane,
                                             const std::optional<glm::dmat4>& reference);
// The shadow on `plane` from the point light: yours (05.shadow) or `reference`.
std::optional<glm::dmat4> exerciseShadow(const ex::ExerciseMode& mode, const Plane& plane,
                                         const glm::dvec3& light,
                                         const std::optional<glm::dmat4>& reference);
// The elliptical mirror's outline: yours (05.ellipse, `n` points) or `reference`.
std::vector<glm::dvec3> exerciseEllipse(const ex::ExerciseMode& mode, const glm::dvec2& centre,
                                        double a, double b, double z, int n,
                                        const std::vector<glm::dvec3>& reference);
// The reference's ellipse outline as a ghost (a dashed loop), under the current matrices.
void drawEllipseGhost(const std::vector<glm::dvec3>& reference);

} // namespace wb
