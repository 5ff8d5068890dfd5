#pragma once
// Bounding volume hierarchy over every primitive kind of a scene (spheres, quadrics,
// cones, triangles, polyhedra share one tree), built with the binned surface area
// heuristic as a binary tree and, by default, collapsed into a wide tree whose nodes
// hold their children's boxes in float, structure of arrays, so one SIMD operation
// tests a slab of all of them: 8 children with AVX2 where the CPU has it (chosen at run
// time), 4 with SSE2 (the portable baseline); width 2 keeps the binary tree of double
// boxes (the reference the tests compare against). The nearest hit is found front to
// back (nearest child first, stopping at tMax = nearest hit so far); occluded,
// forEachHit and forEachBlocker walk in any order and stop as soon as the visitor says
// so (the any-hit early exit of shadow feelers). Leaves keep runs of one kind side by
// side in float — spheres (centres, radii), triangles (vertices), the other kinds
// (their boxes) — and reject four at a time with conservative float tests; every
// candidate is decided by the primitive's own exact double code, so hits are bit for
// bit those of the plain loop (on equal t the primitive later in the scene wins, as in
// the plain loop). Unbounded primitives (infinite planes, uncut quadrics) are kept
// outside the tree and tested for every ray. Issue 21: shadow queries never ask the flat
// primitive the feeler leaves (`skip`); coherent rays (a camera's row of pixels, a hemicube
// face's) walk the tree as packets of 8 (AVX2/AVX-512) or 4 (SSE2) with the same answers;
// an AVX-512 (F + VL) 8-wide walk is chosen where the CPU has it.
#include "core/raytrace/scene.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace wb::rt {

namespace bvh_detail {
void* bigAlloc(std::size_t bytes); // bvh.cpp: kept mappings from 2 MiB, malloc below
void bigFree(void* p, std::size_t bytes) noexcept;
// Issue 21: the leaf arrays in bigAlloc memory. Through malloc, a million triangles' 14
// arrays (56 MB) were faulted and zeroed by the kernel again whenever glibc had given
// their pages back (20,304 faults, 30 ms of system time in a one-thread build; which
// build paid changed from run to run); a freed Bvh's arrays are now kept for the next.
template <class T> struct KeptAlloc {
    using value_type = T;
    KeptAlloc() = default;
    template <class U> KeptAlloc(const KeptAlloc<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(bigAlloc(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { bigFree(p, n * sizeof(T)); }
    // resize(n) leaves new elements default-initialised (not zeroed): the build writes every
    // element of order_ and orderIndex_ (one leaf each), and the arrays filled with a value
    // use assign. Issue 21 (tenth session): zeroing them was the serial start of the binary
    // tree (balls 5: ~50 us, and in a process's first builds ~500-1,800 page faults taken by
    // the main thread alone while the worker waited); now the leaves' first writes fault,
    // spread over the build's threads.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... A> void construct(U* p, A&&... a) {
        ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
    template <class U> bool operator==(const KeptAlloc<U>&) const noexcept { return true; }
    template <class U> bool operator!=(const KeptAlloc<U>&) const noexcept { return false; }
};
template <class T> using KeptVector = std::vector<T, KeptAlloc<T>>;
} // namespace bvh_detail

// Which SIMD instructions the wide traversal uses (BvhOptions::simd).
enum class BvhSimd {
    Auto, // AVX-512 (F + VL), else AVX2, where the CPU has it (checked at run time), else SSE2
    Sse2, // the portable x86-64 baseline
    Avx2, // AVX2 (falls back to SSE2 on a CPU without it; stats().avx2 says which ran)
    // AVX-512 F + VL: 8-wide nodes, compares into mask registers (issue 21); falls back to
    // AVX2, then SSE2 (stats().avx512 says whether it ran). Auto picks it where the CPU has
    // it (measured faster than AVX2 8-wide, docs/raytrace-scale.md).
    Avx512,
};

enum class BvhNodes { Auto, Float, Quantised };

struct BvhOptions {
    int bins = 16;                 // SAH bins per axis (binned build, Wald 2007); 2..256
    int maxLeafSize = 4;           // a node with at most this many primitives may become a leaf
    double traversalCost = 1.0;    // SAH cost of visiting a node, relative to...
    double intersectionCost = 1.0; // ...one primitive test
    bool floatBoxes = false; // width 2 only: traverse float binary nodes (conservative, same hits)
    // 0: automatic (the default: 8 with AVX2, 4 otherwise — the faster one measured,
    // docs/raytrace-scale.md; the environment variable WB_BVH_PATH = sse4, avx4, avx8 or avx512
    // overrides it when width and simd are both automatic; any other value is ignored with
    // a message on stderr); 4 or 8: wide float nodes
    // (8 needs AVX2, else 4); 2: binary double nodes (the reference the tests use).
    int width = 0;
    BvhSimd simd = BvhSimd::Auto; // instructions of the wide traversal
    int buildThreads = 0; // build threads: 0 = TBB's current arena, 1 = sequential, n = arena of n
    // intersectPacket/occludedPacket share one walk per packet (issue 21); false: they
    // trace the rays one by one (the single-ray reference the bench and tests force).
    bool packets = true;
    // Wide trees: the binary build stops at the subtrees the collapse makes one wide leaf
    // (at most 4 primitives, 8 spheres; issue 21) — the same wide tree, built faster. true:
    // split every node down to the SAH's leaves first, as before (the reference the tests
    // compare the wide trees against). Width 2 always builds the whole binary tree.
    bool fullBinary = false;
    // Node layout of the 8-wide tree (issue 21): Float (each child box as 6 floats, 256
    // bytes a node), Quantised (each child box as 8-bit offsets in the node's own box,
    // rounded outward, 128 bytes a node) or Auto (docs/raytrace-scale.md says which kind
    // of scene gets which, and why). 4-wide trees stay float (quantised they would still
    // take two cache lines). A tree whose boxes float cannot quantise stays float.
    BvhNodes nodes = BvhNodes::Auto;
};

struct BvhStats {
    int nodes = 0;                // in the flattened array
    int leaves = 0;               // leaf nodes
    int maxDepth = 0;             // longest root-to-leaf path
    std::size_t primitives = 0;   // bounded primitives in the tree
    std::size_t unbounded = 0;    // primitives outside the tree (tested for every ray)
    double buildSeconds = 0.0;    // wall time of the build
    double sahCost = 0.0;         // SAH cost of the tree (root area normalised)
    int wideNodes = 0;            // nodes of the wide tree (width 4 or 8), else 0
    double collapseSeconds = 0.0; // of buildSeconds: collapsing into the wide tree
    int width = 2;                // the tree traversed: 2 (binary), 4 or 8
    bool avx2 = false;            // the wide traversal runs AVX2 (or AVX-512) code, else SSE2
    bool avx512 = false;          // ... the AVX-512 code (BvhSimd::Avx512)
    bool quantised = false;       // 8-wide nodes with quantised child boxes (BvhNodes)
    std::size_t nodeBytes = 0;    // bytes of the wide nodes traversed
};

class Bvh : public Aggregate {
  public:
    // Builds over `prims` (kept by reference: the vector must outlive the BVH and not
    // change). Primitives with unbounded, empty or non-finite boxes stay outside the
    // tree and are tested for every ray, as BruteForce would. Throws
    // std::invalid_argument for bad options.
    explicit Bvh(const std::vector<std::unique_ptr<Primitive>>& prims, BvhOptions options = {});

    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    void forEachHit(const Ray& ray, double tMin, double tMax,
                    const std::function<bool(const Hit&)>& visit) const override;
    void forEachBlocker(const Ray& ray, double tMin, double tMax,
                        const std::function<bool(const Primitive&)>& visit,
                        const Primitive* skip = nullptr) const override;
    // Any hit in (tMin, tMax] (shadow feeler for opaque scenes), never asking `skip` (a
    // flat primitive the feeler starts on: Aggregate::forEachBlocker).
    bool occluded(const Ray& ray, double tMin, double tMax, const Primitive* skip = nullptr) const;

    // Packets (issue 21): the rays of `lanes` (bit j: rays[j], j < kMaxPacket) that share
    // the walk's direction signs, have no zero direction component and fit the float walk
    // walk together, packetWidth() at a time (8 on the AVX2 8-wide path, else 4); the
    // others go one by one. Every answer is the single-ray query's, bit for bit (the same
    // float tests per ray, the same exact primitive code).
    unsigned intersectPacket(const Ray* rays, const double* tMin, const double* tMax, Hit* hits,
                             unsigned lanes) const override;
    // Bit j: occluded(rays[j], tMin[j], tMax[j], skip ? skip[j] : nullptr).
    unsigned occludedPacket(const Ray* rays, const double* tMin, const double* tMax,
                            const Primitive* const* skip, unsigned lanes) const override;
    bool hasOccludedPacket() const override { return true; }
    // Rays per shared walk: 8 or 4 (wide trees with packets), 1 (binary tree, or packets off).
    int packetWidth() const;

    const BvhStats& stats() const { return stats_; }
    const BvhOptions& options() const { return options_; }

    // The flattened tree: each node holds the boxes of its two children side by side
    // ([axis][child], so one SSE2 operation tests both) and how to reach them.
    struct alignas(16) Node {
        double lo[3][2], hi[3][2]; // children's boxes (rounded outward from the build's floats)
        std::uint32_t child[2];    // inner child: node index; leaf child: first index into order_
        std::uint16_t count[2];    // 0: inner child; > 0: leaf child with this many primitives
    };
    // The same tree in float (floatBoxes): boxes rounded outward, and the links, in one
    // 64-byte cache line (the double nodes take 104 bytes).
    struct alignas(64) FloatNode {
        float lo[3][2], hi[3][2];
        std::uint32_t child[2];
        std::uint16_t count[2];
    };

    // The wide trees: W children's boxes as [axis][child] floats rounded outward (an
    // empty slot has lo = +inf, hi = −inf, which no ray enters), then the links; W = 4
    // fills two cache lines, W = 8 four.
    template <int W> struct alignas(64) WideNodeT {
        float lo[3][W], hi[3][W];
        std::uint32_t child[W]; // inner child: wide node index; leaf: first index into order_
        std::uint16_t count[W]; // 0: inner child or empty slot; > 0: leaf with this many
    };
    using WideNode = WideNodeT<4>;
    using WideNode8 = WideNodeT<8>;
    // An 8-wide node with quantised child boxes: child c's box on axis a is
    // [org[a] + qlo·scale[a], org[a] + qhi·scale[a]] with qlo = q[a][c], qhi = q[3 + a][c],
    // each product and sum rounded to float as written (scale a power of two, so the
    // product is exact); rounded outward, so it holds the child's float box. 128 bytes.
    struct alignas(64) QuantNode8 {
        float org[3], scale[3];
        std::uint8_t q[6][8];
        std::uint32_t child[8];
        std::uint16_t count[8];
        std::uint8_t valid; // bit c: slot c holds a child (empty slots are never entered)
    };
    // The wide nodes of the tree traversed (empty for width 2, for the other width and
    // for a tree of one leaf): the tests aim rays at their boxes' corners, edges and faces.
    const bvh_detail::KeptVector<WideNode>& wideNodes() const { return wnodes_; }
    const bvh_detail::KeptVector<WideNode8>& wideNodes8() const { return wnodes8_; }
    // The quantised nodes (empty unless BvhStats::quantised), and the same nodes with
    // their boxes decoded as the walk decodes them (for the tests: rays at their corners).
    const std::vector<QuantNode8>& quantNodes8() const { return qnodes8_; }
    std::vector<WideNode8> decodedQuantNodes8() const;

  private:
    template <class Visit>
    void traverse(const Ray& ray, double tMin, double& tMax, Visit&& visit) const;
    // Wide trees: the collapse (bvh_wide.cpp), the walk templated on the SIMD lanes
    // (bvh_wide_impl.h, compiled for SSE2 in bvh_wide.cpp and for AVX2 in
    // bvh_wide_avx2.cpp), entered through the path chosen at build time.
    // The entry points of one SIMD path and width (bvh_wide_impl.h fills them in).
    struct WidePath {
        int width; // 4 or 8 children per node
        bool avx2; // compiled for AVX2 (bvh_wide_avx2.cpp), else SSE2 (bvh_wide.cpp)
        bool (*intersect)(const Bvh&, const Ray&, double, double, Hit&);
        bool (*occluded)(const Bvh&, const Ray&, double, double, const Primitive*);
        void (*forEachHit)(const Bvh&, const Ray&, double, double,
                           const std::function<bool(const Hit&)>&);
        void (*forEachBlocker)(const Bvh&, const Ray&, double, double,
                               const std::function<bool(const Primitive&)>&, const Primitive*);
        unsigned (*intersectPacket)(const Bvh&, const Ray*, const double*, const double*, Hit*,
                                    unsigned);
        unsigned (*occludedPacket)(const Bvh&, const Ray*, const double*, const double*,
                                   const Primitive* const*, unsigned);
        // The same path for a tree of triangles only (triOnly_): its single-ray entries
        // skip the leaves' kind dispatch. Null in that path itself.
        const WidePath* tri;
    };
    template <class Lanes, bool Quantised = false> struct WideWalk;
    static const WidePath* ssePath(int width);  // bvh_wide.cpp: width 4 only
    // bvh_wide_avx2.cpp: width 4 or 8 (quantised: 8 only)
    static const WidePath* avx2Path(int width, bool quantised);
    static const WidePath* avx512Path(bool quantised); // bvh_wide_avx512.cpp: width 8
    bool quantiseNodes(); // wnodes8_ into qnodes8_; false (nothing changed) if a box cannot be
    void collapseWide(const void* buildNodes, std::size_t count);
    // besideTasks and besideAppend: the caller's work run beside the collapse's parallel
    // tasks and beside their serial append (bvh_wide.cpp).
    template <int W>
    void collapseInto(const void* buildNodes, bvh_detail::KeptVector<WideNodeT<W>>& out,
                      const std::function<void()>& besideTasks,
                      const std::function<void()>& besideAppend);
    void sortLeaf(std::uint32_t first, std::uint32_t count);
    void fillLeafData(std::uint32_t i);
    // Inline: one indirect call from the query to the walk (a cheap ray's cost counts).
    bool intersectWide(const Ray& ray, double tMin, double tMax, Hit& hit) const {
        return path_->intersect(*this, ray, tMin, tMax, hit);
    }
    void forEachHitWide(const Ray& ray, double tMin, double tMax,
                        const std::function<bool(const Hit&)>& visit) const {
        path_->forEachHit(*this, ray, tMin, tMax, visit);
    }
    void forEachBlockerWide(const Ray& ray, double tMin, double tMax,
                            const std::function<bool(const Primitive&)>& visit,
                            const Primitive* skip) const {
        path_->forEachBlocker(*this, ray, tMin, tMax, visit, skip);
    }
    bool occludedWide(const Ray& ray, double tMin, double tMax, const Primitive* skip) const {
        return path_->occluded(*this, ray, tMin, tMax, skip);
    }

    BvhOptions options_;
    std::vector<Node> nodes_;
    std::vector<FloatNode> fnodes_; // parallel to nodes_ when options_.floatBoxes
    double rootLo_[3] = {0, 0, 0}, rootHi_[3] = {0, 0, 0}; // box of the whole tree
    std::uint32_t rootLeafCount_ = 0;         // > 0: the whole tree is one leaf (no nodes_)
    // Wide trees: the union of the root node's float child boxes (lo x, y, z, hi x, y, z),
    // tested by the walk before a ray's lanes are set up (bvh_wide_impl.h, initRay).
    alignas(16) float rootF_[2][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}};
    // Issue 21: the per-primitive arrays (order_, orderIndex_, kind_, run_) in kept memory
    // too: malloc'd, a million triangles' 15 MB came back as fresh pages in every
    // two-thread build once the wide nodes no longer left a freed chunk for them (3,636
    // faults).
    bvh_detail::KeptVector<const Primitive*> order_; // primitives in leaf order
    std::vector<const Primitive*> unbounded_; // tested for every ray
    // Wide trees only:
    const WidePath* path_ = nullptr;            // the SIMD path and width traversed
    // Issue 21: kept memory (bvh_detail::KeptAlloc), as the leaf arrays: through malloc a
    // million triangles' 27 MB of nodes were faulted afresh by every build (6,633 faults).
    bvh_detail::KeptVector<WideNode> wnodes_;   // width 4
    bvh_detail::KeptVector<WideNode8> wnodes8_; // width 8
    std::vector<QuantNode8> qnodes8_;           // width 8, quantised (wnodes8_ then empty)
    bvh_detail::KeptVector<std::uint32_t> orderIndex_; // scene index of order_[i] (ties:
                                                       // later wins)
    std::vector<std::uint32_t> unboundedIndex_; // scene index of unbounded_[i]
    // Leaves are sorted into runs: spheres, then triangles, then the rest.
    // Of order_[i]: the exact code to call (bvh_wide.cpp kinds).
    bvh_detail::KeptVector<std::uint8_t> kind_;
    std::vector<std::uint8_t> sceneKind_; // the build's kinds per scene index, until collapsed
    // At the first of a run of one float test: its length.
    bvh_detail::KeptVector<std::uint16_t> run_;
    // Every primitive a (plain or smooth) triangle: path_ is its path's `tri`, whose
    // float-only single walks skip the leaves' kind dispatch (bvh_wide_impl.h, visitLeaf's kTri).
    bool triOnly_ = false;
    using Floats = bvh_detail::KeptVector<float>;
    Floats sx_, sy_, sz_, sr_, sm_; // spheres at their order_ index: float centre,
                                    // radius, their part of the float test's margin
    // Triangles at their order_ index (issue 21: the filter on precomputed edges): float
    // v0, v0 − v1, v2 − v0 and the normal (axis-major), the filter bound's two parts.
    Floats tv_[3], te_[9], tp_[2];
    Floats ob_[6]; // the other kinds at their order_ index: float box lo xyz, hi xyz
    BvhStats stats_;
};

// Below this many primitives the plain loop over objects is at least as fast as the
// BVH: raytrace_scale_bench measured the BVH as fast at 1 and faster from 2 on
// (docs/bench/raytrace.md).
constexpr std::size_t kBvhCrossover = 2;

// The aggregate a scene should use: a Bvh when it has at least `crossover`
// primitives, nullptr (the scene's own brute-force loop) otherwise. Install it with
// scene.setAggregate(result.get()); keep it alive while the scene is traced.
std::unique_ptr<Bvh> makeAggregate(const Scene& scene, std::size_t crossover = kBvhCrossover,
                                   BvhOptions options = {});

} // namespace wb::rt
