#pragma once
// Visibility between patches through the project's BVH (core/raytrace): every patch becomes
// one (triangle) or two (quad) watertight rt::Triangles, whose `material` field holds the
// patch id. Used by the ray form factors (any-hit between two points) and by the CPU
// hemicube (nearest patch along a pixel's ray).
#include "core/radiosity/mesh.h"
#include "core/raytrace/bvh.h"

#include <memory>
#include <vector>

namespace wb::rad {

class PatchBvh {
  public:
    explicit PatchBvh(const PatchMesh& mesh);
    PatchBvh(const PatchBvh&) = delete;
    PatchBvh& operator=(const PatchBvh&) = delete;

    // Id of the nearest patch hit by the ray origin + t·dir, t in (tMin, tMax], whose FRONT
    // side faces the ray; −1 when nothing is hit or the nearest hit is a patch's back side
    // (a back side blocks: behind it is the inside of a body, seen from nowhere).
    int nearestPatch(const glm::dvec3& origin, const glm::dvec3& dir, double tMin,
                     double tMax) const;

    // nearestPatch(origin, dirs[j], 0, inf) for j < n (n <= rt::kMaxPacket), the rays
    // traced as one packet (issue 21: a hemicube face's neighbouring pixels), into ids[j].
    void nearestPatches(const glm::dvec3& origin, const glm::dvec3* dirs, int n, int* ids) const;

    // True when the open segment from a to b (the end points' own patches excluded by
    // shortening it a relative 1e-9 at both ends) meets no patch.
    bool visible(const glm::dvec3& a, const glm::dvec3& b) const;

    const rt::BvhStats& stats() const { return bvh_->stats(); }

    // What the CPU hemicube's rasteriser (hemicube.cpp) needs to give nearestPatch's answers
    // without the walk: the mesh, and the triangles in scene order (rt::Triangle, material =
    // patch id; on equal t the walk keeps the one later in this order).
    const PatchMesh& mesh() const { return mesh_; }
    const std::vector<std::unique_ptr<rt::Primitive>>& triangles() const { return prims_; }

  private:
    // The patch seen along `ray` given its nearest hit (the back-side rule above).
    int patchOf(const rt::Ray& ray, const rt::Hit& hit) const;

    const PatchMesh& mesh_;
    std::vector<std::unique_ptr<rt::Primitive>> prims_;
    std::unique_ptr<rt::Bvh> bvh_;
};

} // namespace wb::rad
