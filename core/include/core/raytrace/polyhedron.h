#pragma once
// Convex polyhedron as the intersection of k half-spaces n_i·x <= d_i (practical
// 11.4): entries ("front", u·n < 0) and exits ("back") are collected as fMax and
// bMin; the ray meets the body iff fMax <= bMin. Works for unbounded bodies too.
#include "core/raytrace/primitive.h"

#include <vector>

namespace wb::rt {

class ConvexPolyhedron : public Primitive {
  public:
    struct Face {
        glm::dvec3 normal; // outward, any non-zero length (normalised by the constructor)
        double d;          // n·x <= d inside (with the normalised normal after construction)
    };
    // Throws std::invalid_argument for no faces or a zero / non-finite normal.
    explicit ConvexPolyhedron(std::vector<Face> faces);

    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    // Box of the vertices (intersections of triples of planes that satisfy all
    // half-spaces); infinite if the body is unbounded.
    Aabb bounds() const override;
    bool solid() const override { return true; }

    std::vector<Face> faces;

  private:
    Aabb bounds_;
};

} // namespace wb::rt
