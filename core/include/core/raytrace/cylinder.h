#pragma once
// Finite circular cylinder or truncated cone with both caps (practical 11.5; a cone
// is what NFF's `c` with two radii means): axis from base centre c0 (radius r0) to
// top centre c1 (radius r1). The lateral surface is x² + y² = (r0 + k·z)² in a frame
// with z along the axis, k = (r1 − r0)/h; the body is its inside between 0 <= z <= h.
// Texture coordinates: (angle/2π, z/h) on the side, the disc mapped to [0,1]² on a cap.
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Cone : public Primitive {
  public:
    // r0, r1 >= 0, not both 0; c0 != c1. Throws std::invalid_argument otherwise.
    Cone(const glm::dvec3& c0, double r0, const glm::dvec3& c1, double r1);
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    Aabb bounds() const override;
    bool solid() const override { return true; }

    glm::dvec3 c0, c1;
    double r0, r1;

  private:
    glm::dvec3 axis_, ex_, ey_; // orthonormal frame, axis_ from c0 to c1
    double h_, k_;
};

// A cylinder is a cone with equal radii.
inline Cone makeCylinder(const glm::dvec3& c0, const glm::dvec3& c1, double r) {
    return Cone(c0, r, c1, r);
}

} // namespace wb::rt
