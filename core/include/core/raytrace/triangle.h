#pragma once
// Watertight ray–triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): the ray is sheared so it runs along +z and the edge
// functions are evaluated in 2D; two triangles sharing an edge compute the same edge
// function for it, so no ray passes between them. Edge functions that come out as
// exactly 0 are recomputed in long double, as the paper recomputes in double.
#include "core/raytrace/primitive.h"

namespace wb::rt {

// The ray's part of the watertight test: the axes (kz the dominant axis of the direction,
// kx/ky swapped for a negative d[kz]) and the shear. Triangle::intersect computes it in
// every call; a caller that tests many triangles with one ray (the BVH) computes it once
// and passes it to intersectSheared, which then gives the same bits.
struct TriangleShear {
    int kx, ky, kz;    // set by triangleShear (no defaults: the BVH keeps one per ray unset
    double sx, sy, sz; // until its first triangle); d[kx]/d[kz], d[ky]/d[kz], 1/d[kz]
};
TriangleShear triangleShear(const glm::dvec3& direction);

class Triangle : public Primitive {
  public:
    // Degenerate (zero-area) triangles are allowed and never hit.
    // `closedMesh`: the triangle belongs to a closed mesh, so it bounds a body.
    Triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
             bool closedMesh = false);
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    // intersect() with the shear of ray.direction computed by the caller (triangleShear).
    bool intersectSheared(const Ray& ray, const TriangleShear& shear, double tMin, double tMax,
                          Hit& hit) const;
    Aabb bounds() const override;
    bool solid() const override { return closed_; }
    bool planar() const override { return true; }

    glm::dvec3 v0, v1, v2;

  private:
    glm::dvec3 normal_; // unit, (v1−v0)×(v2−v0) (counter-clockwise = front); 0 if degenerate
    bool closed_;
};

} // namespace wb::rt
