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
constexpr float kSphereMargin = 0x1p-16f; // relative margin of the float sphere test
constexpr float kTriMargin = 0x1p-19f;    // relative error bound of the triangle test's inputs
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
