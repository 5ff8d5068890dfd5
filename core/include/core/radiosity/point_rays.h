#pragma once
// Form factors by rays (§1.15.1) for the shooting groups of progressive refinement, computed
// at the RECEIVER (Wallace, Elmquist, Haines 1989: ray-traced progressive radiosity): a group
// is a block of ~11×11 patches, 0.3 m in the Cornell box, and F from its centroid (what a
// hemicube at the centroid gives) is 10-85% off for the block faces next to it (near field,
// measured against per-patch shooting). Here, for every receiving patch j:
//   F(dA_j → G) = pointToPolygon(centre_j, normal_j, hull of G)   (exact, closed_forms.h)
//   V_j         = fraction of k rays from centre_j to k member centres of G unblocked
// and the row entry the solver uses (it adds R_j·ΔB_G·F_Gj·A_G/A_j) is
//   F_Gj = A_j · F(dA_j → G) · V_j / A_live,
// A_live the area of the members any receiver saw: members hidden under a block (meshed but
// never lit) shoot nothing, so the group's pooled power leaves from its visible part only.
// Deterministic (members picked in a fixed stratified order), receivers on all cores (TBB).
#include "core/radiosity/patch_bvh.h"

#include <vector>

namespace wb::rad {

// out[j] for group g of mesh.groups (out resized to the patch count). k in 1..4096.
void groupGatherRow(const PatchMesh& mesh, const PatchBvh& bvh, int g, int k,
                    std::vector<float>& out);

// The group's outline: convex hull of its members' corners (in its surface's plane).
std::vector<glm::dvec3> groupHull(const PatchMesh& mesh, int g);

} // namespace wb::rad
