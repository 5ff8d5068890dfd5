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

struct GroupNearField;
// out[j] for group g of mesh.groups (out resized to the patch count). k in 1..4096.
// `near`: g's near field (FormFactors::nearFieldReady), whose receivers the solver shoots member
// by member: their entries are left 0 and only their visibility rays are cast (they count in
// A_live as before), which skips their point-to-polygon terms (16 points each next to the
// group's plane; all of an emitter's row).
// `exactPieces`: a group whose members do not fill its hull (ragged: a floor group round a block's
// foot) sums F over its members' exposed pieces (exact; the default). false: F to the hull
// scaled by members' area / hull area, one contour per receiver instead of one per piece (lab
// 08's preview at 0.30 m groups, whose floor groups hold ~100 pieces each: a first picture, not
// the answer).
void groupGatherRow(const PatchMesh& mesh, const PatchBvh& bvh, int g, int k,
                    std::vector<float>& out, const GroupNearField* near = nullptr,
                    bool exactPieces = true);

// The near field of group g: the receivers within `radius` of the group's centroid, and for
// each the gather form factor to every member m, w_jm = F(dA_j → P_m) · V(j, m) (exact point-
// to-polygon, scaled by the member's exposed fraction; one visibility ray centre to centre).
// A group pools its members' unshot radiosity and shoots the mean: a receiver close to it
// sees its near members most, and where the group straddles a shadow edge (the floor at a
// block's foot) the mean is far from what those members hold. The solver shoots a near
// receiver's share member by member: it gets R_j Σ_m ΔB_m w_jm (docs/bench/radiosity.md).
struct GroupNearField {
    std::vector<int> receivers; // patch ids
    std::vector<float> w;       // receivers.size() × members, row-major
    // Every receiver in front of the group is in the near field (an emitter's groups): the
    // group's row is then not needed (the solver does not ask for it).
    bool everyReceiver = false;
    // Far receivers (the rest, in front of the group): where the group's members are, as j sees
    // them: the offset from the group's centroid of the members' centroid weighted by the
    // unoccluded point kernel cos·cos/r² from j's centre, along the group's u and v axes (m);
    // n entries, 0 for near receivers and those behind. A group shoots its members' ΔB pooled;
    // the solver fits ΔB's gradient over the members and j gets the pooled mean plus the
    // gradient times this offset (first order in the group's size: Σ_m A_m ΔB_m F_mj). Pooled
    // flat, a receiver that sees the group's bright side nearer got its mean: the ceiling in
    // front of the light 1.5% too dark from the tall block's top (docs/bench/radiosity.md).
    std::vector<float> du, dv;
    // Whether the ray from receiver r's centre to member m's centre is unblocked (same layout
    // as w; 0 also where it was not cast: member behind the receiver's plane or the receiver
    // behind the member's). groupGatherRow reads it for the near receivers' visibility samples
    // instead of casting the same rays again.
    std::size_t members = 0;
    std::vector<unsigned char> visible;
};
// `offsets`: fill du/dv too (FormFactorConfig::groupGradient). `shareEdges`: members sharing an
// edge share its contour term, computed once per receiving point (bit-identical to each
// member's own pointToPolygon; false computes it that way, the reference the tests compare
// with).
GroupNearField groupNearField(const PatchMesh& mesh, const PatchBvh& bvh, int g, double radius,
                              bool offsets = false, bool shareEdges = true);
// The group's outline: convex hull of its members' corners (in its surface's plane).
std::vector<glm::dvec3> groupHull(const PatchMesh& mesh, int g);

} // namespace wb::rad
