#include "core/radiosity/smoothing.h"

#include <stdexcept>

namespace wb::rad {
std::vector<glm::dvec3> vertexRadiosity(const PatchMesh&, const std::vector<glm::dvec3>&) { throw std::logic_error("radiosity: smoothing not implemented yet"); }
} // namespace wb::rad
