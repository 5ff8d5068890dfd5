// The wide BVH's walk compiled for AVX2 (bvh_wide_impl.h), 4-wide and 8-wide, entered
// only where the CPU has AVX2 (bvh_wide.cpp checks at run time). Everything this file
// includes is included first, before AVX2 is switched on for the rest of the file, so
// the library code it inlines (std::, glm) keeps its plain x86-64 definitions and only
// the walk itself is compiled for AVX2. AVX2 only, not FMA: no product is fused with a
// sum, so the float tests round exactly as their error bounds assume.
#include "bvh_internal.h"
#include "bvh_wide_kinds.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

namespace wb::rt::avx2 {

// Eight lanes: a node of eight children tested at once.
struct L8 {
    static constexpr int W = 8;
    using V = __m256;
    static V set1(float x) { return _mm256_set1_ps(x); }
    static V load(const float* p) { return _mm256_load_ps(p); }
    static V sub(V a, V b) { return _mm256_sub_ps(a, b); }
    static V add(V a, V b) { return _mm256_add_ps(a, b); }
    // Eight bytes as floats (the quantised nodes' offsets): exact.
    static V fromU8(const std::uint8_t* p) {
        return _mm256_cvtepi32_ps(
            _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p))));
    }
    static V mul(V a, V b) { return _mm256_mul_ps(a, b); }
    static V min(V a, V b) { return _mm256_min_ps(a, b); }
    static V max(V a, V b) { return _mm256_max_ps(a, b); }
    // Ordered, quiet: false for NaN, as SSE's cmpleps.
    static int le(V a, V b) { return _mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_LE_OQ)); }
    static void store(float* p, V v) { _mm256_store_ps(p, v); }
    static __m128 low(V v) { return _mm256_castps256_ps128(v); }
    // The packets' transposed leaf tests (Lanes4's comments): SSE's cmpngt, cmplt and cmpgt.
    static V abs(V a) { return _mm256_and_ps(a, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff))); }
    static int ngt(V a, V b) { return _mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_NGT_UQ)); }
    static int ltGt(V a, V b, V c, V d) { // a < b and c > d (false for NaN)
        return _mm256_movemask_ps(
            _mm256_and_ps(_mm256_cmp_ps(a, b, _CMP_LT_OQ), _mm256_cmp_ps(c, d, _CMP_GT_OQ)));
    }
};

} // namespace wb::rt::avx2

#include "bvh_wide_impl.h" // Lanes4 (here VEX-encoded) and the walk

namespace wb::rt {
// Instantiated here, inside the AVX2 region.
template struct Bvh::WideWalk<Lanes4<1>>;
template struct Bvh::WideWalk<avx2::L8>;
template struct Bvh::WideWalk<avx2::L8, true>;
} // namespace wb::rt

#if defined(__clang__)
#pragma clang attribute pop
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

namespace wb::rt {

const Bvh::WidePath* Bvh::avx2Path(int width, bool quantised) {
    if (width == 8)
        return quantised ? WideWalk<avx2::L8, true>::path(true) : WideWalk<avx2::L8>::path(true);
    return WideWalk<Lanes4<1>>::path(true);
}

} // namespace wb::rt
