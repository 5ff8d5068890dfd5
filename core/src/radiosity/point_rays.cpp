#include "core/radiosity/point_rays.h"

#include "core/radiosity/closed_forms.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wb::rad {

void pointRayRow(const PatchMesh& mesh, const PatchBvh& bvh, const HemicubeFrame& frame, int k,
                 std::vector<float>& out) {
    if (k < 1 || k > 4096)
        throw std::invalid_argument("point ray row: k = " + std::to_string(k) + " outside 1..4096");
    const std::size_t n = mesh.patches.size();
    out.assign(n, 0.0f);
    const int side = std::max(1, int(std::lround(std::sqrt(double(k))))); // √k × √k grid
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t j) {
        const Patch& p = mesh.patches[j];
        if (glm::dot(p.normal, frame.origin - p.centre) <= 0.0) return; // its back to the point
        std::vector<glm::dvec3> poly;
        for (int c = 0; c < p.cornerCount; ++c) poly.push_back(mesh.vertices[size_t(p.corners[size_t(c)])]);
        const double f = pointToPolygon(frame.origin, frame.n, poly);
        if (f <= 0.0) return;
        int seen = 0, total = 0;
        for (int a = 0; a < side; ++a)
            for (int b = 0; b < side; ++b) {
                const double u = (a + 0.5) / side, v = (b + 0.5) / side;
                glm::dvec3 q;
                if (p.cornerCount == 4) {
                    q = (1 - u) * (1 - v) * poly[0] + u * (1 - v) * poly[1] + u * v * poly[2] +
                        (1 - u) * v * poly[3];
                } else { // fold the square onto the triangle (u + v <= 1)
                    const double uu = u + v > 1 ? 1 - u : u, vv = u + v > 1 ? 1 - v : v;
                    q = (1 - uu - vv) * poly[0] + uu * poly[1] + vv * poly[2];
                }
                ++total;
                if (bvh.visible(frame.origin, q)) ++seen;
            }
        out[j] = float(f * double(seen) / double(total));
    });
}

} // namespace wb::rad
