#pragma once
// What the wide BVH's collapse (bvh_wide.cpp) and its walks (bvh_wide_impl.h, one per
// instruction set) share: the primitive kinds of the leaves and their margins. Included
// before any code compiled for AVX2, so these inline definitions are plain x86-64 code
// in every translation unit.
#include "core/raytrace/bvh.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <cstdint>
#include <typeinfo>

namespace wb::rt {

namespace bvh_detail {
// |v|₁ = |x| + |y| + |z|, summed in that order (the margins below are written for it).
inline double l1Norm(const glm::dvec3& v) {
    return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
}
// Exact code per kind: Sphere and Triangle are called directly, SmoothTriangle (the
// triangle test, then its normal) and the rest through the virtual call.
constexpr std::uint8_t kOther = 0, kSphere = 1, kTriangle = 2, kSmoothTriangle = 3;
// Runs of a leaf sorted by their float test: spheres, triangles (both kinds), the rest
// (a float test of their own box).
constexpr std::uint8_t kRunSphere = 0, kRunTriangle = 1, kRunOther = 2;
// Bit c of the index as byte c (0 or 1) of the entry: a ray's mask of the W <= 8 children
// it enters, shifted by its lane, ORs into each child's mask of rays, a byte a child
// (walkPacket's nodes of a few rays; little-endian, as x86).
struct SpreadTable {
    std::uint64_t v[256];
    constexpr SpreadTable() : v() {
        for (int m = 0; m < 256; ++m)
            for (int c = 0; c < 8; ++c)
                if ((m >> c) & 1) v[m] |= std::uint64_t(1) << (8 * c);
    }
    constexpr std::uint64_t operator[](int m) const { return v[m]; }
};
inline constexpr SpreadTable kSpread{};
// The leaves' float filters (visitLeaf in bvh_wide_impl.h) may only over-report: a
// primitive the exact double code hits is never rejected. u = 2^-24 is float's unit
// roundoff; every bound below is a sum of such roundings, taken with room to spare.
// - Spheres: ll = |(o − c) − h·d|² in float against (r + m)², m = |o|₁·kSphereMargin +
//   the sphere's own part sm_ (its |c|₁ and r, bvh_wide.cpp). Rounding o, c, d and the
//   ~12 operations moves the distance from the line by a small multiple of
//   u·(|o|₁ + |c|₁ + r) (one u per rounding, ~20 of them, for a unit d); kSphereMargin =
//   2^-16 = 256u leaves a wide factor over that. (The test "the leaves' float filters
//   keep their margins" fails with 2^-28, below the error; it passes with 2^-24.)
// - Triangles (issue 21, branch rtmesh4, for single rays and the packets' transposed test;
//   it replaced the watertight edge functions in float, which needed a per-ray shear): on
//   edges precomputed at the build (Möller–Trumbore's), e1 = v1 − v0, e2 = v2 − v0, n = e1 × e2,
//   each taken in double from the double vertices and rounded to float. With a = v0 − o, R = a × d
//   the three edge functions of the ray are the signed volumes F0 = det(v1 − o, v2 − o, d),
//   F1 = det(v2 − o, a, d) = R·e2, F2 = det(a, v1 − o, d) = −R·e1 and F0 = n·d − F1 − F2
//   (F0 + F1 + F2 = det(e1, e2, d)). The watertight test's u, v, w are F0, F1, F2 times one
//   common factor (±1/d[kz]), so its verdict "mixed signs" is theirs. The filter computes
//   a, R, F1 = R·e2, F2 = R·(−e1) (−e1 stored: negation is exact) and F0 = (n·d − F1) − F2
//   in float and rejects only when one of them is below −B and another above B (min/max
//   of the three), B bounding:
//   * the float error. With D = |d|∞, A = |v0|₁ + |o|₁ (>= |a|₁), E = max(|e1|₁, |e2|₁) and
//     |(x × y)·z| <= |x|₁·|y|∞·|z|₁: rounding v0, o and a − (2u·A), d (u·D), e (2u·E):
//     5u·D·E·A for F1 and for G; R's two products and difference and the dot's three
//     products and two sums: another 5u·D·E·A each; n·d (n rounded, d rounded, three
//     products, two sums): 5u·D·|n|₁ + 5u_d·D·E² (n's and e's double roundings, u_d = 2^-53);
//     F0's two sums: 2u·(D·|n|₁ + 2D·E·A). In all <= 25u·D·E·A + 7.1u·D·|n|₁ + 5u_d·D·E².
//   * the double test's own error (it rejects on its computed signs): its sheared
//     coordinates are off by <= 4u_d·|v − o|₁ (|shear| <= 1), so u, v, w by
//     <= 23u_d·|v_i − o|₁·|v_j − o|₁, i.e. F by 23u_d·D·(V + |o|₁)², V = max_i |v_i|₁.
//   So B = D·(kMtEdgeMargin·E·(V + |o|₁) + kMtNormalMargin·|n|₁ + kMtDoubleMargin·(V +
//   |o|₁)²) + kMtFloor: 2^-18 = 64u against 25u, 2^-19 = 32u against 7.1u, 2^-46 = 128u_d
//   against 23u_d + 20u_d (E <= 2V); B's own five roundings take < 1% of those factors.
//   kMtFloor covers underflow: each float operation may also be off by 2^-150 absolutely,
//   in all <= 2^-146·E + 2^-145, which is below 2^-120 for E <= 2^24 and below the first
//   term otherwise (D >= 1e-30 > 2^-100 for a float-walk ray with d ≠ 0; d = 0 makes every
//   F exactly 0). Overflow: no product exceeds 12·D·(V + |o|₁)², so the filter is used only
//   for V <= 2^30 (per triangle: else its parts are +inf, B is inf or NaN and never
//   rejects), |o|₁ <= 2^30 and D <= 2^60 (per ray: else X = Y = +inf): 12·2^62·2^60 < 2^128.
//   Per triangle tp_[0] = P1 = 2^-18·E + 2·2^-46·V and tp_[1] = P2 = 2^-18·E·V +
//   2^-19·|n|₁ + 2^-46·V², per ray X = D·|o|₁, Y = D, Z = 2^-46·D·|o|₁² + 2^-120 (each
//   rounded up): B = X·P1 + Y·P2 + Z. Where B is finite every F is finite (the ranges);
//   a NaN or infinite B rejects nothing (its compares are false).
//   (The test "the precomputed-edge filter's bound" fails with kMtEdgeMargin cut to 2^-30.)
constexpr float kSphereMargin = 0x1p-16f;   // relative margin of the float sphere test
constexpr double kMtEdgeMargin = 0x1p-18;   // × D·E·(V + |o|₁): the float error
constexpr double kMtNormalMargin = 0x1p-19; // × D·|n|₁
constexpr double kMtDoubleMargin = 0x1p-46; // × D·(V + |o|₁)²: the double test's error
constexpr double kMtFloor = 0x1p-120;       // underflow
constexpr double kMtMaxCoord = 0x1p30;      // V and |o|₁ beyond: no rejection (overflow)
constexpr double kMtMaxDir = 0x1p60;        // D beyond: no rejection
// The filter bound's parts raised by 2^-20 over their double values before rounding to float
// (rounding to nearest takes at most 2^-24 of them): mtSetup and triangleLanes.
constexpr double kMtUp = 1 + 0x1p-20;
// The slab test in float: entry = (near − o')·inv, exit = (far − o'')·invFar, where
// inv = 1/float(d) and invFar = inv·(1 + 2^-19), each rounded (u = 2^-24; o', o'' are the
// origin widened for its own rounding). Then inv <= (1/d)(1 + 2u), so an entry comes out
// at most (1 + 4u) times its exact value, and invFar >= (1/d)(1 − 3u)(1 + 32u), so an
// exit at least (1 + 27u) times its exact value: entry <= exit whenever the exact ray
// enters the box, and a box it enters is never missed.
constexpr float kInvFarScaleF = 1 + 0x1p-19f;
// (Issue 21, branch rtmesh4: an FMA form, fmsub(plane, inv, fl(o'·inv)), was built with its
// bound — o's rounding plus the product's, 2u·|o|max, inside the 2^-21 widening, with a
// narrower float range against overflow and a 2^-80 floor on eps against underflow — and
// taken back: GCC keeps the ray's values on the stack (the exact tests' calls in the loop
// clobber every vector register), so the fused form needs the same 43 instructions a node
// and the set-up more: callgrind +2–9% on every row, time within the noise; commit a7764b8.)
// BvhOptions::width 0 with AVX2: the width measured faster (docs/raytrace-scale.md).
constexpr int kAutoWidthAvx2 = 8;
inline std::uint8_t runOf(std::uint8_t kind) {
    return kind == kSphere
               ? kRunSphere
               : (kind == kTriangle || kind == kSmoothTriangle ? kRunTriangle : kRunOther);
}
// The kind of a primitive (the build takes it in scene order, the collapse by index).
inline std::uint8_t primitiveKind(const Primitive* p) {
    if (typeid(*p) == typeid(Sphere)) return kSphere;
    if (typeid(*p) == typeid(Triangle)) return kTriangle;
    if (typeid(*p) == typeid(SmoothTriangle) || dynamic_cast<const Triangle*>(p))
        return kSmoothTriangle; // the triangle's hit test
    return kOther;
}
} // namespace bvh_detail

} // namespace wb::rt
