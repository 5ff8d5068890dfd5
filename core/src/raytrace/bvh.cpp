#include "core/raytrace/bvh.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wb::rt {

namespace {

double area(const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 d = hi - lo;
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

float floatDown(double x) {
    float f = float(x);
    if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float floatUp(double x) {
    float f = float(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

struct Ref {
    glm::dvec3 lo, hi, centre;
    const Primitive* prim;
};

struct Box {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    void extend(const glm::dvec3& l, const glm::dvec3& h) {
        lo = glm::min(lo, l);
        hi = glm::max(hi, h);
    }
};

// Beyond this depth the builder splits at the object median, so the tree depth stays
// below kMaxDepth = kMedianDepth + log2(kNffMaxPrimitives-sized inputs) + slack.
constexpr int kMedianDepth = 96;
constexpr int kMaxDepth = 128;          // traversal stack size
constexpr std::size_t kMaxLeaf = 65535; // Node::count is 16 bits

// PBRT's γ(3) margin: a box's exit distance computed in double may be short by 3
// rounding errors; stretching it keeps grazing rays from missing a box whose
// primitive they hit.
constexpr double kFarScale = 1 + 2 * 3 * (std::numeric_limits<double>::epsilon() / 2) /
                                     (1 - 3 * std::numeric_limits<double>::epsilon() / 2);

} // namespace

Bvh::Bvh(const std::vector<std::unique_ptr<Primitive>>& prims, BvhOptions options)
    : prims_(prims), options_(options) {
    if (options.bins < 2 || options.bins > 256 || options.maxLeafSize < 1 ||
        options.maxLeafSize > 255 || !(options.traversalCost >= 0) ||
        !(options.intersectionCost > 0))
        throw std::invalid_argument("Bvh: bins in 2..256, maxLeafSize in 1..255, costs >= 0");
    const auto start = std::chrono::steady_clock::now();

    std::vector<Ref> refs;
    refs.reserve(prims.size());
    for (const auto& p : prims) {
        const Aabb b = p->bounds();
        const bool finite = std::isfinite(b.lo.x) && std::isfinite(b.lo.y) &&
                            std::isfinite(b.lo.z) && std::isfinite(b.hi.x) &&
                            std::isfinite(b.hi.y) && std::isfinite(b.hi.z);
        if (!finite || b.empty() || !b.bounded())
            unbounded_.push_back(p.get());
        else
            refs.push_back(Ref{b.lo, b.hi, 0.5 * (b.lo + b.hi), p.get()});
    }
    stats_.primitives = refs.size();
    stats_.unbounded = unbounded_.size();
    order_.reserve(refs.size());
    if (!refs.empty()) {
        nodes_.reserve(2 * refs.size() / std::size_t(std::max(1, options.maxLeafSize / 2)) + 1);
        struct Task {
            std::size_t begin, end;
            std::uint32_t parent; // node whose right child this is (npos for left/root)
            int depth;
        };
        constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
        std::vector<Task> stack{{0, refs.size(), kNone, 0}};
        const int nb = options.bins;
        std::vector<Box> binBox(size_t(3 * nb));
        std::vector<std::size_t> binCount(size_t(3 * nb));
        std::vector<double> rightArea(static_cast<size_t>(nb));
        std::vector<std::size_t> rightCount(static_cast<size_t>(nb));
        double rootArea = 0;
        while (!stack.empty()) {
            const Task task = stack.back();
            stack.pop_back();
            const auto idx = std::uint32_t(nodes_.size());
            if (task.parent != kNone) nodes_[task.parent].offset = idx;
            Box box, cbox;
            for (std::size_t i = task.begin; i < task.end; ++i) {
                box.extend(refs[i].lo, refs[i].hi);
                cbox.extend(refs[i].centre, refs[i].centre);
            }
            Node node;
            node.lo = box.lo;
            node.hi = box.hi;
            node.flo = glm::vec3(floatDown(box.lo.x), floatDown(box.lo.y), floatDown(box.lo.z));
            node.fhi = glm::vec3(floatUp(box.hi.x), floatUp(box.hi.y), floatUp(box.hi.z));
            node.offset = 0;
            node.count = 0;
            node.axis = 0;
            const std::size_t n = task.end - task.begin;
            const double parentArea = area(box.lo, box.hi);
            if (idx == 0) rootArea = parentArea > 0 ? parentArea : 1.0;
            stats_.maxDepth = std::max(stats_.maxDepth, task.depth);

            // Best binned SAH split over the three axes.
            int bestAxis = -1, bestBin = 0;
            double bestCost = std::numeric_limits<double>::infinity();
            const glm::dvec3 ext = cbox.hi - cbox.lo;
            if (n > 1 && task.depth < kMedianDepth) {
                std::fill(binBox.begin(), binBox.end(), Box{});
                std::fill(binCount.begin(), binCount.end(), 0);
                glm::dvec3 scale(0.0);
                for (int a = 0; a < 3; ++a)
                    if (ext[a] > 0) scale[a] = nb / ext[a];
                for (std::size_t i = task.begin; i < task.end; ++i)
                    for (int a = 0; a < 3; ++a) {
                        if (scale[a] == 0) continue;
                        const int b =
                            std::min(nb - 1, int((refs[i].centre[a] - cbox.lo[a]) * scale[a]));
                        binBox[size_t(a * nb + b)].extend(refs[i].lo, refs[i].hi);
                        ++binCount[size_t(a * nb + b)];
                    }
                for (int a = 0; a < 3; ++a) {
                    if (scale[a] == 0) continue;
                    Box acc;
                    std::size_t cnt = 0;
                    for (int b = nb - 1; b > 0; --b) {
                        acc.extend(binBox[size_t(a * nb + b)].lo, binBox[size_t(a * nb + b)].hi);
                        cnt += binCount[size_t(a * nb + b)];
                        rightArea[size_t(b)] = cnt ? area(acc.lo, acc.hi) : 0.0;
                        rightCount[size_t(b)] = cnt;
                    }
                    Box left;
                    std::size_t lc = 0;
                    for (int b = 1; b < nb; ++b) {
                        left.extend(binBox[size_t(a * nb + b - 1)].lo,
                                    binBox[size_t(a * nb + b - 1)].hi);
                        lc += binCount[size_t(a * nb + b - 1)];
                        const std::size_t rc = rightCount[size_t(b)];
                        if (lc == 0 || rc == 0) continue;
                        const double cost =
                            double(lc) * area(left.lo, left.hi) + double(rc) * rightArea[size_t(b)];
                        if (cost < bestCost) {
                            bestCost = cost;
                            bestAxis = a;
                            bestBin = b;
                        }
                    }
                }
            }
            const double leafCost = options.intersectionCost * double(n);
            const double splitCost =
                bestAxis < 0 ? std::numeric_limits<double>::infinity()
                             : options.traversalCost + options.intersectionCost * bestCost /
                                                           (parentArea > 0 ? parentArea : 1.0);
            const bool mustSplit = n > kMaxLeaf;
            const bool wantLeaf = n <= std::size_t(options.maxLeafSize) && leafCost <= splitCost;
            const bool canSah = bestAxis >= 0;
            if (!mustSplit &&
                (n == 1 || wantLeaf ||
                 (!canSah && task.depth < kMedianDepth && n <= std::size_t(16) * 16))) {
                // Leaf (also when every centroid coincides and n is modest).
                node.offset = std::uint32_t(order_.size());
                node.count = std::uint16_t(n);
                for (std::size_t i = task.begin; i < task.end; ++i)
                    order_.push_back(refs[i].prim);
                nodes_.push_back(node);
                ++stats_.leaves;
                stats_.sahCost += leafCost * parentArea / rootArea;
                continue;
            }
            std::size_t mid;
            int axis;
            if (canSah && !(task.depth >= kMedianDepth)) {
                axis = bestAxis;
                const double lo = cbox.lo[axis], sc = nb / ext[axis];
                auto it = std::partition(
                    refs.begin() + std::ptrdiff_t(task.begin),
                    refs.begin() + std::ptrdiff_t(task.end), [&](const Ref& r) {
                        return std::min(nb - 1, int((r.centre[axis] - lo) * sc)) < bestBin;
                    });
                mid = std::size_t(it - refs.begin());
            } else {
                // Object median on the widest centroid axis (also for coincident centroids).
                axis = (ext.x >= ext.y && ext.x >= ext.z) ? 0 : (ext.y >= ext.z ? 1 : 2);
                mid = task.begin + n / 2;
                std::nth_element(
                    refs.begin() + std::ptrdiff_t(task.begin), refs.begin() + std::ptrdiff_t(mid),
                    refs.begin() + std::ptrdiff_t(task.end),
                    [axis](const Ref& x, const Ref& y) { return x.centre[axis] < y.centre[axis]; });
            }
            node.axis = std::uint16_t(axis);
            nodes_.push_back(node);
            stats_.sahCost += options.traversalCost * parentArea / rootArea;
            // Right first on the stack so the left child is built next, right after its parent.
            stack.push_back({mid, task.end, idx, task.depth + 1});
            stack.push_back({task.begin, mid, kNone, task.depth + 1});
        }
    }
    stats_.nodes = int(nodes_.size());
    if (stats_.maxDepth >= kMaxDepth)
        throw std::logic_error("Bvh: tree deeper than the traversal stack"); // cannot happen
    stats_.buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Visit>
void Bvh::traverse(const Ray& ray, double tMin, double& tMax, Visit&& visit) const {
    if (nodes_.empty()) return;
    const glm::dvec3 o = ray.origin;
    const glm::dvec3 inv = 1.0 / ray.direction;
    const int neg[3] = {std::signbit(inv.x), std::signbit(inv.y), std::signbit(inv.z)};
    const glm::vec3 fo(o), finv(inv);
    const bool useFloat = options_.floatBoxes;
    std::array<std::uint32_t, kMaxDepth> stack;
    int sp = 0;
    std::uint32_t idx = 0;
    while (true) {
        const Node& node = nodes_[idx];
        bool hitBox;
        if (useFloat) {
            // NaN (0·inf for a ray in a slab's plane) compares false: the slab is not a limit.
            float t0 = float(tMin), t1 = float(tMax);
            for (int a = 0; a < 3; ++a) {
                const float near = ((neg[a] ? node.fhi[a] : node.flo[a]) - fo[a]) * finv[a];
                const float far = ((neg[a] ? node.flo[a] : node.fhi[a]) - fo[a]) * finv[a];
                t0 = near > t0 ? near : t0;
                t1 = far * 1.0000004f < t1 ? far * 1.0000004f : t1;
            }
            hitBox = t0 <= t1;
        } else {
            double t0 = tMin, t1 = tMax;
            for (int a = 0; a < 3; ++a) {
                const double near = ((neg[a] ? node.hi[a] : node.lo[a]) - o[a]) * inv[a];
                const double far = ((neg[a] ? node.lo[a] : node.hi[a]) - o[a]) * inv[a] * kFarScale;
                t0 = near > t0 ? near : t0;
                t1 = far < t1 ? far : t1;
            }
            hitBox = t0 <= t1;
        }
        if (hitBox) {
            if (node.count > 0) {
                for (std::uint32_t i = node.offset, e = node.offset + node.count; i < e; ++i)
                    if (!visit(*order_[i], tMax)) return;
            } else {
                const std::uint32_t first = neg[node.axis] ? node.offset : idx + 1;
                const std::uint32_t second = neg[node.axis] ? idx + 1 : node.offset;
                stack[size_t(sp++)] = second;
                idx = first;
                continue;
            }
        }
        if (sp == 0) return;
        idx = stack[size_t(--sp)];
    }
}

bool Bvh::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
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
    Hit h;
    for (const Primitive* p : unbounded_)
        if (p->intersect(ray, tMin, tMax, h) && !visit(h)) return;
    traverse(ray, tMin, tMax, [&](const Primitive& p, double&) {
        return !(p.intersect(ray, tMin, tMax, h) && !visit(h));
    });
}

bool Bvh::occluded(const Ray& ray, double tMin, double tMax) const {
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
