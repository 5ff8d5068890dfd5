#pragma once
// Infinite plane n·x = d (practical 11.2). Optionally carries a texture bound by
// three points (seed 001's TPlaneTex): p0 maps to uv (0,0), p1 to (1,0), p2 to (0,1).
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Plane : public Primitive {
  public:
    // normal: any non-zero length (normalised here); the plane passes through `point`.
    // Throws std::invalid_argument for a zero or non-finite normal.
    Plane(const glm::dvec3& point, const glm::dvec3& normal);
    // Binds texture coordinates by three points of the plane (p0 -> (0,0), p1 -> (1,0),
    // p2 -> (0,1)); throws std::invalid_argument if they are collinear.
    void bindTexture(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2);

    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    Aabb bounds() const override { return Aabb::infinite(); }
    bool solid() const override { return false; }
    bool planar() const override { return true; }

    glm::dvec3 normal; // unit normal (the "front" side)
    double d;          // plane offset: n·x = d

  private:
    bool textured_ = false;
    glm::dvec3 texOrigin_{0.0}, ku_{0.0}, kv_{0.0}; // uv = ((p-o)·ku, (p-o)·kv)
};

} // namespace wb::rt
