#pragma once
// Form factors by rays (§1.15.1) from a point, for the shooting groups of progressive
// refinement (a group shoots from its centroid, it is not a patch): F(dA at `frame.origin`
// with normal `frame.n` → P_j) = V_j · F_exact, F_exact the point-to-polygon contour integral
// (closed_forms.h, P_j clipped to the point's front half-space) and V_j the fraction of k rays
// from the point to k points on P_j (a √k×√k grid of cell centres in the patch's corners'
// bilinear / barycentric parameters) that PatchBvh::visible lets through. Patches that turn
// their back to the point get 0. Deterministic (no random jitter), rows on all cores (TBB).
#include "core/radiosity/hemicube.h"
#include "core/radiosity/patch_bvh.h"

#include <vector>

namespace wb::rad {

// out[j] = F from the point to patch j (out resized to the patch count). k in 1..4096.
void pointRayRow(const PatchMesh& mesh, const PatchBvh& bvh, const HemicubeFrame& frame, int k,
                 std::vector<float>& out);

} // namespace wb::rad
