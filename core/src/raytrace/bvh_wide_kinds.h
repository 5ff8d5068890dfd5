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
// Exact code per kind: Sphere and Triangle are called directly, SmoothTriangle (the
// triangle test, then its normal) and the rest through the virtual call.
constexpr std::uint8_t kOther = 0, kSphere = 1, kTriangle = 2, kSmoothTriangle = 3;
// Runs of a leaf sorted by their float test: spheres, triangles (both kinds), the rest
// (a float test of their own box).
constexpr std::uint8_t kRunSphere = 0, kRunTriangle = 1, kRunOther = 2;
// The leaves' float filters (visitLeaf in bvh_wide_impl.h) may only over-report: a
// primitive the exact double code hits is never rejected. u = 2^-24 is float's unit
// roundoff; every bound below is a sum of such roundings, taken with room to spare.
// - Spheres: ll = |(o − c) − h·d|² in float against (r + m)², m = |o|₁·kSphereMargin +
//   the sphere's own part sm_ (its |c|₁ and r, bvh_wide.cpp). Rounding o, c, d and the
//   ~12 operations moves the distance from the line by a small multiple of
//   u·(|o|₁ + |c|₁ + r) (one u per rounding, ~20 of them, for a unit d); kSphereMargin =
//   2^-16 = 256u leaves a wide factor over that. (The test "the leaves' float filters
//   keep their margins" fails with 2^-28, below the error; it passes with 2^-24.)
// - Triangles: the watertight test's edge functions u, v, w = px·py' − py·px' in float.
//   Each sheared input px = (v − o)[kx] − sx·(v − o)[kz] is off from its double value by
//   rounding v, o, sx (|sx| <= 1) and three operations: <= 6u·(|v|₁ + |o|₁ + |v − o|₁),
//   which kTriMargin = 2^-19 = 32u bounds as δ <= (2·Σ|v|₁ + 4·|o|₁)·2^-19 (tm_ + tom).
//   With inputs off by <= δ each product is off by <= δ(|a| + |b|) + δ², so an edge
//   function by <= 2δ(Q + 2δ), Q = Σ|px| + |py|; rounding its two products and their
//   difference adds <= 3u·Q² <= Q²·kTriProductMargin (2^-20 = 16u). A triangle is
//   rejected only when one edge function is below −e and another above e. (The same
//   test fails with kTriMargin cut to 2^-32; it passes with 2^-24: the |·|₁ sums over
//   all coordinates make δ a wide bound.)
constexpr float kSphereMargin = 0x1p-16f;    // relative margin of the float sphere test
constexpr float kTriMargin = 0x1p-19f;       // relative error bound of the triangle test's inputs
constexpr float kTriProductMargin = 0x1p-20f; // of the edge functions' own roundings (× Q²)
// The slab test in float: entry = (near − o')·inv, exit = (far − o'')·invFar, where
// inv = 1/float(d) and invFar = inv·(1 + 2^-19), each rounded (u = 2^-24; o', o'' are the
// origin widened for its own rounding). Then inv <= (1/d)(1 + 2u), so an entry comes out
// at most (1 + 4u) times its exact value, and invFar >= (1/d)(1 − 3u)(1 + 32u), so an
// exit at least (1 + 27u) times its exact value: entry <= exit whenever the exact ray
// enters the box, and a box it enters is never missed.
constexpr float kInvFarScaleF = 1 + 0x1p-19f;
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
