#pragma once
// Four hits' doubles in AVX's lanes for PhongModel::directLanes (issue 21), chosen at run
// time where the CPU has AVX. Only "avx" is enabled here, not FMA, so no product is fused
// with a sum: each operation is the IEEE one the scalar code does per hit, as in
// lanes_sse2.h (add, sub, mul, div and sqrt are correctly rounded in any width).
#include "core/raytrace/scene.h"

#include <glm/glm.hpp>
#include <immintrin.h>

#pragma GCC push_options
#pragma GCC target("avx")

namespace wb::rt::avxlanes {

static_assert(kMaxPacket % 4 == 0, "packets are shaded four lanes at a time");

struct D4 {
    __m256d v;
};
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
inline D4 sqrt4(D4 a) {
    return {_mm256_sqrt_pd(a.v)};
}
inline D4 splat4(double x) {
    return {_mm256_set1_pd(x)};
}
// The comparisons of lanes_sse2.h (cmpgt, cmplt: ordered; cmpeq: ordered).
inline __m256d greater(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_GT_OS);
}
inline __m256d less(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_LT_OS);
}
inline __m256d equal(D4 a, D4 b) {
    return _mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ);
}
// m ? a : b lane by lane (m: all ones or all zeros, from a comparison).
inline D4 select(__m256d m, D4 a, D4 b) {
    return {_mm256_or_pd(_mm256_and_pd(m, a.v), _mm256_andnot_pd(m, b.v))};
}
// std::max(x, lo) = (x < lo) ? lo : x (NaN stays x): vmaxpd(lo, x), as lanes_sse2.h's.
inline D4 maxOf(D4 x, D4 lo) {
    return {_mm256_max_pd(lo.v, x.v)};
}
struct V4 { // a dvec3 of four hits
    D4 x, y, z;
};
inline V4 operator+(const V4& a, const V4& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V4 operator-(const V4& a, const V4& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V4 operator*(const V4& a, const V4& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
inline V4 operator*(D4 k, const V4& a) {
    return {k * a.x, k * a.y, k * a.z};
}
inline V4 operator/(const V4& a, D4 k) {
    return {a.x / k, a.y / k, a.z / k};
}
inline D4 dot(const V4& a, const V4& b) { // glm: (x·x' + y·y') + z·z'
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V4 select(__m256d m, const V4& a, const V4& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
inline V4 splat4(const glm::dvec3& v) {
    return {splat4(v.x), splat4(v.y), splat4(v.z)};
}
// Element k of the result is lane k's value (_mm256_set_pd takes the highest element first).
inline D4 quad(double a, double b, double c, double d) {
    return {_mm256_set_pd(d, c, b, a)};
}
inline V4 quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    return {quad(a.x, b.x, c.x, d.x), quad(a.y, b.y, c.y, d.y), quad(a.z, b.z, c.z, d.z)};
}
} // namespace wb::rt::avxlanes

#pragma GCC pop_options
