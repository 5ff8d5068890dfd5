#pragma once
// Two hits' doubles in SSE2's lanes (baseline x86-64, no run-time check) for the packet
// path's shading (issue 21: PhongModel::directLanes, Tracer::traceFromPacket). Each
// operation is the IEEE one the scalar code does per hit (no FMA: the library is built
// without it), so a lane's value is the scalar value bit for bit when the formula is
// written with the same operations in the same order.
#include "core/raytrace/scene.h"

#include <emmintrin.h>
#include <glm/glm.hpp>

namespace wb::rt::sse2lanes {

constexpr int kWidth = 2; // lanes in a D
// The packet path's lanes go in pairs: lanes i and i + 1 for even i < kMaxPacket.
static_assert(kMaxPacket % kWidth == 0, "packets are shaded two lanes at a time");

struct D2 {
    __m128d v;
};
using D = D2;
using Mask = __m128d; // a comparison's lanes: all ones or all zeros
inline D2 operator+(D2 a, D2 b) {
    return {_mm_add_pd(a.v, b.v)};
}
inline D2 operator-(D2 a, D2 b) {
    return {_mm_sub_pd(a.v, b.v)};
}
inline D2 operator*(D2 a, D2 b) {
    return {_mm_mul_pd(a.v, b.v)};
}
inline D2 operator/(D2 a, D2 b) {
    return {_mm_div_pd(a.v, b.v)};
}
inline D2 operator-(D2 a) { // −x flips the sign bit, as the scalar negation does
    return {_mm_xor_pd(a.v, _mm_set1_pd(-0.0))};
}
inline D2 sqrtOf(D2 a) {
    return {_mm_sqrt_pd(a.v)};
}
inline D2 splat(double x) {
    return {_mm_set1_pd(x)};
}
// m ? a : b lane by lane (m: all ones or all zeros, from a comparison).
inline D2 select(__m128d m, D2 a, D2 b) {
    return {_mm_or_pd(_mm_and_pd(m, a.v), _mm_andnot_pd(m, b.v))};
}
// std::max(x, lo) = (x < lo) ? lo : x (NaN stays x): maxpd(lo, x) is lo > x ? lo : x,
// the same value in every case (a NaN x fails both comparisons and stays x; x == lo gives
// x, a ±0 pair the x of std::max too).
inline D2 maxOf(D2 x, D2 lo) {
    return {_mm_max_pd(lo.v, x.v)};
}
#include "lanes_vec3_body.h"
using V2 = V;
// Lanes a and b of a per-hit vector or number.
inline V2 pair(const glm::dvec3& a, const glm::dvec3& b) {
    return {{_mm_set_pd(a.x, b.x)}, {_mm_set_pd(a.y, b.y)}, {_mm_set_pd(a.z, b.z)}};
}
inline D2 pair(double a, double b) {
    return {_mm_set_pd(a, b)};
}
// phong_lanes_impl.h's names (lanes_avx.h has the same): comparisons all ones or all zeros
// lane by lane, greater, lessEqual and equal ordered (false with a NaN), notEqualOrNaN
// unordered (true with a NaN, as C's !=); lane k is element k (the low element is lane 0
// here, unlike pair's order).
inline Mask greater(D2 a, D2 b) {
    return _mm_cmpgt_pd(a.v, b.v);
}
inline Mask lessEqual(D2 a, D2 b) {
    return _mm_cmple_pd(a.v, b.v);
}
inline Mask equal(D2 a, D2 b) {
    return _mm_cmpeq_pd(a.v, b.v);
}
inline Mask notEqualOrNaN(D2 a, D2 b) {
    return _mm_cmpneq_pd(a.v, b.v);
}
inline Mask isNaN(D2 a) {
    return _mm_cmpunord_pd(a.v, a.v);
}
inline Mask maskAnd(Mask a, Mask b) {
    return _mm_and_pd(a, b);
}
inline Mask maskOr(Mask a, Mask b) {
    return _mm_or_pd(a, b);
}
inline unsigned maskBits(Mask m) { // bit k: lane k
    return unsigned(_mm_movemask_pd(m));
}
// Lane k = f(k) (a number or a dvec3).
template <class F> inline auto gather(F f) {
    return pair(f(1), f(0));
}
inline D2 loadLanes(const double* p) { // p[k] to lane k, any alignment
    return {_mm_loadu_pd(p)};
}
inline void storeLanes(double* p, D2 a) { // p: 16-byte aligned
    _mm_store_pd(p, a.v);
}

} // namespace wb::rt::sse2lanes
