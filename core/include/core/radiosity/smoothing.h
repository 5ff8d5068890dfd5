#pragma once
// The course's last step (figures 13.42 -> 13.43): a value per vertex from the patches around
// it, for Gouraud display. A vertex's value is the area-weighted mean of the radiosities of
// the patches of its own surface that contain it (as a corner or, for a T-vertex, on an edge),
// so light never leaks across surfaces. Vertices on a surface's boundary are not extrapolated
// (a simple mean: the course's averaging).
#include "core/radiosity/mesh.h"

#include <vector>

namespace wb::rad {

// One RGB value per vertex of `mesh` from one RGB value per patch.
std::vector<glm::dvec3> vertexRadiosity(const PatchMesh& mesh, const std::vector<glm::dvec3>& B);

} // namespace wb::rad
