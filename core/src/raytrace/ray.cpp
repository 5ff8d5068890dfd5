#include "core/raytrace/ray.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace wb::rt {

namespace {
// Ray Tracing Gems ch. 6 uses, for float, origin() = 1/32, float_scale() = 1/65536 and
// int_scale() = 256 ULPs (~3e-5 relative). Double has 29 more mantissa bits; 2^20 ULPs
// is 2^-32 ~ 2.3e-10 relative: about 10^5 times the error of a hit point refined onto
// its surface (a few ULPs), yet far below anything visible. Below |x| = 1/32 the ULPs
// shrink towards 0, so an absolute offset of 2^-37 (the relative offset at 1/32) is used.
constexpr double kOrigin = 1.0 / 32.0;
constexpr double kAbsScale = 1.0 / 137438953472.0; // 2^-37
constexpr double kIntScale = 1048576.0;            // 2^20 ULPs

double offsetUlps(double p, double n) {
    const auto of = static_cast<int64_t>(kIntScale * n);
    int64_t bits;
    std::memcpy(&bits, &p, sizeof bits);
    bits += (p < 0) ? -of : of;
    double q;
    std::memcpy(&q, &bits, sizeof q);
    return q;
}
} // namespace

glm::dvec3 offsetRayOrigin(const glm::dvec3& p, const glm::dvec3& n) {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = std::fabs(p[i]) < kOrigin ? p[i] + kAbsScale * n[i] : offsetUlps(p[i], n[i]);
    return r;
}

} // namespace wb::rt
