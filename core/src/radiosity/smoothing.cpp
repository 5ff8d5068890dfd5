#include "core/radiosity/smoothing.h"

#include <stdexcept>
#include <string>

namespace wb::rad {

std::vector<glm::dvec3> vertexRadiosity(const PatchMesh& mesh, const std::vector<glm::dvec3>& B) {
    if (B.size() != mesh.patches.size())
        throw std::invalid_argument("radiosity smoothing: " + std::to_string(B.size()) +
                                    " values for " + std::to_string(mesh.patches.size()) +
                                    " patches");
    std::vector<glm::dvec3> sum(mesh.vertices.size(), glm::dvec3(0.0));
    std::vector<double> weight(mesh.vertices.size(), 0.0);
    // Outlines hold corners and T-vertices, and vertices belong to one surface, so every
    // patch touching a vertex (on its surface) contributes, weighted by its area.
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        for (int v : p.outline) {
            sum[static_cast<std::size_t>(v)] += p.area * B[i];
            weight[static_cast<std::size_t>(v)] += p.area;
        }
    }
    for (std::size_t v = 0; v < sum.size(); ++v)
        if (weight[v] > 0.0) sum[v] /= weight[v];
    // Stitched vertices (on a patch edge where another surface meets it): interpolated along
    // that edge, in the order they were put there (an end may be an earlier one).
    for (const auto& sv : mesh.seamVertices)
        sum[static_cast<std::size_t>(sv.vertex)] =
            (1.0 - sv.t) * sum[static_cast<std::size_t>(sv.a)] + sv.t * sum[static_cast<std::size_t>(sv.b)];
    // Centre vertices (apex of a T-vertex patch's fan): the mean of its outline's values.
    for (const Patch& p : mesh.patches) {
        if (p.centreVertex < 0) continue;
        glm::dvec3 m(0.0);
        for (int v : p.outline) m += sum[static_cast<std::size_t>(v)];
        sum[static_cast<std::size_t>(p.centreVertex)] = m / static_cast<double>(p.outline.size());
    }
    return sum;
}

} // namespace wb::rad
