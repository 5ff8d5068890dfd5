// The wide BVH (BvhOptions::width 0, 4 or 8): collapse of the binned SAH binary tree
// into 4- or 8-wide nodes, the choice of the SIMD path at run time, and the SSE2 walk
// (the portable baseline; bvh_wide_avx2.cpp has the AVX2 one, bvh_wide_impl.h the walk
// both compile).
//
// 1. Collapse rather than a wide build of its own: the binary builder is tested and
//    fuzzed (degenerate centroids, float-range boxes, depth limit), and pulling up the
//    grandchild of largest surface area until a node has W children is how wide trees
//    are usually made from a binary SAH tree (Wald, Benthin, Boulos 2008; Embree's
//    BVH4/BVH8 builders open the largest child likewise), at the cost of one linear pass.
// 2. Leaves sorted into runs of one kind (spheres, triangles, the rest), with the float
//    data of their leaf tests side by side (bvh_wide_impl.h).
// 3. The path: AVX-512 (F + VL, 8-wide) where the CPU has it, else AVX2 8-wide
//    (__builtin_cpu_supports, which also checks that the OS saves the registers), else
//    SSE2; BvhOptions or WB_BVH_PATH force one.
#include "core/raytrace/bvh.h"

#include "bvh_internal.h"
#include "bvh_wide_impl.h" // the SSE2 walk (Lanes4<0>)
#include "bvh_wide_kinds.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace wb::rt {

using namespace bvh_detail;

const Bvh::WidePath* Bvh::ssePath(int) {
    return WideWalk<Lanes4<0>>::path(false);
}

namespace {

// The path the options ask for (see BvhOptions::width and simd).
struct PathChoice {
    int width; // 4 or 8
    bool avx2;
    bool avx512 = false; // AVX-512 F + VL, 8-wide (avx2 is then true as well)
};

PathChoice choosePath(const BvhOptions& o) {
    int width = o.width;
    BvhSimd simd = o.simd;
    if (width == 0 && simd == BvhSimd::Auto) {
        if (const char* env = std::getenv("WB_BVH_PATH"); env && *env) {
            const std::string v = env;
            if (v == "sse4")
                width = 4, simd = BvhSimd::Sse2;
            else if (v == "avx4")
                width = 4, simd = BvhSimd::Avx2;
            else if (v == "avx8")
                width = 8, simd = BvhSimd::Avx2;
            else if (v == "avx512")
                width = 8, simd = BvhSimd::Avx512;
            else {
                // An environment variable is no API argument: a wrong one must not end a
                // lab (it threw through lab 07 and lab 08's patch BVH). Said once, ignored.
                static std::once_flag said;
                std::call_once(said, [&] {
                    std::fprintf(
                        stderr,
                        "WB_BVH_PATH='%s' ignored: expected sse4, avx4, avx8 or avx512; using the "
                        "automatic choice\n",
                        v.c_str());
                });
            }
        }
    }
    const bool avx2 = simd != BvhSimd::Sse2 && __builtin_cpu_supports("avx2");
    // AVX-512 (F + VL), 8-wide: asked for, or automatic where the CPU has it (measured
    // faster than AVX2 8-wide in two runs, ours/Embree eye / shadow rays: balls 4 0.78 /
    // 1.15 against 0.74 / 1.10, mesh 0.77 / 0.87 against 0.74 / 0.84, jacks 4 equal;
    // docs/raytrace-scale.md, issue 21).
    const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
    if (avx512 && width != 4 && (simd == BvhSimd::Avx512 || (simd == BvhSimd::Auto && width == 0)))
        return {8, true, true};
    if (width == 0) width = avx2 ? kAutoWidthAvx2 : 4;
    if (!avx2) width = 4;
    return {width, avx2};
}

} // namespace

void Bvh::sortLeaf(std::uint32_t first, std::uint32_t cnt) {
    // Stable, by run: leaves are small, so insertion sort in place. Reads kind_ only.
    for (std::uint32_t k = first + 1; k < first + cnt; ++k) {
        std::uint32_t j = k;
        while (j > first && runOf(kind_[j - 1]) > runOf(kind_[j])) {
            std::swap(kind_[j - 1], kind_[j]);
            std::swap(order_[j - 1], order_[j]);
            std::swap(orderIndex_[j - 1], orderIndex_[j]);
            --j;
        }
    }
    for (std::uint32_t k = 0; k < cnt;) { // run lengths
        std::uint32_t e = k + 1;
        while (e < cnt && runOf(kind_[first + e]) == runOf(kind_[first + k]))
            ++e;
        run_[first + k] = std::uint16_t(e - k);
        k = e;
    }
}

// The leaves' float data of order_[i] (its kind's arrays). Kept apart from the run sort:
// run over i in order (below) it reads the primitives with prefetching, where the
// collapse's leaf order made every read a cache miss (sortLeaf was 10% of a build).
void Bvh::fillLeafData(std::uint32_t i) {
    if (kind_[i] == kSphere) {
        const auto* s = static_cast<const Sphere*>(order_[i]);
        sx_[i] = float(s->centre.x);
        sy_[i] = float(s->centre.y);
        sz_[i] = float(s->centre.z);
        sr_[i] = float(s->radius);
        sm_[i] = float(l1Norm(s->centre) + s->radius) * kSphereMargin;
    } else if (runOf(kind_[i]) == kRunTriangle) {
        const auto* t = static_cast<const Triangle*>(order_[i]);
        for (int a = 0; a < 3; ++a)
            tv_[a][i] = float(t->v0[a]);
        // The filter's edges, normal and bound parts (bvh_wide_kinds.h), in double
        // from the double vertices, rounded to float (the parts rounded up).
        const glm::dvec3 e1 = t->v1 - t->v0, e2 = t->v2 - t->v0, nn = glm::cross(e1, e2);
        const glm::dvec3 ne1 = -e1; // the filter reads −e1 (exactly negated): F2 = R·(−e1)
        const glm::dvec3* es[3] = {&ne1, &e2, &nn};
        for (int j = 0; j < 3; ++j)
            for (int a = 0; a < 3; ++a)
                te_[j * 3 + a][i] = float((*es[j])[a]);
        const double vmax = std::max({l1Norm(t->v0), l1Norm(t->v1), l1Norm(t->v2)});
        const double em = std::max(l1Norm(e1), l1Norm(e2));
        const double p1 = kMtEdgeMargin * em + 2 * kMtDoubleMargin * vmax;
        const double p2 = kMtEdgeMargin * em * vmax + kMtNormalMargin * l1Norm(nn) +
                          kMtDoubleMargin * vmax * vmax;
        const bool small = vmax <= kMtMaxCoord; // false for NaN
        tp_[0][i] = small ? floatUp(p1 * (1 + 0x1p-20)) : std::numeric_limits<float>::infinity();
        tp_[1][i] = small ? floatUp(p2 * (1 + 0x1p-20)) : std::numeric_limits<float>::infinity();
    } else {
        // Rounded outward; a box float cannot hold (or an empty one) is never rejected.
        const Aabb bx = order_[i]->bounds();
        for (int a = 0; a < 3; ++a) {
            ob_[a][i] = floatDown(bx.lo[a]);
            ob_[3 + a][i] = floatUp(bx.hi[a]);
            if (!(ob_[a][i] <= ob_[3 + a][i]) || !std::isfinite(ob_[a][i]) ||
                !std::isfinite(ob_[3 + a][i])) {
                ob_[a][i] = -std::numeric_limits<float>::infinity();
                ob_[3 + a][i] = std::numeric_limits<float>::infinity();
            }
        }
    }
}

template <int W>
void Bvh::collapseInto(const void* buildNodes, bvh_detail::KeptVector<WideNodeT<W>>& out,
                       const std::function<void()>& besideTasks,
                       const std::function<void()>& besideAppend) {
    const auto* build = static_cast<const BuildNode*>(buildNodes);
    auto area = [&](std::size_t i) {
        const glm::dvec3 e = build[i].hi - build[i].lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    };
    // Build nodes in the subtree of i, at most kSizeCap (BuildNode::size: the array has
    // gaps between the build's parallel subtrees, so the places no longer tell it).
    auto subtreeSize = [&](std::size_t i) { return std::size_t(build[i].size); };
    // An inner subtree of at most kMergePrims primitives becomes one leaf of the wide tree
    // (its leaves are contiguous in order_): the leaves' float tests take four primitives
    // at a time, so one leaf of four costs what one of one does, and the slots it frees
    // fill the nodes. Spheres (the cheapest float test) up to twice that: balls 4 eye rays
    // +2% (AVX2 8-wide, 5 alternated runs); for triangles 8 lost 5% on mesh shadow rays.
    // Returns its primitive count, or 0 if it is larger.
    constexpr std::uint32_t kMergePrims = 4;
    auto mergedCount = [&](std::size_t i) -> std::uint32_t {
        // At most 2·kMergePrims leaves, so at most that many inner nodes on either spine:
        // a longer spine is a larger subtree (the walk stays O(1) per child).
        std::size_t l = i, r = i;
        for (std::uint32_t d = 0; build[l].count == 0; ++d) {
            if (d >= 2 * kMergePrims) return 0;
            l = l + 1;
        }
        for (std::uint32_t d = 0; build[r].count == 0; ++d) {
            if (d >= 2 * kMergePrims) return 0;
            r = build[r].offset;
        }
        const std::uint32_t first = build[l].offset;
        const std::uint32_t n = build[r].offset + build[r].count - first;
        if (n <= kMergePrims) return n;
        if (n > 2 * kMergePrims) return 0;
        for (std::uint32_t k = first; k < first + n; ++k)
            if (kind_[k] != kSphere) return 0;
        return n;
    };
    auto isLeaf = [&](std::size_t i) { return build[i].count > 0 || mergedCount(i) > 0; };
    // 1. The top: subtrees of more than kTaskNodes build nodes are opened here; smaller
    //    ones become tasks, their wide child index a placeholder.
    // 2. The tasks, in parallel, each into its own array (indices local to it).
    // 3. Their arrays appended in task order, the placeholders and the tasks' inner links
    //    made global. The layout depends on the tree only, not on the threads (tested).
    constexpr std::size_t kTaskNodes = 4096;
    static_assert(2 * kTaskNodes < kSizeCap, "subtreeSize is compared with these uncapped");
    // A task's wide nodes, in the one buffer of all tasks (below).
    struct Span {
        WideNodeT<W>* data = nullptr;
        std::size_t n = 0;
        std::size_t size() const { return n; }
        void emplace_back() { ++n; } // the slot is written when the node is done
        WideNodeT<W>& operator[](std::size_t i) { return data[i]; }
    };
    struct Task {
        std::size_t buildIndex;    // root of the subtree
        Span nodes;                // its wide nodes, root first
        std::uint32_t owner, slot; // the top node and child slot pointing at it
    };
    std::vector<Task> tasks;
    // Collapses the subtree at bi into `into` depth first (a node's first inner child
    // tends to follow it in memory); with `top`, small inner subtrees become tasks.
    auto collapse = [&](auto&& self, auto& into, std::size_t bi, bool top) -> std::uint32_t {
        const auto idx = std::uint32_t(into.size());
        into.emplace_back();
        std::array<std::size_t, W> kids{};
        std::array<double, W> areas{}; // inner children's areas; −1 for leaves
        kids[0] = bi + 1;
        kids[1] = build[bi].offset;
        areas[0] = isLeaf(kids[0]) ? -1 : area(kids[0]);
        areas[1] = isLeaf(kids[1]) ? -1 : area(kids[1]);
        int nk = 2;
        while (nk < W) { // open the inner child of largest area
            int best = -1;
            double bestArea = -1;
            for (int k = 0; k < nk; ++k)
                if (areas[size_t(k)] > bestArea) {
                    bestArea = areas[size_t(k)];
                    best = k;
                }
            if (best < 0) break;
            const std::size_t open = kids[size_t(best)];
            kids[size_t(best)] = open + 1;
            kids[size_t(nk)] = build[open].offset;
            areas[size_t(best)] = isLeaf(open + 1) ? -1 : area(open + 1);
            areas[size_t(nk)] = isLeaf(build[open].offset) ? -1 : area(build[open].offset);
            ++nk;
        }
        WideNodeT<W> w;
        std::memset(&w, 0, sizeof w); // padding too: trees compare bytewise (tests)
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < W; ++c) {
                w.lo[a][c] = std::numeric_limits<float>::infinity();
                w.hi[a][c] = -std::numeric_limits<float>::infinity();
            }
        for (int c = 0; c < nk; ++c) {
            const std::size_t kb = kids[size_t(c)];
            const BuildNode& k = build[kb];
            for (int a = 0; a < 3; ++a) { // exact: the build's boxes are floats
                w.lo[a][c] = float(k.lo[a]);
                w.hi[a][c] = float(k.hi[a]);
            }
            if (k.count > 0) {
                w.child[c] = k.offset;
                w.count[c] = k.count;
                sortLeaf(k.offset, k.count);
            } else if (const std::uint32_t m = mergedCount(kb); m > 0) {
                std::size_t l = kb;
                while (build[l].count == 0)
                    l = l + 1;
                w.child[c] = build[l].offset;
                w.count[c] = std::uint16_t(m);
                sortLeaf(build[l].offset, m);
            } else if (top && subtreeSize(kb) <= kTaskNodes) {
                w.child[c] = 0; // the task's array, appended below
                tasks.push_back({kb, {}, idx, std::uint32_t(c)});
            } else {
                w.child[c] = self(self, into, kb, top);
            }
        }
        into[idx] = w;
        return idx;
    };
    // Small trees in one go: tasks would cost more than they share out.
    collapse(collapse, out, 0, subtreeSize(0) > 2 * kTaskNodes);
    // The tasks' nodes in one bigAlloc buffer, each task its room: a wide node per inner
    // build node at most, (size − 1) / 2 of a subtree. Issue 21: each task had a vector of
    // its own, malloc'd by whichever thread ran it; glibc gives a worker thread's freed
    // heap back to the kernel, so every two-thread build faulted and zeroed those pages
    // again (clear_page_erms 2.3-3.3% of a two-thread balls 5 build's samples once the
    // stitch no longer kept that heap in use). A kept mapping is not given back.
    std::size_t room = 0;
    for (Task& t : tasks) {
        t.nodes.n = room; // the task's first place, until it runs
        room += subtreeSize(t.buildIndex) / 2;
    }
    struct Buffer {
        std::size_t bytes;
        void* raw;
        ~Buffer() { bigFree(raw, bytes); }
    } buffer{room * sizeof(WideNodeT<W>) + 64, nullptr};
    buffer.raw = bigAlloc(buffer.bytes);
    auto* const first = reinterpret_cast<WideNodeT<W>*>(
        (reinterpret_cast<std::uintptr_t>(buffer.raw) + 63) / 64 * 64); // the nodes' alignment
    for (Task& t : tasks) {
        t.nodes.data = first + t.nodes.n;
        t.nodes.n = 0;
    }
    auto runTask = [&](std::size_t t) {
        collapse(collapse, tasks[t].nodes, tasks[t].buildIndex, false);
    };
    // Called inside the build's arena (Bvh::Bvh): parallelFor uses its threads.
    const bool threads = options_.buildThreads != 1;
    auto runTasks = [&] {
        if (!threads || tasks.size() < 2) {
            for (std::size_t t = 0; t < tasks.size(); ++t)
                runTask(t);
        } else {
            // Largest first (each task writes its own array, so the order they run in
            // changes nothing): the last task to start is a small one, and the two
            // threads finish together (tasks are up to kTaskNodes each, a sixth of balls
            // 5's collapse).
            std::vector<std::uint32_t> bySize(tasks.size());
            for (std::size_t t = 0; t < tasks.size(); ++t)
                bySize[t] = std::uint32_t(t);
            std::stable_sort(bySize.begin(), bySize.end(), [&](std::uint32_t a, std::uint32_t b) {
                return subtreeSize(tasks[a].buildIndex) > subtreeSize(tasks[b].buildIndex);
            });
            // Taken one at a time from the list by whichever thread is free (TBB's
            // parallel_for would hand each thread a half of the list).
            std::atomic<std::size_t> next{0};
            const auto workers = std::size_t(std::max(1, tbb::this_task_arena::max_concurrency()));
            parallelFor(std::min(workers, tasks.size()), [&](std::size_t) {
                for (std::size_t k = next++; k < tasks.size(); k = next++)
                    runTask(bySize[k]);
            });
        }
    };
    auto append = [&] {
        std::size_t total = out.size();
        for (const Task& t : tasks)
            total += t.nodes.size();
        out.reserve(total);
        for (Task& t : tasks) {
            const auto base = std::uint32_t(out.size());
            out[t.owner].child[t.slot] = base;
            for (std::size_t i = 0; i < t.nodes.size(); ++i) {
                WideNodeT<W>& w = t.nodes[i];
                for (int c = 0; c < W; ++c)
                    if (w.count[c] == 0 && w.lo[0][c] <= w.hi[0][c]) w.child[c] += base; // inner
                out.push_back(w);
            }
        }
    };
    // Issue 21: the caller's serial work beside the tasks and beside the append (one
    // thread each; the other takes the parallel side): with 2 threads these were the
    // build's serial part (1 M triangles: 16 ms of zeroing the leaf arrays and 20 ms of
    // appending 106,115 nodes, 8% of a one-thread build). The layout does not change.
    if (threads) {
        parallelInvoke(besideTasks, runTasks);
        parallelInvoke(append, besideAppend);
    } else {
        besideTasks();
        runTasks();
        append();
        besideAppend();
    }
}

void Bvh::collapseWide(const void* buildNodes, std::size_t count) {
    const PathChoice pc = choosePath(options_);
    path_ = pc.avx512 ? avx512Path(false) : pc.avx2 ? avx2Path(pc.width, false) : ssePath(pc.width);
    options_.width = pc.width;
    options_.simd = pc.avx512 ? BvhSimd::Avx512 : pc.avx2 ? BvhSimd::Avx2 : BvhSimd::Sse2;
    stats_.width = pc.width;
    stats_.avx2 = pc.avx2;
    stats_.avx512 = pc.avx512;
    const auto* build = static_cast<const BuildNode*>(buildNodes);
    // Leaves: runs of spheres, triangles, the rest (stable within a run).
    const std::size_t n = order_.size();
    kind_.assign(n, kOther);
    run_.assign(n, 0);
    // Per primitive in order_'s order, in blocks of the same size for any thread count
    // (parallel with the build's threads), each read of a primitive prefetched 16 ahead:
    // order_ is leaf order, so the objects are scattered in memory. Issue 21: blocks of
    // 4096 (were 16,384): balls 5's leaf data was 5 blocks beside the append, split 3/2
    // (with the append) between two threads; that step took 0.47 ms at two threads for 0.78
    // at one, 0.42 with these blocks (medians of 35 quiet pairs). Tenth session: 2048 (the
    // last block a thread takes is the step's tail): jacks 5's step 0.533 -> 0.523 ms at two
    // threads (three alternated pairs of 40 quiet builds each, lower in all three).
    auto perPrimitive = [&](auto&& f) {
        constexpr std::size_t kBlockPrims = 2048;
        const std::size_t blocks = (n + kBlockPrims - 1) / kBlockPrims;
        auto block = [&](std::size_t b) {
            const std::size_t lo = b * kBlockPrims, hi = std::min(n, lo + kBlockPrims);
            for (std::size_t i = lo; i < hi; ++i) {
                if (i + 16 < hi) {
                    const char* p = reinterpret_cast<const char*>(order_[i + 16]);
                    __builtin_prefetch(p);      // the vtable pointer (typeid, bounds())
                    __builtin_prefetch(p + 64); // the shape's data past the Primitive base
                }
                f(i);
            }
        };
        if (options_.buildThreads == 1 || blocks < 2) {
            for (std::size_t b = 0; b < blocks; ++b)
                block(b);
            return;
        }
        parallelFor(blocks, block); // inside the build's arena
    };
    // Kinds: taken by the build in scene order (sceneKind_), here by index. Each block
    // notes the run kinds it saw (`has` below), so no serial pass over kind_ follows
    // (issue 21: part of the two-thread build's serial time).
    constexpr std::size_t kBlockKinds = 16384;
    const std::size_t kindBlocks = (n + kBlockKinds - 1) / kBlockKinds;
    std::vector<unsigned> seen(kindBlocks, 0); // per block: bit r for run kind r
    if (sceneKind_.size() >= n) {
        // No object is read: blocks without perPrimitive's prefetches, parallel with the
        // build's threads (a serial pass here was part of the 2-thread build's serial time).
        auto block = [&](std::size_t b) {
            unsigned bits = 0;
            for (std::size_t i = b * kBlockKinds, e = std::min(n, i + kBlockKinds); i < e; ++i) {
                kind_[i] = sceneKind_[orderIndex_[i]];
                bits |= 1u << runOf(kind_[i]);
            }
            seen[b] = bits;
        };
        if (options_.buildThreads == 1 || kindBlocks < 2) {
            for (std::size_t b = 0; b < kindBlocks; ++b)
                block(b);
        } else {
            parallelFor(kindBlocks, block); // inside the build's arena
        }
    } else {
        perPrimitive([&](std::size_t i) { kind_[i] = primitiveKind(order_[i]); });
        for (std::size_t i = 0; i < n; ++i)
            seen[i / kBlockKinds] |= 1u << runOf(kind_[i]);
    }
    std::vector<std::uint8_t>().swap(sceneKind_);
    bool has[3] = {false, false, false}; // per run kind
    for (const unsigned bits : seen)
        for (int r = 0; r < 3; ++r)
            has[r] = has[r] || ((bits >> r) & 1);
    triOnly_ = has[kRunTriangle] && !has[kRunSphere] && !has[kRunOther];
    if (triOnly_) path_ = path_->tri;
    // The float arrays of the kinds present only (a leaf test reads its own kind's):
    // the collapse writes less memory for a scene of one kind. Zeroed beside the
    // collapse's tasks (collapseInto), which do not read them.
    // Issue 21: one array per parallel item. Zeroed one after another by the thread beside
    // the tasks, the 14 arrays of a million triangles (56 MB, faulted in again whenever
    // malloc had given their pages back) took longer than the tasks themselves, and the
    // other thread waited: the two-thread build's serial part on that row.
    std::vector<Floats*> zeroed;
    if (has[kRunSphere])
        for (auto* v : {&sx_, &sy_, &sz_, &sr_, &sm_})
            zeroed.push_back(v);
    if (has[kRunTriangle]) {
        for (auto& v : tv_)
            zeroed.push_back(&v);
        for (auto& v : te_)
            zeroed.push_back(&v);
        for (auto& v : tp_)
            zeroed.push_back(&v);
    }
    if (has[kRunOther])
        for (auto& v : ob_)
            zeroed.push_back(&v);
    auto arrays = [&] {
        // n + 8: the 8-wide sphere test reads up to seven floats past a run's last.
        auto zero = [&](std::size_t k) { zeroed[k]->assign(n + 8, 0.0f); };
        if (options_.buildThreads == 1 || zeroed.size() < 2) {
            for (std::size_t k = 0; k < zeroed.size(); ++k)
                zero(k);
        } else {
            parallelFor(zeroed.size(), zero); // beside the collapse's tasks, in the build's arena
        }
    };
    // The leaves' float data once the collapse has sorted each leaf into its runs (beside
    // the append of the collapse's tasks, which does not touch them).
    auto fill = [&] { perPrimitive([&](std::size_t i) { fillLeafData(std::uint32_t(i)); }); };
    if (count <= 1) {
        arrays();
        if (count == 0) return;
        // The whole tree is one leaf (rootLeafCount_).
        sortLeaf(0, build[0].count);
        fill();
        stats_.wideNodes = 0;
        return;
    }
    // The root node's float child boxes, united (empty slots are inverted infinite boxes
    // and add nothing): the walk's first test of a ray (initRay).
    auto rootBox = [this](const auto& root, int w) {
        for (int a = 0; a < 3; ++a) {
            rootF_[0][a] = root.lo[a][0];
            rootF_[1][a] = root.hi[a][0];
            for (int c = 1; c < w; ++c) {
                rootF_[0][a] = std::min(rootF_[0][a], root.lo[a][c]);
                rootF_[1][a] = std::max(rootF_[1][a], root.hi[a][c]);
            }
        }
    };
    if (pc.width == 8) {
        wnodes8_.reserve(std::min<std::size_t>(count / 7 + 1, 4096)); // the top; tasks append
        collapseInto<8>(buildNodes, wnodes8_, arrays, fill);
        rootBox(wnodes8_[0], 8); // before quantiseNodes empties wnodes8_
        stats_.wideNodes = int(wnodes8_.size());
        stats_.nodeBytes = wnodes8_.size() * sizeof(WideNode8);
        // The collapse's output stage: the node layout (BvhNodes). Auto keeps float nodes
        // on every kind of scene: quantised ones measured slower on all of them (the
        // decode costs more than the halved node loads save; docs/raytrace-scale.md).
        const bool quantise = options_.nodes == BvhNodes::Quantised;
        if (quantise && quantiseNodes()) {
            stats_.quantised = true;
            stats_.nodeBytes = qnodes8_.size() * sizeof(QuantNode8);
            path_ = pc.avx512 ? avx512Path(true) : avx2Path(8, true);
            if (triOnly_) path_ = path_->tri;
        }
    } else {
        wnodes_.reserve(std::min<std::size_t>(count / 3 + 1, 4096));
        collapseInto<4>(buildNodes, wnodes_, arrays, fill);
        rootBox(wnodes_[0], 4);
        stats_.wideNodes = int(wnodes_.size());
        stats_.nodeBytes = wnodes_.size() * sizeof(WideNode);
    }
}

// Child boxes as 8-bit offsets in the node's box (Embree's compressed nodes do the same):
// per axis the node's lower corner org (the children's smallest lo, a float) and a
// power of two scale with org + 255·scale >= the children's largest hi; each child's lo
// rounded down to a q with org + q·scale <= lo, its hi up to one with org + q·scale >= hi,
// both checked with the walk's own decode (quantDecode), so every decoded box holds the
// float box it replaces and the float tests on it stay conservative (no hit is lost).
// Node boxes float cannot quantise (infinite, or a span beyond 255·2^127) keep the
// whole tree float.
bool Bvh::quantiseNodes() {
    std::vector<QuantNode8> out(wnodes8_.size());
    for (std::size_t i = 0; i < wnodes8_.size(); ++i) {
        const WideNode8& w = wnodes8_[i];
        QuantNode8& q = out[i];
        std::memset(&q, 0, sizeof q); // padding too: trees compare bytewise (tests)
        for (int c = 0; c < 8; ++c) {
            q.child[c] = w.child[c];
            q.count[c] = w.count[c];
            if (w.lo[0][c] <= w.hi[0][c]) q.valid |= std::uint8_t(1u << c);
        }
        for (int a = 0; a < 3; ++a) {
            float lo = std::numeric_limits<float>::infinity(), hi = -lo;
            for (int c = 0; c < 8; ++c)
                if ((q.valid >> c) & 1) {
                    lo = std::min(lo, w.lo[a][c]);
                    hi = std::max(hi, w.hi[a][c]);
                }
            if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
            // The smallest power of two with 255·scale >= hi − lo (then checked in float).
            int e = 0;
            std::frexp((double(hi) - double(lo)) / 255, &e);
            float scale = std::ldexp(1.0f, std::max(e, -126));
            while (std::isfinite(scale) && quantDecode(lo, scale, 255) < hi)
                scale *= 2;
            if (!std::isfinite(scale) || !std::isfinite(quantDecode(lo, scale, 255))) return false;
            q.org[a] = lo;
            q.scale[a] = scale;
            for (int c = 0; c < 8; ++c) {
                if (!((q.valid >> c) & 1)) { // never entered (valid); an inverted box anyway
                    q.q[a][c] = 255;
                    q.q[3 + a][c] = 0;
                    continue;
                }
                int ql = std::clamp(int(std::floor((double(w.lo[a][c]) - lo) / scale)), 0, 255);
                while (ql > 0 && quantDecode(lo, scale, ql) > w.lo[a][c])
                    --ql;
                int qh = std::clamp(int(std::ceil((double(w.hi[a][c]) - lo) / scale)), 0, 255);
                while (qh < 255 && quantDecode(lo, scale, qh) < w.hi[a][c])
                    ++qh;
                if (quantDecode(lo, scale, ql) > w.lo[a][c] ||
                    quantDecode(lo, scale, qh) < w.hi[a][c])
                    return false; // cannot happen (q 0 and 255 hold them): the proof, checked
                q.q[a][c] = std::uint8_t(ql);
                q.q[3 + a][c] = std::uint8_t(qh);
            }
        }
    }
    qnodes8_ = std::move(out);
    bvh_detail::KeptVector<WideNode8>().swap(wnodes8_);
    return true;
}

std::vector<Bvh::WideNode8> Bvh::decodedQuantNodes8() const {
    std::vector<WideNode8> out(qnodes8_.size());
    for (std::size_t i = 0; i < qnodes8_.size(); ++i) {
        const QuantNode8& q = qnodes8_[i];
        WideNode8& w = out[i];
        std::memset(&w, 0, sizeof w);
        for (int c = 0; c < 8; ++c) {
            w.child[c] = q.child[c];
            w.count[c] = q.count[c];
            for (int a = 0; a < 3; ++a) {
                const bool valid = (q.valid >> c) & 1;
                w.lo[a][c] = valid ? quantDecode(q.org[a], q.scale[a], q.q[a][c])
                                   : std::numeric_limits<float>::infinity();
                w.hi[a][c] = valid ? quantDecode(q.org[a], q.scale[a], q.q[3 + a][c])
                                   : -std::numeric_limits<float>::infinity();
            }
        }
    }
    return out;
}

} // namespace wb::rt
