#pragma once
// Parallelepiped by the slab method of seed 000 ("ПАРАЛЛЕЛЕПИПЕД"): corner Loc and
// edge vectors E1, E2, E3; three pairs of parallel planes with normals
// N1 = E1×E2, N2 = E1×E3, N3 = E2×E3; the ray's interval inside each slab is
// intersected, the entry is the largest near distance, the exit the smallest far one.
// Seed 000's listing has slips (Center = Loc + 0.5(E2+E2+E3), "VD < 0.01" for
// "VD < −0.01", no hit from inside); this follows the method, not the slips.
// Texture coordinates of a face: the hit point's fractions along the face's two edges.
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Box : public Primitive {
  public:
    // Throws std::invalid_argument when the edges are linearly dependent or not finite.
    Box(const glm::dvec3& loc, const glm::dvec3& e1, const glm::dvec3& e2, const glm::dvec3& e3);
    // Axis-aligned box from two opposite corners.
    static Box axisAligned(const glm::dvec3& lo, const glm::dvec3& hi);

    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    Aabb bounds() const override;
    bool solid() const override { return true; }

    glm::dvec3 loc, e1, e2, e3, centre;
    glm::dvec3 n[3]; // unit slab normals
    double d1[3];    // slab i is d1[i] <= n[i]·x <= d2[i]
    double d2[3];

  private:
    glm::dmat3 toEdges_; // point − loc -> coordinates along (e1, e2, e3), for uv
};

} // namespace wb::rt
