#include "core/raytrace/bvh.h"

#include "bvh_internal.h"
#include "bvh_wide_kinds.h"
#include "core/raytrace/sphere.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <emmintrin.h>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <tbb/task_arena.h>
#include <typeinfo>
#ifdef WB_TSAN_THREADS
#include <atomic>
#include <thread>
#else
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#endif
#include <utility>
#include <xmmintrin.h>
#ifdef __linux__
#include <sys/mman.h>
#endif

namespace wb::rt {

using namespace bvh_detail;

namespace {

// The binned SAH build (Wald 2007) in SSE on float boxes. Every decision is the one of
// the scalar builder it replaced (same bins, the same SAH costs in double, the same
// ties), so the tree is the same; what changed is how the work is done:
//  - a primitive's box is fetched once through the virtual bounds() into a 32-byte
//    record (two SSE loads); centroids, bin indices of all three axes, bin boxes and
//    the children's centroid bounds are SSE operations;
//  - the children's boxes come from the bins (unions of the same float boxes, so
//    exact); the partition is a branchless stable scatter into a second buffer (the
//    children continue there) that gathers their centroid bounds on the way;
//  - one- and two-primitive nodes (~70% of all nodes on balls 5) skip the bins;
//  - nodes of more than kBlockNode primitives are binned and partitioned in fixed
//    blocks (per-block bins, then the scatter block by block), in
//    parallel with TBB when the build has threads: the top levels are no longer one
//    task each. Blocks are fixed by the node's range, not by the thread count, so the
//    order of the references — and the tree — is the same for any number of threads;
//  - below kParallelGrain a subtree is built depth first by one task straight into a
//    node array (with one thread: the final array), leaves write their primitives at
//    their own index range (the references are in leaf order already).

// A primitive's box in float, rounded outward (node boxes are unions of these, so they
// still enclose every primitive exactly), and its scene index in lane 3 of the first
// half. Lane 3 is masked off before any arithmetic (an index read as a float is a
// denormal or NaN).
struct alignas(16) Ref {
    float lo[3];
    std::uint32_t prim;
    float hi[3];
    float zero; // lane 3 of the hi load: 0
    // Halves first: lo + hi overflows to inf for boxes near float's range.
    float centre(int a) const { return 0.5f * lo[a] + 0.5f * hi[a]; }
};
static_assert(sizeof(Ref) == 32, "two SSE loads");

inline __m128 lanes012() {
    return _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
}
inline __m128 loadLo(const Ref& r, __m128 mask) {
    return _mm_and_ps(_mm_load_ps(r.lo), mask);
}
inline __m128 loadHi(const Ref& r) {
    return _mm_load_ps(r.hi);
}
// 0.5·lo + 0.5·hi per lane: the scalar Ref::centre exactly (IEEE single, no fusing).
inline __m128 centroid(__m128 lo, __m128 hi) {
    const __m128 half = _mm_set1_ps(0.5f);
    return _mm_add_ps(_mm_mul_ps(lo, half), _mm_mul_ps(hi, half));
}

// A float box in two SSE registers (lane 3 unused).
struct Box4 {
    __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
    __m128 hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    void extend(__m128 l, __m128 h) {
        lo = _mm_min_ps(lo, l);
        hi = _mm_max_ps(hi, h);
    }
    void extend(const Box4& b) { extend(b.lo, b.hi); }
    void extendPoint(__m128 p) { extend(p, p); }
    float lane(__m128 v, int a) const {
        alignas(16) float f[4];
        _mm_store_ps(f, v);
        return f[a];
    }
    float lo_(int a) const { return lane(lo, a); }
    float hi_(int a) const { return lane(hi, a); }
    // Surface area in double from the float corners (the SAH's unit):
    // 2·((dx·dy + dy·dz) + dz·dx), the extents' differences taken in double.
    double area() const {
        const __m128d dxy = _mm_sub_pd(_mm_cvtps_pd(hi), _mm_cvtps_pd(lo));
        const __m128d dz =
            _mm_sub_sd(_mm_cvtps_pd(_mm_movehl_ps(hi, hi)), _mm_cvtps_pd(_mm_movehl_ps(lo, lo)));
        const __m128d p = _mm_mul_pd(dxy, _mm_shuffle_pd(dxy, dz, 1)); // dx·dy, dy·dz
        const __m128d s = _mm_add_sd(p, _mm_unpackhi_pd(p, p));
        return 2 * _mm_cvtsd_f64(_mm_add_sd(s, _mm_mul_sd(dz, dxy)));
    }
};

// Beyond this depth the builder splits at the object median, so the tree depth stays
// below kMaxDepth = kMedianDepth + log2(any input size) + slack.
constexpr int kMedianDepth = 80;
constexpr std::size_t kMaxLeaf = 65535; // Node::count is 16 bits
// Nodes above this many primitives are binned and partitioned in blocks of kBlock
// (in parallel when the build has threads); above kParallelGrain their children are
// separate TBB tasks. A node over 256 primitives is never a leaf (Builder::finish: a
// leaf has at most maxLeafSize <= 255, or is a group of <= 256 coincident centroids), so
// the blocked path has no leaf case. Issue 21: blocked from 16,384 (was 65,536): the
// root of jacks 5 (42k) and the first levels under balls 5's root were one task each,
// binned and partitioned by one thread while the other waited — the 2-thread build's
// serial part. The decision and the partition are the same either way (bins merged over
// blocks; the stable scatter block by block at prefix offsets), so is the tree.
constexpr std::size_t kBlock = 4096;
constexpr std::size_t kBlockNode = 16384;
constexpr std::size_t kParallelGrain = 2048;
static_assert(kBlockNode > 256, "the blocked path has no leaf case");

// 1. Binning: the bin of a centroid, per axis, clamped in float before the conversion
//    (a huge or NaN product converted to int is undefined behaviour; found by
//    fuzz_nff): max(NaN, 0) is 0 in SSE, as the scalar !(f >= 0) test was.
struct BinSetup {
    int nb = 0;              // bins per axis
    float scale[3] = {};     // bins per unit of centroid extent; 0: axis not binnable
    __m128 clo, cscale, top; // the same as vectors; top = nb − 1
    bool binnable = false;
    BinSetup(const Box4& cbox, int bins) : nb(bins) {
        for (int a = 0; a < 3; ++a) {
            const float ext = cbox.hi_(a) - cbox.lo_(a);
            // Slightly under nb/ext so the largest centroid falls in bin nb−1.
            scale[a] = ext > 0 ? float(nb) * (1 - 1e-6f) / ext : 0.0f;
            binnable = binnable || scale[a] > 0;
        }
        clo = cbox.lo;
        cscale = _mm_set_ps(0, scale[2], scale[1], scale[0]);
        top = _mm_set1_ps(float(nb - 1));
    }
    __m128i bins(__m128 c) const {
        __m128 f = _mm_mul_ps(_mm_sub_ps(c, clo), cscale);
        f = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), top);
        return _mm_cvttps_epi32(f);
    }
};

// Bins of one range of references: boxes and counts, [axis·nb + bin].
void binRange(const Ref* refs, std::size_t n, const BinSetup& s, Box4* box, std::uint32_t* count) {
    const int nb = s.nb;
    // Issue 21 (ninth session): the empty bins copied from a template (memcpy's wide
    // stores) and the counts zeroed by memset: the loop of three stores a bin was ~300
    // instructions a node, 13,000 nodes a balls 5 build.
    static const struct EmptyBins {
        Box4 b[3 * 256]; // BvhOptions::bins <= 256
    } empty{};
    std::memcpy(static_cast<void*>(box), empty.b, sizeof(Box4) * std::size_t(3 * nb));
    std::memset(count, 0, sizeof(std::uint32_t) * std::size_t(3 * nb));
    const __m128 mask = lanes012();
    Box4 *bx = box, *by = box + nb, *bz = box + 2 * nb;
    std::uint32_t *cx = count, *cy = count + nb, *cz = count + 2 * nb;
    // Issue 21: the bins of a chunk of references first, then their boxes merged into
    // the bins. In one loop a bin's load waited for the address of the previous
    // reference's bin store (its own chain: the reference's load, centroid, scale,
    // conversion), since consecutive references often share a bin and the CPU then
    // orders the load behind the store; here the stores' addresses come from a
    // precomputed array, known as soon as it is loaded.
    constexpr std::size_t kChunk = 64;
    alignas(16) std::uint8_t bins[kChunk][4];
    for (std::size_t c = 0; c < n; c += kChunk) {
        const std::size_t m = std::min(kChunk, n - c);
        const Ref* r = refs + c;
        for (std::size_t i = 0; i < m; ++i) {
            const __m128 lo = loadLo(r[i], mask), hi = loadHi(r[i]);
            const __m128i b = s.bins(centroid(lo, hi));
            // bins < 256: the low byte of each lane, packed into one 32-bit word
            const __m128i p16 = _mm_packs_epi32(b, b);
            const __m128i p8 = _mm_packus_epi16(p16, p16);
            const int word = _mm_cvtsi128_si32(p8);
            std::memcpy(bins[i], &word, 4);
        }
        for (std::size_t i = 0; i < m; ++i) {
            const __m128 lo = loadLo(r[i], mask), hi = loadHi(r[i]);
            const int b0 = bins[i][0], b1 = bins[i][1], b2 = bins[i][2];
            bx[b0].extend(lo, hi);
            ++cx[b0];
            by[b1].extend(lo, hi);
            ++cy[b1];
            bz[b2].extend(lo, hi);
            ++cz[b2];
        }
    }
}

// Per-thread (per-task) scratch of one node's decision.
struct Scratch {
    std::vector<Box4> binBox, rightBox;
    std::vector<std::uint32_t> binCount;
    std::vector<double> rightArea;
    std::vector<std::size_t> rightCount;
    // sweepLanes: the bins transposed (per bin lo x, y, z, hi x, y, z, counts; lane = axis)
    // and the right sides' areas and counts.
    struct V {
        __m128 v;
    };
    std::vector<V> lanes, rightAreaL, rightCountL;
    explicit Scratch(int maxBins)
        : binBox(std::size_t(3 * maxBins)), rightBox(std::size_t(maxBins)),
          binCount(std::size_t(3 * maxBins)), rightArea(std::size_t(maxBins)),
          rightCount(std::size_t(maxBins)), lanes(std::size_t(7 * maxBins)),
          rightAreaL(std::size_t(maxBins)), rightCountL(std::size_t(maxBins)) {}
};

// The best binned split: SAH cost lc·A(left) + rc·A(right) over every bin boundary of
// every binnable axis, the first of equal costs (axis 0 first, low bins first).
struct Split {
    int axis = -1, bin = 0;
    double cost = std::numeric_limits<double>::infinity();
    Box4 left, right; // the children's boxes (unions of their bins)
};

void sweepDouble(const BinSetup& s, Scratch& sc, Split& best) {
    // An empty bin changes neither box nor count: its boundary costs the same as the one
    // before it (never strictly better), and the area of an unchanged box is not taken again.
    const int nb = s.nb;
    for (int a = 0; a < 3; ++a) {
        if (s.scale[a] == 0) continue;
        const Box4* box = sc.binBox.data() + a * nb;
        const std::uint32_t* count = sc.binCount.data() + a * nb;
        Box4 acc;
        std::size_t cnt = 0;
        double area = 0;
        for (int b = nb - 1; b > 0; --b) {
            if (count[b]) {
                acc.extend(box[b]);
                cnt += count[b];
                area = acc.area();
            }
            sc.rightArea[std::size_t(b)] = area;
            sc.rightCount[std::size_t(b)] = cnt;
            sc.rightBox[std::size_t(b)] = acc;
        }
        Box4 left;
        std::size_t lc = 0;
        for (int b = 1; b < nb; ++b) {
            if (!count[b - 1]) continue;
            left.extend(box[b - 1]);
            lc += count[b - 1];
            const std::size_t rc = sc.rightCount[std::size_t(b)];
            if (rc == 0) break;
            const double cost =
                double(lc) * left.area() + double(rc) * sc.rightArea[std::size_t(b)];
            if (cost < best.cost) {
                best.cost = cost;
                best.axis = a;
                best.bin = b;
                best.left = left;
                best.right = sc.rightBox[std::size_t(b)];
            }
        }
    }
}

// Issue 21: the same sweep with the three axes side by side, one per lane, in float
// (Embree's binned builder does the same): per bin boundary one SIMD step for all axes
// where the double sweep above took an area per axis and side. The bins are transposed
// once (lane a = axis a's bin), extents are scaled by a power of two that brings the
// node's largest extent near 1 (exact; no overflow or underflow of the products), and
// the first of equal costs wins in each lane (strict <), then axis 0 before 1 before 2:
// the double sweep's order. Costs in float can order near-ties differently from double,
// so the tree may differ where two splits' costs agree to ~1e-7 (the tree is valid either
// way; its SAH cost is compared in the tests and the bench). Empty sides give NaN costs
// (0 · inf), which never compare below the best. The chosen split's boxes and its cost
// are then taken in double, as before, for the leaf test. False (the double sweep runs)
// when the node's extent is beyond the scale's range (|log2| > 100).
bool sweepLanes(const BinSetup& s, Scratch& sc, const Box4& nodeBox, Split& best) {
    const int nb = s.nb;
    double ext = 0;
    for (int a = 0; a < 3; ++a)
        ext = std::max(ext, double(nodeBox.hi_(a)) - double(nodeBox.lo_(a)));
    if (!(ext > 0)) return false;
    const int e = std::ilogb(ext);
    if (e < -100 || e > 100) return false;
    const __m128 k = _mm_set1_ps(std::ldexp(1.0f, -e));
    const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
    const __m128 ninf = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    __m128* T = &sc.lanes.data()->v; // V is one __m128: the array is one of __m128
    // Issue 21 (ninth session): three rows to three columns in five shuffles (lane 3 of
    // each column: lane 3 of z, 0 for a bin with references, ±inf for an empty one), the
    // arrays' pointers in locals (the __m128 stores may alias anything, so `sc.binBox[…]`
    // reloaded them at every bin): 54 -> 35 instructions a bin. Lane 3 never wins below
    // (its best cost is NaN from the start) and no other lane reads it.
    auto columns = [](__m128 x, __m128 y, __m128 z, __m128* t) {
        const __m128 xy01 = _mm_unpacklo_ps(x, y), xy23 = _mm_unpackhi_ps(x, y);
        t[0] = _mm_shuffle_ps(xy01, z, _MM_SHUFFLE(3, 0, 1, 0)); // x0 y0 z0 z3
        t[1] = _mm_shuffle_ps(xy01, z, _MM_SHUFFLE(3, 1, 3, 2)); // x1 y1 z1 z3
        t[2] = _mm_shuffle_ps(xy23, z, _MM_SHUFFLE(3, 2, 1, 0)); // x2 y2 z2 z3
    };
    const Box4* binBox = sc.binBox.data();
    const std::uint32_t* c = sc.binCount.data();
    for (int b = 0; b < nb; ++b) {
        const Box4 &x = binBox[b], &y = binBox[nb + b], &z = binBox[2 * nb + b];
        __m128* t = T + 7 * b;
        columns(x.lo, y.lo, z.lo, t);
        columns(x.hi, y.hi, z.hi, t + 3);
        t[6] = _mm_cvtepi32_ps(_mm_set_epi32(0, std::int32_t(c[2 * nb + b]),
                                             std::int32_t(c[nb + b]), std::int32_t(c[b])));
    }
    // The running union of bins (per lane: lo x, y, z, hi x, y, z) and their count, one
    // bin at a time: the right-to-left pass and the left-to-right pass below share it.
    struct Running {
        __m128 l[3], h[3], cnt;
        Running(__m128 inf, __m128 ninf)
            : l{inf, inf, inf}, h{ninf, ninf, ninf}, cnt(_mm_setzero_ps()) {}
        void add(const __m128* t) {
            for (int a = 0; a < 3; ++a) {
                l[a] = _mm_min_ps(l[a], t[a]);
                h[a] = _mm_max_ps(h[a], t[3 + a]);
            }
            cnt = _mm_add_ps(cnt, t[6]);
        }
    };
    // dx·dy + dy·dz + dz·dx of the scaled extents (half the area, in the node's units).
    auto area = [k](const Running& r) {
        const __m128 dx = _mm_mul_ps(_mm_sub_ps(r.h[0], r.l[0]), k);
        const __m128 dy = _mm_mul_ps(_mm_sub_ps(r.h[1], r.l[1]), k);
        const __m128 dz = _mm_mul_ps(_mm_sub_ps(r.h[2], r.l[2]), k);
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dy), _mm_mul_ps(dy, dz)), _mm_mul_ps(dz, dx));
    };
    {
        Running right(inf, ninf);
        for (int b = nb - 1; b > 0; --b) {
            right.add(T + 7 * b);
            sc.rightAreaL[std::size_t(b)].v = area(right);
            sc.rightCountL[std::size_t(b)].v = right.cnt;
        }
    }
    // Lanes that cannot win: the fourth, and axes that are not binnable. NaN: no cost
    // compares below it, and it compares below no best.
    const float inff = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    __m128 bestCost = _mm_set_ps(nan, s.scale[2] > 0 ? inff : nan, s.scale[1] > 0 ? inff : nan,
                                 s.scale[0] > 0 ? inff : nan);
    __m128i bestBin = _mm_setzero_si128();
    {
        Running left(inf, ninf);
        const __m128i one = _mm_set1_epi32(1);
        __m128i bin = one; // b in every lane
        for (int b = 1; b < nb; ++b) {
            left.add(T + 7 * (b - 1));
            const __m128 cost = _mm_add_ps(
                _mm_mul_ps(left.cnt, area(left)),
                _mm_mul_ps(sc.rightCountL[std::size_t(b)].v, sc.rightAreaL[std::size_t(b)].v));
            const __m128 better = _mm_cmplt_ps(cost, bestCost);
            // minps is `cost < best ? cost : best` per lane: the select by `better` (NaN
            // costs keep the best, a NaN best stays).
            bestCost = _mm_min_ps(cost, bestCost);
            const __m128i m = _mm_castps_si128(better);
            bestBin = _mm_or_si128(_mm_and_si128(m, bin), _mm_andnot_si128(m, bestBin));
            bin = _mm_add_epi32(bin, one);
        }
    }
    alignas(16) float costs[4];
    alignas(16) std::int32_t bins[4];
    _mm_store_ps(costs, bestCost);
    _mm_store_si128(reinterpret_cast<__m128i*>(bins), bestBin);
    float bestF = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a)
        if (costs[a] < bestF) {
            bestF = costs[a];
            best.axis = a;
            best.bin = bins[a];
        }
    if (best.axis < 0) return true; // no boundary with references on both sides
    const Box4* box = sc.binBox.data() + best.axis * nb;
    const std::uint32_t* count = sc.binCount.data() + best.axis * nb;
    std::size_t lc = 0, rc = 0;
    for (int b = 0; b < nb; ++b) {
        if (b < best.bin) {
            best.left.extend(box[b]);
            lc += count[b];
        } else {
            best.right.extend(box[b]);
            rc += count[b];
        }
    }
    best.cost = double(lc) * best.left.area() + double(rc) * best.right.area();
    return true;
}

void sweep(const BinSetup& s, Scratch& sc, const Box4& nodeBox, Split& best) {
    if (!sweepLanes(s, sc, nodeBox, best)) sweepDouble(s, sc, best);
}

// 2. One node: a task is a range of references in one of the two buffers, with the
//    bounds of their boxes and of their centroids.
struct Task {
    std::size_t begin = 0, end = 0;
    int depth = 0;
    int buffer = 0; // which of the two reference buffers holds the range
    Box4 box, cbox;
};

// The decision of a node: a leaf, or two children with their references partitioned.
struct Decision {
    bool leaf = false;
    double leafCost = 0;
    int axis = 0;
    Task left, right;
};

// Shared state of one build.
struct Builder {
    const BvhOptions& options;
    double rootArea = 1;
    Ref* buf[2] = {nullptr, nullptr};
    std::uint32_t* order = nullptr; // scene index per leaf slot
    // The primitive per leaf slot (Bvh::order_), written with `order` (issue 21, ninth
    // session: a parallel pass of its own after the tree, each of its loads a random
    // read of prims, barely faster with two threads than with one).
    const Primitive** leafPrim = nullptr;
    const std::unique_ptr<Primitive>* prims = nullptr;
    bool parallel = false; // blocks and subtrees as TBB tasks
    // Wide trees (issue 21): the collapse makes every subtree of at most 4 primitives
    // (8 when all are exactly Sphere) one wide leaf whatever its inner splits
    // (Bvh::collapseInto, mergedCount), so the build stops there: such a node becomes a
    // leaf at once. The wide tree is the same node for node (tested); only the order
    // inside such a leaf differs, and no answer depends on it (ties go to the scene
    // index). ~80% of the binary nodes were below that line (balls 5: 132,427 binary
    // nodes, 3,996 wide nodes). Null for width 2 (the binary tree is traversed).
    const std::uint8_t* kind = nullptr; // per scene index (bvh_wide_kinds.h); null: no stop

    bool mergedLeaf(const Task& t) const {
        const std::size_t n = t.end - t.begin;
        if (!kind || n > 8) return false;
        if (n <= 4) return true;
        const Ref* refs = buf[t.buffer];
        for (std::size_t i = t.begin; i < t.end; ++i)
            if (kind[refs[i].prim] != kSphere) return false;
        return true;
    }

    template <class F> void forBlocks(std::size_t blocks, F&& f) const {
        if (parallel && blocks > 1)
            parallelFor(blocks, f);
        else
            for (std::size_t k = 0; k < blocks; ++k)
                f(k);
    }

    // Object median on the widest centroid axis (deep trees, coincident centroids), in
    // place; the children's bounds in one more pass.
    void medianSplit(const Task& t, Decision& d) const {
        Ref* refs = buf[t.buffer];
        float best = -1;
        int axis = 0;
        for (int a = 0; a < 3; ++a)
            if (t.cbox.hi_(a) - t.cbox.lo_(a) > best) {
                best = t.cbox.hi_(a) - t.cbox.lo_(a);
                axis = a;
            }
        const std::size_t mid = t.begin + (t.end - t.begin) / 2;
        std::nth_element(
            refs + t.begin, refs + mid, refs + t.end,
            [axis](const Ref& x, const Ref& y) { return x.centre(axis) < y.centre(axis); });
        d.axis = axis;
        d.left = Task{t.begin, mid, t.depth + 1, t.buffer, {}, {}};
        d.right = Task{mid, t.end, t.depth + 1, t.buffer, {}, {}};
        const __m128 mask = lanes012();
        for (std::size_t i = t.begin; i < t.end; ++i) {
            Task& c = i < mid ? d.left : d.right;
            const __m128 lo = loadLo(refs[i], mask), hi = loadHi(refs[i]);
            c.box.extend(lo, hi);
            c.cbox.extendPoint(centroid(lo, hi));
        }
    }

    // Stable, branchless partition of in[0, n) into the other buffer: references whose
    // bin on `axis` is below `bin` to l[...], the others to r[...]; the centroid bounds
    // of both sides on the way. (A branch per reference mispredicts half the time.)
    static void scatter(const Ref* in, std::size_t n, Ref* l, Ref* r, const BinSetup& s, int axis,
                        int bin, Box4& lc, Box4& rc) {
        switch (axis) {
        case 0:
            return scatterAxis<0>(in, n, l, r, s, bin, lc, rc);
        case 1:
            return scatterAxis<1>(in, n, l, r, s, bin, lc, rc);
        default:
            return scatterAxis<2>(in, n, l, r, s, bin, lc, rc);
        }
    }
    template <int Axis>
    static void scatterAxis(const Ref* in, std::size_t n, Ref* l, Ref* r, const BinSetup& s,
                            int bin, Box4& lc, Box4& rc) {
        const __m128 mask = lanes012();
        const __m128i split = _mm_set1_epi32(bin);
        // Issue 21 (ninth session): the centroid that does not belong to a side is made a
        // NaN for it (all exponent and mantissa bits set), and minps/maxps with a NaN first
        // operand return the second: one or and one min or max per bound, where selecting
        // c or ±inf by the left mask took three more. (Written `min(c, lo)`, not `min(lo,
        // c)`, for that: the two differ only in which zero of an equal ±0 they keep, and
        // the bounds' zero signs change no bin, extent or axis choice.) The destination
        // is picked from the two moving pointers with goesLeft opaque to the compiler (the
        // empty asm): knowing it 0 or 1, GCC made the loop body a branch on it, which
        // mispredicts half the time on references in random order (a million random
        // triangles: 25% slower builds).
        const __m128 nanBits = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
        __m128 llo = lc.lo, lhi = lc.hi, rlo = rc.lo, rhi = rc.hi;
        for (std::size_t i = 0; i < n; ++i) {
            const __m128 raw = _mm_load_ps(in[i].lo), hi = loadHi(in[i]);
            const __m128 c = centroid(_mm_and_ps(raw, mask), hi);
            // All ones where the reference goes left (its bin on Axis below the split).
            const __m128 left =
                _mm_castsi128_ps(_mm_shuffle_epi32(_mm_cmplt_epi32(s.bins(c), split), Axis * 0x55));
            auto goesLeft = std::size_t(_mm_movemask_ps(left) & 1);
            asm("" : "+r"(goesLeft));
            Ref* dst = goesLeft ? l : r;
            _mm_store_ps(dst->lo, raw);
            _mm_store_ps(dst->hi, hi);
            l += goesLeft;
            r += 1 - goesLeft;
            const __m128 cl = _mm_or_ps(c, _mm_andnot_ps(left, nanBits));
            const __m128 cr = _mm_or_ps(c, _mm_and_ps(left, nanBits));
            llo = _mm_min_ps(cl, llo);
            lhi = _mm_max_ps(cl, lhi);
            rlo = _mm_min_ps(cr, rlo);
            rhi = _mm_max_ps(cr, rhi);
        }
        lc.lo = llo;
        lc.hi = lhi;
        rc.lo = rlo;
        rc.hi = rhi;
    }

    // A node of at most kBlockNode references: leaf or split.
    Decision decide(const Task& t, Scratch& sc) const {
        Decision d;
        const std::size_t n = t.end - t.begin;
        d.leafCost = options.intersectionCost * double(n);
        if (n == 1) {
            d.leaf = true;
            return d;
        }
        if (n == 2 && t.depth < kMedianDepth) return decidePair(t);
        Ref* refs = buf[t.buffer];
        // Small nodes need few bins (n + 1 separate n distinct centroids well enough);
        // clearing and sweeping 16 bins for 2 primitives would dominate the build.
        const int nb = int(std::min<std::size_t>(std::size_t(options.bins), n + 1));
        const BinSetup s(t.cbox, nb);
        Split best;
        if (s.binnable && t.depth < kMedianDepth) {
            binRange(refs + t.begin, n, s, sc.binBox.data(), sc.binCount.data());
            sweep(s, sc, t.box, best);
        }
        if (finish(t, best, d)) return d;
        if (best.axis >= 0) {
            std::size_t left = 0; // from the bins
            for (int b = 0; b < best.bin; ++b)
                left += sc.binCount[std::size_t(best.axis * nb + b)];
            const std::size_t mid = t.begin + left;
            Ref* out = buf[1 - t.buffer];
            Box4 lc, rc;
            scatter(refs + t.begin, n, out + t.begin, out + mid, s, best.axis, best.bin, lc, rc);
            d.axis = best.axis;
            d.left = Task{t.begin, mid, t.depth + 1, 1 - t.buffer, best.left, lc};
            d.right = Task{mid, t.end, t.depth + 1, 1 - t.buffer, best.right, rc};
        } else {
            medianSplit(t, d);
        }
        return d;
    }

    // Two primitives (half of all inner nodes): what binning them would decide, without
    // the bins. On the first binnable axis the lower centroid is alone in bin 0 (it is
    // the bounds' lo) and the other lands in bin >= 1 (its offset is the whole extent,
    // about nb bins), so the split is one|one at bin 1, cost A(low) + A(high) (the other
    // axes give the same sum: never strictly better).
    Decision decidePair(const Task& t) const {
        Decision d;
        d.leafCost = options.intersectionCost * 2;
        Ref* refs = buf[t.buffer] + t.begin;
        const float nb = float(std::min(options.bins, 3));
        Split best;
        for (int a = 0; a < 3; ++a) {
            const float ext = t.cbox.hi_(a) - t.cbox.lo_(a);
            if (ext > 0 && nb * (1 - 1e-6f) / ext > 0) {
                best.axis = a;
                best.bin = 1;
                break;
            }
        }
        const __m128 mask = lanes012();
        __m128 lo0 = loadLo(refs[0], mask), hi0 = loadHi(refs[0]);
        __m128 lo1 = loadLo(refs[1], mask), hi1 = loadHi(refs[1]);
        __m128 c0 = centroid(lo0, hi0), c1 = centroid(lo1, hi1);
        if (best.axis >= 0) {
            alignas(16) float f0[4], f1[4];
            _mm_store_ps(f0, c0);
            _mm_store_ps(f1, c1);
            if (f1[best.axis] < f0[best.axis]) {
                std::swap(refs[0], refs[1]);
                std::swap(lo0, lo1);
                std::swap(hi0, hi1);
                std::swap(c0, c1);
            }
            best.left.extend(lo0, hi0);
            best.right.extend(lo1, hi1);
            best.cost = 1.0 * best.left.area() + 1.0 * best.right.area();
        }
        if (finish(t, best, d)) return d;
        if (best.axis < 0) { // not binnable: object median (depth < kMedianDepth: a leaf above)
            medianSplit(t, d);
            return d;
        }
        d.axis = best.axis;
        d.left = Task{t.begin, t.begin + 1, t.depth + 1, t.buffer, best.left, {}};
        d.right = Task{t.begin + 1, t.end, t.depth + 1, t.buffer, best.right, {}};
        d.left.cbox.extendPoint(c0);
        d.right.cbox.extendPoint(c1);
        return d;
    }

    // The leaf test of the SAH: true (d.leaf) when the node stays a leaf.
    bool finish(const Task& t, const Split& best, Decision& d) const {
        const std::size_t n = t.end - t.begin;
        const double boxArea = t.box.area();
        const double parentArea = boxArea > 0 ? boxArea : 1e-300;
        const double splitCost = best.axis < 0 ? std::numeric_limits<double>::infinity()
                                               : options.traversalCost + options.intersectionCost *
                                                                             best.cost / parentArea;
        const bool canSah = best.axis >= 0;
        const bool wantLeaf = n <= std::size_t(options.maxLeafSize) && d.leafCost <= splitCost;
        // Coincident centroids cannot be binned: a modest group becomes one leaf.
        const bool stuck = !canSah && t.depth < kMedianDepth && n <= 256;
        d.leaf = n <= kMaxLeaf && (n == 1 || wantLeaf || stuck);
        return d.leaf;
    }

    // A node of more than kBlockNode references: binned per block, partitioned by a
    // stable scatter of each block into the other buffer (blocks fixed by the range,
    // so the order is the same for any thread count). Never a leaf (kBlockNode > 256).
    Decision decideBlocked(const Task& t, Scratch& sc) const {
        Decision d;
        const std::size_t n = t.end - t.begin;
        d.leafCost = options.intersectionCost * double(n);
        const Ref* refs = buf[t.buffer] + t.begin;
        const int nb = options.bins;
        const BinSetup s(t.cbox, nb);
        const std::size_t blocks = (n + kBlock - 1) / kBlock, per = std::size_t(3 * nb);
        auto blockLen = [&](std::size_t k) { return std::min(kBlock, n - k * kBlock); };
        Split best;
        std::vector<std::uint32_t> counts;
        if (s.binnable && t.depth < kMedianDepth) {
            std::vector<Box4> boxes(blocks * per);
            counts.resize(blocks * per);
            forBlocks(blocks, [&](std::size_t k) {
                binRange(refs + k * kBlock, blockLen(k), s, &boxes[k * per], &counts[k * per]);
            });
            for (std::size_t j = 0; j < per; ++j) {
                Box4 b;
                std::uint32_t c = 0;
                for (std::size_t k = 0; k < blocks; ++k) {
                    b.extend(boxes[k * per + j]);
                    c += counts[k * per + j];
                }
                sc.binBox[j] = b;
                sc.binCount[j] = c;
            }
            sweep(s, sc, t.box, best);
        }
        if (finish(t, best, d)) return d; // cannot happen (n > kBlockNode > 256)
        if (best.axis < 0) {
            medianSplit(t, d);
            return d;
        }
        // Left counts of each block from its bins, their prefix sums: where it writes.
        std::vector<std::size_t> leftAt(blocks + 1), rightAt(blocks + 1);
        leftAt[0] = 0;
        rightAt[0] = 0;
        for (std::size_t k = 0; k < blocks; ++k) {
            std::size_t left = 0;
            for (int b = 0; b < best.bin; ++b)
                left += counts[k * per + std::size_t(best.axis * nb + b)];
            leftAt[k + 1] = leftAt[k] + left;
            rightAt[k + 1] = rightAt[k] + (blockLen(k) - left);
        }
        const std::size_t mid = t.begin + leftAt[blocks];
        Ref* out = buf[1 - t.buffer];
        std::vector<Box4> lcs(blocks), rcs(blocks);
        forBlocks(blocks, [&](std::size_t k) {
            scatter(refs + k * kBlock, blockLen(k), out + t.begin + leftAt[k],
                    out + mid + rightAt[k], s, best.axis, best.bin, lcs[k], rcs[k]);
        });
        Box4 lc, rc;
        for (std::size_t k = 0; k < blocks; ++k) {
            lc.extend(lcs[k]);
            rc.extend(rcs[k]);
        }
        d.axis = best.axis;
        d.left = Task{t.begin, mid, t.depth + 1, 1 - t.buffer, best.left, lc};
        d.right = Task{mid, t.end, t.depth + 1, 1 - t.buffer, best.right, rc};
        return d;
    }

    Decision decideAny(const Task& t, Scratch& sc) const {
        return t.end - t.begin > kBlockNode ? decideBlocked(t, sc) : decide(t, sc);
    }

    BuildNode nodeOf(const Task& t) const {
        BuildNode node;
        const __m128 lo = t.box.lo, hi = t.box.hi;
        _mm_storeu_pd(&node.lo.x, _mm_cvtps_pd(lo));
        _mm_store_sd(&node.lo.z, _mm_cvtps_pd(_mm_movehl_ps(lo, lo)));
        _mm_storeu_pd(&node.hi.x, _mm_cvtps_pd(hi));
        _mm_store_sd(&node.hi.z, _mm_cvtps_pd(_mm_movehl_ps(hi, hi)));
        node.offset = 0;
        node.count = 0;
        node.size = 1;
        return node;
    }

    // Leaves keep their references' range: they are in leaf order already.
    void emitLeaf(const Task& t, BuildNode& node) const {
        node.offset = std::uint32_t(t.begin);
        node.count = std::uint16_t(t.end - t.begin);
        const Ref* refs = buf[t.buffer];
        for (std::size_t i = t.begin; i < t.end; ++i) {
            order[i] = refs[i].prim;
            leafPrim[i] = prims[refs[i].prim].get();
        }
    }
};

// Large build arrays: fresh memory costs a page fault per 4 KiB page (the kernel's
// share was ~10% of a build in `perf`); in 2 MiB pages (Linux: a mapping of its own with
// transparent huge pages on request) it is one fault per 2 MiB. Through malloc the
// hint landed on glibc's heap at times and 1 build in 8 took twice as long (balls 5:
// 40 instead of 21 ms); an own mapping measured 20-23 ms every time. Small arrays
// and other systems: malloc.
constexpr std::size_t kHuge = std::size_t(2) << 20;
// Issue 21 (tenth session): arrays from 128 KiB (malloc's first mmap threshold) up to 2 MiB
// are kept mappings too, of 4 KiB pages. Through malloc, the build-rate table's rows (three
// trees alive a round, all freed at its end) faulted in their first three rounds of five
// (balls 5: 1,816 / 749 / 455 faults a two-thread build, jacks 5 889 / 250 / 412): glibc maps
// such chunks afresh and gives heap tops back until its thresholds have grown with the frees,
// and the faults fell in the two-thread build's steps (the leaf arrays' zeroing, the leaves).
constexpr std::size_t kSmallKept = std::size_t(128) << 10;
// Under AddressSanitizer the arrays below 2 MiB stay malloc's, as before the tenth session:
// its chunks carry red zones, a mapping of our own has none, and the tests' scenes have
// arrays of that size.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t kMapFrom = kHuge;
#else
constexpr std::size_t kMapFrom = kSmallKept;
#endif
constexpr std::size_t kPage = 4096;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
// Issue 21: mappings a build has freed, kept for the next build. Fresh memory costs its
// page faults and the kernel's zeroing at first touch: 7% of a one-thread balls 5 build
// (perf: clear_page_erms 3.4%, the faults and munmap the rest) and 15% of a two-thread
// one, where both threads fault on the same 2 MiB page at once and each may zero a page
// of its own (clear_page 9% there). malloc keeps freed memory for reuse the same way (its
// mmap threshold grows to the largest chunk freed, up to 32 MiB), and Embree's reference
// array is an _mm_malloc allocation; at most kKeptBytes are kept for the process, in at
// most kKept mappings. The first build of a process still pays. Issue 21: 512 MiB (was
// 256): a build of a million triangles frees 274 MiB (two reference buffers of 34 MiB,
// the node array of 110 MiB, the collapse's buffer of 84 MiB); with 256 the node array,
// freed last, was unmapped, and every such build mapped it afresh and zeroed its 53 huge
// pages (perf: the kernel ~8% of a one-thread build, under buildSubtree and buildTop).
// Issue 21: 48 mappings (was 8): the Bvh's leaf arrays are bigAlloc memory too (bvh.h,
// KeptAlloc), 14 of them for triangles; raytrace_scale_bench's build table frees two
// trees' arrays and a build's four scratch arrays at once (32 mappings of a million
// triangles, about 450 MiB with each mapping's rounding to 2 MiB and its 2 MiB of room).
// Tenth session: 128 mappings: those from kSmallKept on are kept too (jacks 5: ~13 a tree, and
// the build table keeps three trees alive at once).
// Eleventh session: 768 MiB (was 512), and a mapping freed when the cap is reached pushes out
// the longest-kept ones instead of being unmapped itself. The build table's million-triangle
// row frees 519 MiB a round (three trees and a build's scratch); with 512 one 10 MiB mapping
// (order_'s) was unmapped every round and the next two-thread build mapped it afresh. On
// this VM (Firecracker, free page reporting) fresh memory is backed by the host at its first
// touch: a 2 MiB page took 0.3-24 ms to zero (a scratch loop: 64 MiB in 11-580 ms), and the
// TBB worker zeroed order_'s pages inside buildSubtree for up to 75 ms of a ~200 ms build.
// Mappings an earlier, other-sized build left (balls 6's before the million triangles) are
// the ones pushed out.
struct KeptMappings {
    static constexpr int kKept = 128;
    static constexpr std::size_t kKeptBytes = std::size_t(768) << 20;
    std::mutex lock;
    void* base[kKept] = {};
    std::size_t length[kKept] = {};
    std::uint64_t stamp[kKept] = {}; // when kept: the smallest is pushed out first
    std::size_t asked[kKept] = {};   // the largest array the mapping has held
    std::uint64_t clock = 0;
    std::size_t bytes = 0;
    // A kept mapping of at least `need` bytes and at most twice that (so a small array
    // does not hold a large mapping); of those, one that has held an array of `array`
    // bytes or more, then the smallest; null if none. Eleventh session: a mapping an
    // array of another size left (balls 6's leaf arrays of 2.4 MB in mappings of 6 MiB,
    // taken for a million triangles' 4 MB ones) has pages no array has touched, and the
    // next build faulted them in: 393-1,179 faults in the tasks step of the million-
    // triangle row's second to fourth two-thread builds after balls 6 and jacks 5.
    void* take(std::size_t need, std::size_t array, std::size_t& got, std::size_t& held) {
        std::lock_guard<std::mutex> g(lock);
        int best = -1;
        for (int k = 0; k < kKept; ++k) {
            if (!base[k] || length[k] < need || length[k] / 2 > need) continue;
            const bool full = asked[k] >= array;
            const bool bestFull = best >= 0 && asked[best] >= array;
            if (best < 0 || full > bestFull || (full == bestFull && length[k] < length[best]))
                best = k;
        }
        if (best < 0) return nullptr;
        void* p = base[best];
        got = length[best];
        held = asked[best];
        bytes -= got;
        base[best] = nullptr;
        return p;
    }
    // Keeps the mapping, unmapping the longest-kept ones while the cap would be passed or
    // no place is free; false (the caller unmaps it) when it alone passes the cap.
    bool keep(void* p, std::size_t len, std::size_t held) {
        if (len > kKeptBytes) return false;
        void* out[kKept];
        std::size_t outLength[kKept];
        int nOut = 0;
        {
            std::lock_guard<std::mutex> g(lock);
            auto freeSlot = [&] {
                for (int k = 0; k < kKept; ++k)
                    if (!base[k]) return k;
                return -1;
            };
            int slot = freeSlot();
            while (bytes + len > kKeptBytes || slot < 0) {
                int oldest = -1;
                for (int k = 0; k < kKept; ++k)
                    if (base[k] && (oldest < 0 || stamp[k] < stamp[oldest])) oldest = k;
                out[nOut] = base[oldest];
                outLength[nOut++] = length[oldest];
                bytes -= length[oldest];
                base[oldest] = nullptr;
                slot = freeSlot();
            }
            base[slot] = p;
            length[slot] = len;
            asked[slot] = held;
            stamp[slot] = ++clock;
            bytes += len;
        }
        for (int k = 0; k < nOut; ++k)
            munmap(out[k], outLength[k]);
        return true;
    }
};
// Never destroyed (a build may run while the process exits); the mappings are not
// malloc's, so LeakSanitizer does not report them.
KeptMappings& keptMappings() {
    static KeptMappings* kept = new KeptMappings;
    return *kept;
}
#endif
} // namespace

namespace bvh_detail {
void* bigAlloc(std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes >= kHuge) {
        // Room for the alignment and, just below the aligned start, the mapping's base,
        // length and largest array (the mapping starts at least a 4 KiB page below it).
        std::size_t length = (bytes + kHuge - 1) / kHuge * kHuge + kHuge, kept = 0, held = 0;
        void* base = keptMappings().take(length, bytes, kept, held);
        const bool fresh = base == nullptr;
        if (!fresh) length = kept;
        if (fresh) {
            base =
                mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (base == MAP_FAILED) throw std::bad_alloc();
        }
        const auto start =
            (reinterpret_cast<std::uintptr_t>(base) + 64 + kHuge - 1) / kHuge * kHuge;
        char* p = reinterpret_cast<char*>(start);
        // A hint, for the whole 2 MiB pages the array fills: a huge page is zeroed whole
        // at its first touch, so a tail in one (balls 5's 2.1 MB reference buffers: two
        // pages, 4 MiB zeroed each) cost more clearing than its faults save; the tail
        // takes 4 KiB pages, zeroed as touched (issue 21: clear_page was 8% in perf).
        // A kept mapping has the hint over its largest array's whole pages so far.
        if (bytes > held) madvise(p, bytes / kHuge * kHuge, MADV_HUGEPAGE);
        held = std::max(held, bytes);
        std::memcpy(p - 24, &held, sizeof held);
        std::memcpy(p - 16, &base, sizeof base);
        std::memcpy(p - 8, &length, sizeof length);
        return p;
    }
    if (bytes >= kMapFrom) {
        // 4 KiB pages; the base and length in the first page, the array from the second.
        std::size_t length = (bytes + kPage - 1) / kPage * kPage + kPage, kept = 0, held = 0;
        void* base = keptMappings().take(length, bytes, kept, held);
        if (base) {
            length = kept;
        } else {
            base =
                mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (base == MAP_FAILED) throw std::bad_alloc();
        }
        char* p = static_cast<char*>(base) + kPage;
        held = std::max(held, bytes);
        std::memcpy(p - 24, &held, sizeof held);
        std::memcpy(p - 16, &base, sizeof base);
        std::memcpy(p - 8, &length, sizeof length);
        return p;
    }
#endif
    // 64-byte aligned: the wide nodes (alignas(64), the walk's aligned loads) are kept
    // memory too, and malloc aligns to 16 only.
    void* p = std::aligned_alloc(64, (bytes + 63) / 64 * 64 + (bytes ? 0 : 64));
    if (!p) throw std::bad_alloc();
    return p;
}
void bigFree(void* p, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes >= kMapFrom) {
        void* base;
        std::size_t length, held;
        std::memcpy(&held, static_cast<char*>(p) - 24, sizeof held);
        std::memcpy(&base, static_cast<char*>(p) - 16, sizeof base);
        std::memcpy(&length, static_cast<char*>(p) - 8, sizeof length);
        if (!keptMappings().keep(base, length, held)) munmap(base, length);
        return;
    }
#endif
    (void)bytes;
    std::free(p);
}
} // namespace bvh_detail

namespace {

// The node array (not zeroed on resize: every node is written), in bigAlloc memory
// (KeptAlloc's allocate and deallocate).
template <class T> struct NoInit : bvh_detail::KeptAlloc<T> {
    NoInit() = default;
    template <class U> NoInit(const NoInit<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... A> void construct(U* p, A&&... a) {
        ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
    template <class U> bool operator==(const NoInit<U>&) const noexcept { return true; }
    template <class U> bool operator!=(const NoInit<U>&) const noexcept { return false; }
};
using Nodes = std::vector<BuildNode, NoInit<BuildNode>>;

// Counters of a subtree; its SAH cost summed in depth-first order.
struct Tally {
    int leaves = 0, maxDepth = 0;
    std::size_t nodes = 0;
    double sahCost = 0;
};

// 3. A subtree built depth first by one task (left child right after its parent) into
//    the final array from index `next` on; inner offsets are indices into that array.
//    A subtree of k references takes at most 2k − 1 places (a binary tree of at most k
//    leaves), the room buildTop gives it.
void buildSubtree(const Builder& b, const Task& t, BuildNode* nodes, std::uint32_t& next,
                  Scratch& sc, Tally& tally) {
    const auto idx = next++;
    nodes[idx] = b.nodeOf(t);
    ++tally.nodes;
    tally.maxDepth = std::max(tally.maxDepth, t.depth);
    if (t.end - t.begin == 1 || b.mergedLeaf(t)) { // a leaf as decide (or the collapse) would
        b.emitLeaf(t, nodes[idx]);
        ++tally.leaves;
        tally.sahCost +=
            b.options.intersectionCost * double(t.end - t.begin) * t.box.area() / b.rootArea;
        return;
    }
    const Decision d = b.decideAny(t, sc);
    if (d.leaf) {
        b.emitLeaf(t, nodes[idx]);
        ++tally.leaves;
        tally.sahCost += d.leafCost * t.box.area() / b.rootArea;
        return;
    }
    tally.sahCost += b.options.traversalCost * t.box.area() / b.rootArea;
    buildSubtree(b, d.left, nodes, next, sc, tally);
    nodes[idx].offset = next;
    buildSubtree(b, d.right, nodes, next, sc, tally);
    nodes[idx].size = std::uint16_t(std::min<std::uint32_t>(next - idx, kSizeCap));
}

// 4. The top of the tree: nodes of more than kParallelGrain references are split here,
//    each at its place p in the final array, its left child at p + 1 and its right child
//    at p + 2·(left references) (bvh_internal.h, BuildNode): the places depend on the
//    partition only, so both children are built at once as two TBB tasks (parallel) or
//    one after the other (one thread), into the same array, the same places either way.
//    Smaller subtrees are one task each (buildSubtree). The SAH cost is summed in the
//    same depth-first order as before (each top node's own cost, then each subtree's
//    sum), so it is the same number for any thread count.
//    Issue 21: the parallel build built its subtrees into arrays of their own and copied
//    them into the final one (the stitch: balls 5 0.28 ms at two threads, with its
//    allocations, part of the two-thread build's serial time); now nothing is copied.
struct TopTally {
    Tally own; // split: this node only; else the subtree's
    std::unique_ptr<TopTally> left, right;
    void sumInto(Tally& total) const {
        total.maxDepth = std::max(total.maxDepth, own.maxDepth);
        total.sahCost += own.sahCost;
        total.leaves += own.leaves;
        total.nodes += own.nodes;
        if (left) {
            left->sumInto(total);
            right->sumInto(total);
        }
    }
};

std::uint32_t buildTop(const Builder& b, const Task& t, BuildNode* nodes, std::uint32_t at,
                       Scratch& sc, TopTally& out) {
    if (t.end - t.begin > kParallelGrain) {
        const Decision d = b.decideAny(t, sc);
        if (!d.leaf) {
            nodes[at] = b.nodeOf(t);
            out.own.nodes = 1;
            out.own.maxDepth = t.depth;
            out.own.sahCost = b.options.traversalCost * t.box.area() / b.rootArea;
            out.left = std::make_unique<TopTally>();
            out.right = std::make_unique<TopTally>();
            const auto right = std::uint32_t(at + 2 * (d.left.end - d.left.begin));
            nodes[at].offset = right;
            std::uint32_t sizes[2] = {0, 0};
            if (b.parallel) {
                parallelInvoke(
                    [&] {
                        Scratch own(b.options.bins);
                        sizes[0] = buildTop(b, d.left, nodes, at + 1, own, *out.left);
                    },
                    [&] {
                        Scratch own(b.options.bins);
                        sizes[1] = buildTop(b, d.right, nodes, right, own, *out.right);
                    });
            } else {
                sizes[0] = buildTop(b, d.left, nodes, at + 1, sc, *out.left);
                sizes[1] = buildTop(b, d.right, nodes, right, sc, *out.right);
            }
            const std::uint32_t size = 1 + sizes[0] + sizes[1];
            nodes[at].size = std::uint16_t(std::min(size, kSizeCap));
            return size;
        }
        // A large group that cannot be split (coincident centroids): one task.
    }
    std::uint32_t next = at;
    buildSubtree(b, t, nodes, next, sc, out.own);
    return next - at;
}

// References of a primitive: false if its box is unbounded, empty, non-finite or
// beyond float's range (|x| > 3.4e38: as good as unbounded here).
bool makeRef(const Primitive& p, std::uint32_t index, Ref& r) {
    const Aabb b = p.bounds();
    // Issue 21 (ninth session): the box's doubles read 8 bytes at a time. bounds() has
    // just stored them (Sphere: three 16-byte stores at 0, 16, 32 bytes), and a 16-byte
    // load of hi.x, hi.y (24 bytes in) spans two stores, which the CPU cannot forward: the
    // load waits for both to reach the cache (perf: the hottest instruction of makeRef).
    // An 8-byte load lies within one store of any bounds() that stores whole doubles.
    // (The empty asm keeps GCC from merging the two halves into one 16-byte load again.)
    __m128d lx = _mm_load_sd(&b.lo.x), hx = _mm_load_sd(&b.hi.x);
    asm("" : "+x"(lx), "+x"(hx));
    alignas(16) double v[6];
    _mm_store_pd(v, _mm_loadh_pd(lx, &b.lo.y));
    _mm_store_sd(v + 2, _mm_load_sd(&b.lo.z));
    _mm_storeu_pd(v + 3, _mm_loadh_pd(hx, &b.hi.y));
    _mm_store_sd(v + 5, _mm_load_sd(&b.hi.z));
    __m128 lo, hi;
    floatBoxOutward(v, v + 3, lo, hi);
    _mm_store_ps(r.lo, lo);
    _mm_store_ps(r.hi, hi); // lane 3: r.zero = 0
    r.prim = index;
    // Finite floats: x − x is 0 (NaN for ±inf and NaN). Issue 21 (ninth session): this
    // alone; the same test on the doubles and Aabb::bounded() (|x| < DBL_MAX) said nothing
    // more. A double that is NaN, ±inf or beyond float's range (DBL_MAX among them) is NaN
    // or ±inf in float, and floatBoxOutward only steps a finite float by one ulp (to ±inf
    // at most), so a finite float box comes from a finite, bounded double box.
    const int fits = _mm_movemask_ps(_mm_cmpeq_ps(_mm_sub_ps(lo, lo), _mm_setzero_ps())) &
                     _mm_movemask_ps(_mm_cmpeq_ps(_mm_sub_ps(hi, hi), _mm_setzero_ps()));
    return (fits & 7) == 7 && !b.empty();
}

// 32-byte aligned storage of references (not zeroed: every one used is written).
struct RefBuffer {
    struct Free {
        std::size_t n;
        void operator()(Ref* p) const { bigFree(p, n * sizeof(Ref)); }
    };
    std::unique_ptr<Ref[], Free> data;
    explicit RefBuffer(std::size_t n)
        : data(static_cast<Ref*>(bigAlloc(n * sizeof(Ref))), Free{n}) {}
};

} // namespace

Bvh::Bvh(const std::vector<std::unique_ptr<Primitive>>& prims, BvhOptions options)
    : options_(options) {

    if (options.bins < 2 || options.bins > 256 || options.maxLeafSize < 1 ||
        options.maxLeafSize > 255 || !(options.traversalCost >= 0) ||
        !(options.intersectionCost > 0) ||
        (options.width != 0 && options.width != 2 && options.width != 4 && options.width != 8) ||
        options.buildThreads < 0)
        throw std::invalid_argument("Bvh: bins in 2..256, maxLeafSize in 1..255, costs >= 0, "
                                    "width 0, 2, 4 or 8, buildThreads >= 0");
    const auto start = std::chrono::steady_clock::now();
    const bool parallel = options.buildThreads != 1;
    Nodes build;
    std::size_t buildNodes = 0; // in use in `build` (which has gaps: BuildNode)
    auto buildTree = [&] {
        // References: boxes fetched once, in scene order (unbounded ones set aside).
        const std::size_t count = prims.size();
        RefBuffer bufA(count), bufB(count);
        // Wide trees: each primitive's kind (Builder::mergedLeaf, then the collapse's
        // leaf runs), read while the object is in cache for its bounds. The collapse
        // read them in leaf order, a cache miss per primitive (perf: the vtable load
        // was half of collapseWide's own time).
        const bool wide = options.width != 2;
        if (wide) sceneKind_.resize(count);
        std::uint8_t* const kinds = sceneKind_.data();
        std::size_t n = 0;
        Box4 rootBox, rootCBox;
        const __m128 mask = lanes012();
        auto account = [&](const Ref& r, Box4& box, Box4& cbox) {
            const __m128 lo = loadLo(r, mask), hi = loadHi(r);
            box.extend(lo, hi);
            cbox.extendPoint(centroid(lo, hi));
        };
        if (!parallel || count <= kBlock) {
            for (std::size_t i = 0; i < count; ++i) {
                if (i + 8 < count) __builtin_prefetch(prims[i + 8].get()); // its vtable, box
                Ref& r = bufA.data[n];
                if (wide) kinds[i] = primitiveKind(prims[i].get());
                if (makeRef(*prims[i], std::uint32_t(i), r)) {
                    account(r, rootBox, rootCBox);
                    ++n;
                } else {
                    unbounded_.push_back(prims[i].get());
                    unboundedIndex_.push_back(std::uint32_t(i));
                }
            }
        } else {
            // Blocks: references into buffer A at their scene index; if some were
            // unbounded, compacted into B and the buffers swapped (the same order as
            // the loop above).
            const std::size_t blocks = (count + kBlock - 1) / kBlock;
            std::vector<std::size_t> valid(blocks + 1, 0);
            std::vector<Box4> boxes(blocks), cboxes(blocks);
            std::vector<std::uint8_t> ok(count);
            // Each block's boxes in locals, stored once: through boxes[k] the compiler stored
            // them after every reference (makeRef's virtual call may read any memory), and
            // the 32-byte boxes of neighbouring blocks share cache lines. Issue 21: blocks 9
            // and 10 of jacks 5, the last two and run at once by the two threads, took
            // 200-300 us each against 80 for the others (the line moving between the cores
            // at every reference); the reference pass took 0.69 ms at two threads for 0.86
            // at one.
            parallelFor(blocks, [&](std::size_t k) {
                std::size_t v = 0;
                Box4 box, cbox;
                for (std::size_t i = k * kBlock, e = std::min(count, i + kBlock); i < e; ++i) {
                    ok[i] = makeRef(*prims[i], std::uint32_t(i), bufA.data[i]);
                    if (wide) kinds[i] = primitiveKind(prims[i].get());
                    if (ok[i]) {
                        account(bufA.data[i], box, cbox);
                        ++v;
                    }
                }
                boxes[k] = box;
                cboxes[k] = cbox;
                valid[k + 1] = v;
            });
            for (std::size_t k = 0; k < blocks; ++k) {
                rootBox.extend(boxes[k]);
                rootCBox.extend(cboxes[k]);
                const std::size_t e = std::min(count, (k + 1) * kBlock);
                if (valid[k + 1] != e - k * kBlock)
                    for (std::size_t i = k * kBlock; i < e; ++i)
                        if (!ok[i]) {
                            unbounded_.push_back(prims[i].get());
                            unboundedIndex_.push_back(std::uint32_t(i));
                        }
                valid[k + 1] += valid[k];
            }
            if (valid[blocks] != count) {
                parallelFor(blocks, [&](std::size_t k) {
                    Ref* dst = bufB.data.get() + valid[k];
                    for (std::size_t i = k * kBlock, e = std::min(count, i + kBlock); i < e; ++i)
                        if (ok[i]) *dst++ = bufA.data[i];
                });
                std::swap(bufA.data, bufB.data);
            }
            n = valid[blocks];
        }
        stats_.primitives = n;
        stats_.unbounded = unbounded_.size();
        if (n == 0) return;
        orderIndex_.resize(n);
        order_.resize(n);
        Builder b{options,
                  rootBox.area() > 0 ? rootBox.area() : 1.0,
                  {bufA.data.get(), bufB.data.get()},
                  orderIndex_.data(),
                  order_.data(),
                  prims.data(),
                  parallel,
                  wide && !options.fullBinary ? kinds : nullptr};
        const Task root{0, n, 0, 0, rootBox, rootCBox};
        build.resize(2 * n - 1); // not zeroed (NoInit): the gaps are never read
        Scratch sc(options.bins);
        TopTally top;
        Tally total;
        buildTop(b, root, build.data(), 0, sc, top);
        top.sumInto(total);
        buildNodes = total.nodes;
        stats_.leaves = total.leaves;
        stats_.maxDepth = total.maxDepth;
        stats_.sahCost = total.sahCost;
    };
    // The collapse runs in the build's arena too: its parallel parts use the same threads,
    // and its serial parts run beside them (Bvh::collapseInto).
    auto run = [&] {
        buildTree();
        if (options_.width != 2) {
            const auto t0 = std::chrono::steady_clock::now();
            collapseWide(build.data(), buildNodes);
            stats_.collapseSeconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
    };
    if (options.buildThreads > 1)
        tbb::task_arena(options.buildThreads).execute(run);
    else
        run();
    // Flatten: one Node per inner build node, holding its children's boxes, numbered in
    // depth-first order (the order of the build array's places; its gaps are skipped by
    // following the links, not scanned).
    stats_.nodes = int(buildNodes);
    if (buildNodes == 1) {
        rootLeafCount_ = build[0].count;
    } else if (buildNodes > 1 && options_.width == 2) {
        // Inner nodes numbered in depth-first order as they are reached; each inner child
        // is linked from its parent's slot when its own number is known.
        struct Open {
            std::uint32_t build, parent, slot;
        };
        nodes_.reserve(buildNodes / 2 + 1);
        std::vector<Open> stack{{0, 0, 0}};
        while (!stack.empty()) {
            const Open o = stack.back();
            stack.pop_back();
            const auto k = std::uint32_t(nodes_.size());
            if (o.build != 0) nodes_[o.parent].child[o.slot] = k;
            nodes_.emplace_back();
            Node& w = nodes_[k];
            const std::uint32_t kids[2] = {o.build + 1, build[o.build].offset};
            for (int c = 0; c < 2; ++c) {
                const BuildNode& kn = build[kids[c]];
                for (int a = 0; a < 3; ++a) {
                    w.lo[a][c] = kn.lo[a];
                    w.hi[a][c] = kn.hi[a];
                }
                w.count[c] = kn.count;
                w.child[c] = kn.count ? kn.offset : 0; // inner: set when it is numbered
            }
            for (int c = 1; c >= 0; --c) // the left child is numbered first
                if (build[kids[c]].count == 0) stack.push_back({kids[c], k, std::uint32_t(c)});
        }
    }
    if (buildNodes > 0)
        for (int a = 0; a < 3; ++a) {
            rootLo_[a] = build[0].lo[a];
            rootHi_[a] = build[0].hi[a];
        }
    if (options_.floatBoxes) {
        fnodes_.resize(nodes_.size());
        for (std::size_t i = 0; i < nodes_.size(); ++i)
            for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 2; ++c) {
                    fnodes_[i].lo[a][c] = floatDown(nodes_[i].lo[a][c]);
                    fnodes_[i].hi[a][c] = floatUp(nodes_[i].hi[a][c]);
                    fnodes_[i].child[c] = nodes_[i].child[c];
                    fnodes_[i].count[c] = nodes_[i].count[c];
                }
    }
    if (stats_.maxDepth >= kMaxDepth)
        throw std::logic_error("Bvh: tree deeper than the traversal stack"); // cannot happen
    stats_.buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Visit>
void Bvh::traverse(const Ray& ray, double tMin, double& tMax, Visit&& visit) const {
    if (stats_.primitives == 0) return;
    const glm::dvec3 o = ray.origin;
    const glm::dvec3 inv = 1.0 / ray.direction;
    const int neg[3] = {std::signbit(inv.x), std::signbit(inv.y), std::signbit(inv.z)};
    constexpr double inf = std::numeric_limits<double>::infinity();
    // The root box (scalar). NaN (0·inf for a ray in a slab's plane) compares false:
    // that slab is not a limit. Its far end is tMax widened as the nodes' (limit() below):
    // a hit on the root box's face at t == tMax has a rounded entry distance up to γ(3)
    // past tMax, and was lost here when the segment ended at the hit (a feeler to a point
    // on the box, the tests' tMax = hit.t).
    {
        double t0 = tMin, t1 = tMax * kFarScale;
        for (int a = 0; a < 3; ++a) {
            const double near = ((neg[a] ? rootHi_[a] : rootLo_[a]) - o[a]) * inv[a];
            const double far = ((neg[a] ? rootLo_[a] : rootHi_[a]) - o[a]) * inv[a] * kFarScale;
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
        }
        if (!(t0 <= t1)) return;
    }
    auto visitLeaf = [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t i = first, e = first + count; i < e; ++i)
            if (!visit(*order_[i], tMax)) return false;
        return true;
    };
    if (rootLeafCount_ > 0) {
        visitLeaf(0, rootLeafCount_);
        return;
    }
    const bool useFloat = options_.floatBoxes;
    const __m128d ox = _mm_set1_pd(o.x), oy = _mm_set1_pd(o.y), oz = _mm_set1_pd(o.z);
    const __m128d ix = _mm_set1_pd(inv.x), iy = _mm_set1_pd(inv.y), iz = _mm_set1_pd(inv.z);
    const __m128d farScale = _mm_set1_pd(kFarScale);
    // Float path: the origin rounded to float is off by up to |o|·2^-24 per axis, so
    // every box is widened by |o|max·2^-22; the slab distances carry 3 roundings
    // (covered by kFarScaleF). Boxes are already rounded outward.
    const glm::vec3 fo(o), finv(inv);
    const float eps =
        float(std::max(std::abs(o.x), std::max(std::abs(o.y), std::abs(o.z)))) * 0x1p-22f;
    const __m128 fox = _mm_set1_ps(fo.x), foy = _mm_set1_ps(fo.y), foz = _mm_set1_ps(fo.z);
    const __m128 fix = _mm_set1_ps(finv.x), fiy = _mm_set1_ps(finv.y), fiz = _mm_set1_ps(finv.z);
    const __m128 epsV = _mm_set1_ps(eps), farScaleF = _mm_set1_ps(kFarScaleF);
    // The current nearest hit, widened so a box entered exactly there (a flat box, a
    // primitive touching its box) is not lost to the rounding of its entry distance.
    auto limit = [&]() { return tMax * kFarScale; };
    // Entry distances of both children of node n (inf = missed within (tMin, tMax]).
    auto enter = [&](std::uint32_t n, double d[2]) {
        if (useFloat) {
            const FloatNode& b = fnodes_[n];
            auto pair = [](const float* p) {
                return _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(p)));
            };
            const double lim = limit();
            __m128 t0 = _mm_set1_ps(float(tMin) - std::abs(float(tMin)) * 0x1p-20f);
            __m128 t1 = _mm_set1_ps(lim > 3e38 ? std::numeric_limits<float>::infinity()
                                               : float(lim) * (1 + 0x1p-20f));
            const __m128 nx = _mm_sub_ps(pair(neg[0] ? b.hi[0] : b.lo[0]),
                                         neg[0] ? _mm_sub_ps(_mm_setzero_ps(), epsV) : epsV);
            const __m128 fx = _mm_add_ps(pair(neg[0] ? b.lo[0] : b.hi[0]),
                                         neg[0] ? _mm_sub_ps(_mm_setzero_ps(), epsV) : epsV);
            t0 = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(nx, fox), fix), t0);
            t1 = _mm_min_ps(_mm_mul_ps(_mm_mul_ps(_mm_sub_ps(fx, fox), fix), farScaleF), t1);
            const __m128 ny = _mm_sub_ps(pair(neg[1] ? b.hi[1] : b.lo[1]),
                                         neg[1] ? _mm_sub_ps(_mm_setzero_ps(), epsV) : epsV);
            const __m128 fy = _mm_add_ps(pair(neg[1] ? b.lo[1] : b.hi[1]),
                                         neg[1] ? _mm_sub_ps(_mm_setzero_ps(), epsV) : epsV);
            t0 = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(ny, foy), fiy), t0);
            t1 = _mm_min_ps(_mm_mul_ps(_mm_mul_ps(_mm_sub_ps(fy, foy), fiy), farScaleF), t1);
            const __m128 nz = _mm_sub_ps(pair(neg[2] ? b.hi[2] : b.lo[2]),
                                         neg[2] ? _mm_sub_ps(_mm_setzero_ps(), epsV) : epsV);
            const __m128 fz = _mm_add_ps(pair(neg[2] ? b.lo[2] : b.hi[2]),
                                         neg[2] ? _mm_sub_ps(_mm_setzero_ps(), epsV) : epsV);
            t0 = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(nz, foz), fiz), t0);
            t1 = _mm_min_ps(_mm_mul_ps(_mm_mul_ps(_mm_sub_ps(fz, foz), fiz), farScaleF), t1);
            const int hit = _mm_movemask_ps(_mm_cmple_ps(t0, t1));
            alignas(16) float t[4];
            _mm_store_ps(t, t0);
            d[0] = (hit & 1) ? double(t[0]) : inf;
            d[1] = (hit & 2) ? double(t[1]) : inf;
            return;
        }
        const Node& b = nodes_[n];
        // _mm_max_pd/_mm_min_pd return their second operand when the first is NaN:
        // a NaN slab distance leaves t0/t1 unchanged, as in the scalar test.
        __m128d t0 = _mm_set1_pd(tMin), t1 = _mm_set1_pd(limit());
        const __m128d nx = _mm_load_pd(neg[0] ? b.hi[0] : b.lo[0]);
        const __m128d fx = _mm_load_pd(neg[0] ? b.lo[0] : b.hi[0]);
        t0 = _mm_max_pd(_mm_mul_pd(_mm_sub_pd(nx, ox), ix), t0);
        t1 = _mm_min_pd(_mm_mul_pd(_mm_mul_pd(_mm_sub_pd(fx, ox), ix), farScale), t1);
        const __m128d ny = _mm_load_pd(neg[1] ? b.hi[1] : b.lo[1]);
        const __m128d fy = _mm_load_pd(neg[1] ? b.lo[1] : b.hi[1]);
        t0 = _mm_max_pd(_mm_mul_pd(_mm_sub_pd(ny, oy), iy), t0);
        t1 = _mm_min_pd(_mm_mul_pd(_mm_mul_pd(_mm_sub_pd(fy, oy), iy), farScale), t1);
        const __m128d nz = _mm_load_pd(neg[2] ? b.hi[2] : b.lo[2]);
        const __m128d fz = _mm_load_pd(neg[2] ? b.lo[2] : b.hi[2]);
        t0 = _mm_max_pd(_mm_mul_pd(_mm_sub_pd(nz, oz), iz), t0);
        t1 = _mm_min_pd(_mm_mul_pd(_mm_mul_pd(_mm_sub_pd(fz, oz), iz), farScale), t1);
        const int hit = _mm_movemask_pd(_mm_cmple_pd(t0, t1));
        alignas(16) double t[2];
        _mm_store_pd(t, t0);
        d[0] = (hit & 1) ? t[0] : inf;
        d[1] = (hit & 2) ? t[1] : inf;
    };
    struct Entry {
        std::uint32_t ref;   // node index, or first primitive of a leaf
        std::uint32_t count; // 0: node; > 0: leaf
        double t;            // entry distance: skipped once a nearer hit is known
    };
    std::array<Entry, kMaxDepth> stack;
    int sp = 0;
    std::uint32_t cur = 0;
    while (true) {
        const std::uint32_t* kids = useFloat ? fnodes_[cur].child : nodes_[cur].child;
        const std::uint16_t* counts = useFloat ? fnodes_[cur].count : nodes_[cur].count;
        double d[2];
        enter(cur, d);
        int first = d[1] < d[0] ? 1 : 0; // nearer child first
        bool descended = false;
        for (int k = 0; k < 2; ++k) {
            const int c = k == 0 ? first : 1 - first;
            if (d[c] == inf) continue;
            if (k == 0 && d[1 - c] != inf) {
                // Both hit: keep the farther for later, go on with the nearer.
                const int f = 1 - c;
                stack[size_t(sp++)] = {kids[f], counts[f], d[f]};
            }
            if (counts[c] > 0) {
                if (!visitLeaf(kids[c], counts[c])) return;
            } else {
                cur = kids[c];
                descended = true;
            }
            break;
        }
        if (descended) continue;
        // Next entry still nearer than the nearest hit so far; leaves are visited here.
        while (true) {
            if (sp == 0) return;
            const Entry e = stack[size_t(--sp)];
            if (e.t > limit()) continue;
            if (e.count > 0) {
                if (!visitLeaf(e.ref, e.count)) return;
                continue;
            }
            cur = e.ref;
            break;
        }
    }
}

bool Bvh::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    if (options_.width != 2) return intersectWide(ray, tMin, tMax, hit);
    // The binary walk out of line (a lambda, so bvh.h stays as it is): the wide query is
    // then a jump, without the binary walk's register saves on every ray (issue 21).
    return [&]() __attribute__((noinline)) {
        bool found = false;
        for (const Primitive* p : unbounded_)
            if (p->intersect(ray, tMin, tMax, hit)) {
                tMax = hit.t;
                found = true;
            }
        traverse(ray, tMin, tMax, [&](const Primitive& p, double& tm) {
            if (p.intersect(ray, tMin, tm, hit)) {
                tm = hit.t; // only nearer hits from now on
                found = true;
            }
            return true;
        });
        return found;
    }
    ();
}

void Bvh::forEachHit(const Ray& ray, double tMin, double tMax,
                     const std::function<bool(const Hit&)>& visit) const {
    if (options_.width != 2) {
        forEachHitWide(ray, tMin, tMax, visit);
        return;
    }
    Hit h;
    for (const Primitive* p : unbounded_)
        if (p->intersect(ray, tMin, tMax, h) && !visit(h)) return;
    traverse(ray, tMin, tMax, [&](const Primitive& p, double&) {
        return !(p.intersect(ray, tMin, tMax, h) && !visit(h));
    });
}

void Bvh::forEachBlocker(const Ray& ray, double tMin, double tMax,
                         const std::function<bool(const Primitive&)>& visit,
                         const Primitive* skip) const {
    if (options_.width != 2) {
        forEachBlockerWide(ray, tMin, tMax, visit, skip);
        return;
    }
    for (const Primitive* p : unbounded_)
        if (p != skip && p->occluded(ray, tMin, tMax) && !visit(*p)) return;
    traverse(ray, tMin, tMax, [&](const Primitive& p, double&) {
        return &p == skip || !(p.occluded(ray, tMin, tMax) && !visit(p));
    });
}

bool Bvh::occluded(const Ray& ray, double tMin, double tMax, const Primitive* skip) const {
    if (options_.width != 2) return occludedWide(ray, tMin, tMax, skip);
    return [&]() __attribute__((noinline)) { // out of line, as in intersect
        for (const Primitive* p : unbounded_)
            if (p != skip && p->occluded(ray, tMin, tMax)) return true;
        bool any = false;
        traverse(ray, tMin, tMax, [&](const Primitive& p, double&) {
            any = &p != skip && p.occluded(ray, tMin, tMax);
            return !any;
        });
        return any;
    }
    ();
}

int Bvh::packetWidth() const {
    return options_.width != 2 && options_.packets && path_ ? path_->width : 1;
}

unsigned Bvh::intersectPacket(const Ray* rays, const double* tMin, const double* tMax, Hit* hits,
                              unsigned lanes) const {
    lanes &= (1u << kMaxPacket) - 1;
    const int w = packetWidth();
    if (w == 1) return Aggregate::intersectPacket(rays, tMin, tMax, hits, lanes);
    // The 8-wide paths: the whole packet in one call, no loop over its parts (issue 21: the
    // loop was ~45 instructions a packet, a ninth of what a packet missing the tree costs).
    if (w == kMaxPacket)
        return lanes ? path_->intersectPacket(*this, rays, tMin, tMax, hits, lanes) : 0;
    unsigned found = 0;
    for (int k = 0; k < kMaxPacket; k += w)
        if (const unsigned part = (lanes >> k) & ((1u << w) - 1))
            found |= path_->intersectPacket(*this, rays + k, tMin + k, tMax + k, hits + k, part)
                     << k;
    return found;
}

unsigned Bvh::occludedPacket(const Ray* rays, const double* tMin, const double* tMax,
                             const Primitive* const* skip, unsigned lanes) const {
    lanes &= (1u << kMaxPacket) - 1;
    const int w = packetWidth();
    unsigned blocked = 0;
    if (w == 1) {
        for (int j = 0; j < kMaxPacket; ++j)
            if ((lanes >> j) & 1)
                blocked |= unsigned(occluded(rays[j], tMin[j], tMax[j], skip ? skip[j] : nullptr))
                           << j;
        return blocked;
    }
    if (w == kMaxPacket) // as intersectPacket
        return lanes ? path_->occludedPacket(*this, rays, tMin, tMax, skip, lanes) : 0;
    for (int k = 0; k < kMaxPacket; k += w)
        if (const unsigned part = (lanes >> k) & ((1u << w) - 1))
            blocked |= path_->occludedPacket(*this, rays + k, tMin + k, tMax + k,
                                             skip ? skip + k : nullptr, part)
                       << k;
    return blocked;
}

std::unique_ptr<Bvh> makeAggregate(const Scene& scene, std::size_t crossover, BvhOptions options) {
    if (scene.primitives.size() < crossover) return nullptr;
    return std::make_unique<Bvh>(scene.primitives, options);
}

} // namespace wb::rt
