#include "core/raytrace/bvh.h"

#include "bvh_internal.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <emmintrin.h>
#include <limits>
#include <memory>
#include <stdexcept>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#include <utility>
#include <xmmintrin.h>

namespace wb::rt {

using namespace bvh_detail;

namespace {

// A primitive's box in float, rounded outward: the build works in float (half the
// memory traffic of double); node boxes are unions of these, so they still enclose
// every primitive exactly.
struct Ref {
    float lo[3], hi[3];
    std::uint32_t prim;
    // Halves first: lo + hi overflows to inf for boxes near float's range.
    float centre(int a) const { return 0.5f * lo[a] + 0.5f * hi[a]; }
};

struct FBox {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};
    void extend(const float* l, const float* h) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = l[a] < lo[a] ? l[a] : lo[a];
            hi[a] = h[a] > hi[a] ? h[a] : hi[a];
        }
    }
    void extend(const FBox& b) { extend(b.lo, b.hi); }
    void extendPoint(float x, float y, float z) {
        const float p[3] = {x, y, z};
        extend(p, p);
    }
    double area() const {
        const double dx = double(hi[0]) - lo[0], dy = double(hi[1]) - lo[1],
                     dz = double(hi[2]) - lo[2];
        return 2 * (dx * dy + dy * dz + dz * dx);
    }
};

// Bin of a centroid: clamped in float before the conversion (a huge or NaN product
// converted to int is undefined behaviour; found by fuzz_nff).
inline int binOf(float centre, float lo, float scale, int nb) {
    float f = (centre - lo) * scale;
    if (!(f >= 0)) f = 0;
    if (f > float(nb - 1)) f = float(nb - 1);
    return int(f);
}

// Beyond this depth the builder splits at the object median, so the tree depth stays
// below kMaxDepth = kMedianDepth + log2(any input size) + slack.
constexpr int kMedianDepth = 80;
constexpr std::size_t kMaxLeaf = 65535; // Node::count is 16 bits

// 1. One node's decision: a leaf, or a binned SAH split (object median below
//    kMedianDepth and for coincident centroids) with the refs partitioned and the
//    children's bounds computed in one pass.
struct Task {
    std::size_t begin, end;
    int depth;
    FBox box, cbox; // bounds of the boxes and of the centroids
};
struct Scratch {
    std::vector<FBox> binBox;
    std::vector<std::uint32_t> binCount;
    std::vector<double> rightArea;
    std::vector<std::size_t> rightCount;
    explicit Scratch(int maxBins)
        : binBox(size_t(3 * maxBins)), binCount(size_t(3 * maxBins)), rightArea(size_t(maxBins)),
          rightCount(size_t(maxBins)) {}
};
struct Decision {
    bool leaf = false;
    double leafCost = 0;
    int axis = 0;
    Task left{}, right{};
};

Decision decide(std::vector<Ref>& refs, const Task& task, const BvhOptions& options, Scratch& sc) {
    Decision d;
    const std::size_t n = task.end - task.begin;
    const double parentArea = task.box.area() > 0 ? task.box.area() : 1e-300;
    // Small nodes need few bins (n + 1 separate n distinct centroids well enough);
    // clearing and sweeping 16 bins for 2 primitives would dominate the build.
    const int nb = int(std::min<std::size_t>(std::size_t(options.bins), n + 1));
    int bestAxis = -1, bestBin = 0;
    double bestCost = std::numeric_limits<double>::infinity();
    float scale[3], clo[3];
    for (int a = 0; a < 3; ++a) {
        clo[a] = task.cbox.lo[a];
        const float ext = task.cbox.hi[a] - task.cbox.lo[a];
        // Slightly under nb/ext so the largest centroid falls in bin nb−1.
        scale[a] = ext > 0 ? float(nb) * (1 - 1e-6f) / ext : 0.0f;
    }
    const bool binnable = scale[0] > 0 || scale[1] > 0 || scale[2] > 0;
    if (n > 1 && binnable && task.depth < kMedianDepth) {
        std::fill(sc.binBox.begin(), sc.binBox.begin() + 3 * nb, FBox{});
        std::fill(sc.binCount.begin(), sc.binCount.begin() + 3 * nb, 0u);
        for (std::size_t i = task.begin; i < task.end; ++i) {
            const Ref& r = refs[i];
            for (int a = 0; a < 3; ++a) {
                const int b = binOf(r.centre(a), clo[a], scale[a], nb);
                sc.binBox[size_t(a * nb + b)].extend(r.lo, r.hi);
                ++sc.binCount[size_t(a * nb + b)];
            }
        }
        for (int a = 0; a < 3; ++a) {
            if (scale[a] == 0) continue;
            FBox acc;
            std::size_t cnt = 0;
            for (int b = nb - 1; b > 0; --b) {
                acc.extend(sc.binBox[size_t(a * nb + b)]);
                cnt += sc.binCount[size_t(a * nb + b)];
                sc.rightArea[size_t(b)] = cnt ? acc.area() : 0.0;
                sc.rightCount[size_t(b)] = cnt;
            }
            FBox left;
            std::size_t lc = 0;
            for (int b = 1; b < nb; ++b) {
                left.extend(sc.binBox[size_t(a * nb + b - 1)]);
                lc += sc.binCount[size_t(a * nb + b - 1)];
                const std::size_t rc = sc.rightCount[size_t(b)];
                if (lc == 0 || rc == 0) continue;
                const double cost = double(lc) * left.area() + double(rc) * sc.rightArea[size_t(b)];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = a;
                    bestBin = b;
                }
            }
        }
    }
    d.leafCost = options.intersectionCost * double(n);
    const double splitCost =
        bestAxis < 0 ? std::numeric_limits<double>::infinity()
                     : options.traversalCost + options.intersectionCost * bestCost / parentArea;
    const bool canSah = bestAxis >= 0;
    const bool wantLeaf = n <= std::size_t(options.maxLeafSize) && d.leafCost <= splitCost;
    // Coincident centroids cannot be binned: a modest group becomes one leaf.
    const bool stuck = !canSah && task.depth < kMedianDepth && n <= 256;
    if (n <= kMaxLeaf && (n == 1 || wantLeaf || stuck)) {
        d.leaf = true;
        return d;
    }
    std::size_t mid;
    int axis;
    if (canSah) {
        axis = bestAxis;
        const float lo = clo[axis], sca = scale[axis];
        auto it = std::partition(
            refs.begin() + std::ptrdiff_t(task.begin), refs.begin() + std::ptrdiff_t(task.end),
            [&](const Ref& r) { return binOf(r.centre(axis), lo, sca, nb) < bestBin; });
        mid = std::size_t(it - refs.begin());
    } else {
        // Object median on the widest centroid axis (deep trees, coincident centroids).
        float best = -1;
        axis = 0;
        for (int a = 0; a < 3; ++a)
            if (task.cbox.hi[a] - task.cbox.lo[a] > best) {
                best = task.cbox.hi[a] - task.cbox.lo[a];
                axis = a;
            }
        mid = task.begin + n / 2;
        std::nth_element(
            refs.begin() + std::ptrdiff_t(task.begin), refs.begin() + std::ptrdiff_t(mid),
            refs.begin() + std::ptrdiff_t(task.end),
            [axis](const Ref& x, const Ref& y) { return x.centre(axis) < y.centre(axis); });
    }
    d.axis = axis;
    d.left = Task{task.begin, mid, task.depth + 1, {}, {}};
    d.right = Task{mid, task.end, task.depth + 1, {}, {}};
    for (std::size_t i = task.begin; i < task.end; ++i) {
        Task& t = i < mid ? d.left : d.right;
        t.box.extend(refs[i].lo, refs[i].hi);
        t.cbox.extendPoint(refs[i].centre(0), refs[i].centre(1), refs[i].centre(2));
    }
    return d;
}

BuildNode nodeOf(const Task& t) {
    BuildNode node;
    for (int a = 0; a < 3; ++a) {
        node.lo[a] = t.box.lo[a];
        node.hi[a] = t.box.hi[a];
    }
    node.offset = 0;
    node.count = 0;
    node.axis = 0;
    return node;
}

// 2. A subtree built by one thread, depth first (left child right after its parent),
//    with offsets local to its own node and primitive arrays.
struct Sequential {
    std::vector<BuildNode> nodes;
    std::vector<std::uint32_t> prims; // scene indices in leaf order
    int leaves = 0, maxDepth = 0;
    double sahCost = 0;
};

void buildSequential(std::vector<Ref>& refs, const Task& root, const BvhOptions& options,
                     double rootArea, Sequential& out) {
    Scratch sc(options.bins);
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::pair<Task, std::uint32_t>> stack{{root, kNone}}; // task, parent to link
    while (!stack.empty()) {
        const auto [task, parent] = stack.back();
        stack.pop_back();
        const auto idx = std::uint32_t(out.nodes.size());
        if (parent != kNone) out.nodes[parent].offset = idx;
        BuildNode node = nodeOf(task);
        out.maxDepth = std::max(out.maxDepth, task.depth);
        const Decision d = decide(refs, task, options, sc);
        if (d.leaf) {
            node.offset = std::uint32_t(out.prims.size());
            node.count = std::uint16_t(task.end - task.begin);
            for (std::size_t i = task.begin; i < task.end; ++i)
                out.prims.push_back(refs[i].prim);
            out.nodes.push_back(node);
            ++out.leaves;
            out.sahCost += d.leafCost * task.box.area() / rootArea;
            continue;
        }
        node.axis = std::uint16_t(d.axis);
        out.nodes.push_back(node);
        out.sahCost += options.traversalCost * task.box.area() / rootArea;
        // Right first on the stack so the left child is built next, right after its parent.
        stack.push_back({d.right, idx});
        stack.push_back({d.left, kNone});
    }
}

// 3. The parallel build: nodes with many primitives are split here and their two
//    children built as parallel TBB tasks; smaller ones go to buildSequential. Every
//    decision is the sequential one, so the tree is the same for any thread count.
constexpr std::size_t kParallelGrain = 2048; // below this a subtree is one task
struct Subtree {
    bool split = false;
    BuildNode node{};                     // split: this node (offset set when emitted)
    std::unique_ptr<Subtree> left, right; // split: the children
    Sequential seq;                       // !split: built by one task
};

void buildParallel(std::vector<Ref>& refs, const Task& task, const BvhOptions& options,
                   double rootArea, Subtree& out) {
    if (task.end - task.begin <= kParallelGrain) {
        buildSequential(refs, task, options, rootArea, out.seq);
        return;
    }
    Scratch sc(options.bins);
    const Decision d = decide(refs, task, options, sc);
    if (d.leaf) { // a large group that cannot be split (coincident centroids)
        buildSequential(refs, task, options, rootArea, out.seq);
        return;
    }
    out.split = true;
    out.node = nodeOf(task);
    out.node.axis = std::uint16_t(d.axis);
    out.left = std::make_unique<Subtree>();
    out.right = std::make_unique<Subtree>();
    out.seq.maxDepth = task.depth;
    out.seq.sahCost = options.traversalCost * task.box.area() / rootArea;
    tbb::parallel_invoke([&] { buildParallel(refs, d.left, options, rootArea, *out.left); },
                         [&] { buildParallel(refs, d.right, options, rootArea, *out.right); });
}

// 4. The subtrees into one depth-first array, offsets made global.
void emitSubtree(const Subtree& t, std::vector<BuildNode>& nodes, std::vector<std::uint32_t>& prims,
                 BvhStats& stats) {
    stats.maxDepth = std::max(stats.maxDepth, t.seq.maxDepth);
    stats.sahCost += t.seq.sahCost;
    if (t.split) {
        const std::size_t idx = nodes.size();
        nodes.push_back(t.node);
        emitSubtree(*t.left, nodes, prims, stats);
        nodes[idx].offset = std::uint32_t(nodes.size());
        emitSubtree(*t.right, nodes, prims, stats);
        return;
    }
    const auto base = std::uint32_t(nodes.size()), pbase = std::uint32_t(prims.size());
    for (BuildNode n : t.seq.nodes) {
        n.offset += n.count ? pbase : base;
        nodes.push_back(n);
    }
    prims.insert(prims.end(), t.seq.prims.begin(), t.seq.prims.end());
    stats.leaves += t.seq.leaves;
}

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

    std::vector<Ref> refs;
    refs.reserve(prims.size());
    FBox rootBox, rootCBox;
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const Aabb b = prims[i]->bounds();
        const bool finite = std::isfinite(b.lo.x) && std::isfinite(b.lo.y) &&
                            std::isfinite(b.lo.z) && std::isfinite(b.hi.x) &&
                            std::isfinite(b.hi.y) && std::isfinite(b.hi.z);
        Ref r;
        for (int a = 0; a < 3; ++a) {
            r.lo[a] = floatDown(b.lo[a]);
            r.hi[a] = floatUp(b.hi[a]);
        }
        // Boxes beyond float's range (|x| > 3.4e38) are as good as unbounded here.
        const bool fits = std::isfinite(r.lo[0]) && std::isfinite(r.lo[1]) &&
                          std::isfinite(r.lo[2]) && std::isfinite(r.hi[0]) &&
                          std::isfinite(r.hi[1]) && std::isfinite(r.hi[2]);
        if (!finite || b.empty() || !b.bounded() || !fits) {
            unbounded_.push_back(prims[i].get());
            unboundedIndex_.push_back(std::uint32_t(i));
            continue;
        }
        r.prim = std::uint32_t(i);
        rootBox.extend(r.lo, r.hi);
        rootCBox.extendPoint(r.centre(0), r.centre(1), r.centre(2));
        refs.push_back(r);
    }
    std::vector<BuildNode> build;
    stats_.primitives = refs.size();
    stats_.unbounded = unbounded_.size();
    order_.reserve(refs.size());
    if (!refs.empty()) {
        const double rootArea = rootBox.area() > 0 ? rootBox.area() : 1.0;
        const Task root{0, refs.size(), 0, rootBox, rootCBox};
        Subtree top;
        auto run = [&] {
            if (options.buildThreads == 1)
                buildSequential(refs, root, options, rootArea, top.seq);
            else
                buildParallel(refs, root, options, rootArea, top);
        };
        if (options.buildThreads > 1)
            tbb::task_arena(options.buildThreads).execute(run);
        else
            run();
        build.reserve(2 * refs.size());
        std::vector<std::uint32_t> leafPrims;
        leafPrims.reserve(refs.size());
        emitSubtree(top, build, leafPrims, stats_);
        for (std::uint32_t i : leafPrims) {
            order_.push_back(prims[i].get());
            orderIndex_.push_back(i);
        }
    }
    // Flatten: one Node per inner build node, holding its children's boxes.
    stats_.nodes = int(build.size());
    if (build.size() == 1) {
        rootLeafCount_ = build[0].count;
    } else if (!build.empty() && options_.width == 2) {
        std::vector<std::uint32_t> wide(build.size(), 0);
        std::uint32_t next = 0;
        for (std::size_t i = 0; i < build.size(); ++i)
            if (build[i].count == 0) wide[i] = next++;
        nodes_.resize(next);
        for (std::size_t i = 0; i < build.size(); ++i) {
            if (build[i].count != 0) continue;
            Node& w = nodes_[wide[i]];
            const std::size_t kids[2] = {i + 1, build[i].offset};
            for (int c = 0; c < 2; ++c) {
                const BuildNode& k = build[kids[c]];
                for (int a = 0; a < 3; ++a) {
                    w.lo[a][c] = k.lo[a];
                    w.hi[a][c] = k.hi[a];
                }
                w.count[c] = k.count;
                w.child[c] = k.count ? k.offset : wide[kids[c]];
            }
        }
    }
    if (!build.empty())
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
    if (options_.width != 2) {
        const auto t0 = std::chrono::steady_clock::now();
        collapseWide(build.data(), build.size());
        stats_.collapseSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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
    // that slab is not a limit.
    {
        double t0 = tMin, t1 = tMax;
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
                         const std::function<bool(const Primitive&)>& visit) const {
    if (options_.width != 2) {
        forEachBlockerWide(ray, tMin, tMax, visit);
        return;
    }
    for (const Primitive* p : unbounded_)
        if (p->occluded(ray, tMin, tMax) && !visit(*p)) return;
    traverse(ray, tMin, tMax, [&](const Primitive& p, double&) {
        return !(p.occluded(ray, tMin, tMax) && !visit(p));
    });
}

bool Bvh::occluded(const Ray& ray, double tMin, double tMax) const {
    if (options_.width != 2) return occludedWide(ray, tMin, tMax);
    for (const Primitive* p : unbounded_)
        if (p->occluded(ray, tMin, tMax)) return true;
    bool any = false;
    traverse(ray, tMin, tMax, [&](const Primitive& p, double&) {
        any = p.occluded(ray, tMin, tMax);
        return !any;
    });
    return any;
}

std::unique_ptr<Bvh> makeAggregate(const Scene& scene, std::size_t crossover, BvhOptions options) {
    if (scene.primitives.size() < crossover) return nullptr;
    return std::make_unique<Bvh>(scene.primitives, options);
}

} // namespace wb::rt
