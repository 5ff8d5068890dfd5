#pragma once
// Shared helpers of the radiosity tests: a closed room with a floating closed box (occlusion,
// every surface seen only from the front), and aggregate properties of F.
#include "core/radiosity/form_factors.h"
#include "core/radiosity/scenes.h"

#include <algorithm>
#include <cmath>

namespace wb::rad::test {

inline Scene boxInRoom() {
    Scene s = furnace(0.5, 0.0);
    s.name = "box in room";
    s.surfaces[1].emission = glm::dvec3(1.0); // the ceiling lights
    const glm::dvec3 lo(0.35, 0.3, 0.35), hi(0.65, 0.6, 0.65), c = 0.5 * (lo + hi);
    const glm::dvec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                             {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int quads[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}, {3, 2, 6, 7}, {0, 1, 5, 4}};
    for (const auto& q : quads) {
        std::vector<glm::dvec3> poly = {p[q[0]], p[q[1]], p[q[2]], p[q[3]]};
        glm::dvec3 m(0.0);
        for (const auto& v : poly) m += 0.25 * v;
        if (glm::dot(polygonNormal(poly), m - c) < 0) std::reverse(poly.begin(), poly.end());
        s.surfaces.push_back(Surface{poly, glm::dvec3(0.6, 0.3, 0.2), glm::dvec3(0.0), "box"});
    }
    return s;
}

struct FfStats {
    double maxDiag = 0.0;       // max |F_ii|
    double reciprocity = 0.0;   // Σ|A_i F_ij − A_j F_ji| / Σ A_i F_ij  (aggregate)
    double maxRowError = 0.0;   // max_i |Σ_j F_ij − 1|
    double meanRowError = 0.0;  // mean_i |Σ_j F_ij − 1|
    double minRow = 1e9, maxRow = 0.0;
};

inline FfStats stats(const PatchMesh& m, FormFactors& ff) {
    ff.computeAll();
    const int n = ff.size();
    FfStats s;
    double num = 0.0, den = 0.0;
    for (int i = 0; i < n; ++i) {
        double row = 0.0;
        for (int j = 0; j < n; ++j) {
            const double fij = ff.at(i, j), fji = ff.at(j, i);
            row += fij;
            if (i == j) s.maxDiag = std::max(s.maxDiag, std::abs(fij));
            if (j > i) {
                num += std::abs(m.patches[static_cast<std::size_t>(i)].area * fij -
                                m.patches[static_cast<std::size_t>(j)].area * fji);
                den += m.patches[static_cast<std::size_t>(i)].area * fij +
                       m.patches[static_cast<std::size_t>(j)].area * fji;
            }
        }
        s.maxRowError = std::max(s.maxRowError, std::abs(row - 1.0));
        s.meanRowError += std::abs(row - 1.0) / n;
        s.minRow = std::min(s.minRow, row);
        s.maxRow = std::max(s.maxRow, row);
    }
    s.reciprocity = den > 0 ? 2.0 * num / den : 0.0;
    return s;
}

// F from surface a to surface b of a mesh: Σ_{i∈a} Σ_{j∈b} A_i F_ij / A_a.
inline double surfaceFF(const PatchMesh& m, FormFactors& ff, int a, int b) {
    std::vector<float> scratch;
    double num = 0.0, area = 0.0;
    for (int i = 0; i < ff.size(); ++i) {
        if (m.patches[static_cast<std::size_t>(i)].surface != a) continue;
        const float* row = ff.row(i, scratch);
        area += m.patches[static_cast<std::size_t>(i)].area;
        for (int j = 0; j < ff.size(); ++j)
            if (m.patches[static_cast<std::size_t>(j)].surface == b)
                num += m.patches[static_cast<std::size_t>(i)].area * row[j];
    }
    return num / area;
}

} // namespace wb::rad::test
