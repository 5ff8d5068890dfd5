#pragma once
// Four hits' doubles in AVX's lanes for PhongModel::directLanes (issue 21: phong_lanes_impl.h,
// with the names lanes_sse2.h gives too), chosen at run time where the CPU has AVX. Only "avx" is
// enabled here, not FMA, so no product is fused with a sum: each operation is the IEEE one the
// scalar code does per hit, as in lanes_sse2.h (add, sub, mul, div and sqrt are correctly rounded
// in any width).
#include "core/raytrace/scene.h"

#include <glm/glm.hpp>
#include <immintrin.h>

#pragma GCC push_options
#pragma GCC target("avx")

namespace wb::rt::avxlanes {

constexpr int kWidth = 4; // lanes in a D

struct D4 {
    __m256d v;
};
using D = D4;
using Mask = __m256d; // a comparison's lanes: all ones or all zeros
inline D4 operator+(D4 a, D4 b) {
    return {_mm256_add_pd(a.v, b.v)};
}
inline D4 operator-(D4 a, D4 b) {
    return {_mm256_sub_pd(a.v, b.v)};
}
inline D4 operator*(D4 a, D4 b) {
    return {_mm256_mul_pd(a.v, b.v)};
}
inline D4 operator/(D4 a, D4 b) {
    return {_mm256_div_pd(a.v, b.v)};
}
inline D4 operator-(D4 a) { // −x flips the sign bit, as the scalar negation does
    return {_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0))};
}
inline D4 sqrtOf(D4 a) {
    return {_mm256_sqrt_pd(a.v)};
}
inline D4 splat(double x) {
    return {_mm256_set1_pd(x)};
}
// The comparisons of lanes_sse2.h, lane by lane all ones or all zeros: greater, lessEqual and
// equal ordered (false with a NaN), notEqualOrNaN unordered (true with a NaN, as C's !=).
inline Mask greater(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_GT_OS);
}
inline Mask lessEqual(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_LE_OS);
}
inline Mask equal(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ);
}
inline Mask notEqualOrNaN(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_NEQ_UQ);
}
inline Mask isNaN(D4 a) {
    return _mm256_cmp_pd(a.v, a.v, _CMP_UNORD_Q);
}
inline Mask maskAnd(Mask a, Mask b) {
    return _mm256_and_pd(a, b);
}
inline Mask maskOr(Mask a, Mask b) {
    return _mm256_or_pd(a, b);
}
inline unsigned maskBits(Mask m) { // bit k: lane k
    return unsigned(_mm256_movemask_pd(m));
}
// m ? a : b lane by lane (m: all ones or all zeros, from a comparison).
inline D4 select(__m256d m, D4 a, D4 b) {
    return {_mm256_or_pd(_mm256_and_pd(m, a.v), _mm256_andnot_pd(m, b.v))};
}
// std::max(x, lo) = (x < lo) ? lo : x (NaN stays x): vmaxpd(lo, x), as lanes_sse2.h's.
inline D4 maxOf(D4 x, D4 lo) {
    return {_mm256_max_pd(lo.v, x.v)};
}
#include "lanes_vec3_body.h"
using V4 = V;
// Element k of the result is lane k's value (_mm256_set_pd takes the highest element first).
inline D4 quad(double a, double b, double c, double d) {
    return {_mm256_set_pd(d, c, b, a)};
}
inline V4 quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    return {quad(a.x, b.x, c.x, d.x), quad(a.y, b.y, c.y, d.y), quad(a.z, b.z, c.z, d.z)};
}
// Lane k = f(k) (a number or a dvec3).
template <class F> inline auto gather(F f) {
    return quad(f(0), f(1), f(2), f(3));
}
inline D4 loadLanes(const double* p) { // p[k] to lane k, any alignment
    return {_mm256_loadu_pd(p)};
}
inline void storeLanes(double* p, D4 a) { // p: 32-byte aligned
    _mm256_store_pd(p, a.v);
}

} // namespace wb::rt::avxlanes

#pragma GCC pop_options
