#pragma once
// Parallelogram given by three corners as in seed 000 ("ПРЯМОУГОЛЬНИК"):
// Loc = Q1, E1 = Q2 − Loc, E2 = Q3 − Loc, Normal = E1×E2/|E1×E2|, and the dual basis
// KU = (E1·s22 − E2·s12)/D, KV = (E2·s11 − E1·s12)/D with s_ij = Ei·Ej, D = s11·s22 − s12²,
// U0 = Loc·KU, V0 = Loc·KV; a point P is inside when 0 <= u, v <= 1 with
// u = P·KU − U0, v = P·KV − V0 (evaluated here as (P − Loc)·KU, the same number
// without the cancellation of two large products). uv are also the texture coordinates.
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Rectangle : public Primitive {
  public:
    // Throws std::invalid_argument when Q1, Q2, Q3 are collinear or not finite.
    Rectangle(const glm::dvec3& q1, const glm::dvec3& q2, const glm::dvec3& q3);
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    Aabb bounds() const override;
    bool solid() const override { return false; }
    bool planar() const override { return true; }

    // (u, v) of a point of the plane, seed 000's parametrisation.
    glm::dvec2 uvOf(const glm::dvec3& p) const;

    // Seed 000's precomputed parameters, public for the worked-example tests.
    glm::dvec3 loc, e1, e2, normal, ku, kv;
    double u0, v0;
};

} // namespace wb::rt
