#include "core/radiosity/mesh.h"

#include <stdexcept>

namespace wb::rad {
std::vector<glm::dvec3> PatchMesh::cornersOf(int) const { throw std::logic_error("radiosity: meshing not implemented yet"); }
double PatchMesh::totalArea() const { throw std::logic_error("radiosity: meshing not implemented yet"); }
PatchMesh meshScene(const Scene&, const MeshConfig&) { throw std::logic_error("radiosity: meshing not implemented yet"); }
int refineAdaptive(PatchMesh&, const std::vector<glm::dvec3>&, const RefineConfig&, std::vector<int>*) { throw std::logic_error("radiosity: refinement not implemented yet"); }
std::vector<std::array<int, 3>> displayTriangles(const PatchMesh&, std::vector<int>*) { throw std::logic_error("radiosity: not implemented yet"); }
} // namespace wb::rad
