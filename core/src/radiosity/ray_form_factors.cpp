#include "core/radiosity/ray_form_factors.h"

#include <stdexcept>

namespace wb::rad {
double rayFormFactor(const PatchMesh&, const PatchBvh&, int, int, const RayFormFactorConfig&) { throw std::logic_error("radiosity: ray form factors not implemented yet"); }
void rayFormFactorRow(const PatchMesh&, const PatchBvh&, int, const RayFormFactorConfig&, std::vector<float>&) { throw std::logic_error("radiosity: ray form factors not implemented yet"); }
} // namespace wb::rad
