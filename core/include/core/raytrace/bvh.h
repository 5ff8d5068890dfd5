#pragma once
// Bounding volume hierarchy over every primitive kind of a scene (spheres, quadrics,
// cones, triangles, polyhedra share one tree), built with the binned surface area
// heuristic and flattened into an array (a node's left child follows it, the right
// child is at an index). Traversal is front to back (the child nearer along the
// ray's direction on the split axis first) and stops at tMax = nearest hit so far;
// forEachHit stops as soon as the visitor returns false, which is the any-hit early
// exit of shadow feelers. Unbounded primitives (infinite planes, uncut quadrics) are
// kept outside the tree and tested for every ray.
#include "core/raytrace/scene.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace wb::rt {

struct BvhOptions {
    int bins = 16;                 // SAH bins per axis (binned build, Wald 2007); 2..256
    int maxLeafSize = 4;           // a node with at most this many primitives may become a leaf
    double traversalCost = 1.0;    // SAH cost of visiting a node, relative to...
    double intersectionCost = 1.0; // ...one primitive test
    bool floatBoxes = false; // traverse float nodes (half the memory; conservative, same hits)
};

struct BvhStats {
    int nodes = 0;              // in the flattened array
    int leaves = 0;             // leaf nodes
    int maxDepth = 0;           // longest root-to-leaf path
    std::size_t primitives = 0; // bounded primitives in the tree
    std::size_t unbounded = 0;  // primitives outside the tree (tested for every ray)
    double buildSeconds = 0.0;  // wall time of the build
    double sahCost = 0.0;       // SAH cost of the tree (root area normalised)
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
                        const std::function<bool(const Primitive&)>& visit) const override;
    // Any hit in (tMin, tMax] (shadow feeler for opaque scenes).
    bool occluded(const Ray& ray, double tMin, double tMax) const;

    const BvhStats& stats() const { return stats_; }

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

  private:
    template <class Visit>
    void traverse(const Ray& ray, double tMin, double& tMax, Visit&& visit) const;

    BvhOptions options_;
    std::vector<Node> nodes_;
    std::vector<FloatNode> fnodes_; // parallel to nodes_ when options_.floatBoxes
    double rootLo_[3] = {0, 0, 0}, rootHi_[3] = {0, 0, 0}; // box of the whole tree
    std::uint32_t rootLeafCount_ = 0;         // > 0: the whole tree is one leaf (no nodes_)
    std::vector<const Primitive*> order_;     // primitives in leaf order
    std::vector<const Primitive*> unbounded_; // tested for every ray
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
