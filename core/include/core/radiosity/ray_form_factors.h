#pragma once
// Form factors by ray casting (§1.15.1): k points on each patch (stratified: a jittered
// √k×√k grid, "uniformly spread"), paired at random (a seeded permutation per patch pair, so
// results are deterministic and symmetric), V_ij = fraction of the k rays that reach the
// other patch unblocked (PatchBvh::visible, the project's BVH any-hit query). The geometric
// term is one of:
//  - Centres: the course's (15.20), F_ij = V_ij cos φ_i cos φ_j A_j / (π d²) at the centres;
//  - PointPairs: (15.20) per ray pair, averaged: A_j/k Σ V_s cos cos/(π r_s²);
//  - PointToPolygon: 1/k Σ V_s F(dA at sample s on P_i -> P_j) with the exact contour integral
//    (closed_forms.h): exact for unoccluded pairs up to the sampling of P_i; the contour
//    integral clips P_j to P_i's front half-space, so the visibility rays aim at that part too
//    (an end behind P_i's plane is redrawn on it);
//  - Auto: PointToPolygon for near pairs (centre distance < nearFactor × the larger patch
//    diameter), Centres otherwise.
#include "core/radiosity/patch_bvh.h"

#include <cstdint>

namespace wb::rad {

enum class RayKernel { Centres, PointPairs, PointToPolygon, Auto };

struct RayFormFactorConfig {
    int samples = 16;                    // k points per patch (rays per pair), 1..4096
    RayKernel kernel = RayKernel::Auto;  // geometric term, see above
    double nearFactor = 3.0;             // Auto: "near" = centre distance < this × diameter
    std::uint64_t seed = 1;              // for sample jitter and pairing
};

// F_ij for one pair (0 when i == j or they do not face each other).
double rayFormFactor(const PatchMesh& mesh, const PatchBvh& bvh, int i, int j,
                     const RayFormFactorConfig& config);

// Row i: out[j] = F_ij for every j (out resized to the patch count).
void rayFormFactorRow(const PatchMesh& mesh, const PatchBvh& bvh, int i,
                      const RayFormFactorConfig& config, std::vector<float>& out);

} // namespace wb::rad
