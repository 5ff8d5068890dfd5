#include "core/raytrace/ray.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <emmintrin.h>

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

void offsetRayOrigins(const double* const p[3], const double* const n[3], double* const out[3],
                      int count) {
    const __m128d origin = _mm_set1_pd(kOrigin), absScale = _mm_set1_pd(kAbsScale);
    const __m128d intScale = _mm_set1_pd(kIntScale), signBit = _mm_set1_pd(-0.0);
    for (int a = 0; a < 3; ++a) {
        for (int k = 0; k + 1 < count; k += 2) {
            const __m128d pv = _mm_loadu_pd(&p[a][k]), nv = _mm_loadu_pd(&n[a][k]);
            // |p| < 1/32 (a NaN p: false): p + 2^-37·n.
            const __m128d near =
                _mm_cmplt_pd(_mm_andnot_pd(signBit, pv), origin); // fabs: the sign bit cleared
            const __m128d absolute = _mm_add_pd(pv, _mm_mul_pd(absScale, nv));
            // offsetUlps: of = int64(2^20·n) truncated (cvttsd2si, as the cast), added to
            // p's bits, negated where p < 0; the integer sums wrap as the scalar code's do.
            alignas(16) double scaled[2];
            _mm_store_pd(scaled, _mm_mul_pd(intScale, nv));
            const __m128i of = _mm_set_epi64x(_mm_cvttsd_si64(_mm_set_sd(scaled[1])),
                                              _mm_cvttsd_si64(_mm_set_sd(scaled[0])));
            const __m128i negative = _mm_castpd_si128(_mm_cmplt_pd(pv, _mm_setzero_pd()));
            const __m128i step = _mm_sub_epi64(_mm_xor_si128(of, negative), negative);
            const __m128d ulps = _mm_castsi128_pd(_mm_add_epi64(_mm_castpd_si128(pv), step));
            _mm_storeu_pd(&out[a][k],
                          _mm_or_pd(_mm_and_pd(near, absolute), _mm_andnot_pd(near, ulps)));
        }
    }
}

} // namespace wb::rt
