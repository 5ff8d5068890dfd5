// The 4-wide BVH (BvhOptions::width 4): collapse of the binned SAH binary tree, SSE
// float traversal, leaves whose spheres are rejected four at a time, exact decisions.
//
// 1. Collapse rather than a wide build of its own: the binary builder is tested and
//    fuzzed (degenerate centroids, float-range boxes, depth limit), and pulling up the
//    grandchild of largest surface area until a node has four children is how wide
//    trees are usually made from a binary SAH tree (Wald, Benthin, Boulos 2008; Embree's
//    BVH4 builders open the largest child likewise), at the cost of one linear pass.
// 2. Boxes in float, rounded outward; the ray's origin in float is widened by
//    |o|max·2^-21 per axis (its rounding is at most |o|max·2^-24), exit distances are
//    stretched by γ(3) in float (subtraction, product, rounded 1/d), tMin is lowered and
//    tMax raised by 2^-20 relative: a box the exact ray enters is never missed. Rays
//    float cannot carry (|o| > 1e30, a direction component beyond 1e±30) take the
//    same walk with each box tested in double.
// 3. Children visited nearest first (entry distances sorted), the others kept on a
//    stack with their entry distance and dropped when a nearer hit has been found.
// 4. Leaves: spheres first, their float centres and radii side by side; a conservative
//    float test of the distance from the centre to the ray's line rejects four at a
//    time (margin 2^-16 of |o|+|c|+r, thousands of times the float error). Every
//    candidate is decided by its primitive's exact double code, called directly
//    (no virtual call) for spheres and plain triangles.
#include "core/raytrace/bvh.h"

#include "bvh_internal.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <emmintrin.h>
#include <typeinfo>
#include <xmmintrin.h>

namespace wb::rt {

using namespace bvh_detail;

namespace {
// Exact code per kind: Sphere and Triangle are called directly, SmoothTriangle (the
// triangle test, then its normal) and the rest through the virtual call.
constexpr std::uint8_t kOther = 0, kSphere = 1, kTriangle = 2, kSmoothTriangle = 3;
// Runs of a leaf sorted by their float test: spheres, triangles (both kinds), the rest.
constexpr std::uint8_t kRunSphere = 0, kRunTriangle = 1, kRunOther = 2;
constexpr float kSphereMargin = 0x1p-16f; // relative margin of the float sphere test
constexpr float kTriMargin = 0x1p-19f;    // relative error bound of the triangle test's inputs
inline std::uint8_t runOf(std::uint8_t kind) {
    return kind == kSphere
               ? kRunSphere
               : (kind == kTriangle || kind == kSmoothTriangle ? kRunTriangle : kRunOther);
}
constexpr int kWideStack = 4 * kMaxDepth; // at most 3 pushes per level of the binary depth
} // namespace

// Per-ray data of the float walk.
struct Bvh::WideRay {
    bool useFloat = false;             // boxes tested in float (else in double)
    bool prefilter = false;            // spheres rejected by the float test (unit direction only)
    int neg[3] = {0, 0, 0};            // direction sign per axis: which of lo/hi is the near plane
    std::size_t nearOff[3], farOff[3]; // byte offsets of the near and far planes in a WideNode
    __m128 on[3], of[3];    // origin moved by ∓eps for near planes and ±eps for far planes
    __m128 inv[3];          // 1/d in float
    __m128 tMin, farScale;  // lowered tMin; γ(3) stretch
    float tMaxScale = 1.0f; // raise of tMax (the current nearest hit) in float
    // Sphere test: origin, direction, and |o|·margin.
    __m128 fo[3], fd[3], om;
    // Triangle test: the watertight shear (kz the dominant axis of d), the origin in
    // (kx, ky, kz) order, |o|₁·margin.
    bool triReady = false; // computed at the first triangle run (scenes without skip it)
    int k[3] = {0, 1, 2};
    __m128 to[3], shx, shy, tom;
    void triangleSetup() {
        // The watertight test's axes (triangle.cpp): kz dominant, kx/ky swapped for d[kz] < 0.
        const glm::dvec3 ad = glm::abs(d);
        const int kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
        int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
        if (d[kz] < 0) std::swap(kx, ky);
        k[0] = kx;
        k[1] = ky;
        k[2] = kz;
        to[0] = _mm_set1_ps(float(o[kx]));
        to[1] = _mm_set1_ps(float(o[ky]));
        to[2] = _mm_set1_ps(float(o[kz]));
        shx = _mm_set1_ps(float(d[kx] / d[kz]));
        shy = _mm_set1_ps(float(d[ky] / d[kz]));
        tom = _mm_set1_ps(float(std::abs(o.x) + std::abs(o.y) + std::abs(o.z)) * kTriMargin);
        triReady = true;
    }
    // The ray in double.
    glm::dvec3 o{0.0}, d{0.0}, invd{0.0};
};

void Bvh::collapseWide(const void* buildNodes, std::size_t count) {
    const auto* build = static_cast<const BuildNode*>(buildNodes);
    // Leaves: runs of spheres, triangles, the rest (stable within a run).
    const std::size_t n = order_.size();
    kind_.assign(n, kOther);
    run_.assign(n, 0);
    for (auto* v : {&sx_, &sy_, &sz_, &sr_, &sm_, &tm_})
        v->assign(n + 4, 0.0f);
    for (auto& v : tv_)
        v.assign(n + 4, 0.0f);
    auto kindOf = [](const Primitive* p) {
        if (typeid(*p) == typeid(Sphere)) return kSphere;
        if (typeid(*p) == typeid(Triangle)) return kTriangle;
        if (typeid(*p) == typeid(SmoothTriangle) || dynamic_cast<const Triangle*>(p))
            return kSmoothTriangle; // the triangle's hit test
        return kOther;
    };
    for (std::size_t i = 0; i < n; ++i)
        kind_[i] = kindOf(order_[i]);
    auto sortLeaf = [&](std::uint32_t first, std::uint32_t cnt) {
        // Stable, by run: leaves are small, so insertion sort in place.
        for (std::uint32_t k = first + 1; k < first + cnt; ++k) {
            std::uint32_t j = k;
            while (j > first && runOf(kind_[j - 1]) > runOf(kind_[j])) {
                std::swap(kind_[j - 1], kind_[j]);
                std::swap(order_[j - 1], order_[j]);
                std::swap(orderIndex_[j - 1], orderIndex_[j]);
                --j;
            }
        }
        for (std::uint32_t k = 0; k < cnt; ++k) {
            const std::uint32_t i = first + k;
            if (kind_[i] == kSphere) {
                const auto* s = static_cast<const Sphere*>(order_[i]);
                sx_[i] = float(s->centre.x);
                sy_[i] = float(s->centre.y);
                sz_[i] = float(s->centre.z);
                sr_[i] = float(s->radius);
                sm_[i] = float(std::abs(s->centre.x) + std::abs(s->centre.y) +
                               std::abs(s->centre.z) + s->radius) *
                         kSphereMargin;
            } else if (runOf(kind_[i]) == kRunTriangle) {
                const auto* t = static_cast<const Triangle*>(order_[i]);
                const glm::dvec3* vs[3] = {&t->v0, &t->v1, &t->v2};
                double mag = 0;
                for (int j = 0; j < 3; ++j)
                    for (int a = 0; a < 3; ++a) {
                        tv_[j * 3 + a][i] = float((*vs[j])[a]);
                        mag += std::abs((*vs[j])[a]);
                    }
                tm_[i] = float(mag) * kTriMargin;
            }
        }
        for (std::uint32_t k = 0; k < cnt;) { // run lengths
            std::uint32_t e = k + 1;
            while (e < cnt && runOf(kind_[first + e]) == runOf(kind_[first + k]))
                ++e;
            run_[first + k] = std::uint16_t(e - k);
            k = e;
        }
    };
    if (count == 0) return;
    if (count == 1) { // the whole tree is one leaf (rootLeafCount_)
        sortLeaf(0, build[0].count);
        stats_.wideNodes = 0;
        return;
    }
    auto area = [&](std::size_t i) {
        const glm::dvec3 e = build[i].hi - build[i].lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    };
    wnodes_.reserve(count / 3 + 1); // a wide node replaces up to 3 inner binary nodes
    // Depth first, so a node's first inner child tends to follow it in memory.
    auto collapse = [&](auto&& self, std::size_t bi) -> std::uint32_t {
        const auto idx = std::uint32_t(wnodes_.size());
        wnodes_.emplace_back();
        std::array<std::size_t, 4> kids{bi + 1, build[bi].offset, 0, 0};
        int nk = 2;
        while (nk < 4) { // open the inner child of largest area
            int best = -1;
            double bestArea = -1;
            for (int k = 0; k < nk; ++k)
                if (build[kids[size_t(k)]].count == 0 && area(kids[size_t(k)]) > bestArea) {
                    bestArea = area(kids[size_t(k)]);
                    best = k;
                }
            if (best < 0) break;
            const std::size_t open = kids[size_t(best)];
            kids[size_t(best)] = open + 1;
            kids[size_t(nk++)] = build[open].offset;
        }
        WideNode w;
        std::memset(&w, 0, sizeof w); // padding too: trees compare bytewise (tests)
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 4; ++c) {
                w.lo[a][c] = std::numeric_limits<float>::infinity();
                w.hi[a][c] = -std::numeric_limits<float>::infinity();
            }
        for (int c = 0; c < 4; ++c) {
            w.child[c] = 0;
            w.count[c] = 0;
        }
        for (int c = 0; c < nk; ++c) {
            const BuildNode& k = build[kids[size_t(c)]];
            for (int a = 0; a < 3; ++a) { // exact: the build's boxes are floats
                w.lo[a][c] = float(k.lo[a]);
                w.hi[a][c] = float(k.hi[a]);
            }
            if (k.count > 0) {
                w.child[c] = k.offset;
                w.count[c] = k.count;
                sortLeaf(k.offset, k.count);
            } else {
                w.child[c] = self(self, kids[size_t(c)]);
            }
        }
        wnodes_[idx] = w;
        return idx;
    };
    collapse(collapse, 0);
    stats_.wideNodes = int(wnodes_.size());
}

template <class Visit>
bool Bvh::visitLeafWide(WideRay& wr, std::uint32_t first, std::uint32_t count, float,
                        Visit&& visit) const {
    const std::uint32_t end = first + count;
    for (std::uint32_t r = first; r < end;) {
        const std::uint32_t rEnd = r + run_[r];
        const std::uint8_t runKind = runOf(kind_[r]);
        if (runKind == kRunOther || !wr.prefilter) {
            for (std::uint32_t i = r; i < rEnd; ++i)
                if (!visit(i)) return false;
            r = rEnd;
            continue;
        }
        for (std::uint32_t i = r; i < rEnd; i += 4) {
            int mask;
            if (runKind == kRunSphere) {
                // Squared distance of each centre from the ray's line against (r + margin)²:
                // a sphere the exact code can hit (disc >= 0) is never rejected.
                const __m128 fx = _mm_sub_ps(wr.fo[0], _mm_loadu_ps(&sx_[i]));
                const __m128 fy = _mm_sub_ps(wr.fo[1], _mm_loadu_ps(&sy_[i]));
                const __m128 fz = _mm_sub_ps(wr.fo[2], _mm_loadu_ps(&sz_[i]));
                const __m128 h =
                    _mm_add_ps(_mm_add_ps(_mm_mul_ps(fx, wr.fd[0]), _mm_mul_ps(fy, wr.fd[1])),
                               _mm_mul_ps(fz, wr.fd[2]));
                const __m128 lx = _mm_sub_ps(fx, _mm_mul_ps(h, wr.fd[0]));
                const __m128 ly = _mm_sub_ps(fy, _mm_mul_ps(h, wr.fd[1]));
                const __m128 lz = _mm_sub_ps(fz, _mm_mul_ps(h, wr.fd[2]));
                const __m128 ll = _mm_add_ps(_mm_add_ps(_mm_mul_ps(lx, lx), _mm_mul_ps(ly, ly)),
                                             _mm_mul_ps(lz, lz));
                const __m128 rm =
                    _mm_add_ps(_mm_loadu_ps(&sr_[i]), _mm_add_ps(wr.om, _mm_loadu_ps(&sm_[i])));
                // cmpngt: NaN counts as a candidate. (Also rejecting spheres beyond the
                // nearest hit, −h − r − margin > limit, measured no gain: not kept.)
                mask = _mm_movemask_ps(_mm_cmpngt_ps(ll, _mm_mul_ps(rm, rm)));
            } else {
                if (!wr.triReady) wr.triangleSetup();
                // The watertight test's edge functions in float (same shear); rejected only
                // when one is surely negative and another surely positive: e bounds their
                // float error (inputs off by δ after rounding vertices and origin, the
                // shear and the differences; products and their difference rounded).
                __m128 px[3], py[3], mag = _mm_setzero_ps();
                const __m128 absMask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
                for (int j = 0; j < 3; ++j) {
                    const __m128 X = _mm_sub_ps(_mm_loadu_ps(&tv_[j * 3 + wr.k[0]][i]), wr.to[0]);
                    const __m128 Y = _mm_sub_ps(_mm_loadu_ps(&tv_[j * 3 + wr.k[1]][i]), wr.to[1]);
                    const __m128 Z = _mm_sub_ps(_mm_loadu_ps(&tv_[j * 3 + wr.k[2]][i]), wr.to[2]);
                    px[j] = _mm_sub_ps(X, _mm_mul_ps(wr.shx, Z));
                    py[j] = _mm_sub_ps(Y, _mm_mul_ps(wr.shy, Z));
                    mag = _mm_add_ps(mag, _mm_add_ps(_mm_and_ps(X, absMask),
                                                     _mm_add_ps(_mm_and_ps(Y, absMask),
                                                                _mm_and_ps(Z, absMask))));
                }
                const __m128 u = _mm_sub_ps(_mm_mul_ps(px[2], py[1]), _mm_mul_ps(py[2], px[1]));
                const __m128 v = _mm_sub_ps(_mm_mul_ps(px[0], py[2]), _mm_mul_ps(py[0], px[2]));
                const __m128 w = _mm_sub_ps(_mm_mul_ps(px[1], py[0]), _mm_mul_ps(py[1], px[0]));
                __m128 q = _mm_setzero_ps();
                for (int j = 0; j < 3; ++j)
                    q = _mm_add_ps(
                        q, _mm_add_ps(_mm_and_ps(px[j], absMask), _mm_and_ps(py[j], absMask)));
                // δ = (|v|₁ + |o|₁ + Σ|v − o|)·2^-19; e = 2δ(Q + 2δ) + Q²·2^-20.
                const __m128 delta = _mm_add_ps(_mm_add_ps(_mm_loadu_ps(&tm_[i]), wr.tom),
                                                _mm_mul_ps(mag, _mm_set1_ps(kTriMargin)));
                const __m128 twoD = _mm_add_ps(delta, delta);
                const __m128 e = _mm_add_ps(_mm_mul_ps(twoD, _mm_add_ps(q, twoD)),
                                            _mm_mul_ps(_mm_mul_ps(q, q), _mm_set1_ps(0x1p-20f)));
                const __m128 ne = _mm_sub_ps(_mm_setzero_ps(), e);
                const __m128 someNeg = _mm_or_ps(
                    _mm_or_ps(_mm_cmplt_ps(u, ne), _mm_cmplt_ps(v, ne)), _mm_cmplt_ps(w, ne));
                const __m128 somePos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, e), _mm_cmpgt_ps(v, e)),
                                                 _mm_cmpgt_ps(w, e));
                mask = 0xF & ~_mm_movemask_ps(_mm_and_ps(someNeg, somePos));
            }
            if (rEnd - i < 4) mask &= (1 << (rEnd - i)) - 1;
            while (mask) {
                const int l = __builtin_ctz(unsigned(mask));
                mask &= mask - 1;
                if (!visit(i + std::uint32_t(l))) return false;
            }
        }
        r = rEnd;
    }
    return true;
}

template <class Leaf>
void Bvh::traverseWide(const Ray& ray, double tMin, double& tMax, Leaf&& leaf) const {
    if (stats_.primitives == 0) return;
    if (rootLeafCount_ > 0) {
        // A tree of one leaf (up to maxLeafSize primitives): the root box in double and the
        // exact tests, without the float set-up, which costs more than it saves here.
        double t0 = tMin, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            const double inv = 1.0 / ray.direction[a];
            const bool neg = std::signbit(inv);
            const double near = ((neg ? rootHi_[a] : rootLo_[a]) - ray.origin[a]) * inv;
            const double far = ((neg ? rootLo_[a] : rootHi_[a]) - ray.origin[a]) * inv * kFarScale;
            t0 = near > t0 ? near : t0; // NaN (0·inf): no limit
            t1 = far < t1 ? far : t1;
        }
        if (!(t0 <= t1)) return;
        for (std::uint32_t i = 0; i < rootLeafCount_; ++i)
            if (!leaf(i)) return;
        return;
    }
    WideRay wr;
    const glm::dvec3 o = ray.origin, d = ray.direction;
    const double om = std::max(std::abs(o.x), std::max(std::abs(o.y), std::abs(o.z)));
    bool ok = om < 1e30;
    for (int a = 0; a < 3; ++a) {
        wr.neg[a] = std::signbit(d[a]);
        ok = ok && (d[a] == 0 || (std::abs(d[a]) >= 1e-30 && std::abs(d[a]) <= 1e30));
    }
    wr.useFloat = ok;
    for (int a = 0; a < 3; ++a) {
        const std::size_t lo = offsetof(WideNode, lo) + std::size_t(a) * 16,
                          hi = offsetof(WideNode, hi) + std::size_t(a) * 16;
        wr.nearOff[a] = wr.neg[a] ? hi : lo;
        wr.farOff[a] = wr.neg[a] ? lo : hi;
    }
    const double dd = glm::dot(d, d);
    wr.prefilter = ok && std::abs(dd - 1) < 1e-6;
    wr.o = o;
    wr.d = d;
    wr.invd = 1.0 / d;
    if (ok) {
        const float eps = float(om) * 0x1p-21f;
        for (int a = 0; a < 3; ++a) {
            const float fo = float(o[a]);
            const float s = wr.neg[a] ? -eps : eps;
            wr.on[a] = _mm_set1_ps(fo + s);
            wr.of[a] = _mm_set1_ps(fo - s);
            wr.inv[a] = _mm_set1_ps(float(wr.invd[a]));
            wr.fo[a] = _mm_set1_ps(fo);
            wr.fd[a] = _mm_set1_ps(float(d[a]));
        }
        const float ftMin = float(tMin);
        wr.tMin = _mm_set1_ps(ftMin - std::abs(ftMin) * 0x1p-20f);
        wr.farScale = _mm_set1_ps(kFarScaleF);
        wr.om = _mm_set1_ps(float(std::abs(o.x) + std::abs(o.y) + std::abs(o.z)) * kSphereMargin);
    }
    // The current limit: entries farther than the nearest hit (widened) are dropped.
    auto limitF = [&]() {
        const double lim = tMax * kFarScale;
        return lim > 3e38 ? std::numeric_limits<float>::infinity() : float(lim) * (1 + 0x1p-20f);
    };
    struct Entry {
        std::uint32_t child;
        std::uint32_t count;
        float t;
    };
    std::array<Entry, kWideStack> stack;
    int sp = 0;
    float flim = limitF(); // limitF() of the current tMax (renewed after each leaf)
    std::uint32_t cur = 0;
    while (true) {
        const WideNode& nd = wnodes_[cur];
        alignas(16) float t[4];
        int mask;
        if (wr.useFloat) {
            const char* base = reinterpret_cast<const char*>(&nd);
            __m128 t0 = wr.tMin, t1 = _mm_set1_ps(flim);
            for (int a = 0; a < 3; ++a) {
                const __m128 nearP =
                    _mm_load_ps(reinterpret_cast<const float*>(base + wr.nearOff[a]));
                const __m128 farP =
                    _mm_load_ps(reinterpret_cast<const float*>(base + wr.farOff[a]));
                // max/min return the second operand for NaN (0·inf: a ray in the slab's
                // plane): that slab is no limit.
                t0 = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(nearP, wr.on[a]), wr.inv[a]), t0);
                t1 = _mm_min_ps(
                    _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(farP, wr.of[a]), wr.inv[a]), wr.farScale), t1);
            }
            mask = _mm_movemask_ps(_mm_cmple_ps(t0, t1));
            _mm_store_ps(t, t0);
        } else {
            mask = 0;
            const double lim = tMax * kFarScale;
            for (int c = 0; c < 4; ++c) {
                if (nd.lo[0][c] > nd.hi[0][c]) continue; // empty slot
                double t0 = tMin, t1 = lim;
                for (int a = 0; a < 3; ++a) {
                    const double nearP = wr.neg[a] ? nd.hi[a][c] : nd.lo[a][c];
                    const double farP = wr.neg[a] ? nd.lo[a][c] : nd.hi[a][c];
                    const double tn = (nearP - o[a]) * wr.invd[a];
                    const double tf = (farP - o[a]) * wr.invd[a] * kFarScale;
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
        // One child hit: go on with it; two: the nearer now, the farther pushed; more:
        // sorted by entry distance, the farther ones pushed farthest first. A leaf met as
        // the nearest is visited at once.
        std::uint32_t next = 0;
        bool haveNext = false;
        if (mask != 0) {
            const int c0 = __builtin_ctz(unsigned(mask));
            const int rest = mask & (mask - 1);
            if (rest == 0) {
                next = std::uint32_t(c0);
                haveNext = true;
            } else if ((rest & (rest - 1)) == 0) {
                const int c1 = __builtin_ctz(unsigned(rest));
                const int nearC = t[c1] < t[c0] ? c1 : c0, farC = nearC == c0 ? c1 : c0;
                stack[size_t(sp++)] = {nd.child[farC], nd.count[farC], t[farC]};
                next = std::uint32_t(nearC);
                haveNext = true;
            } else {
                int order[4], n = 0;
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
                    stack[size_t(sp++)] = {nd.child[c], nd.count[c], t[c]};
                }
                next = std::uint32_t(order[n - 1]);
                haveNext = true;
            }
        }
        if (haveNext) {
            if (nd.count[next] == 0) {
                cur = nd.child[next];
                continue;
            }
            if (!visitLeafWide(wr, nd.child[next], nd.count[next], flim, leaf)) return;
            flim = limitF();
        }
        while (true) {
            if (sp == 0) return;
            const Entry e = stack[size_t(--sp)];
            if (e.t > flim) continue;
            if (e.count > 0) {
                if (!visitLeafWide(wr, e.child, e.count, flim, leaf)) return;
                flim = limitF();
                continue;
            }
            cur = e.child;
            break;
        }
    }
}

namespace {
// The exact decisions, called directly for the kinds the leaves know.
inline bool exactIntersect(const Primitive& p, std::uint8_t kind, const Ray& ray, double tMin,
                           double tMax, Hit& hit) {
    if (kind == kSphere)
        return static_cast<const Sphere&>(p).Sphere::intersect(ray, tMin, tMax, hit);
    if (kind == kTriangle)
        return static_cast<const Triangle&>(p).Triangle::intersect(ray, tMin, tMax, hit);
    return p.intersect(ray, tMin, tMax, hit);
}
inline bool exactOccluded(const Primitive& p, std::uint8_t kind, const Ray& ray, double tMin,
                          double tMax) {
    if (kind == kSphere) return static_cast<const Sphere&>(p).Sphere::occluded(ray, tMin, tMax);
    return p.occluded(ray, tMin, tMax);
}
} // namespace

bool Bvh::intersectWide(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    // Candidates write straight into `hit` (each is asked only for t <= the nearest so
    // far). On equal t the plain loop keeps the primitive later in the scene; when an
    // earlier one ties, the later one's record is restored by asking it again (the same
    // exact code gives the same bits). Exact ties are rare: this keeps records uncopied.
    const Primitive* best = nullptr;
    std::uint8_t bestKind = kOther;
    std::uint32_t bestIndex = 0;
    auto offer = [&](const Primitive& p, std::uint8_t kind, std::uint32_t index) {
        const double before = tMax;
        if (!exactIntersect(p, kind, ray, tMin, tMax, hit)) return;
        if (best && hit.t == before && index < bestIndex) {
            exactIntersect(*best, bestKind, ray, tMin, before, hit);
            return;
        }
        best = &p;
        bestKind = kind;
        bestIndex = index;
        tMax = hit.t;
    };
    for (std::size_t i = 0; i < unbounded_.size(); ++i)
        offer(*unbounded_[i], kOther, unboundedIndex_[i]);
    traverseWide(ray, tMin, tMax, [&](std::uint32_t i) {
        offer(*order_[i], kind_[i], orderIndex_[i]);
        return true;
    });
    return best != nullptr;
}

void Bvh::forEachHitWide(const Ray& ray, double tMin, double tMax,
                         const std::function<bool(const Hit&)>& visit) const {
    Hit h;
    for (const Primitive* p : unbounded_)
        if (p->intersect(ray, tMin, tMax, h) && !visit(h)) return;
    traverseWide(ray, tMin, tMax, [&](std::uint32_t i) {
        return !(exactIntersect(*order_[i], kind_[i], ray, tMin, tMax, h) && !visit(h));
    });
}

void Bvh::forEachBlockerWide(const Ray& ray, double tMin, double tMax,
                             const std::function<bool(const Primitive&)>& visit) const {
    for (const Primitive* p : unbounded_)
        if (p->occluded(ray, tMin, tMax) && !visit(*p)) return;
    traverseWide(ray, tMin, tMax, [&](std::uint32_t i) {
        return !(exactOccluded(*order_[i], kind_[i], ray, tMin, tMax) && !visit(*order_[i]));
    });
}

bool Bvh::occludedWide(const Ray& ray, double tMin, double tMax) const {
    for (const Primitive* p : unbounded_)
        if (p->occluded(ray, tMin, tMax)) return true;
    bool any = false;
    traverseWide(ray, tMin, tMax, [&](std::uint32_t i) {
        any = exactOccluded(*order_[i], kind_[i], ray, tMin, tMax);
        return !any;
    });
    return any;
}

} // namespace wb::rt
