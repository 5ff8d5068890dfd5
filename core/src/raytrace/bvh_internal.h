#pragma once
// What bvh.cpp (the binned SAH build, binary traversal) and bvh_wide.cpp (the 4-wide
// collapse and traversal) share: outward float rounding, the build's node record and
// the rounding margins of the slab test.
#include <glm/glm.hpp>

#include <emmintrin.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <thread>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace wb::rt::bvh_detail {

// std::nextafter(f, ∓inf) without the library call (every primitive's box goes through
// these): one step of the bit pattern away from zero or towards it; ±0 steps to the
// smallest denormal; +inf steps down to FLT_MAX, FLT_MAX·(−1) down to −inf. f is not NaN.
inline float floatStep(float f, bool down) {
    if (f == 0)
        return down ? -std::numeric_limits<float>::denorm_min()
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

// floatDown of lo[0..2] and floatUp of hi[0..2] at once, without a branch per value (the
// scalar ones mispredict about half the time): lanes 0-2 of the results, lane 3 zero.
inline void floatBoxOutward(const double* lo, const double* hi, __m128& flo, __m128& fhi) {
    auto round = [](const double* x, bool down) {
        const __m128d xy = _mm_loadu_pd(x), z = _mm_load_sd(x + 2);
        const __m128 f = _mm_movelh_ps(_mm_cvtpd_ps(xy), _mm_cvtpd_ps(z)); // nearest, lane 3 = 0
        // Where the float is beyond x on the wrong side (the z lane's upper half: 0 vs 0).
        const __m128d fxy = _mm_cvtps_pd(f), fz = _mm_cvtps_pd(_mm_movehl_ps(f, f));
        const __m128d wxy = down ? _mm_cmpgt_pd(fxy, xy) : _mm_cmplt_pd(fxy, xy);
        const __m128d wz = down ? _mm_cmpgt_pd(fz, z) : _mm_cmplt_pd(fz, z);
        const __m128i wrong = _mm_castps_si128(
            _mm_shuffle_ps(_mm_castpd_ps(wxy), _mm_castpd_ps(wz), _MM_SHUFFLE(2, 0, 2, 0)));
        // floatStep in lanes: the magnitude ±1 by the sign; ±0 to ∓/± the smallest denormal.
        const __m128i u = _mm_castps_si128(f);
        const __m128i sgn2 = _mm_add_epi32(_mm_srai_epi32(u, 31), _mm_srai_epi32(u, 31));
        const __m128i delta =
            down ? _mm_sub_epi32(_mm_set1_epi32(-1), sgn2) : _mm_add_epi32(_mm_set1_epi32(1), sgn2);
        const __m128i zero = _mm_castps_si128(_mm_cmpeq_ps(f, _mm_setzero_ps()));
        const __m128i tiny = _mm_set1_epi32(down ? std::int32_t(0x80000001u) : 1);
        const __m128i step = _mm_or_si128(_mm_and_si128(zero, tiny),
                                          _mm_andnot_si128(zero, _mm_add_epi32(u, delta)));
        return _mm_castsi128_ps(
            _mm_or_si128(_mm_and_si128(wrong, step), _mm_andnot_si128(wrong, u)));
    };
    flo = round(lo, true);
    fhi = round(hi, false);
}

// A quantised box plane (Bvh::QuantNode8): org + q·scale, the product and the sum each
// rounded to float, as the walk's lanes compute it (no FMA anywhere it is compiled).
inline float quantDecode(float org, float scale, int q) {
    const float prod = float(q) * scale;
    return org + prod;
}

// A node of the binary tree as built (depth first, left child right after its parent).
// Its box is a union of float boxes rounded outward, so it is exact in float.
// Issue 21: the array has room for 2n − 1 nodes and a node's place follows from the
// partition alone (bvh.cpp, buildTop): a node over references [b, e) at index p has its
// left child at p + 1 and its right child at p + 2·(m − b), m the split, so subtrees built
// in parallel write the final array directly. The subtrees under kParallelGrain are dense
// (depth first, as before); between them the array has unused gaps, which nothing reads
// (every walk follows the links).
struct BuildNode {
    glm::dvec3 lo, hi;    // box
    std::uint32_t offset; // leaf: first index into order_; inner: right child index
    std::uint16_t count;  // leaf: number of primitives; inner: 0
    std::uint16_t size;   // nodes in its subtree, itself included, at most 65,535 (kSizeCap)
};
// BuildNode::size saturates here: the collapse compares it with a few thousand only.
constexpr std::uint32_t kSizeCap = 65535;

// Large build arrays: bigAlloc and bigFree (declared in bvh.h, for the leaf arrays'
// allocator; defined in bvh.cpp): 2 MiB pages where whole, and mappings a build freed kept
// for the next build (no page faults and zeroing after the first); malloc below 2 MiB.

constexpr int kMaxDepth = 128; // binary traversal stack size (the build keeps the depth below)

// PBRT's γ(3) margin: a box's exit distance computed in double may be short by 3
// rounding errors; stretching it keeps grazing rays from missing a box whose
// primitive they hit.
constexpr double kFarScale = 1 + 2 * 3 * (std::numeric_limits<double>::epsilon() / 2) /
                                     (1 - 3 * std::numeric_limits<double>::epsilon() / 2);
constexpr float kFarScaleF = 1 + 2 * 3 * (std::numeric_limits<float>::epsilon() / 2) /
                                     (1 - 3 * std::numeric_limits<float>::epsilon() / 2);

// The parallel parts: TBB normally; in the ThreadSanitizer build (-DWORKBENCH_TSAN=ON,
// WB_TSAN_THREADS) std::threads, because Debian's TBB is not instrumented and TSan
// cannot see its hand-offs (as renderParallel does). The work split is the same. Used by the build
// (bvh.cpp) and the collapse (bvh_wide.cpp).
template <class F> inline void parallelFor(std::size_t count, const F& f) {
#ifdef WB_TSAN_THREADS
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i = next++; i < count; i = next++)
            f(i);
    };
    std::thread helper(work);
    work();
    helper.join();
#else
    tbb::parallel_for(std::size_t(0), count, [&](std::size_t i) { f(i); });
#endif
}
template <class A, class B> inline void parallelInvoke(const A& a, const B& b) {
#ifdef WB_TSAN_THREADS
    std::thread helper(b);
    a();
    helper.join();
#else
    tbb::parallel_invoke(a, b);
#endif
}

} // namespace wb::rt::bvh_detail
