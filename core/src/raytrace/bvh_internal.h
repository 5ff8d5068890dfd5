#pragma once
// What bvh.cpp (the binned SAH build, binary traversal) and bvh_wide.cpp (the 4-wide
// collapse and traversal) share: outward float rounding, the build's node record and
// the rounding margins of the slab test.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace wb::rt::bvh_detail {

// std::nextafter(f, ∓inf) without the library call (every primitive's box goes through
// these): one step of the bit pattern away from zero or towards it; ±0 steps to the
// smallest denormal; +inf steps down to FLT_MAX, FLT_MAX·(−1) down to −inf. f is not NaN.
inline float floatStep(float f, bool down) {
    if (f == 0) return down ? -std::numeric_limits<float>::denorm_min()
                            : std::numeric_limits<float>::denorm_min();
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    const bool negative = (u >> 31) != 0;
    u = negative == down ? u + 1 : u - 1; // away from zero: +1 on the magnitude
    std::memcpy(&f, &u, sizeof f);
    return f;
}
inline float floatDown(double x) {
    const float f = float(x);
    return double(f) > x ? floatStep(f, true) : f;
}
inline float floatUp(double x) {
    const float f = float(x);
    return double(f) < x ? floatStep(f, false) : f;
}

// A node of the binary tree as built (depth first, left child right after its parent).
// Its box is a union of float boxes rounded outward, so it is exact in float.
struct BuildNode {
    glm::dvec3 lo, hi;    // box
    std::uint32_t offset; // leaf: first index into order_; inner: right child index
    std::uint16_t count;  // leaf: number of primitives; inner: 0
    std::uint16_t axis;   // inner: split axis
};

constexpr int kMaxDepth = 128; // binary traversal stack size (the build keeps the depth below)

// PBRT's γ(3) margin: a box's exit distance computed in double may be short by 3
// rounding errors; stretching it keeps grazing rays from missing a box whose
// primitive they hit.
constexpr double kFarScale = 1 + 2 * 3 * (std::numeric_limits<double>::epsilon() / 2) /
                                     (1 - 3 * std::numeric_limits<double>::epsilon() / 2);
constexpr float kFarScaleF = 1 + 2 * 3 * (std::numeric_limits<float>::epsilon() / 2) /
                                     (1 - 3 * std::numeric_limits<float>::epsilon() / 2);

} // namespace wb::rt::bvh_detail
