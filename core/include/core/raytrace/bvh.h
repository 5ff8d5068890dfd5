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
    bool floatBoxes = false; // test node boxes in float (boxes rounded outward; origin rounded)
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
    // Any hit in (tMin, tMax] (shadow feeler for opaque scenes).
    bool occluded(const Ray& ray, double tMin, double tMax) const;

    const BvhStats& stats() const { return stats_; }

    struct Node {
        glm::dvec3 lo, hi;    // box (rounded outward from the float boxes of the build)
        std::uint32_t offset; // leaf: first index into order_; inner: right child index
        std::uint16_t count;  // leaf: number of primitives; inner: 0
        std::uint16_t axis;   // inner: split axis
    };
    struct FloatBox {
        glm::vec3 lo, hi; // a node's box in float, rounded outward (floatBoxes traversal)
    };

  private:
    template <class Visit>
    void traverse(const Ray& ray, double tMin, double& tMax, Visit&& visit) const;

    BvhOptions options_;
    std::vector<Node> nodes_;
    std::vector<FloatBox> fboxes_;            // parallel to nodes_ when options_.floatBoxes
    std::vector<const Primitive*> order_;     // primitives in leaf order
    std::vector<const Primitive*> unbounded_; // tested for every ray
    BvhStats stats_;
};

// Below this many primitives the plain loop over objects is at least as fast as the
// BVH (measured by bench_raytrace_scale on this machine; see docs/raytrace-scale.md).
constexpr std::size_t kBvhCrossover = 8;

// The aggregate a scene should use: a Bvh when it has at least `crossover`
// primitives, nullptr (the scene's own brute-force loop) otherwise. Install it with
// scene.setAggregate(result.get()); keep it alive while the scene is traced.
std::unique_ptr<Bvh> makeAggregate(const Scene& scene, std::size_t crossover = kBvhCrossover,
                                   BvhOptions options = {});

} // namespace wb::rt
