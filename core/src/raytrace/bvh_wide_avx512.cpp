// The wide BVH's walk compiled for AVX-512 (F + VL; bvh_wide_impl.h), 8-wide nodes in
// 256-bit registers with the compares into mask registers (issue 21: a "masked 8-lane"
// path), entered only where the CPU has AVX-512F and VL (bvh_wide.cpp checks at run time)
// (the automatic choice there: it measured faster than AVX2 8-wide, docs/raytrace-scale.md;
// BvhOptions::simd Avx2 or WB_BVH_PATH=avx8 force the AVX2 walk). Everything this file
// includes is included first, before AVX2 is switched on for the rest of the file, so
// the library code it inlines (std::, glm) keeps its plain x86-64 definitions and only
// the walk itself is compiled for AVX-512. Not FMA: no product is fused with a sum, so
// the float tests round exactly as their error bounds assume: GCC's avx512f turns FMA on
// and contracted 143 products and sums into vfmadd, so this file is compiled with
// -ffp-contract=off (the whole library is: core/CMakeLists.txt); objdump shows no vfmadd in it.
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
#pragma clang attribute push(__attribute__((target("avx512f,avx512vl"))), apply_to = function)
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl")
#endif

namespace wb::rt::avx512 {

// Eight lanes, the compare straight into a mask register (no movemask).
struct L8 {
    static constexpr int W = 8;
    // The float-only walks' node test takes the ray's values as {1to8} memory operands.
    static constexpr bool kFold = true;
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
    static int le(V a, V b) { return int(_mm256_cmp_ps_mask(a, b, _CMP_LE_OQ)); }
    static void store(float* p, V v) { _mm256_store_ps(p, v); }
    static __m128 low(V v) { return _mm256_castps256_ps128(v); }
    // The packets' transposed leaf tests (bvh_wide_impl.h's Lanes4): SSE's cmpngt, cmplt and cmpgt.
    static V abs(V a) { return _mm256_and_ps(a, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff))); }
    static int ngt(V a, V b) { return int(_mm256_cmp_ps_mask(a, b, _CMP_NGT_UQ)); }
    static int ltGt(V a, V b, V c, V d) { // a < b and c > d (false for NaN)
        return int(_mm256_cmp_ps_mask(a, b, _CMP_LT_OQ) & _mm256_cmp_ps_mask(c, d, _CMP_GT_OQ));
    }
};

} // namespace wb::rt::avx512

#include "bvh_wide_impl.h" // the walk

namespace wb::rt {
// Instantiated here, inside the AVX-512 region.
template struct Bvh::WideWalk<avx512::L8>;
template struct Bvh::WideWalk<avx512::L8, true>;
} // namespace wb::rt

#if defined(__clang__)
#pragma clang attribute pop
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

namespace wb::rt {

const Bvh::WidePath* Bvh::avx512Path(bool quantised) {
    return quantised ? WideWalk<avx512::L8, true>::path(true) : WideWalk<avx512::L8>::path(true);
}

} // namespace wb::rt
