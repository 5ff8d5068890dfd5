#pragma once
// Lab 08 - radiosity (practicals 13-15, §1.13-1.15) as graded tasks: the form factor of
// two patches by the course's formula (15.20), one Jacobi sweep of B = E + R·F·B (14.16,
// 14.18), and the form factor by rays with visibility (§1.15.1). You write the bodies in
// exercises.cpp; `./wb check lab08` grades them against the reference and the closed forms
// core already has (core/radiosity/closed_forms.h).
#include "common/exercise.h"

#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace wb::lab08 {

// A patch: a planar convex quadrilateral, corners p[0..3] in order, counter-clockwise seen
// from its front. Its centre c = (p0 + p1 + p2 + p3)/4; with the diagonals
// a = p2 - p0, b = p3 - p1 its unit normal is normalize(a × b) (the front side) and its
// area |a × b|/2 (both exact for any planar quadrilateral).
struct Quad {
    glm::dvec3 p[4];
};

// ③ (15.20) The form factor F_ij from patch i to patch j, the patches small against their
// distance:  F_ij = cos φ_i · cos φ_j · A_j / (π d²),
// d = |c_j - c_i|, φ_i the angle between n_i and c_j - c_i, φ_j between n_j and c_i - c_j.
// 0 when the patches do not face each other (cos φ_i <= 0 or cos φ_j <= 0: one sees the
// other's back) and when the centres coincide (d = 0). Sizes 1e-2..1e2.
double formFactor(const Quad& i, const Quad& j);

// ④ One Jacobi sweep of the radiosity system B = E + R·F·B (14.16 with 14.18):
//   B'_i = E_i + R_i · Σ_j F_ij B_j     for every i, all from the OLD B.
// n = B.size() = E.size() = R.size(); F is n×n, row-major: F_ij = F[i·n + j] (F_ii = 0).
// Returns B' (a new vector; B itself is not changed). n may be 0 (returns an empty vector).
std::vector<double> jacobiSweep(const std::vector<double>& B, const std::vector<double>& E,
                                const std::vector<double>& R, const std::vector<double>& F);

// Whether the segment from `a` to `b` is free of other objects (true = visible). Given by
// the lab (it knows the scene); the patches i and j themselves never block.
using Visible = std::function<bool(const glm::dvec3& a, const glm::dvec3& b)>;

// ⑤ (§1.15.1) The form factor by rays with visibility: F_ij = V_ij · (15.20), where
// V_ij is the fraction of k rays between the two patches that no object interrupts.
// Take k points spread evenly on each patch (k = m², 1 <= m <= 32: the centres of an m×m
// grid of the quad's bilinear parameters (s, t) in [0,1]², point = bilinear mix of the
// corners), pair the points of i with those of j at random (a permutation from `seed`, e.g.
// std::mt19937 and std::shuffle), and cast one ray per pair: V_ij = visible rays / k.
// The geometric term is (15.20) at the centres, as in ③ (0 when they do not face).
double formFactorRays(const Quad& i, const Quad& j, int k, unsigned seed, const Visible& visible);

// The exercise table, in task order.
struct Table {
    double (*formFactor)(const Quad&, const Quad&);
    std::vector<double> (*jacobiSweep)(const std::vector<double>&, const std::vector<double>&,
                                       const std::vector<double>&, const std::vector<double>&);
    double (*formFactorRays)(const Quad&, const Quad&, int, unsigned, const Visible&);
};

} // namespace wb::lab08
