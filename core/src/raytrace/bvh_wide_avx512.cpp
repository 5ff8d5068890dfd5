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
// -ffp-contract=off (core/raytrace.cmake); objdump shows no vfmadd in it.
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
    // The packets' transposed leaf tests (bvh_wide_impl.h's Lanes4): SSE's cmpngt, cmplt, cmpgt.
    static V abs(V a) { return _mm256_and_ps(a, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff))); }
    static int ngt(V a, V b) { return int(_mm256_cmp_ps_mask(a, b, _CMP_NGT_UQ)); }
    static int lt(V a, V b) { return int(_mm256_cmp_ps_mask(a, b, _CMP_LT_OQ)); }
    static int gt(V a, V b) { return int(_mm256_cmp_ps_mask(a, b, _CMP_GT_OQ)); }

    // The nearest-hit walk's child order without branches (issue 21: the scalar insertion
    // sort mispredicted ~3.8 times a ray on balls 4). Each hit lane's key is its entry
    // distance's bits (t >= 0 orders as an int; a negative t, from a negative tMin, counts
    // as 0: the order is only a heuristic, the stack keeps the true t for the drop test)
    // with the slot in the low 3 bits; missed lanes are −1. A sorting network (19
    // comparators in 6 layers, checked on all 2^8 0-1 inputs) puts the keys farthest
    // first, and the hit slots' child, leaf count and t go to the stack in that order
    // (all 8 lanes written: the caller's stack has W spare entries; it keeps popcount).
    static constexpr bool kPushSorted = true;
    static void pushSorted(int mask, V t, const std::uint32_t* child, const std::uint16_t* count,
                           std::uint32_t* outChild, std::uint32_t* outCount, float* outT) {
        const __m256i slot = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        __m256i k = _mm256_or_si256(
            _mm256_and_si256(_mm256_max_epi32(_mm256_castps_si256(t), _mm256_setzero_si256()),
                             _mm256_set1_epi32(~7)),
            slot);
        k = _mm256_mask_mov_epi32(_mm256_set1_epi32(-1), __mmask8(mask), k);
        // One layer: each pair's lower slot (bit set in `lower`) keeps the larger key.
        auto layer = [&k](__m256i p, unsigned lower) {
            k = _mm256_mask_blend_epi32(__mmask8(lower), _mm256_min_epi32(k, p),
                                        _mm256_max_epi32(k, p));
        };
        layer(_mm256_shuffle_epi32(k, _MM_SHUFFLE(1, 0, 3, 2)), 0x33);    // 0-2 1-3 4-6 5-7
        layer(_mm256_permute4x64_epi64(k, _MM_SHUFFLE(1, 0, 3, 2)), 0x0F); // 0-4 1-5 2-6 3-7
        layer(_mm256_shuffle_epi32(k, _MM_SHUFFLE(2, 3, 0, 1)), 0x55);    // 0-1 2-3 4-5 6-7
        layer(_mm256_permutexvar_epi32(_mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7), k), 0x0C);
        layer(_mm256_permutexvar_epi32(_mm256_setr_epi32(0, 4, 2, 6, 1, 5, 3, 7), k), 0x0A);
        layer(_mm256_permutexvar_epi32(_mm256_setr_epi32(0, 2, 1, 4, 3, 6, 5, 7), k), 0x2A);
        const __m256i idx = _mm256_and_si256(k, _mm256_set1_epi32(7));
        const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(child));
        const __m256i n =
            _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(count)));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(outChild), _mm256_permutexvar_epi32(idx, c));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(outCount), _mm256_permutexvar_epi32(idx, n));
        _mm256_storeu_ps(outT, _mm256_permutexvar_ps(idx, t));
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
