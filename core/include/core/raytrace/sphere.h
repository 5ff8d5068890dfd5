#pragma once
// Sphere (practical 11.1): roots from the distance of the centre to the ray's line,
// which stays accurate for grazing rays and far origins, in cancellation-free form.
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Sphere : public Primitive {
  public:
    // radius >= 0 (a zero radius gives a sphere nothing hits); throws std::invalid_argument
    // for a negative or non-finite radius or centre.
    Sphere(const glm::dvec3& centre, double radius);
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    // The same decision as intersect() without filling a hit record.
    bool occluded(const Ray& ray, double tMin, double tMax) const override;
    glm::dvec2 textureCoords(const Hit& hit) const override;
    Aabb bounds() const override;
    bool solid() const final { return true; } // final: intersect passes true
    // f = point − centre and c = (|f| − r)(|f| + r), the bits occluded() computes for a
    // feeler from `point` (nearest's f and c): the tracer's sphereCannotBlock.
    bool feelerSelfTerms(const glm::dvec3& point, glm::dvec3& f, double& c) const override;

    glm::dvec3 centre;
    double radius;
};

} // namespace wb::rt
