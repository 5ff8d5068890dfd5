#pragma once
// The wide BVH's walk, templated on the SIMD lanes of its node test: bvh_wide.cpp
// compiles it with SSE2 for 4-wide nodes (the portable baseline), bvh_wide_avx2.cpp
// with AVX2 for 4- and 8-wide nodes (chosen at run time). Every function here is a
// member of Bvh::WideWalk<Lanes>, and each file's Lanes are types of their own (Lanes4<0>,
// Lanes4<1>, avx2::L8), so no function compiled for AVX2 can stand in for an SSE2 one at
// link time. bvh_wide_avx2.cpp includes everything this file includes before it turns
// AVX2 on, so only the code below is compiled for AVX2 there.
//
// Lanes: W (4 or 8), V (the register), set1, load (aligned), sub, mul, min, max (NaN in
// either operand gives the second), le (a movemask of a <= b, false for NaN), store,
// low (the first four lanes as __m128, for the leaf tests, which stay 4-wide), and for
// the packets add, abs, ngt, lt and gt.
//
// 1. Per ray: the near/far planes picked by byte offsets from the direction's signs; the
//    origin in float widened by |o|max·2^-21 per axis (its rounding is at most
//    |o|max·2^-24), 1/d in float for entries and 1/d·(1 + 2^-19) for exits (kInvFarScaleF),
//    tMin lowered and the limit raised by 2^-20: a box the exact ray enters is never
//    missed. Rays float cannot carry (|o| > 1e30, a direction component beyond 1e±30)
//    take the same walk with each box tested in double.
// 2. Nearest hit: hit children sorted by entry distance, the nearest descended into (or
//    visited at once if a leaf), the rest pushed with their entry distance and dropped
//    when a nearer hit is known. Any hit (shadow feelers, every-hit and every-blocker
//    walks, which never shrink the limit): no sort, no distances, leaves visited as met.
// 3. Leaves hold runs of one kind: spheres (float distance from the centre to the ray's
//    line against r + margin), triangles (the watertight edge functions in float with an
//    error bound), the rest (their own float box, with the node test's margins), four at
//    a time; every candidate goes to the primitive's exact double code, called directly
//    for spheres and plain triangles, so hits are the plain loop's bit for bit.
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
#include <utility>

namespace wb::rt {

// SSE's arithmetic in four lanes, for Lanes4 and the single walk's leaf tests (each
// instance's Tag a type of its own file or walk, so no instance compiled for AVX2 can stand
// in for an SSE2 one at link time).
template <class Tag> struct Sse4 {
    using V = __m128;
    static V set1(float x) { return _mm_set1_ps(x); }
    static V add(V a, V b) { return _mm_add_ps(a, b); }
    static V sub(V a, V b) { return _mm_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm_mul_ps(a, b); }
    static V min(V a, V b) { return _mm_min_ps(a, b); }
    static V max(V a, V b) { return _mm_max_ps(a, b); }
    // a < b and c > d in each lane (false for NaN), as a movemask.
    static int ltGt(V a, V b, V c, V d) {
        return _mm_movemask_ps(_mm_and_ps(_mm_cmplt_ps(a, b), _mm_cmpgt_ps(c, d)));
    }
    static int ngt(V a, V b) { return _mm_movemask_ps(_mm_cmpngt_ps(a, b)); } // true for NaN
};

// Four lanes: SSE2 in bvh_wide.cpp, the same code VEX-encoded in bvh_wide_avx2.cpp; the
// tag (0 and 1) keeps each file's instantiations its own.
template <int Tag> struct Lanes4 : Sse4<std::integral_constant<int, Tag>> {
    static constexpr int W = 4;
    using V = __m128;
    static V load(const float* p) { return _mm_load_ps(p); }
    static int le(V a, V b) { return _mm_movemask_ps(_mm_cmple_ps(a, b)); }
    static void store(float* p, V v) { _mm_store_ps(p, v); }
    static __m128 low(V v) { return v; }
    // The packets' transposed leaf tests (one primitive against the lanes): the same
    // operations as the single ray's 4-wide leaf tests, lane by lane.
    static V abs(V a) { return _mm_and_ps(a, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff))); }
};

// L::kFold: the node test takes the ray's values as broadcast memory operands (AVX-512).
template <class T, class = void> struct FoldOf : std::false_type {};
template <class T>
struct FoldOf<T, std::void_t<decltype(T::kFold)>> : std::bool_constant<T::kFold> {};

template <class L, bool Q> struct Bvh::WideWalk {
    static constexpr int W = L::W;
    using V = typename L::V;
    // Q: quantised 8-wide nodes (QuantNode8), each plane decoded in the lanes as
    // quantDecode does it; else float nodes.
    using Node = std::conditional_t<Q, QuantNode8, WideNodeT<W>>;
    // At most W − 1 pushes per wide node, at most one wide node per binary level.
    static constexpr int kStack = (W - 1) * bvh_detail::kMaxDepth;

    struct FloatStart;
    // Per-ray data.
    struct RayData {
        const std::size_t* off; // byte offsets in a Node: near planes x, y, z, far planes x, y, z
        V on[3], of[3];         // origin moved by ∓eps for near and ±eps for far planes
        V inv[3], invFar[3];    // 1/d and 1/d·(1 + 2^-19) in float (kInvFarScaleF)
        V tMin;                 // lowered tMin
        bool useFloat = false;  // boxes tested in float (else in double)
        bool unitD = false;     // unit direction (and useFloat): the float sphere test applies
        int signs;              // bit a: d[a] < 0
        // The ray itself (its origin and direction in double, read by the set-ups below; a
        // pointer, not a copy: six moves a ray less, issue 21's seventh session).
        const Ray* ray;
        // The start values (intersect's or occluded's, in its frame) when the node test takes
        // them as broadcast memory operands (L::kFold, the float-only walks): on, of, inv,
        // invFar and tMin above are then not filled, and the leaves read these.
        const FloatStart* start = nullptr;
        glm::dvec3 invd; // double walk only
        bool neg(int a) const { return (signs >> a) & 1; }
        // Sphere test (set up at the first sphere run): unitD, origin, direction, |o|₁·margin.
        bool sphReady = false;
        V fo[3], fd[3], om; // in W lanes: the 8-wide paths test eight spheres at a time

        // The watertight test's shear in double, set up at the first exact test of a plain
        // triangle, which reuses it: mutable, the exact tests get const RayData.
        mutable bool shReady = false;
        mutable TriangleShear sh;
        // The single ray's triangle filter on precomputed edges (set up at the first triangle
        // run; bvh_wide_kinds.h): the float origin and direction, the bound's X, Y, Z.
        bool mtReady = false;
        __m128 mo[3], md[3], mx, my, mz;

        // Out of line (once per ray at most): inlined, they made the walk's own code
        // longer on every scene, jacks 4's eye walk without a triangle included (callgrind).
        __attribute__((noinline)) void shearSetup() const {
            sh = triangleShear(ray->direction);
            shReady = true;
        }
        __attribute__((noinline)) void mtSetup() {
            const glm::dvec3& o = ray->origin;
            const glm::dvec3& d = ray->direction;
            const __m128d zero = _mm_setzero_pd();
            const __m128 vo =
                _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&o.x)),
                              _mm_cvtpd_ps(_mm_unpackhi_pd(_mm_loadu_pd(&o.y), zero)));
            const __m128 vd =
                _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&d.x)),
                              _mm_cvtpd_ps(_mm_unpackhi_pd(_mm_loadu_pd(&d.y), zero)));
            mo[0] = _mm_shuffle_ps(vo, vo, 0x00);
            mo[1] = _mm_shuffle_ps(vo, vo, 0x55);
            mo[2] = _mm_shuffle_ps(vo, vo, 0xAA);
            md[0] = _mm_shuffle_ps(vd, vd, 0x00);
            md[1] = _mm_shuffle_ps(vd, vd, 0x55);
            md[2] = _mm_shuffle_ps(vd, vd, 0xAA);
            const double ol = bvh_detail::l1Norm(o);
            const double dm = std::max(std::abs(d.x), std::max(std::abs(d.y), std::abs(d.z)));
            // The bound's parts, each raised by 2^-20 over its double value (float's rounding
            // to nearest takes at most 2^-24 of it; an underflow at most 2^-150, which
            // kMtFloor covers); beyond the ranges X = Y = +inf: no rejection.
            constexpr double kUp = bvh_detail::kMtUp;
            const bool ok = ol <= bvh_detail::kMtMaxCoord && dm <= bvh_detail::kMtMaxDir;
            const double x = dm * ol;
            constexpr float kInfF = std::numeric_limits<float>::infinity();
            mx = _mm_set1_ps(ok ? float(x * kUp) : kInfF);
            my = _mm_set1_ps(ok ? float(dm * kUp) : kInfF);
            mz = _mm_set1_ps(
                float(bvh_detail::kMtDoubleMargin * kUp * x * ol + bvh_detail::kMtFloor));
            mtReady = true;
        }

        void sphereSetup() {
            const glm::dvec3& o = ray->origin;
            const glm::dvec3& d = ray->direction;
            unitD = std::abs(glm::dot(d, d) - 1) < 1e-6;
            for (int a = 0; a < 3; ++a) {
                fo[a] = L::set1(float(o[a]));
                fd[a] = L::set1(float(d[a]));
            }
            om = L::set1(float(bvh_detail::l1Norm(o)) * bvh_detail::kSphereMargin);
            sphReady = true;
        }
    };

    // RayData::off for each sign pattern of the direction (bit a: d[a] < 0).
    struct Offsets {
        std::size_t v[8][6];
    };
    static constexpr Offsets makeOffsets() {
        Offsets t{};
        std::size_t kHiMinusLo = 0, loBase = 0, plane = 0;
        if constexpr (Q) {
            kHiMinusLo = 3 * W;
            loBase = offsetof(Node, q);
            plane = W;
        } else {
            kHiMinusLo = offsetof(Node, hi) - offsetof(Node, lo);
            loBase = offsetof(Node, lo);
            plane = W * sizeof(float);
        }
        for (int signs = 0; signs < 8; ++signs)
            for (int a = 0; a < 3; ++a) {
                const std::size_t lo = loBase + std::size_t(a) * plane;
                const bool neg = (signs >> a) & 1;
                t.v[signs][a] = lo + (neg ? kHiMinusLo : 0);
                t.v[signs][3 + a] = lo + (neg ? 0 : kHiMinusLo);
            }
        return t;
    }
    static constexpr Offsets kOffsets = makeOffsets();

    // The W planes of axis a at byte offset off in the node (near or far planes).
    __attribute__((always_inline)) static V planes(const Node& nd, std::size_t off, int a) {
        const char* base = reinterpret_cast<const char*>(&nd);
        if constexpr (Q) {
            const V qv = L::fromU8(reinterpret_cast<const std::uint8_t*>(base + off));
            return L::add(L::set1(nd.org[a]), L::mul(qv, L::set1(nd.scale[a])));
        } else {
            (void)a;
            return L::load(reinterpret_cast<const float*>(base + off));
        }
    }
    // The slots holding a child (the float nodes' empty slots have inverted infinite
    // boxes and are never entered).
    static int validMask(const Node& nd) {
        if constexpr (Q)
            return nd.valid;
        else
            return (1 << W) - 1;
    }
    // Child c's box on axis a, as the lanes decode it.
    static float boxLo(const Node& nd, int a, int c) {
        if constexpr (Q)
            return bvh_detail::quantDecode(nd.org[a], nd.scale[a], nd.q[a][c]);
        else
            return nd.lo[a][c];
    }
    static float boxHi(const Node& nd, int a, int c) {
        if constexpr (Q)
            return bvh_detail::quantDecode(nd.org[a], nd.scale[a], nd.q[3 + a][c]);
        else
            return nd.hi[a][c];
    }

    static const auto& nodesOf(const Bvh& b) {
        if constexpr (Q)
            return b.qnodes8_;
        else if constexpr (W == 4)
            return b.wnodes_;
        else
            return b.wnodes8_;
    }

    // Four lanes of SSE for the single walk's leaf tests, whatever L is.
    using Quad = Sse4<WideWalk>;

    // The triangle filter on the edges precomputed at the build (Möller–Trumbore's
    // quantities), written once for the single walk (S = Quad: four triangles against one
    // ray) and the packets' transposed leaves (S = L: one triangle against the packet's
    // rays): the edge functions F1 = R·e2, F2 = R·(−e1), F0 = n·d − F1 − F2 with
    // R = (v0 − o) × d, a lane rejected only when one is below −B and another above B, B
    // their written-down error bound (bvh_wide_kinds.h) from the ray's parts x, y, z and the
    // triangle's tp_. tri(a) gives the triangle values of the array a in the lanes (loads of
    // four triangles, or one triangle's broadcast); o, d, x, y, z the ray values in the
    // lanes. The same operations in the same order for every S: a lane's verdict is its
    // ray's and triangle's, whichever walk asks. Returns the rejected lanes' mask.
    template <class S, class Tri>
    __attribute__((always_inline)) static int
    triangleRejects(const Bvh& b, Tri&& tri, const typename S::V* o, const typename S::V* d,
                    typename S::V x, typename S::V y, typename S::V z) {
        using SV = typename S::V;
        const SV ax = S::sub(tri(b.tv_[0].data()), o[0]);
        const SV ay = S::sub(tri(b.tv_[1].data()), o[1]);
        const SV az = S::sub(tri(b.tv_[2].data()), o[2]);
        const SV rx = S::sub(S::mul(ay, d[2]), S::mul(az, d[1]));
        const SV ry = S::sub(S::mul(az, d[0]), S::mul(ax, d[2]));
        const SV rz = S::sub(S::mul(ax, d[1]), S::mul(ay, d[0]));
        auto dot = [&](int e) __attribute__((always_inline)) {
            return S::add(
                S::add(S::mul(rx, tri(b.te_[e].data())), S::mul(ry, tri(b.te_[e + 1].data()))),
                S::mul(rz, tri(b.te_[e + 2].data())));
        };
        // te_[0..2] holds −e1 (negated exactly): F2 = R·(−e1) = −(R·e1) bit for bit, and
        // F0 = (n·d − F1) − F2 = (n·d − F1) + R·e1.
        const SV f1 = dot(3), f2 = dot(0);
        const SV nd =
            S::add(S::add(S::mul(tri(b.te_[6].data()), d[0]), S::mul(tri(b.te_[7].data()), d[1])),
                   S::mul(tri(b.te_[8].data()), d[2]));
        const SV f0 = S::sub(S::sub(nd, f1), f2);
        const SV bound =
            S::add(S::add(S::mul(x, tri(b.tp_[0].data())), S::mul(y, tri(b.tp_[1].data()))), z);
        // Some F below −B and another above B. min/max drop a NaN operand, but no F is NaN
        // or infinite where B is finite (bvh_wide_kinds.h: the ranges), and a NaN or
        // infinite B rejects nothing (its compares are false).
        const SV lo = S::min(S::min(f0, f1), f2), hi = S::max(S::max(f0, f1), f2);
        return S::ltGt(lo, S::sub(S::set1(0.0f), bound), hi, bound);
    }

    // The sphere filter, written once for the single walk (S = Quad: four spheres against one
    // ray; S = L on the 8-wide paths: eight) and the packets' transposed leaves (S = L: one
    // sphere against the packet's rays): the squared distance of each centre from the ray's
    // line, ll, against (r + (om + sm))², om the ray's |o|₁·margin and sm the sphere's; a
    // sphere the exact code can hit (disc >= 0) is never rejected. sph(a) gives the spheres'
    // values of the array a in the lanes (loads, or one sphere's broadcast); fo, fd, om the
    // ray values. Returns the candidates' mask (cmpngt: NaN counts as a candidate). (Also
    // rejecting spheres beyond the nearest hit, −h − r − margin > limit, measured no gain.)
    template <class S, class Sph>
    __attribute__((always_inline)) static int
    sphereCandidates(const Bvh& b, Sph&& sph, const typename S::V* fo, const typename S::V* fd,
                     typename S::V om) {
        using SV = typename S::V;
        const SV fx = S::sub(fo[0], sph(b.sx_.data()));
        const SV fy = S::sub(fo[1], sph(b.sy_.data()));
        const SV fz = S::sub(fo[2], sph(b.sz_.data()));
        const SV h = S::add(S::add(S::mul(fx, fd[0]), S::mul(fy, fd[1])), S::mul(fz, fd[2]));
        const SV lx = S::sub(fx, S::mul(h, fd[0]));
        const SV ly = S::sub(fy, S::mul(h, fd[1]));
        const SV lz = S::sub(fz, S::mul(h, fd[2]));
        const SV ll = S::add(S::add(S::mul(lx, lx), S::mul(ly, ly)), S::mul(lz, lz));
        const SV rm = S::add(sph(b.sr_.data()), S::add(om, sph(b.sm_.data())));
        return S::ngt(ll, S::mul(rm, rm));
    }

    // Runs the leaf's float tests and calls visit(i, r) for every candidate i (an index into
    // order_); stops and returns false as soon as visit does. `limit`: the walk's limit
    // when the leaf was entered (the other kinds' boxes beyond it are skipped).
    // kFloatOnly: r.useFloat is known to be true (the float-only walks), so not tested.
    // kStart: the ray's float values are r.start's (the walk's kFold), not r's lanes.
    // kTri: the tree holds triangles only (Bvh::triOnly_) and the walk is float-only: every
    // leaf is one triangle run, so no run lengths, kinds or useFloat are read.
    // kFew (the single nearest-hit walk): a run of one or two triangles met before the ray's
    // triangle filter is set up (r.mtReady) goes to the exact tests unfiltered.
    template <bool kFloatOnly = false, bool kStart = false, bool kTri = false, bool kFew = false,
              class Visit>
    // Inlined into the walk (GCC would call it): +2–4% on shadow rays with AVX2 8-wide,
    // no change with SSE2 (driver, alternated medians).
    __attribute__((always_inline)) static bool visitLeaf(const Bvh& b, RayData& r,
                                                         std::uint32_t first, std::uint32_t count,
                                                         float limit, Visit&& visit) {
        using namespace bvh_detail;
        const std::uint32_t end = first + count;
        if constexpr (kTri) {
            // The triangle run's filter below, the same operations on the same values.
            if (!r.mtReady) r.mtSetup();
            for (std::uint32_t i = first; i < end; i += 4) {
                auto tri = [&](const float* a) __attribute__((always_inline)) {
                    return _mm_loadu_ps(a + i);
                };
                // The lanes past the leaf's end cleared without a branch (a min, a shift):
                // the branch on a leaf's last group mispredicted on a third of the mesh's
                // shadow rays' leaf visits (callgrind --branch-sim).
                const int mask = ~triangleRejects<Quad>(b, tri, r.mo, r.md, r.mx, r.my, r.mz) &
                                 int(0xFu >> (4 - std::min(end - i, std::uint32_t(4))));
                for (int m = mask; m; m &= m - 1)
                    if (!visit(i + std::uint32_t(__builtin_ctz(unsigned(m))), &r)) return false;
            }
            return true;
        }
        for (std::uint32_t run = first; run < end;) {
            const std::uint32_t rEnd = run + b.run_[run];
            const std::uint8_t runKind = runOf(b.kind_[run]);
            if (runKind == kRunSphere && !r.sphReady) r.sphereSetup();
            // kFew: the filter's set-up (mtSetup, ~64 instructions) and one group (~72) cost
            // more than an exact test that misses (~112 to its edge signs, the shear set-up
            // shared with the hit), and such a run's box was hit. Balls 4's floor is such a run
            // (a quad, two triangles in one leaf), the first and final one of 68% of its eye
            // rays: per floor ray 893 -> 858 instructions (callgrind, AVX2 8-wide) and ~11% of
            // the CPU time, the filter-then-call chain gone (issue 21, thirteenth session).
            // Not in the any-hit walks: balls 4's floor feelers meet the run beside their own
            // triangle, which the filter rejects; without it occluded took 4.8% more
            // instructions there (jacks 4 0.9%), so they keep the filter.
            if (runKind == kRunSphere
                    ? !r.unitD
                    : !(kFloatOnly || r.useFloat) ||
                          (kFew && runKind == kRunTriangle && rEnd - run <= 2 && !r.mtReady)) {
                for (std::uint32_t i = run; i < rEnd; ++i)
                    if (!visit(i, &r)) return false;
                run = rEnd;
                continue;
            }
            if constexpr (W == 8) {
                if (runKind == kRunSphere) {
                    // sphereCandidates in eight lanes: a leaf's run of up to eight spheres
                    // in one group.
                    for (std::uint32_t i = run; i < rEnd; i += 8) {
                        auto sph = [&](const float* a) __attribute__((always_inline)) {
                            return _mm256_loadu_ps(a + i);
                        };
                        int mask = sphereCandidates<L>(b, sph, r.fo, r.fd, r.om);
                        if (rEnd - i < 8) mask &= (1 << (rEnd - i)) - 1;
                        while (mask) {
                            const int l = __builtin_ctz(unsigned(mask));
                            mask &= mask - 1;
                            if (!visit(i + std::uint32_t(l), &r)) return false;
                        }
                    }
                    run = rEnd;
                    continue;
                }
            }
            for (std::uint32_t i = run; i < rEnd; i += 4) {
                int mask;
                if (runKind == kRunSphere) {
                    // sphereCandidates, four spheres against this ray.
                    auto sph = [&](const float* a) __attribute__((always_inline)) {
                        return _mm_loadu_ps(a + i);
                    };
                    const __m128 fo[3] = {L::low(r.fo[0]), L::low(r.fo[1]), L::low(r.fo[2])};
                    const __m128 fd[3] = {L::low(r.fd[0]), L::low(r.fd[1]), L::low(r.fd[2])};
                    mask = sphereCandidates<Quad>(b, sph, fo, fd, L::low(r.om));
                } else if (runKind == kRunTriangle) {
                    if (!r.mtReady) r.mtSetup();
                    // The filter on the edges precomputed at the build (triangleRejects), four
                    // triangles against this ray. Issue 21: the watertight shear filter took
                    // ~122 instructions a run and a per-ray shear.
                    auto tri = [&](const float* a) __attribute__((always_inline)) {
                        return _mm_loadu_ps(a + i);
                    };
                    mask = 0xF & ~triangleRejects<Quad>(b, tri, r.mo, r.md, r.mx, r.my, r.mz);
                } else {
                    // The other kinds: their own float box (rounded outward) with the node
                    // test's margins, up to the limit.
                    // The same values either way: r's lanes are broadcasts of r.start's.
                    __m128 t0, t1 = _mm_set1_ps(limit), on[3], of[3], inv[3], invFar[3];
                    if constexpr (kStart) {
                        t0 = _mm_set1_ps(r.start->tMin);
                        for (int a = 0; a < 3; ++a) {
                            on[a] = _mm_set1_ps(r.start->on[a]);
                            of[a] = _mm_set1_ps(r.start->of[a]);
                            inv[a] = _mm_set1_ps(r.start->inv[a]);
                            invFar[a] = _mm_set1_ps(r.start->invFar[a]);
                        }
                    } else {
                        t0 = L::low(r.tMin);
                        for (int a = 0; a < 3; ++a) {
                            on[a] = L::low(r.on[a]);
                            of[a] = L::low(r.of[a]);
                            inv[a] = L::low(r.inv[a]);
                            invFar[a] = L::low(r.invFar[a]);
                        }
                    }
                    for (int a = 0; a < 3; ++a) {
                        const __m128 nearP = _mm_loadu_ps(&b.ob_[r.neg(a) ? 3 + a : a][i]);
                        const __m128 farP = _mm_loadu_ps(&b.ob_[r.neg(a) ? a : 3 + a][i]);
                        t0 = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(nearP, on[a]), inv[a]), t0);
                        t1 = _mm_min_ps(_mm_mul_ps(_mm_sub_ps(farP, of[a]), invFar[a]), t1);
                    }
                    mask = _mm_movemask_ps(_mm_cmple_ps(t0, t1));
                }
                if (rEnd - i < 4) mask &= (1 << (rEnd - i)) - 1;
                while (mask) {
                    const int l = __builtin_ctz(unsigned(mask));
                    mask &= mask - 1;
                    if (!visit(i + std::uint32_t(l), &r)) return false;
                }
            }
            run = rEnd;
        }
        return true;
    }

    // The float values of a ray the float walk can carry, in four lanes (x, y, z, unused),
    // for initRay (joinPacket computes the same operations for four rays at a time): 1/d in one
    // division (a zero component gives ±inf, the slab then no limit, as in double; see
    // kInvFarScaleF for the roundings), the origin widened by eps = |o|max·2^-21 with the
    // direction's signs. Written to plain float arrays, as both callers had it: shared as a
    // function of __m128 values, GCC 12 put a register-to-register vmovq (C5 79 D6) into the AVX2
    // walk, which valgrind 3.19 cannot decode (docs/raytrace-scale.md; callgrind is how the AVX2
    // walk is profiled).
    __attribute__((always_inline)) static void floatRay(const Ray& ray, double om, float* inv,
                                                        float* invFar, float* on, float* of) {
        const __m128d zero = _mm_setzero_pd();
        const __m128 fd =
            _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&ray.direction[0])),
                          _mm_cvtpd_ps(_mm_unpackhi_pd(_mm_loadu_pd(&ray.direction[1]), zero)));
        const __m128 fo =
            _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&ray.origin[0])),
                          _mm_cvtpd_ps(_mm_unpackhi_pd(_mm_loadu_pd(&ray.origin[1]), zero)));
        const __m128 finv = _mm_div_ps(_mm_set1_ps(1.0f), fd);
        const __m128 sgnEps =
            _mm_xor_ps(_mm_set1_ps(float(om) * 0x1p-21f), _mm_and_ps(fd, _mm_set1_ps(-0.0f)));
        _mm_store_ps(inv, finv);
        _mm_store_ps(invFar, _mm_mul_ps(finv, _mm_set1_ps(bvh_detail::kInvFarScaleF)));
        _mm_store_ps(on, _mm_add_ps(fo, sgnEps));
        _mm_store_ps(of, _mm_sub_ps(fo, sgnEps));
    }

    // The range check of two doubles, branch-free: bit i set when lane i is 0 (if kZero) or
    // 1e-30 <= |v| <= 1e30 (false for NaN).
    template <bool kZero = true> __attribute__((always_inline)) static int inRange(__m128d v) {
        const __m128d av = _mm_andnot_pd(_mm_set1_pd(-0.0), v);
        const __m128d in =
            _mm_and_pd(_mm_cmpge_pd(av, _mm_set1_pd(1e-30)), _mm_cmple_pd(av, _mm_set1_pd(1e30)));
        if constexpr (kZero)
            return _mm_movemask_pd(_mm_or_pd(_mm_cmpeq_pd(av, _mm_setzero_pd()), in));
        return _mm_movemask_pd(in);
    }

    // A ray's RayData fields that initRay and the packets' joinPacket both set: the plane
    // offsets and axis signs of `signs` (bit a: d[a] < 0), the float-walk flag, the ray (by
    // pointer: it outlives the walk in both callers).
    __attribute__((always_inline)) static void setRayData(RayData& r, int signs, bool useFloat,
                                                          const Ray& ray) {
        r.off = kOffsets.v[signs];
        r.signs = signs;
        r.useFloat = useFloat;
        r.ray = &ray;
    }

    // A float ray's start values (floatRay's, the lowered tMin, the direction's signs), kept
    // in memory: the walk broadcasts each from there into the node test's lanes.
    struct FloatStart {
        alignas(16) float inv[4], invFar[4], on[4], of[4];
        float tMin;
        int signs;
    };
    enum Start { kMissed, kFloat, kDouble };

    // The per-ray checks and float values of the walk: kDouble for a ray the float walk
    // cannot carry (then only f.signs is set). kMissed: a float ray that surely misses the
    // root node's boxes (b.rootF_, their union) on (tMin, limit] (issue 21: on the mesh
    // bench, 55% of the eye rays miss the whole mesh's box, and their set-up and one node
    // test were most of their cost). The test is the node test's, on the union box: its
    // near planes are at or before every child's and its far planes at or after, and
    // rounding is monotonic, so its entry is at most every child's entry and its exit at
    // least every child's exit; a ray the node test would let into a child is never turned
    // away here. Only for nearest hits (kRoot): any-hit rays (shadow feelers) start on a
    // surface inside the box, where the test is ~20 instructions of waste (callgrind, mesh
    // shadow rays: +2%).
    template <bool kRoot>
    __attribute__((always_inline)) static Start startRay(FloatStart& f, const Bvh& b,
                                                         const Ray& ray, double tMin, float limit) {
        const glm::dvec3 o = ray.origin;
        const double om = std::max(std::abs(o.x), std::max(std::abs(o.y), std::abs(o.z)));
        // Signs and the range check in SSE2 doubles, branch-free: this set-up is a good
        // part of a cheap ray's cost (a ray that misses the tree or meets one leaf).
        const __m128d dxy = _mm_loadu_pd(&ray.direction[0]), dz = _mm_load_sd(&ray.direction[2]);
        f.signs = _mm_movemask_pd(dxy) | (_mm_movemask_pd(dz) << 2);
        if (!(om < 1e30 && inRange(dxy) == 3 && (inRange(dz) & 1))) return kDouble;
        floatRay(ray, om, f.inv, f.invFar, f.on, f.of);
        const float ftMin = float(tMin);
        const float lowered = ftMin - std::abs(ftMin) * 0x1p-20f;
        f.tMin = lowered;
        if constexpr (kRoot) {
            // The root box in lanes x, y, z: near planes lo where d >= 0 (the sign bit of
            // 1/d is d's), far planes the other; then the node test's max/min chains (NaN,
            // 0·inf, gives the accumulated operand: no limit).
            const __m128 vinv = _mm_load_ps(f.inv);
            const __m128 lo = _mm_load_ps(b.rootF_[0]), hi = _mm_load_ps(b.rootF_[1]);
            __m128 nearP, farP;
            if constexpr (!std::is_same_v<L, Lanes4<0>>) {
                // Every Lanes but the SSE2 file's is compiled for AVX2 or AVX-512: SSE4.1's
                // blend by the sign bit (of 1/d, which is d's).
                nearP = _mm_blendv_ps(lo, hi, vinv);
                farP = _mm_blendv_ps(hi, lo, vinv);
            } else {
                const __m128 neg = _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(vinv), 31));
                nearP = _mm_or_ps(_mm_and_ps(neg, hi), _mm_andnot_ps(neg, lo));
                farP = _mm_or_ps(_mm_and_ps(neg, lo), _mm_andnot_ps(neg, hi));
            }
            const __m128 tn = _mm_mul_ps(_mm_sub_ps(nearP, _mm_load_ps(f.on)), vinv);
            const __m128 tf =
                _mm_mul_ps(_mm_sub_ps(farP, _mm_load_ps(f.of)), _mm_load_ps(f.invFar));
            __m128 t0 = _mm_max_ss(tn, _mm_set_ss(lowered));
            __m128 t1 = _mm_min_ss(tf, _mm_set_ss(limit));
            t0 = _mm_max_ss(_mm_shuffle_ps(tn, tn, 1), t0);
            t1 = _mm_min_ss(_mm_shuffle_ps(tf, tf, 1), t1);
            t0 = _mm_max_ss(_mm_shuffle_ps(tn, tn, 2), t0);
            t1 = _mm_min_ss(_mm_shuffle_ps(tf, tf, 2), t1);
            if (!_mm_comile_ss(t0, t1)) return kMissed;
        }
        return kFloat;
    }

    // A float ray's RayData from its start values: the node test's lanes, each broadcast
    // from memory (one instruction a value).
    __attribute__((always_inline)) static void fillRay(RayData& r, const FloatStart& f,
                                                       const Ray& ray) {
        setRayData(r, f.signs, true, ray);
        for (int a = 0; a < 3; ++a) {
            r.on[a] = L::set1(f.on[a]);
            r.of[a] = L::set1(f.of[a]);
            r.inv[a] = L::set1(f.inv[a]);
            r.invFar[a] = L::set1(f.invFar[a]);
        }
        r.tMin = L::set1(f.tMin);
    }

    // The per-ray set-up of the walk (r.useFloat false: the double walk, r.invd set).
    // False: the ray surely misses every box (startRay's kMissed).
    template <bool kRoot>
    __attribute__((always_inline)) static bool initRay(RayData& r, const Bvh& b, const Ray& ray,
                                                       double tMin, float limit) {
        FloatStart f;
        switch (startRay<kRoot>(f, b, ray, tMin, limit)) {
        case kMissed:
            return false;
        case kFloat:
            fillRay(r, f, ray);
            return true;
        case kDouble:
            break;
        }
        setRayData(r, f.signs, false, ray);
        r.invd = 1.0 / ray.direction;
        return true;
    }

    // The walk's limit in float for a nearest hit so far at tMax (widened).
    // A limit beyond kLimitCap is infinite in float; a finite one is raised by kLimitUp over
    // its rounding (limitOf, and walkPacket's lanes).
    static constexpr double kLimitCap = 3e38;
    static constexpr float kLimitUp = 1 + 0x1p-20f;
    static float limitOf(double tMax) {
        const double lim = tMax * bvh_detail::kFarScale;
        return lim > kLimitCap ? std::numeric_limits<float>::infinity() : float(lim) * kLimitUp;
    }

    // Calls leaf(i, ray data or nullptr) for the primitives of every leaf the ray's segment (tMin,
    // tMax] may meet (after the leaves' float tests); leaf returns false to stop. Nearest hit
    // (kAnyHit false): leaf may lower tMax, nearest children first. Any hit: tMax fixed.
    // `pre`: the ray's start values if the caller has already taken them (startRay gave
    // kFloat for this tMin and tMax), else null.
    // kFloatOnly: pre is given, the tree has nodes (no rootLeafCount_) and every box test is
    // in float (no per-node check of useFloat).
    // kTri (with kFloatOnly): the tree holds triangles only (visitLeaf's kTri).
    template <bool kAnyHit, bool kFloatOnly = false, bool kTri = false, class Leaf>
    // Inlined into its one caller per instantiation (intersect, occluded, forEachHit,
    // forEachBlocker): one call and one prologue less per ray (issue 21).
    __attribute__((always_inline)) static void walk(const Bvh& b, const Ray& ray, double tMin,
                                                    double& tMax, Leaf&& leaf,
                                                    const FloatStart* pre = nullptr) {
        using namespace bvh_detail;
        static_assert(kFloatOnly || !kTri);
        if (!kFloatOnly && b.stats_.primitives == 0) return;
        if (!kFloatOnly && b.rootLeafCount_ > 0) {
            // A tree of one leaf (up to maxLeafSize primitives): the root box in double and
            // the exact tests, without the float set-up, which costs more than it saves.
            double t0 = tMin, t1 = tMax;
            for (int a = 0; a < 3; ++a) {
                const double inv = 1.0 / ray.direction[a];
                const bool neg = std::signbit(inv);
                const double near = ((neg ? b.rootHi_[a] : b.rootLo_[a]) - ray.origin[a]) * inv;
                const double far =
                    ((neg ? b.rootLo_[a] : b.rootHi_[a]) - ray.origin[a]) * inv * kFarScale;
                t0 = near > t0 ? near : t0; // NaN (0·inf): no limit
                t1 = far < t1 ? far : t1;
            }
            if (!(t0 <= t1)) return;
            for (std::uint32_t i = 0; i < b.rootLeafCount_; ++i)
                if (!leaf(i, nullptr)) return; // no ray data: the exact tests set up their own
            return;
        }
        const auto& nodes = nodesOf(b);
        // The leaves' useFloat test left out only in the any-hit walks: in the nearest-hit
        // walk GCC then laid the loop out worse (callgrind, eye rays: mesh 481 -> 487, balls
        // 4 1108 -> 1120 instructions a ray; issue 21, eighth session).
        constexpr bool kLeafFloat = kAnyHit && kFloatOnly;
        // The current limit: entries farther than the nearest hit (widened) are dropped.
        auto limitF = [&]() {
            const double lim = tMax * kFarScale;
            return lim > 3e38 ? std::numeric_limits<float>::infinity()
                              : float(lim) * (1 + 0x1p-20f);
        };
        float flim = limitF(); // limitF() of the current tMax (renewed after each leaf)
        RayData r;
        // L::kFold (AVX-512): the float-only walks' node test takes the ray's values as
        // broadcast memory operands ({1to8}) from the caller's FloatStart (intersect's or
        // occluded's), so the 13 broadcasts and their stores of fillRay go (issue 21, tenth
        // session). With AVX2 a broadcast is an instruction of its own at every node: there
        // fillRay's lanes stay.
        constexpr bool kFold = kFloatOnly && FoldOf<L>::value;
        if constexpr (kFold) {
            setRayData(r, pre->signs, true, ray);
            r.start = pre;
        } else if (kFloatOnly || pre)
            fillRay(r, *pre, ray);
        else if (!initRay<!kAnyHit>(r, b, ray, tMin, flim))
            return;
        const glm::dvec3 o = ray.origin;
        struct Entry {
            std::uint32_t child;
            std::uint32_t count;
            float t;
        };
        Entry stack[kStack];
        int sp = 0;
        std::uint32_t cur = 0;
        while (true) {
            // The ray's node-test values are read from RayData in memory at every node (an
            // empty asm that "may change" them): GCC had kept them in registers and, as the
            // leaves' exact tests are calls, reloaded all twelve and the six plane offsets
            // (~30 instructions) on every way back into this loop, which costs more than their
            // memory operands in the node test (issue 21, eighth session: callgrind, eye rays,
            // balls 4 1098.8 -> 1078.2, mesh 477.0 -> 467.0, jacks 4 1378.8 -> 1339.8
            // instructions a ray). The any-hit walk's node test reads them from memory already.
            // (kFold: the same for the start values, in both walks; the callers' FloatStart is
            // not const.)
            if constexpr (kFold)
                asm("" : "+m"(*const_cast<FloatStart*>(pre)));
            else if constexpr (kFloatOnly && !kAnyHit)
                asm("" : "+m"(r.on), "+m"(r.of), "+m"(r.inv), "+m"(r.invFar), "+m"(r.tMin));
            const Node& nd = nodes[cur];
            // The links (the fourth cache line of an 8-wide node) are read only after the
            // box test: fetch them alongside the boxes.
            if constexpr (sizeof(Node) > 128)
                _mm_prefetch(reinterpret_cast<const char*>(&nd.child[0]), _MM_HINT_T0);
            alignas(32) float t[W];
            int mask;
            if (kFloatOnly || r.useFloat) {
                V t0, t1 = L::set1(flim);
                if constexpr (kFold)
                    t0 = L::set1(pre->tMin);
                else
                    t0 = r.tMin;
                for (int a = 0; a < 3; ++a) {
                    const V nearP = planes(nd, r.off[a], a);
                    const V farP = planes(nd, r.off[3 + a], a);
                    // max/min return the second operand for NaN (0·inf: a ray in the slab's
                    // plane): that slab is no limit.
                    if constexpr (kFold) {
                        t0 = L::max(
                            L::mul(L::sub(nearP, L::set1(pre->on[a])), L::set1(pre->inv[a])), t0);
                        t1 = L::min(
                            L::mul(L::sub(farP, L::set1(pre->of[a])), L::set1(pre->invFar[a])), t1);
                    } else {
                        t0 = L::max(L::mul(L::sub(nearP, r.on[a]), r.inv[a]), t0);
                        t1 = L::min(L::mul(L::sub(farP, r.of[a]), r.invFar[a]), t1);
                    }
                }
                mask = L::le(t0, t1);
                if constexpr (Q) mask &= validMask(nd);
                if (!kAnyHit) L::store(t, t0);
            } else {
                mask = 0;
                const double lim = tMax * kFarScale;
                for (int c = 0; c < W; ++c) {
                    if (!((validMask(nd) >> c) & 1) || boxLo(nd, 0, c) > boxHi(nd, 0, c))
                        continue; // empty slot
                    double t0 = tMin, t1 = lim;
                    for (int a = 0; a < 3; ++a) {
                        const double nearP = r.neg(a) ? boxHi(nd, a, c) : boxLo(nd, a, c);
                        const double farP = r.neg(a) ? boxLo(nd, a, c) : boxHi(nd, a, c);
                        const double tn = (nearP - o[a]) * r.invd[a];
                        const double tf = (farP - o[a]) * r.invd[a] * kFarScale;
                        t0 = tn > t0 ? tn : t0;
                        t1 = tf < t1 ? tf : t1;
                    }
                    if (t0 <= t1) {
                        mask |= 1 << c;
                        // Rounded down, so the float drop test below never drops it wrongly.
                        t[c] = floatDown(t0);
                    }
                }
            }
            if constexpr (kAnyHit) {
                // Any order: leaves visited as met, inner children pushed, the last one
                // descended into.
                bool haveNext = false;
                while (mask) {
                    const int c = __builtin_ctz(unsigned(mask));
                    mask &= mask - 1;
                    if (nd.count[c] > 0) {
                        if (!visitLeaf<kLeafFloat, kFold, kTri>(b, r, nd.child[c], nd.count[c],
                                                                flim, leaf))
                            return;
                    } else {
                        if (haveNext) stack[sp++] = {cur, 0, 0.0f};
                        cur = nd.child[c];
                        haveNext = true;
                    }
                }
                if (haveNext) continue;
                if (sp == 0) return;
                cur = stack[--sp].child;
                continue;
            } else {
                // One child hit: go on with it; two: the nearer now, the farther pushed;
                // more: sorted by entry distance, the farther ones pushed farthest first.
                // A leaf met as the nearest is visited at once.
                if (mask != 0) {
                    int next;
                    const int c0 = __builtin_ctz(unsigned(mask));
                    const int rest = mask & (mask - 1);
                    if (rest == 0) {
                        next = c0;
                    } else if ((rest & (rest - 1)) == 0) {
                        const int c1 = __builtin_ctz(unsigned(rest));
                        const int nearC = t[c1] < t[c0] ? c1 : c0, farC = nearC == c0 ? c1 : c0;
                        stack[sp++] = {nd.child[farC], nd.count[farC], t[farC]};
                        next = nearC;
                    } else if (const int rest2 = rest & (rest - 1), rest3 = rest2 & (rest2 - 1);
                               (rest3 & (rest3 - 1)) == 0) {
                        // Three or four hits (most nodes of 3+): keys t's bits above the slot,
                        // sorted farthest first by compare-exchanges in registers (cmov), not
                        // the insertion loop's branches on t, which mispredict. A t below 0
                        // (its bits compare above every positive t) only changes the order of
                        // visits, never which child is pushed or its t, nor the nearest hit
                        // (offerNearest breaks ties by index, not by order).
                        auto key = [&](int c) __attribute__((always_inline)) {
                            std::uint32_t bits;
                            std::memcpy(&bits, &t[c], sizeof bits);
                            return (std::uint64_t(bits) << 32) | std::uint32_t(c);
                        };
                        auto swapUp = [](std::uint64_t & x, std::uint64_t & y)
                            __attribute__((always_inline)) {
                            const std::uint64_t hi = std::max(x, y);
                            y = std::min(x, y);
                            x = hi;
                        };
                        std::uint64_t k0 = key(c0), k1 = key(__builtin_ctz(unsigned(rest))),
                                      k2 = key(__builtin_ctz(unsigned(rest2)));
                        auto push = [&](std::uint64_t k) __attribute__((always_inline)) {
                            const int c = int(k & 0xFFFFFFFFu);
                            stack[sp++] = {nd.child[c], nd.count[c], t[c]};
                        };
                        if (rest3 == 0) {
                            swapUp(k0, k1);
                            swapUp(k1, k2);
                            swapUp(k0, k1);
                            push(k0);
                            push(k1);
                            next = int(k2 & 0xFFFFFFFFu);
                        } else {
                            std::uint64_t k3 = key(__builtin_ctz(unsigned(rest3)));
                            swapUp(k0, k1);
                            swapUp(k2, k3);
                            swapUp(k0, k2);
                            swapUp(k1, k3);
                            swapUp(k1, k2);
                            push(k0);
                            push(k1);
                            push(k2);
                            next = int(k3 & 0xFFFFFFFFu);
                        }
                    } else {
                        int order[W], n = 0;
                        while (mask) {
                            const int c = __builtin_ctz(unsigned(mask));
                            mask &= mask - 1;
                            int k = n++;
                            while (k > 0 && t[order[k - 1]] < t[c]) { // descending
                                order[k] = order[k - 1];
                                --k;
                            }
                            order[k] = c;
                        }
                        for (int k = 0; k + 1 < n; ++k) {
                            const int c = order[k];
                            stack[sp++] = {nd.child[c], nd.count[c], t[c]};
                        }
                        next = order[n - 1];
                    }
                    if (nd.count[next] == 0) {
                        cur = nd.child[next];
                        continue;
                    }
                    if (!visitLeaf<kLeafFloat, kFold, kTri, true>(b, r, nd.child[next],
                                                                  nd.count[next], flim, leaf))
                        return;
                    flim = limitF();
                }
                while (true) {
                    if (sp == 0) return;
                    // The entry's fields read in place: a copy of the whole Entry went
                    // through the stack frame (a 12-byte store, then t loaded back from it).
                    const Entry& e = stack[--sp];
                    if (e.t > flim) continue;
                    const std::uint32_t child = e.child, count = e.count;
                    if (count > 0) {
                        if (!visitLeaf<kLeafFloat, kFold, kTri, true>(b, r, child, count, flim,
                                                                      leaf))
                            return;
                        flim = limitF();
                        continue;
                    }
                    cur = child;
                    break;
                }
            }
        }
    }

    // ---- Packets (issue 21): up to W coherent rays (W = the node width: 8 with AVX2
    // 8-wide, 4 otherwise) share one walk. The rays of a packet have the same direction
    // signs, no zero direction component and the float walk (the others are traced one by
    // one). Per node: one interval test of its W children for the whole packet (the
    // rays' origins, 1/d and limits as intervals: a child no ray can enter is dropped in
    // one step, as a single ray's test), then, for each child left, the rays' own tests in
    // the lanes (ray j in lane j: the same float operations on the same values as ray j's
    // single walk, so the same verdict). Children are pushed with the mask of the rays
    // that enter them; rays finish (any hit) or shrink their limit (nearest hit) lane by
    // lane. A leaf entered by few rays runs each one's own leaf tests (visitLeaf); one
    // entered by kTransposeLanes or more runs its sphere and triangle runs transposed:
    // one primitive against all the entering rays in the lanes, lane j computing ray j's
    // own float leaf test operation for operation (the same values, the same roundings:
    // the single walk's verdict, with its written-down margins), then each candidate's
    // exact code. So every hit is the one its single walk finds.
    struct Packet {
        // Without RayData's default initializers (W·5 flag stores a packet): joinLane sets
        // what a joined lane's walk and set-ups read (issue 21, eighth session).
        union {
            RayData r[W];
        };
        Packet() {}
        alignas(32) float on[3][W], of[3][W], inv[3][W], invFar[3][W], tMin[W], lim[W];
        const std::size_t* off;
        // The transposed leaf tests' per-lane values (set up at the first run of their
        // kind): RayData's fo, fd, om (spheres) and mo, md, mx, my, mz (triangles) of each
        // lane's ray. sphLanes: lanes with a unit direction (the others visit every
        // sphere, as their single walk does); triLanes: every lane of the packet (the
        // triangle filter has no per-ray axes).
        alignas(32) float sfo[3][W], sfd[3][W], som[W];
        // The rays' origins and directions in double, lane by lane (joinPacket; lanes
        // outside the packet hold the first ray's): sphereLanes' source.
        alignas(32) double oo[3][W], dd[3][W];
        alignas(32) float tmo[3][W], tmd[3][W], tmx[W], tmy[W], tmz[W];
        unsigned sphLanes = 0, triLanes = 0;
        unsigned filled = 0; // lanes whose RayData registers are set (fillLane)
        bool sphSet = false, triSet = false;
    };
    // Rays entering a leaf from which its runs are tested transposed (fewer: one by one;
    // docs/raytrace-scale.md has the measurements: 3 until the eighth session, 2 since the
    // transposed triangle set-up became cheap; 1 measured worse on every scene).
    static constexpr int kTransposeLanes = 2;
    // A node of the any-hit walk reached by 2 to this many rays tests each ray against the W
    // children (walkPacket; 4 measured worse on the mesh and jacks 4).
    static constexpr int kRayMajorRays = 3;
    // A triangle run of n is tested ray by ray, four triangles at a time
    // (triangleQuadTest), when popcount · ceil(n / 4) · kQuadCost < n · kLanesCost: the
    // instructions of one ray against four triangles and of one triangle against the lanes
    // (callgrind, the mesh's eye packets: ~55 and ~47; issue 21, eleventh session).
    // With AVX-512 (kFold) the transposed test's eleven triangle broadcasts that feed a
    // product fold into it as {1to8} operands: one triangle against the lanes costs less.
    static constexpr unsigned kQuadCost = 6, kLanesCost = FoldOf<L>::value ? 4 : 5;

    // The smallest and largest lane, in every lane (the packets' intervals over their
    // rays; no lane NaN). V is __m256 for W = 8 (the AVX2 and AVX-512 files), else __m128.
    template <bool kMax> static V op(V x, V y) {
        if constexpr (kMax)
            return L::max(x, y);
        else
            return L::min(x, y);
    }
    template <bool kMax> static V reduceLanes(V a) {
        if constexpr (W == 8) {
            a = op<kMax>(a, _mm256_permute2f128_ps(a, a, 1));
            a = op<kMax>(a, _mm256_shuffle_ps(a, a, 0x4E));
            return op<kMax>(a, _mm256_shuffle_ps(a, a, 0xB1));
        } else {
            a = op<kMax>(a, _mm_shuffle_ps(a, a, 0x4E));
            return op<kMax>(a, _mm_shuffle_ps(a, a, 0xB1));
        }
    }
    static V hmin(V a) { return reduceLanes<false>(a); }
    static V hmax(V a) { return reduceLanes<true>(a); }

    static float lane0(__m128 v) { return _mm_cvtss_f32(v); }
    // The transposed tests' values of the rays of `lanes` (the other lanes keep the first
    // ray's, never read: their results are masked).
    // RayData::sphereSetup's values for all W lanes at once, from the packet's doubles: the
    // same IEEE operations in the same order (float(o[a]) and float(d[a]) as _mm_cvtpd_ps,
    // |o|₁ = (|x| + |y|) + |z| and d·d = (x·x + y·y) + z·z in double), so the same bits.
    // The rays' own RayData keep theirs unset (sphereSetup fills them if they run their
    // own leaf tests).
    static void sphereLanes(Packet& p, unsigned lanes) {
        const __m128d absMask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
        unsigned unit = 0;
        for (int j = 0; j < W; j += 2) {
            __m128d ol = _mm_setzero_pd(), dd = _mm_setzero_pd();
            for (int a = 0; a < 3; ++a) {
                const __m128d o = _mm_load_pd(&p.oo[a][j]), d = _mm_load_pd(&p.dd[a][j]);
                const __m128 fo = _mm_cvtpd_ps(o), fd = _mm_cvtpd_ps(d);
                _mm_storel_pi(reinterpret_cast<__m64*>(&p.sfo[a][j]), fo);
                _mm_storel_pi(reinterpret_cast<__m64*>(&p.sfd[a][j]), fd);
                ol = a == 0 ? _mm_and_pd(o, absMask) : _mm_add_pd(ol, _mm_and_pd(o, absMask));
                dd = a == 0 ? _mm_mul_pd(d, d) : _mm_add_pd(dd, _mm_mul_pd(d, d));
            }
            const __m128 om = _mm_mul_ps(_mm_cvtpd_ps(ol), _mm_set1_ps(bvh_detail::kSphereMargin));
            _mm_storel_pi(reinterpret_cast<__m64*>(&p.som[j]), om);
            const __m128d dev = _mm_and_pd(_mm_sub_pd(dd, _mm_set1_pd(1)), absMask);
            unit |= unsigned(_mm_movemask_pd(_mm_cmplt_pd(dev, _mm_set1_pd(1e-6)))) << j;
        }
        p.sphLanes = unit & lanes;
        p.sphSet = true;
    }
    static void triangleLanes(Packet& p, unsigned lanes) {
        if constexpr (W == 8) {
            // RayData::mtSetup's values four lanes at a time from the packet's doubles (the
            // lanes outside the packet hold its first ray's): the same IEEE operations in
            // the same order (float(o[a]), float(d[a]); |o|₁ = (|x| + |y|) + |z|; the
            // largest |d[a]| as std::max's, which is _mm256_max_pd(b, a) for std::max(a,
            // b); the bound's products in double, then rounded to float), so the same bits.
            // The rays' own RayData keep theirs unset (mtSetup fills them if they run their
            // own leaf tests).
            using namespace bvh_detail;
            constexpr double kUp = kMtUp;
            const __m256d absMask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffff));
            for (int j = 0; j < W; j += 4) {
                __m256d ao[3], ad[3];
                for (int a = 0; a < 3; ++a) {
                    const __m256d o = _mm256_load_pd(&p.oo[a][j]), d = _mm256_load_pd(&p.dd[a][j]);
                    _mm_store_ps(&p.tmo[a][j], _mm256_cvtpd_ps(o));
                    _mm_store_ps(&p.tmd[a][j], _mm256_cvtpd_ps(d));
                    ao[a] = _mm256_and_pd(o, absMask);
                    ad[a] = _mm256_and_pd(d, absMask);
                }
                const __m256d ol = _mm256_add_pd(_mm256_add_pd(ao[0], ao[1]), ao[2]);
                const __m256d dm = _mm256_max_pd(_mm256_max_pd(ad[2], ad[1]), ad[0]);
                const __m256d ok =
                    _mm256_and_pd(_mm256_cmp_pd(ol, _mm256_set1_pd(kMtMaxCoord), _CMP_LE_OQ),
                                  _mm256_cmp_pd(dm, _mm256_set1_pd(kMtMaxDir), _CMP_LE_OQ));
                const __m256d x = _mm256_mul_pd(dm, ol), up = _mm256_set1_pd(kUp);
                const __m256d inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
                _mm_store_ps(&p.tmx[j],
                             _mm256_cvtpd_ps(_mm256_blendv_pd(inf, _mm256_mul_pd(x, up), ok)));
                _mm_store_ps(&p.tmy[j],
                             _mm256_cvtpd_ps(_mm256_blendv_pd(inf, _mm256_mul_pd(dm, up), ok)));
                const __m256d z =
                    _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(kMtDoubleMargin * kUp), x), ol);
                _mm_store_ps(&p.tmz[j],
                             _mm256_cvtpd_ps(_mm256_add_pd(z, _mm256_set1_pd(kMtFloor))));
            }
            p.triLanes = lanes;
            p.triSet = true;
            return;
        }
        const int first = __builtin_ctz(lanes);
        for (int j = 0; j < W; ++j) {
            RayData& r = p.r[(lanes >> j) & 1 ? j : first];
            if (!r.mtReady) r.mtSetup();
            for (int a = 0; a < 3; ++a) {
                p.tmo[a][j] = lane0(r.mo[a]);
                p.tmd[a][j] = lane0(r.md[a]);
            }
            p.tmx[j] = lane0(r.mx);
            p.tmy[j] = lane0(r.my);
            p.tmz[j] = lane0(r.mz);
        }
        p.triLanes = lanes; // the filter has no per-ray axes: every lane is transposed
        p.triSet = true;
    }
    // Sphere i against the lanes: sphereCandidates with ray j's values in lane j (ray j's
    // single-walk verdict: the same function).
    __attribute__((always_inline)) static unsigned sphereLanesTest(const Bvh& b, const Packet& p,
                                                                   std::uint32_t i) {
        auto sph = [i](const float* a) __attribute__((always_inline)) {
            return L::set1(a[i]);
        };
        V fo[3], fd[3];
        for (int a = 0; a < 3; ++a) {
            fo[a] = L::load(p.sfo[a]);
            fd[a] = L::load(p.sfd[a]);
        }
        return unsigned(sphereCandidates<L>(b, sph, fo, fd, L::load(p.som)));
    }
    // Triangle i against the lanes of triLanes: triangleRejects with ray j's float origin,
    // direction and bound parts in lane j (ray j's single-walk verdict: the same function).
    __attribute__((always_inline)) static unsigned triangleLanesTest(const Bvh& b, const Packet& p,
                                                                     std::uint32_t i) {
        const V o[3] = {L::load(p.tmo[0]), L::load(p.tmo[1]), L::load(p.tmo[2])};
        const V d[3] = {L::load(p.tmd[0]), L::load(p.tmd[1]), L::load(p.tmd[2])};
        auto tri = [&](const float* a) __attribute__((always_inline)) {
            return L::set1(a[i]);
        };
        const int reject =
            triangleRejects<L>(b, tri, o, d, L::load(p.tmx), L::load(p.tmy), L::load(p.tmz));
        return ~unsigned(reject) & ((1u << W) - 1);
    }

    // Triangles i..i+3 against the ray of lane j: the single walk's filter (triangleRejects
    // with Quad, visitLeaf's) with the ray's values from the packet's lanes (triangleLanes:
    // mtSetup's values, the same bits). Returns the candidates' mask (4 bits).
    __attribute__((always_inline)) static int triangleQuadTest(const Bvh& b, const Packet& p, int j,
                                                               std::uint32_t i) {
        const __m128 o[3] = {_mm_set1_ps(p.tmo[0][j]), _mm_set1_ps(p.tmo[1][j]),
                             _mm_set1_ps(p.tmo[2][j])};
        const __m128 d[3] = {_mm_set1_ps(p.tmd[0][j]), _mm_set1_ps(p.tmd[1][j]),
                             _mm_set1_ps(p.tmd[2][j])};
        auto tri = [&](const float* a) __attribute__((always_inline)) {
            return _mm_loadu_ps(a + i);
        };
        return 0xF & ~triangleRejects<Quad>(b, tri, o, d, _mm_set1_ps(p.tmx[j]),
                                            _mm_set1_ps(p.tmy[j]), _mm_set1_ps(p.tmz[j]));
    }

    // joinPacket's per-ray part for 8 lanes, four rays at a time: each ray's origin and
    // direction loaded as two rows of four doubles and transposed into the packet's lanes
    // (oo, dd), then initRay's checks for four rays in one (|d| in [1e-30, 1e30] on every
    // axis, the origin's largest |component| below 1e30) and the direction signs as three
    // movemasks. The same decisions as the ray-by-ray loop: std::max(a, b) is (a < b ? b :
    // a), which is _mm256_max_pd(b, a) also for a NaN operand. Lanes outside `lanes` load
    // the first ray of `lanes` (rays[j] may not exist there). Returns the joined rays and
    // their signs (signsOut); omax and tm are set in every lane. (Their RayData: joinLanes,
    // once the root test has kept them.) Inlined: GCC left it out of line once
    // joinPacket took the root test, and balls 4's shadow packets took 5.7 instructions a
    // ray more (callgrind; the eye packets the same within 0.5).
    // kFull: every lane in the packet (lanes == 0xFF, most of a picture's packets), each
    // lane loading its own ray without the choice.
    template <bool kFull>
    __attribute__((always_inline)) static unsigned
    joinChecks(Packet& p, const Ray* rays, const double* tMin, unsigned lanes, double* omax,
               double* tm, int& signsOut) {
        const int firstLane = __builtin_ctz(lanes);
        const __m256d absMask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffff));
        const __m256d lo = _mm256_set1_pd(1e-30), hi = _mm256_set1_pd(1e30);
        unsigned valid = 0, sx = 0, sy = 0, sz = 0;
        for (int j = 0; j < W; j += 4) {
            __m256d a[4], d[4];
            for (int k = 0; k < 4; ++k) {
                const int src = kFull || (lanes >> (j + k)) & 1 ? j + k : firstLane;
                a[k] = _mm256_loadu_pd(&rays[src].origin.x);    // ox oy oz dx
                d[k] = _mm256_loadu_pd(&rays[src].direction.x); // dx dy dz (weight)
                if constexpr (!kFull) tm[j + k] = tMin[src];
            }
            if constexpr (kFull) _mm256_store_pd(tm + j, _mm256_loadu_pd(tMin + j));
            const __m256d t0 = _mm256_unpacklo_pd(a[0], a[1]), t1 = _mm256_unpackhi_pd(a[0], a[1]);
            const __m256d t2 = _mm256_unpacklo_pd(a[2], a[3]), t3 = _mm256_unpackhi_pd(a[2], a[3]);
            const __m256d u0 = _mm256_unpacklo_pd(d[0], d[1]), u1 = _mm256_unpackhi_pd(d[0], d[1]);
            const __m256d u2 = _mm256_unpacklo_pd(d[2], d[3]), u3 = _mm256_unpackhi_pd(d[2], d[3]);
            const __m256d o[3] = {_mm256_permute2f128_pd(t0, t2, 0x20),
                                  _mm256_permute2f128_pd(t1, t3, 0x20),
                                  _mm256_permute2f128_pd(t0, t2, 0x31)};
            const __m256d dir[3] = {_mm256_permute2f128_pd(t1, t3, 0x31),
                                    _mm256_permute2f128_pd(u1, u3, 0x20),
                                    _mm256_permute2f128_pd(u0, u2, 0x31)};
            const __m256d om = _mm256_max_pd(
                _mm256_max_pd(_mm256_and_pd(o[2], absMask), _mm256_and_pd(o[1], absMask)),
                _mm256_and_pd(o[0], absMask));
            __m256d ok = _mm256_cmp_pd(om, hi, _CMP_LT_OQ);
            _mm256_store_pd(omax + j, om);
            for (int c = 0; c < 3; ++c) {
                _mm256_store_pd(&p.oo[c][j], o[c]);
                _mm256_store_pd(&p.dd[c][j], dir[c]);
                const __m256d ad = _mm256_and_pd(dir[c], absMask);
                ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(ad, lo, _CMP_GE_OQ),
                                                     _mm256_cmp_pd(ad, hi, _CMP_LE_OQ)));
            }
            valid |= unsigned(_mm256_movemask_pd(ok)) << j;
            sx |= unsigned(_mm256_movemask_pd(dir[0])) << j;
            sy |= unsigned(_mm256_movemask_pd(dir[1])) << j;
            sz |= unsigned(_mm256_movemask_pd(dir[2])) << j;
        }
        valid &= lanes;
        if (!valid) return 0;
        // The first ray that passes sets the signs; the others must share them.
        // Each axis's sign of the first ray as all ones or zero, the rays that differ from it
        // by an xor (no branch or select per axis).
        const int f = __builtin_ctz(valid);
        const unsigned bx = 0u - ((sx >> f) & 1), by = 0u - ((sy >> f) & 1),
                       bz = 0u - ((sz >> f) & 1);
        signsOut = int((bx & 1) | (by & 2) | (bz & 4));
        return valid & ~((sx ^ bx) | (sy ^ by) | (sz ^ bz));
    }
    // The RayData of the lanes that walk (joinPacket, 8 lanes).
    static void joinLanes(Packet& p, const Ray* rays, unsigned walk, int signs) {
        // Every lane (most packets of a picture): the eight lanes unrolled at fixed
        // offsets, no loop over the bits (17 instructions a lane to ~5; issue 21, eighth
        // session).
        if (walk == (1u << W) - 1) {
            for (int j = 0; j < W; ++j)
                joinLane(p.r[j], signs, rays[j]);
            return;
        }
        for (unsigned m = walk; m; m &= m - 1) {
            const int j = __builtin_ctz(m);
            joinLane(p.r[j], signs, rays[j]);
        }
    }
    // A joined ray's RayData: setRayData's fields and the set-up flags RayData's
    // initializers would clear (Packet::r has none run).
    __attribute__((always_inline)) static void joinLane(RayData& r, int signs, const Ray& ray) {
        setRayData(r, signs, true, ray);
        r.sphReady = false;
        r.shReady = false;
        r.mtReady = false;
    }
    // Eight doubles rounded to float (joinPacket, 8 lanes). V, not __m256, as the return
    // type: the SSE2 file never instantiates it (an __m256 return there is an ABI warning).
    template <class T = V> static T toFloat8(const double* x) {
        return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(_mm256_load_pd(x))),
                                    _mm256_cvtpd_ps(_mm256_load_pd(x + 4)), 1);
    }
    // Sets up the rays of `lanes` that can join the packet and returns their mask; the others
    // (double walk, a zero direction component, or other signs than the first joining
    // ray's) are traced one by one. initRay's checks per ray; then initRay's float values
    // (the same IEEE operations lane by lane: conversions, 1/d, products, sums, so the same
    // bits) four rays at a time, stored straight into the packet's lanes: one division for
    // four rays instead of one a ray (issue 21: the per-ray set-up was a fifth of a mesh
    // packet's instructions). The ray's own RayData registers are filled when it first
    // runs its own leaf tests (fillLane). The range checks are initRay's (inRange); the
    // float values are floatRay's operations, written out four rays at a time (one call per
    // ray would cost the division per ray this saves).
    // Then the limits (limitLanes) and, for nearest hits (kRoot), the root test (rootLanes):
    // `walk` is set to the joined rays that may enter the root's children, the others'
    // limits to −inf; only the rays of `walk` get their RayData (8 lanes; all joined ones
    // with 4). A packet no ray of which walks is done with the float values and the test
    // (issue 21: 77% of the mesh's eye rays meet no leaf, and more than half its packets
    // miss the root's boxes). Inlined into its two callers: a packet turned away then
    // pays one function's entry and exit (callgrind: eye mesh −3.3 instructions a ray).
    template <bool kRoot>
    __attribute__((always_inline)) static unsigned
    joinPacket(const Bvh& b, Packet& p, const Ray* rays, const double* tMin, const double* tMax,
               unsigned lanes, unsigned& walk) {
        alignas(32) double omax[W], tm[W];
        int signs = 0;
        double(&oo)[3][W] = p.oo;
        double(&dd)[3][W] = p.dd;
        unsigned joined = 0;
        // No lane asked (occludedPacket's lanes all blocked already): joinChecks takes its
        // first lane's ray for the lanes outside the packet, and there is none.
        walk = 0;
        if (!lanes) return 0;
        if constexpr (W == 8) {
            joined = lanes == 0xFFu ? joinChecks<true>(p, rays, tMin, lanes, omax, tm, signs)
                                    : joinChecks<false>(p, rays, tMin, lanes, omax, tm, signs);
        } else {
            signs = -1;
            for (unsigned m = lanes; m; m &= m - 1) {
                const int j = __builtin_ctz(m);
                const Ray& ray = rays[j];
                const glm::dvec3 o = ray.origin, d = ray.direction;
                const __m128d dxy = _mm_loadu_pd(&ray.direction[0]),
                              dz = _mm_load_sd(&ray.direction[2]);
                const int sg = _mm_movemask_pd(dxy) | (_mm_movemask_pd(dz) << 2);
                if (signs >= 0 && sg != signs) continue;
                const double om = std::max(std::abs(o.x), std::max(std::abs(o.y), std::abs(o.z)));
                // initRay's range check with a zero direction component refused too.
                if (!(om < 1e30 && inRange<false>(dxy) == 3 && (inRange<false>(dz) & 1))) continue;
                signs = sg;
                joined |= 1u << j;
                joinLane(p.r[j], sg, ray);
                const double* op = &o.x;
                const double* dp = &d.x;
                for (int a = 0; a < 3; ++a) {
                    oo[a][j] = op[a];
                    dd[a][j] = dp[a];
                }
                omax[j] = om;
                tm[j] = tMin[j];
            }
        }
        if (!joined) return 0;
        // Lanes outside the packet compute the first ray's values: the intervals over all W
        // lanes (walkPacket) are then those over the packet's rays. (joinChecks filled the
        // lanes outside `lanes` with them already: copied only when a ray was refused.)
        const int first = __builtin_ctz(joined);
        for (int j = 0; j < W && (W != 8 || joined != lanes); ++j) {
            if ((joined >> j) & 1) continue;
            for (int a = 0; a < 3; ++a) {
                oo[a][j] = oo[a][first];
                dd[a][j] = dd[a][first];
            }
            omax[j] = omax[first];
            tm[j] = tm[first];
        }
        p.off = kOffsets.v[signs];
        if constexpr (W == 8) {
            // The same operations in eight lanes at once (AVX: the L8 files only).
            const __m256 eps = _mm256_mul_ps(toFloat8(omax), _mm256_set1_ps(0x1p-21f));
            for (int a = 0; a < 3; ++a) {
                const __m256 fd = toFloat8(dd[a]), fo = toFloat8(oo[a]);
                const __m256 finv = _mm256_div_ps(_mm256_set1_ps(1.0f), fd);
                const __m256 sgnEps = _mm256_xor_ps(eps, _mm256_and_ps(fd, _mm256_set1_ps(-0.0f)));
                _mm256_store_ps(p.inv[a], finv);
                _mm256_store_ps(p.invFar[a],
                                _mm256_mul_ps(finv, _mm256_set1_ps(bvh_detail::kInvFarScaleF)));
                _mm256_store_ps(p.on[a], _mm256_add_ps(fo, sgnEps));
                _mm256_store_ps(p.of[a], _mm256_sub_ps(fo, sgnEps));
            }
            const __m256 ftMin = toFloat8(tm);
            const __m256 absT =
                _mm256_and_ps(ftMin, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff)));
            _mm256_store_ps(p.tMin,
                            _mm256_sub_ps(ftMin, _mm256_mul_ps(absT, _mm256_set1_ps(0x1p-20f))));
            walk = limitLanes<kRoot>(b, p, joined, tMax);
            if (walk) joinLanes(p, rays, walk, signs);
            return joined;
        }
        auto toFloat = [](const double* x) { // four doubles rounded to float, as _mm_cvtpd_ps
            return _mm_movelh_ps(_mm_cvtpd_ps(_mm_load_pd(x)), _mm_cvtpd_ps(_mm_load_pd(x + 2)));
        };
        for (int j = 0; j < W; j += 4) {
            // float(om)·2^-21 with the direction's sign, as initRay's sgnEps.
            const __m128 eps = _mm_mul_ps(toFloat(omax + j), _mm_set1_ps(0x1p-21f));
            for (int a = 0; a < 3; ++a) {
                const __m128 fd = toFloat(dd[a] + j), fo = toFloat(oo[a] + j);
                const __m128 finv = _mm_div_ps(_mm_set1_ps(1.0f), fd);
                const __m128 sgnEps = _mm_xor_ps(eps, _mm_and_ps(fd, _mm_set1_ps(-0.0f)));
                _mm_store_ps(&p.inv[a][j], finv);
                _mm_store_ps(&p.invFar[a][j],
                             _mm_mul_ps(finv, _mm_set1_ps(bvh_detail::kInvFarScaleF)));
                _mm_store_ps(&p.on[a][j], _mm_add_ps(fo, sgnEps));
                _mm_store_ps(&p.of[a][j], _mm_sub_ps(fo, sgnEps));
            }
            const __m128 ftMin = toFloat(tm + j);
            const __m128 absT = _mm_and_ps(ftMin, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)));
            _mm_store_ps(&p.tMin[j], _mm_sub_ps(ftMin, _mm_mul_ps(absT, _mm_set1_ps(0x1p-20f))));
        }
        walk = limitLanes<kRoot>(b, p, joined, tMax);
        return joined;
    }
    // Ray j's RayData registers as initRay sets them, from the packet's lanes (before the
    // ray's own leaf tests).
    static void fillLane(Packet& p, int j) {
        if ((p.filled >> j) & 1) return;
        RayData& r = p.r[j];
        for (int a = 0; a < 3; ++a) {
            r.on[a] = L::set1(p.on[a][j]);
            r.of[a] = L::set1(p.of[a][j]);
            r.inv[a] = L::set1(p.inv[a][j]);
            r.invFar[a] = L::set1(p.invFar[a][j]);
        }
        r.tMin = L::set1(p.tMin[j]);
        p.filled |= 1u << j;
    }

    // The interval test's bounds of a ray's entry and exit on one axis. A ray's entry is
    // fl(fl(n − on)·inv), n the near plane. Where d > 0 (inv > 0) it grows with n − on,
    // and fl(n − on) >= x = fl(n − onHi) (rounding is monotonic); where d < 0 it shrinks
    // with n − on, and fl(n − on) <= x = fl(n − onLo) (walkPacket's iaOn). So every
    // ray's entry is at least fl(x·inv) for its own inv, and x·y, linear in y, takes its
    // smallest value over [invLo, invHi] at an end: min(fl(x·invLo), fl(x·invHi)) bounds
    // every ray's rounded entry from below. The exit, fl(fl(f − of)·invFar), the same way
    // from above with x = fl(f − ofFar): max(fl(x·invFarLo), fl(x·invFarHi)). Two products
    // where the sign of x is not known, not the four corner products of both intervals
    // (issue 21: balls 4 eye packets, callgrind).
    static V minProduct(V x, V y0, V y1) { return L::min(L::mul(x, y0), L::mul(x, y1)); }
    static V maxProduct(V x, V y0, V y1) { return L::max(L::mul(x, y0), L::mul(x, y1)); }

    // The rays of the packet that may enter a child of the root: startRay's root-box test
    // (b.rootF_, the union of the root's child boxes, against each ray's own float values
    // and limit, the same operations in the same order), eight rays at once. A ray it turns
    // away enters no child (startRay's argument: the union's entry is at most every child's,
    // its exit at least), so dropping it changes no ray's walk; a packet none of whose rays
    // passes is done before the walk's set-up (issue 21: 77% of the mesh's eye rays meet no
    // leaf).
    static unsigned rootLanes(const Bvh& b, const Packet& p, unsigned lanes) {
        V t0 = L::load(p.tMin), t1 = L::load(p.lim);
        for (int a = 0; a < 3; ++a) {
            const V inv = L::load(p.inv[a]);
            V nearP, farP;
            if constexpr (W == 8) {
                // By each lane's own sign bit of 1/d (d's), as startRay: no scalar choice.
                const V lo = L::set1(b.rootF_[0][a]), hi = L::set1(b.rootF_[1][a]);
                nearP = _mm256_blendv_ps(lo, hi, inv);
                farP = _mm256_blendv_ps(hi, lo, inv);
            } else {
                const int neg = (p.r[__builtin_ctz(lanes)].signs >> a) & 1; // every ray's
                nearP = L::set1(b.rootF_[neg][a]);
                farP = L::set1(b.rootF_[1 - neg][a]);
            }
            t0 = L::max(L::mul(L::sub(nearP, L::load(p.on[a])), inv), t0);
            t1 = L::min(L::mul(L::sub(farP, L::load(p.of[a])), L::load(p.invFar[a])), t1);
        }
        return unsigned(L::le(t0, t1)) & lanes;
    }

    // The walk's limits of the packet's lanes (p.lim; limitOf's), then, with kRoot, the rays
    // of `lanes` that pass the root test (the others' limits −inf, as a done lane's); without,
    // `lanes`. A full packet of unbounded segments leaves the rays turned away at +inf: out
    // of the walk's rays, they enter nothing (every per-ray test is masked by them), and only
    // the interval test's largest limit sees them (it stays +inf after the other rays' hits).
    // Setting them −inf there too (one blend) measured +0.7 / +1.1 instructions a ray (eye
    // mesh / balls 4, callgrind).
    template <bool kRoot>
    static unsigned limitLanes(const Bvh& b, Packet& p, unsigned lanes, const double* tMax) {
        constexpr float kInfF = std::numeric_limits<float>::infinity();
        // Lanes outside the packet: the limit −inf (no box is entered by them).
        if constexpr (W == 8) {
            // Eye rays: a full packet of unbounded segments (limitOf(inf) is inf), the
            // common case of nearest hits, in a compare (issue 21: the general code below
            // is ~40 instructions a packet).
            if constexpr (kRoot) {
                const __m256d inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
                if (lanes == (1u << W) - 1 &&
                    _mm256_movemask_pd(_mm256_and_pd(
                        _mm256_cmp_pd(_mm256_loadu_pd(tMax), inf, _CMP_EQ_OQ),
                        _mm256_cmp_pd(_mm256_loadu_pd(tMax + 4), inf, _CMP_EQ_OQ))) == 0xF) {
                    L::store(p.lim, L::set1(kInfF));
                    return rootLanes(b, p, lanes);
                }
            }
            // limitOf four lanes at a time: the same double product, compare and rounding
            // (an infinite limit where limitOf gives one). tMax is read in the packet's
            // lanes only (a masked load: the caller's array may end before lane 8).
            const __m128i bits = _mm_setr_epi32(1, 2, 4, 8);
            for (int h = 0; h < W; h += 4) {
                const __m128i in =
                    _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(int(lanes >> h)), bits), bits);
                const __m256d lim =
                    _mm256_mul_pd(_mm256_maskload_pd(tMax + h, _mm256_cvtepi32_epi64(in)),
                                  _mm256_set1_pd(bvh_detail::kFarScale));
                const __m256d capped =
                    _mm256_blendv_pd(lim, _mm256_set1_pd(std::numeric_limits<double>::infinity()),
                                     _mm256_cmp_pd(lim, _mm256_set1_pd(kLimitCap), _CMP_GT_OQ));
                const __m128 f = _mm_mul_ps(_mm256_cvtpd_ps(capped), _mm_set1_ps(kLimitUp));
                _mm_store_ps(&p.lim[h],
                             _mm_blendv_ps(_mm_set1_ps(-kInfF), f, _mm_castsi128_ps(in)));
            }
        } else {
            for (int j = 0; j < W; ++j)
                p.lim[j] = (lanes >> j) & 1 ? limitOf(tMax[j]) : -kInfF;
        }
        if constexpr (!kRoot) return lanes;
        const unsigned in = rootLanes(b, p, lanes);
        for (unsigned m = lanes & ~in; m; m &= m - 1)
            p.lim[__builtin_ctz(m)] = -kInfF; // out of the walk, as a done lane
        return in;
    }

    // Calls leaf(j, i, ray data) for ray j of `lanes` and the primitives i of every leaf
    // its segment may meet; tMax[j] as in walk() (nearest hit: the leaf may lower it and
    // the walk re-reads it after each leaf). Any hit: leaf returns false when ray j is
    // done (found a blocker); the walk ends when every ray is.
    template <bool kAnyHit, class Leaf>
    static void walkPacket(const Bvh& b, Packet& p, unsigned lanes, const double* tMax,
                           Leaf&& leaf) {
        const auto& nodes = nodesOf(b);
        constexpr float kInfF = std::numeric_limits<float>::infinity();
        // p.lim: joinPacket's (limitLanes): −inf outside the packet's joined rays; those the
        // root test turned away (outside `lanes` too) −inf or, in an unbounded full packet,
        // +inf.
        // The intervals over the packet's rays, in every lane (joinPacket gave the lanes
        // outside the packet the first ray's values). The origin bound per axis: the near
        // plane's smallest difference n − on where d > 0 (the largest on), its largest where
        // d < 0; the far plane's largest f − of where d > 0 (the smallest of), its smallest
        // where d < 0. The packet's rays share their direction signs (joinPacket).
        const RayData& lead = p.r[__builtin_ctz(lanes)]; // its signs are every ray's
        V iaOn[3], iaOf[3], iaInvLo[3], iaInvHi[3], iaFarLo[3], iaFarHi[3];
        for (int a = 0; a < 3; ++a) {
            const V on = L::load(p.on[a]), of = L::load(p.of[a]), inv = L::load(p.inv[a]);
            iaOn[a] = lead.neg(a) ? hmin(on) : hmax(on);
            iaOf[a] = lead.neg(a) ? hmax(of) : hmin(of);
            iaInvLo[a] = hmin(inv);
            iaInvHi[a] = hmax(inv);
            // invFar = fl(inv·s) lane by lane (joinPacket), s > 0: rounding is monotonic, so
            // the smallest and largest invFar are those of the smallest and largest inv,
            // the same bits as their own reductions (no lane NaN: the rays' |d| are in
            // range).
            const V s = L::set1(bvh_detail::kInvFarScaleF);
            iaFarLo[a] = L::mul(iaInvLo[a], s);
            iaFarHi[a] = L::mul(iaInvHi[a], s);
        }
        // A NaN tMin (its lane never enters a box) counts as +inf, so it lowers no bound.
        const V tMinV = L::load(p.tMin), iaTMin = hmin(L::min(tMinV, L::set1(kInfF)));
        V limV = L::load(p.lim);
        unsigned active = lanes;
        // The largest limit of the active rays, in every lane: the other lanes' limits are
        // −inf (outside the packet, or done), and a NaN limit (its lane enters no box)
        // counts as −inf.
        auto maxLim = [&]() { return hmax(L::max(limV, L::set1(-kInfF))); };
        V limHi = maxLim();
        // Visits a leaf for the rays of m; false when no ray is left (any hit). Inlined
        // into its three calls: out of line, its entry and exit (saved registers, the
        // captured state reloaded) were ~60 instructions a leaf (issue 21, eighth session).
        auto visitLeaves = [&](std::uint32_t first, std::uint32_t count, unsigned m)
            __attribute__((always_inline)) {
            m &= active;
            const int nm = __builtin_popcount(m);
            // A leaf whose first run is of triangles takes the run loop for any number of
            // rays: its triangle runs are tested from the packet's lanes (below), without
            // the ray's own set-up (fillLane, mtSetup).
            if (nm >= kTransposeLanes ||
                bvh_detail::runOf(b.kind_[first]) == bvh_detail::kRunTriangle) {
                using namespace bvh_detail;
                unsigned offered = 0; // lanes a primitive was offered to (their tMax may be lower)
                // A lane done (any hit): out of the leaf and the walk.
                auto done = [&](int j) {
                    m &= ~(1u << j);
                    active &= ~(1u << j);
                    p.lim[j] = -std::numeric_limits<float>::infinity();
                };
                // Nearest hit: a triangle run's candidates (lane, primitive) are kept in the
                // order the filters give them and confirmed after the run by one out-of-line
                // call (the visitor's confirm). Inlined here, each exact test cost ~84
                // instructions around its call and lengthened the walk's code; the loop in
                // confirm takes ~68 a candidate and ~25 a call (mesh eye packets 324.6 ->
                // 319.9 instructions a ray; issue 21, twelfth session, callgrind). The same
                // exact tests in the same order: within a leaf the filters read only the
                // lanes' limits, which change after the leaf. Any hit keeps its test in place
                // (a blocked lane leaves the run at once), and so do spheres (jacks 4's short
                // sphere runs: the call per run cost more than it saved).
                constexpr int kDeferred = 32; // flushed when full: a run may be long
                std::uint32_t deferI[kAnyHit ? 1 : kDeferred];
                std::uint8_t deferJ[kAnyHit ? 1 : kDeferred];
                int deferred = 0;
                auto flush = [&]() __attribute__((always_inline)) {
                    if constexpr (!kAnyHit) {
                        if (deferred) leaf.confirm(p.r, deferI, deferJ, deferred);
                        deferred = 0;
                    }
                };
                auto defer = [&](int j, std::uint32_t i) __attribute__((always_inline)) {
                    deferI[deferred] = i;
                    deferJ[deferred] = std::uint8_t(j);
                    if (++deferred == kDeferred) flush();
                };
                (void)defer;
                const std::uint32_t end = first + count;
                for (std::uint32_t run = first; run < end && m;) {
                    const std::uint32_t rEnd = run + b.run_[run];
                    const std::uint8_t runKind = runOf(b.kind_[run]);
                    unsigned mt = 0; // lanes tested transposed
                    if (runKind == kRunSphere) {
                        if (nm >= kTransposeLanes) {
                            if (!p.sphSet) sphereLanes(p, lanes);
                            mt = m & p.sphLanes;
                        }
                    } else if (runKind == kRunTriangle) {
                        if (!p.triSet) triangleLanes(p, lanes);
                        mt = m & p.triLanes;
                        // Few rays against the run: each ray against four triangles at a
                        // time (the single walk's filter, its values from the packet's
                        // lanes) costs less than each triangle against the eight lanes.
                        const std::uint32_t n = rEnd - run;
                        if (unsigned(__builtin_popcount(mt)) * ((n + 3) / 4) * kQuadCost <
                            n * kLanesCost) {
                            for (unsigned k = mt; k; k &= k - 1) {
                                const int j = __builtin_ctz(k);
                                for (std::uint32_t i = run; i < rEnd; i += 4) {
                                    int cand = triangleQuadTest(b, p, j, i);
                                    if (rEnd - i < 4) cand &= (1 << (rEnd - i)) - 1;
                                    if (cand) offered |= 1u << j;
                                    for (; cand; cand &= cand - 1) {
                                        const std::uint32_t t =
                                            i + std::uint32_t(__builtin_ctz(unsigned(cand)));
                                        if constexpr (kAnyHit) {
                                            if (!leaf(j, t, &p.r[j])) {
                                                done(j);
                                                i = rEnd;
                                                break;
                                            }
                                        } else {
                                            defer(j, t);
                                        }
                                    }
                                }
                            }
                            flush();
                            run = rEnd;
                            continue;
                        }
                    }
                    // The other lanes (and the other kinds): each ray's own tests of this
                    // run (visitLeaf of one run: run_[run] ends it at rEnd).
                    for (unsigned k = m & ~mt; k; k &= k - 1) {
                        const int j = __builtin_ctz(k);
                        fillLane(p, j);
                        const bool more =
                            visitLeaf(b, p.r[j], run, rEnd - run, p.lim[j],
                                      [&](std::uint32_t i, RayData* r) { return leaf(j, i, r); });
                        if (kAnyHit && !more) done(j);
                    }
                    offered |= m & ~mt;
                    if (!kAnyHit && runKind == kRunTriangle) {
                        for (std::uint32_t i = run; i < rEnd && mt; ++i) {
                            unsigned cand = mt & triangleLanesTest(b, p, i);
                            offered |= cand;
                            for (; cand; cand &= cand - 1)
                                defer(__builtin_ctz(cand), i);
                        }
                        flush();
                        run = rEnd;
                        continue;
                    }
                    for (std::uint32_t i = run; i < rEnd && mt; ++i) {
                        unsigned cand = mt & (runKind == kRunSphere ? sphereLanesTest(b, p, i)
                                                                    : triangleLanesTest(b, p, i));
                        offered |= cand;
                        for (; cand; cand &= cand - 1) {
                            const int j = __builtin_ctz(cand);
                            if (!leaf(j, i, &p.r[j]) && kAnyHit) {
                                done(j);
                                mt &= ~(1u << j);
                            }
                        }
                    }
                    run = rEnd;
                }
                if constexpr (!kAnyHit) {
                    // Only a lane offered a primitive can have lowered its tMax.
                    if (!offered) return true;
                    for (unsigned k = offered; k; k &= k - 1)
                        p.lim[__builtin_ctz(k)] = limitOf(tMax[__builtin_ctz(k)]);
                } else {
                    (void)offered;
                }
                limV = L::load(p.lim);
                limHi = maxLim();
                return active != 0;
            }
            for (; m; m &= m - 1) {
                const int j = __builtin_ctz(m);
                fillLane(p, j);
                const bool more =
                    visitLeaf(b, p.r[j], first, count, p.lim[j],
                              [&](std::uint32_t i, RayData* r) { return leaf(j, i, r); });
                if constexpr (kAnyHit) {
                    if (!more) {
                        active &= ~(1u << j);
                        p.lim[j] = -std::numeric_limits<float>::infinity();
                    }
                } else {
                    p.lim[j] = limitOf(tMax[j]);
                }
            }
            limV = L::load(p.lim);
            limHi = maxLim();
            return active != 0;
        };
        struct Entry {
            std::uint32_t child;
            std::uint16_t count;
            std::uint16_t rays;
            float t;
        };
        Entry stack[kStack];
        int sp = 0;
        std::uint32_t cur = 0;
        unsigned curRays = active;
        while (true) {
            const Node& nd = nodes[cur];
            if constexpr (sizeof(Node) > 128)
                _mm_prefetch(reinterpret_cast<const char*>(&nd.child[0]), _MM_HINT_T0);
            // A child's rays: lane bits, a byte a child where the few-ray test below writes
            // them whole (any hit); the nearest-hit walk keeps unsigned (bytes there cost
            // ~2 instructions a ray in its node loop, callgrind).
            static_assert(W <= 8, "a child's rays are a byte of lane bits");
            using RayBits = std::conditional_t<kAnyHit, std::uint8_t, unsigned>;
            alignas(8) RayBits rays[W];
            alignas(32) float tc[W];
            int mask = 0;
            curRays &= active;
            if (curRays && !(curRays & (curRays - 1))) {
                // One ray left (a fifth of the mesh's nodes): its own test of the W children
                // at once, the lanes' operations of the per-ray test below with the ray's
                // values broadcast (the same verdicts), without the interval test. A
                // child's distance is the ray's own entry (a lower bound of it, as the
                // drop test needs).
                const int j = __builtin_ctz(curRays);
                V r0 = L::set1(p.tMin[j]), r1 = L::set1(p.lim[j]);
                for (int a = 0; a < 3; ++a) {
                    const V n = planes(nd, p.off[a], a), f = planes(nd, p.off[3 + a], a);
                    r0 = L::max(L::mul(L::sub(n, L::set1(p.on[a][j])), L::set1(p.inv[a][j])), r0);
                    r1 =
                        L::min(L::mul(L::sub(f, L::set1(p.of[a][j])), L::set1(p.invFar[a][j])), r1);
                }
                mask = L::le(r0, r1) & validMask(nd);
                if constexpr (!kAnyHit) L::store(tc, r0);
                for (int k = mask; k; k &= k - 1)
                    rays[__builtin_ctz(unsigned(k))] = RayBits(curRays);
            } else if (kAnyHit && __builtin_popcount(curRays) <= kRayMajorRays) {
                // Any hit, two or three rays: each ray's own test of the W children at once
                // (the one-ray test above, the same verdicts as the per-child lane test
                // below), without the interval test; the rays' child masks turned into each
                // child's ray mask, a byte a child (kSpread). Not for the nearest hit: there
                // the children's order comes from the interval test's entries, and the
                // rays' smallest entry instead (with bytes for rays) cost more than it
                // saved (mesh eye packets 319.9 -> 322.8 instructions a ray, callgrind).
                V n[3], f[3];
                for (int a = 0; a < 3; ++a) {
                    n[a] = planes(nd, p.off[a], a);
                    f[a] = planes(nd, p.off[3 + a], a);
                }
                std::uint64_t spread = 0;
                for (unsigned k = curRays; k; k &= k - 1) {
                    const int j = __builtin_ctz(k);
                    V r0 = L::set1(p.tMin[j]), r1 = L::set1(p.lim[j]);
                    for (int a = 0; a < 3; ++a) {
                        r0 = L::max(L::mul(L::sub(n[a], L::set1(p.on[a][j])), L::set1(p.inv[a][j])),
                                    r0);
                        r1 = L::min(
                            L::mul(L::sub(f[a], L::set1(p.of[a][j])), L::set1(p.invFar[a][j])), r1);
                    }
                    const int mj = L::le(r0, r1);
                    mask |= mj;
                    spread |= bvh_detail::kSpread[mj] << j;
                }
                mask &= validMask(nd);
                std::memcpy(rays, &spread, W);
            } else {
                alignas(32) float nearA[3][W], farA[3][W]; // the decoded planes (Q)
                const float* nearP[3];
                const float* farP[3];
                // The interval test: the W children against the whole packet at once.
                V t0 = iaTMin, t1 = limHi;
                for (int a = 0; a < 3; ++a) {
                    const V n = planes(nd, p.off[a], a), f = planes(nd, p.off[3 + a], a);
                    if constexpr (Q) {
                        L::store(nearA[a], n);
                        L::store(farA[a], f);
                        nearP[a] = nearA[a];
                        farP[a] = farA[a];
                    } else {
                        const char* base = reinterpret_cast<const char*>(&nd);
                        nearP[a] = reinterpret_cast<const float*>(base + p.off[a]);
                        farP[a] = reinterpret_cast<const float*>(base + p.off[3 + a]);
                    }
                    t0 = L::max(minProduct(L::sub(n, iaOn[a]), iaInvLo[a], iaInvHi[a]), t0);
                    t1 = L::min(maxProduct(L::sub(f, iaOf[a]), iaFarLo[a], iaFarHi[a]), t1);
                }
                int cand = L::le(t0, t1) & validMask(nd);
                // Each candidate child against each ray (lane j: ray j's own test). A child's
                // distance (its order, and its drop once nearer hits are known) is the interval
                // test's entry, at most every ray's own entry (monotonic rounding, as above).
                if constexpr (!kAnyHit) L::store(tc, t0);
                while (cand) {
                    const int c = __builtin_ctz(unsigned(cand));
                    cand &= cand - 1;
                    V r0 = tMinV, r1 = limV;
                    for (int a = 0; a < 3; ++a) {
                        // The packet's lanes read from p at each use (memory operands): held in
                        // locals, GCC copied all twelve vectors to its stack at every packet's
                        // start (~50 moves; issue 21, eighth session).
                        r0 = L::max(L::mul(L::sub(L::set1(nearP[a][c]), L::load(p.on[a])),
                                           L::load(p.inv[a])),
                                    r0);
                        r1 = L::min(L::mul(L::sub(L::set1(farP[a][c]), L::load(p.of[a])),
                                           L::load(p.invFar[a])),
                                    r1);
                    }
                    const unsigned m = unsigned(L::le(r0, r1)) & curRays;
                    if (!m) continue;
                    mask |= 1 << c;
                    rays[c] = RayBits(m);
                }
            }
            bool haveNext = false;
            if constexpr (kAnyHit) {
                while (mask) {
                    const int c = __builtin_ctz(unsigned(mask));
                    mask &= mask - 1;
                    if (nd.count[c] > 0) {
                        if (!visitLeaves(nd.child[c], nd.count[c], rays[c])) return;
                    } else {
                        if (haveNext) stack[sp++] = {cur, 0, std::uint16_t(curRays), 0.0f};
                        cur = nd.child[c];
                        curRays = rays[c];
                        haveNext = true;
                    }
                }
            } else if (mask) {
                // Nearest first: sorted by the packet's smallest entry distance, the farther
                // ones pushed farthest first; a leaf met as the nearest is visited at once.
                // The entries go straight onto the stack, each sorted in among this node's
                // (the same stable order as sorting indices first, then pushing: issue 21,
                // eleventh session, callgrind), and the nearest is popped back; one child
                // (most nodes) skips the stack.
                Entry next;
                const int c0 = __builtin_ctz(unsigned(mask));
                const int rest = mask & (mask - 1);
                if (!rest) {
                    next = {nd.child[c0], nd.count[c0], std::uint16_t(rays[c0]), 0.0f};
                } else if (!(rest & (rest - 1))) {
                    // Two: the nearer is next, the other pushed (on equal or unordered
                    // distances the second, as the stable sort below has it).
                    const int c1 = __builtin_ctz(unsigned(rest));
                    const Entry e0{nd.child[c0], nd.count[c0], std::uint16_t(rays[c0]), tc[c0]};
                    const Entry e1{nd.child[c1], nd.count[c1], std::uint16_t(rays[c1]), tc[c1]};
                    const bool firstNearer = e0.t < e1.t;
                    stack[sp++] = firstNearer ? e1 : e0;
                    next = firstNearer ? e0 : e1;
                } else {
                    const int base = sp;
                    while (mask) {
                        const int c = __builtin_ctz(unsigned(mask));
                        mask &= mask - 1;
                        const Entry e{nd.child[c], nd.count[c], std::uint16_t(rays[c]), tc[c]};
                        int k = sp++;
                        while (k > base && stack[k - 1].t < e.t) {
                            stack[k] = stack[k - 1];
                            --k;
                        }
                        stack[k] = e;
                    }
                    next = stack[--sp];
                }
                if (next.count == 0) {
                    cur = next.child;
                    curRays = next.rays;
                    haveNext = true;
                } else {
                    visitLeaves(next.child, next.count, next.rays);
                }
            }
            if (haveNext) continue;
            while (true) {
                if (sp == 0) return;
                const Entry e = stack[--sp];
                const unsigned m = e.rays & active;
                if (!m) continue;
                if constexpr (!kAnyHit) {
                    // Dropped when it lies beyond the limit of every ray of m (a NaN limit
                    // keeps it: a wasted visit, never a lost one).
                    if (!(L::ngt(L::set1(e.t), limV) & int(m))) continue;
                    if (e.count > 0) {
                        visitLeaves(e.child, e.count, m);
                        continue;
                    }
                }
                cur = e.child;
                curRays = m;
                break;
            }
        }
    }

    // Nearest hits of the rays of `lanes` (bit j: rays[j], j < W): hits[j] and the returned
    // mask as intersect(rays[j], tMin[j], tMax[j], hits[j]) gives them, bit for bit.
    static unsigned intersectPacket(const Bvh& b, const Ray* rays, const double* tMin,
                                    const double* tMaxIn, Hit* hits, unsigned lanes) {
        unsigned found = 0;
        if (b.stats_.primitives == 0 || b.rootLeafCount_ > 0) {
            for (; lanes; lanes &= lanes - 1) {
                const int j = __builtin_ctz(lanes);
                found |= unsigned(intersect(b, rays[j], tMin[j], tMaxIn[j], hits[j])) << j;
            }
            return found;
        }
        Packet p;
        double tMax[W];
        Best best[W];
        unsigned walk;
        const unsigned packet = joinPacket<true>(b, p, rays, tMin, tMaxIn, lanes, walk);
        for (unsigned m = lanes & ~packet; m; m &= m - 1) {
            const int j = __builtin_ctz(m);
            found |= unsigned(intersect(b, rays[j], tMin[j], tMaxIn[j], hits[j])) << j;
        }
        // No ray of the packet enters the root's boxes: only the unbounded primitives are
        // left for its rays.
        if (!walk && (!packet || b.unbounded_.empty())) return found;
        // Every lane's best cleared (W stores, no loop over the packet's bits); tMax copied
        // whole when the packet holds all W lanes (then tMaxIn has W entries).
        for (int j = 0; j < W; ++j)
            best[j].p = nullptr;
        if (packet == (1u << W) - 1) {
            std::memcpy(tMax, tMaxIn, sizeof tMax);
        } else {
            for (unsigned m = packet; m; m &= m - 1)
                tMax[__builtin_ctz(m)] = tMaxIn[__builtin_ctz(m)];
        }
        // intersect()'s offer, per ray (offerNearest: its rule for ties too).
        auto offer = [&](int j, const Primitive& q, std::uint8_t kind, std::uint32_t index,
                         const RayData* r) {
            offerNearest(q, kind, index, r, rays[j], tMin[j], tMax[j], hits[j], best[j]);
        };
        if (!b.unbounded_.empty())
            for (unsigned m = packet; m; m &= m - 1)
                for (std::size_t i = 0; i < b.unbounded_.size(); ++i)
                    offer(__builtin_ctz(m), *b.unbounded_[i], bvh_detail::kOther,
                          b.unboundedIndex_[i], nullptr);
        if (walk) {
            // The walk's leaf visitor holds the arrays' pointers themselves: a lambda
            // capturing by reference read each through the closure and then the variable,
            // ~8 loads more at every exact test (issue 21, eleventh session, callgrind).
            PacketNearest visit{b.order_.data(),
                                b.kind_.data(),
                                b.orderIndex_.data(),
                                rays,
                                tMin,
                                tMax,
                                hits,
                                best};
            walkPacket<false>(b, p, walk, tMax, visit);
        }
        // Every lane at once, no loop over the packet's bits (a branch and ~8 instructions a
        // ray): the lanes outside the packet kept their cleared best (issue 21, eighth session).
        if constexpr (W == 8) {
            // best[j].p is the first of Best's two quadwords: two records a 32-byte load, the
            // pointers of four as one unpack (lanes 0 2 1 3) and a permute, their zero test
            // as one movemask.
            static_assert(sizeof(Best) == 16 && offsetof(Best, p) == 0);
            const __m256i zero = _mm256_setzero_si256();
            auto nulls = [&](int j) {
                const __m256i* q = reinterpret_cast<const __m256i*>(&best[j]);
                const __m256i ps = _mm256_permute4x64_epi64(
                    _mm256_unpacklo_epi64(_mm256_loadu_si256(q), _mm256_loadu_si256(q + 1)), 0xD8);
                return unsigned(
                    _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(ps, zero))));
            };
            return found | (~(nulls(0) | nulls(4) << 4) & 0xFFu);
        }
        for (int j = 0; j < W; ++j)
            found |= unsigned(best[j].p != nullptr) << j;
        return found;
    }

    // Any hits of the rays of `lanes`: the returned mask as occluded(rays[j], tMin[j],
    // tMax[j], skip ? skip[j] : nullptr) gives it.
    static unsigned occludedPacket(const Bvh& b, const Ray* rays, const double* tMin,
                                   const double* tMax, const Primitive* const* skip,
                                   unsigned lanes) {
        unsigned blocked = 0;
        auto skipOf = [&](int j) { return skip ? skip[j] : nullptr; };
        if (b.stats_.primitives == 0 || b.rootLeafCount_ > 0) {
            for (; lanes; lanes &= lanes - 1) {
                const int j = __builtin_ctz(lanes);
                blocked |= unsigned(occluded(b, rays[j], tMin[j], tMax[j], skipOf(j))) << j;
            }
            return blocked;
        }
        Packet p;
        for (unsigned m = b.unbounded_.empty() ? 0 : lanes; m; m &= m - 1) {
            const int j = __builtin_ctz(m);
            for (const Primitive* q : b.unbounded_)
                if (q != skipOf(j) && q->occluded(rays[j], tMin[j], tMax[j])) {
                    blocked |= 1u << j;
                    break;
                }
        }
        unsigned walk;
        const unsigned packet = joinPacket<false>(b, p, rays, tMin, tMax, lanes & ~blocked, walk);
        for (unsigned m = lanes & ~blocked & ~packet; m; m &= m - 1) {
            const int j = __builtin_ctz(m);
            blocked |= unsigned(occluded(b, rays[j], tMin[j], tMax[j], skipOf(j))) << j;
        }
        if (!packet) return blocked;
        // As intersectPacket's PacketNearest: the arrays' pointers held, not captured.
        PacketOccluded visit{b.order_.data(), b.kind_.data(), rays, tMin, tMax, skip, &blocked};
        walkPacket<true>(b, p, packet, tMax, visit);
        return blocked;
    }

    // The exact decisions, called directly for the kinds the leaves know (the same
    // functions the virtual calls would reach: kSphere and kTriangle are exact types).
    // A plain triangle takes the shear the leaf test computed, if it did (the same bits as
    // Triangle::intersect computing it).
    static bool exactIntersect(const Primitive& p, std::uint8_t kind, const RayData* r,
                               const Ray& ray, double tMin, double tMax, Hit& hit) {
        if (kind == bvh_detail::kSphere)
            return static_cast<const Sphere&>(p).Sphere::intersect(ray, tMin, tMax, hit);
        if (kind == bvh_detail::kTriangle) {
            const auto& t = static_cast<const Triangle&>(p);
            if (!r) return t.Triangle::intersect(ray, tMin, tMax, hit);
            if (!r->shReady) r->shearSetup();
            return t.intersectSheared(ray, r->sh, tMin, tMax, hit);
        }
        return p.intersect(ray, tMin, tMax, hit);
    }
    static bool exactOccluded(const Primitive& p, std::uint8_t kind, const RayData* r,
                              const Ray& ray, double tMin, double tMax) {
        if (kind == bvh_detail::kSphere)
            return static_cast<const Sphere&>(p).Sphere::occluded(ray, tMin, tMax);
        if (kind == bvh_detail::kTriangle) {
            // Triangle keeps Primitive::occluded, which is its intersect with a scratch hit.
            Hit h;
            return exactIntersect(p, kind, r, ray, tMin, tMax, h);
        }
        return p.occluded(ray, tMin, tMax);
    }

    // The nearest-hit rule of intersect() and intersectPacket() (one per ray): primitive p
    // (`index`: its place in the scene) offered to a ray whose nearest so far is `best` at
    // tMax. Candidates write straight into `hit` (each is asked only for t <= the nearest so
    // far). On equal t the plain loop keeps the primitive later in the scene; when an
    // earlier one ties, the later one's record is restored by asking it again (the same
    // exact code gives the same bits). Exact ties are rare: records stay uncopied.
    // Inlined into both callers: the state stays in the caller's registers or arrays.
    // A ray's nearest so far (p null: none yet). No member initialisers: the packets'
    // arrays of them set p alone, for their rays only.
    struct Best {
        const Primitive* p;
        std::uint8_t kind;
        std::uint32_t index;
    };
    __attribute__((always_inline)) static void offerNearest(const Primitive& p, std::uint8_t kind,
                                                            std::uint32_t index, const RayData* r,
                                                            const Ray& ray, double tMin,
                                                            double& tMax, Hit& hit, Best& best) {
        const double before = tMax;
        if (!exactIntersect(p, kind, r, ray, tMin, tMax, hit)) return;
        if (best.p && hit.t == before && index < best.index) {
            exactIntersect(*best.p, best.kind, r, ray, tMin, before, hit);
            return;
        }
        best.p = &p;
        best.kind = kind;
        best.index = index;
        tMax = hit.t;
    }

    // intersectPacket's leaf visitor: intersect()'s offer (offerNearest) for ray j.
    struct PacketNearest {
        const Primitive* const* order;
        const std::uint8_t* kind;
        const std::uint32_t* orderIndex;
        const Ray* rays;
        const double* tMin;
        double* tMax;
        Hit* hits;
        Best* best;
        __attribute__((always_inline)) bool operator()(int j, std::uint32_t i,
                                                       const RayData* r) const {
            offerNearest(*order[i], kind[i], orderIndex[i], r, rays[j], tMin[j], tMax[j], hits[j],
                         best[j]);
            return true;
        }
        // The offers of n candidates, in order: primitive ci[k] to ray cj[k] (walkPacket's
        // deferred exact tests). A plain triangle (nearly all of them) takes offerNearest's
        // steps written out, the visitor's fields held in locals (not reloaded after each
        // call); the other kinds go through operator(). Its tie rule must stay offerNearest's:
        // "packets: a mesh with shared edges and vertices, ties" (packet_test.cpp) goes red
        // when they differ. Not shared (thirteenth session, callgrind, mesh): the rule and the
        // record in one inline helper cost confirm +3.8 instructions a candidate (the rare
        // branch's arguments set up on every hit), the rule alone as a predicate cost the
        // single walk +10 instructions a ray (GCC laid nearestFrom out anew).
        __attribute__((noinline)) void confirm(const RayData* r, const std::uint32_t* ci,
                                               const std::uint8_t* cj, int n) const {
            const Primitive* const* const ord = order;
            const std::uint8_t* const kd = kind;
            const std::uint32_t* const oi = orderIndex;
            for (int k = 0; k < n; ++k) {
                const int j = cj[k];
                const std::uint32_t i = ci[k];
                const RayData* const rj = r + j;
                if (kd[i] != bvh_detail::kTriangle) {
                    (*this)(j, i, rj);
                    continue;
                }
                if (!rj->shReady) { // inlined here: this function is already out of line
                    rj->sh = triangleShear(rj->ray->direction);
                    rj->shReady = true;
                }
                const Triangle& t = static_cast<const Triangle&>(*ord[i]);
                Hit& hit = hits[j];
                const double before = tMax[j];
                if (!t.intersectSheared(rays[j], rj->sh, tMin[j], before, hit)) continue;
                Best& bj = best[j];
                const std::uint32_t index = oi[i];
                if (bj.p && hit.t == before && index < bj.index) {
                    exactIntersect(*bj.p, bj.kind, rj, rays[j], tMin[j], before, hit);
                    continue;
                }
                bj.p = &t;
                bj.kind = bvh_detail::kTriangle;
                bj.index = index;
                tMax[j] = hit.t;
            }
        }
    };
    // occludedPacket's leaf visitor: occluded()'s test for ray j; false once it is blocked.
    struct PacketOccluded {
        const Primitive* const* order;
        const std::uint8_t* kind;
        const Ray* rays;
        const double* tMin;
        const double* tMax;
        const Primitive* const* skip;
        unsigned* blocked;
        __attribute__((always_inline)) bool operator()(int j, std::uint32_t i,
                                                       const RayData* r) const {
            const Primitive* q = order[i];
            if ((skip && q == skip[j]) || !exactOccluded(*q, kind[i], r, rays[j], tMin[j], tMax[j]))
                return true;
            *blocked |= 1u << j;
            return false;
        }
    };
    // intersect()'s leaf visitor. Its state (the nearest so far, the limit) lives in its own
    // members rather than in references to the caller's locals: with a lambda capturing
    // them by reference GCC kept the closure in memory, stored ~10 pointers per ray and read
    // each field through one (issue 21, seventh session: the per-ray set-up).
    struct Nearest {
        const Bvh& b;
        const Ray& ray;
        Hit& hit;
        double tMin, tMax;
        Best best{nullptr, bvh_detail::kOther, 0};

        __attribute__((always_inline)) void offer(const Primitive& p, std::uint8_t kind,
                                                  std::uint32_t index, const RayData* r) {
            offerNearest(p, kind, index, r, ray, tMin, tMax, hit, best);
        }
        __attribute__((always_inline)) bool operator()(std::uint32_t i, const RayData* r) {
            offer(*b.order_[i], b.kind_[i], b.orderIndex_[i], r);
            return true;
        }
    };
    // The nearest-hit query, in two parts (issue 21, seventh session): this one, small
    // (no callee-saved registers, no frame for the walk's stack), takes a float ray's start
    // values and its root-box test, and returns at once for a ray that misses the root box
    // (55% of the mesh bench's eye rays); the walk itself (nearestFrom) is out of line and
    // starts from those values. Rays the float walk cannot carry, trees of one leaf and
    // scenes with unbounded primitives go to nearestFrom whole, which sets them up itself.
    static bool intersect(const Bvh& b, const Ray& ray, double tMin, double tMax, Hit& hit) {
        if (b.unbounded_.empty() && b.stats_.primitives != 0 && b.rootLeafCount_ == 0) {
            FloatStart f;
            const Start k = startRay<true>(f, b, ray, tMin, limitOf(tMax));
            if (k == kMissed) return false;
            if (k == kFloat) return nearestFrom<true>(b, ray, tMin, tMax, hit, &f);
        }
        return nearestFrom<false>(b, ray, tMin, tMax, hit, nullptr);
    }
    // intersect for a tree of triangles only (pathTri: the path's entry chosen at the build,
    // so the other trees' intersect has no test of Bvh::triOnly_ per ray).
    static bool intersectTri(const Bvh& b, const Ray& ray, double tMin, double tMax, Hit& hit) {
        if (b.unbounded_.empty() && b.stats_.primitives != 0 && b.rootLeafCount_ == 0) {
            FloatStart f;
            const Start k = startRay<true>(f, b, ray, tMin, limitOf(tMax));
            if (k == kMissed) return false;
            if (k == kFloat) return nearestFrom<true, true>(b, ray, tMin, tMax, hit, &f);
        }
        return nearestFrom<false>(b, ray, tMin, tMax, hit, nullptr);
    }
    // kFloatOnly (pre given): a walk of its own, without the checks intersect has made and
    // without the double box test; else the general walk.
    template <bool kFloatOnly, bool kTri = false>
    __attribute__((noinline)) static bool nearestFrom(const Bvh& b, const Ray& ray, double tMin,
                                                      double tMax, Hit& hit,
                                                      const FloatStart* pre) {
        Nearest s{b, ray, hit, tMin, tMax};
        if constexpr (!kFloatOnly)
            for (std::size_t i = 0; i < b.unbounded_.size(); ++i)
                s.offer(*b.unbounded_[i], bvh_detail::kOther, b.unboundedIndex_[i], nullptr);
        walk<false, kFloatOnly, kTri>(b, ray, tMin, s.tMax, s, pre);
        return s.best.p != nullptr;
    }

    // `skip`: a flat primitive the feeler starts on (Aggregate::forEachBlocker), never asked;
    // compared by pointer, so the test of its neighbours in the leaf is untouched.
    static bool occluded(const Bvh& b, const Ray& ray, double tMin, double tMax,
                         const Primitive* skip) {
        return occludedOf<false>(b, ray, tMin, tMax, skip);
    }
    // A tree of triangles only (pathTri): its float walk without the leaves' kind dispatch.
    static bool occludedTri(const Bvh& b, const Ray& ray, double tMin, double tMax,
                            const Primitive* skip) {
        return occludedOf<true>(b, ray, tMin, tMax, skip);
    }
    template <bool kTri>
    __attribute__((always_inline)) static bool occludedOf(const Bvh& b, const Ray& ray, double tMin,
                                                          double tMax, const Primitive* skip) {
        for (const Primitive* p : b.unbounded_)
            if (p != skip && p->occluded(ray, tMin, tMax)) return true;
        if (b.stats_.primitives != 0 && b.rootLeafCount_ == 0) {
            FloatStart f;
            // No root-box test (kRoot false): feelers start inside the box; the limit is unused.
            if (startRay<false>(f, b, ray, tMin, 0.0f) == kFloat)
                return blockedFrom<true, kTri>(b, ray, tMin, tMax, skip, &f);
        }
        return blockedFrom<false>(b, ray, tMin, tMax, skip, nullptr);
    }
    // occluded's walk. kFloatOnly (pre given, as nearestFrom<true>): without the checks
    // occluded has made, the double box test and the per-node test of useFloat (issue 21,
    // eighth session); else the general walk. Both instances are inlined into occludedOf.
    template <bool kFloatOnly, bool kTri = false>
    __attribute__((always_inline)) static bool
    blockedFrom(const Bvh& b, const Ray& ray, double tMin, double tMax, const Primitive* skip,
                const FloatStart* pre) {
        bool any = false;
        walk<true, kFloatOnly, kTri>(
            b, ray, tMin, tMax,
            [&](std::uint32_t i, const RayData* r) {
                const Primitive* p = b.order_[i];
                any = p != skip && exactOccluded(*p, b.kind_[i], r, ray, tMin, tMax);
                return !any;
            },
            pre);
        return any;
    }

    static void forEachHit(const Bvh& b, const Ray& ray, double tMin, double tMax,
                           const std::function<bool(const Hit&)>& visit) {
        Hit h;
        for (const Primitive* p : b.unbounded_)
            if (p->intersect(ray, tMin, tMax, h) && !visit(h)) return;
        walk<true>(b, ray, tMin, tMax, [&](std::uint32_t i, const RayData* r) {
            return !(exactIntersect(*b.order_[i], b.kind_[i], r, ray, tMin, tMax, h) && !visit(h));
        });
    }

    static void forEachBlocker(const Bvh& b, const Ray& ray, double tMin, double tMax,
                               const std::function<bool(const Primitive&)>& visit,
                               const Primitive* skip) {
        for (const Primitive* p : b.unbounded_)
            if (p != skip && p->occluded(ray, tMin, tMax) && !visit(*p)) return;
        walk<true>(b, ray, tMin, tMax, [&](std::uint32_t i, const RayData* r) {
            const Primitive* p = b.order_[i];
            return p == skip || !(exactOccluded(*p, b.kind_[i], r, ray, tMin, tMax) && !visit(*p));
        });
    }

    // The path's entries for a tree of triangles only (Bvh::triOnly_; WidePath::tri).
    static const WidePath* pathTri(bool avx2) {
        static const WidePath p{W,
                                avx2,
                                &intersectTri,
                                &occludedTri,
                                &forEachHit,
                                &forEachBlocker,
                                &intersectPacket,
                                &occludedPacket,
                                nullptr};
        return &p;
    }
    static const WidePath* path(bool avx2) {
        static const WidePath p{W,
                                avx2,
                                &intersect,
                                &occluded,
                                &forEachHit,
                                &forEachBlocker,
                                &intersectPacket,
                                &occludedPacket,
                                pathTri(avx2)};
        return &p;
    }
};

} // namespace wb::rt
