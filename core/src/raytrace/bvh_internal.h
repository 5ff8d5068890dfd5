#pragma once
// What bvh.cpp (the binned SAH build, binary traversal) and bvh_wide.cpp (the 4-wide
// collapse and traversal) share: outward float rounding, the build's node record and
// the rounding margins of the slab test.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

namespace wb::rt::bvh_detail {

inline float floatDown(double x) {
    float f = float(x);
    if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
inline float floatUp(double x) {
    float f = float(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
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
