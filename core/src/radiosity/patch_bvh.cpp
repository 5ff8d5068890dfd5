#include "core/radiosity/patch_bvh.h"

#include "core/raytrace/triangle.h"

#include <cmath>
#include <limits>

namespace wb::rad {

PatchBvh::PatchBvh(const PatchMesh& mesh) : mesh_(mesh) {
    prims_.reserve(mesh.patches.size());
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        const auto at = [&](int k) { return mesh.vertices[static_cast<std::size_t>(p.corners[static_cast<std::size_t>(k)])]; };
        const int id = static_cast<int>(i);
        if (p.cornerCount == 3) {
            prims_.push_back(std::make_unique<rt::Triangle>(at(0), at(1), at(2)));
            prims_.back()->material = id;
            continue;
        }
        // Two watertight triangles sharing the diagonal c0–c2 (core/raytrace's Woop et al.
        // test: no ray slips between triangles with bitwise equal shared vertices, which the
        // patches of one surface have; an rt::Rectangle would be cheaper but is not watertight).
        prims_.push_back(std::make_unique<rt::Triangle>(at(0), at(1), at(2)));
        prims_.back()->material = id;
        prims_.push_back(std::make_unique<rt::Triangle>(at(0), at(2), at(3)));
        prims_.back()->material = id;
    }
    rt::BvhOptions opt;
    opt.maxLeafSize = 2; // patches are cheap to test but numerous: small leaves
    bvh_ = std::make_unique<rt::Bvh>(prims_, opt);
}

int PatchBvh::nearestPatch(const glm::dvec3& origin, const glm::dvec3& dir, double tMin,
                           double tMax) const {
    rt::Ray ray;
    ray.origin = origin;
    ray.direction = dir;
    rt::Hit hit;
    if (!bvh_->intersect(ray, tMin, tMax, hit)) return -1;
    return patchOf(ray, hit);
}

void PatchBvh::nearestPatches(const glm::dvec3& origin, const glm::dvec3* dirs, int n,
                              int* ids) const {
    rt::Ray rays[rt::kMaxPacket];
    rt::Hit hits[rt::kMaxPacket];
    double tMin[rt::kMaxPacket], tMax[rt::kMaxPacket];
    for (int j = 0; j < rt::kMaxPacket; ++j) {
        tMin[j] = 0.0;
        tMax[j] = std::numeric_limits<double>::infinity();
    }
    for (int j = 0; j < n; ++j) {
        rays[j].origin = origin;
        rays[j].direction = dirs[j];
    }
    const unsigned found = bvh_->intersectPacket(rays, tMin, tMax, hits, (1u << n) - 1);
    for (int j = 0; j < n; ++j)
        ids[j] = (found >> j) & 1 ? patchOf(rays[j], hits[j]) : -1;
}

int PatchBvh::patchOf(const rt::Ray& ray, const rt::Hit& hit) const {
    const glm::dvec3& dir = ray.direction;
    const int id = hit.material;
    if (glm::dot(mesh_.patches[static_cast<std::size_t>(id)].normal, dir) < 0.0) return id;
    // Back sides face the inside of a body or the outside of the room: they block, unseen.
    // A ray through a convex edge of a body meets the back of one face and the front of the
    // other at the same distance; take the front one if there is one (a tie within 1e-9 t).
    int front = -1;
    const double t = hit.t;
    bvh_->forEachHit(ray, t * (1.0 - 1e-9), t * (1.0 + 1e-9), [&](const rt::Hit& h) {
        if (glm::dot(mesh_.patches[static_cast<std::size_t>(h.material)].normal, dir) < 0.0) {
            front = h.material;
            return false;
        }
        return true;
    });
    return front;
}

bool PatchBvh::visible(const glm::dvec3& a, const glm::dvec3& b) const {
    const glm::dvec3 d = b - a;
    const double len = glm::length(d);
    if (!(len > 0.0)) return true;
    rt::Ray ray;
    ray.origin = a;
    ray.direction = d / len;
    // The end points lie on their own patches: keep 1e-9 of the length away from both
    // (intersection rounding is ~1e-16 of the coordinates, far below).
    return !bvh_->occluded(ray, 1e-9 * len, len * (1.0 - 1e-9));
}

} // namespace wb::rad
