#pragma once
// Watertight ray–triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): the ray is sheared so it runs along +z and the edge
// functions are evaluated in 2D; two triangles sharing an edge compute the same edge
// function for it, so no ray passes between them. Edge functions that come out as
// exactly 0 are recomputed in long double, as the paper recomputes in double.
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Triangle : public Primitive {
  public:
    // Degenerate (zero-area) triangles are allowed and never hit.
    // `closedMesh`: the triangle belongs to a closed mesh, so it bounds a body.
    Triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
             bool closedMesh = false);
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    Aabb bounds() const override;
    bool solid() const override { return closed_; }
    bool planar() const override { return true; }

    glm::dvec3 v0, v1, v2;

  private:
    glm::dvec3 normal_; // unit, (v1−v0)×(v2−v0) (counter-clockwise = front); 0 if degenerate
    bool closed_;
};

} // namespace wb::rt
