#pragma once
// Watertight ray–triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): the ray is sheared so it runs along +z and the edge
// functions are evaluated in 2D; two triangles sharing an edge compute the same edge
// function for it, so no ray passes between them. Edge functions that come out as
// exactly 0 are recomputed in long double, as the paper recomputes in double.
#include "core/raytrace/primitive.h"

#include <cmath>
#include <utility>

namespace wb::rt {

// The ray's part of the watertight test: the axes (kz the dominant axis of the direction,
// kx/ky swapped for a negative d[kz]) and the shear. Triangle::intersect computes it in
// every call; a caller that tests many triangles with one ray (the BVH) computes it once
// and passes it to intersectSheared, which then gives the same bits.
struct TriangleShear {
    int kx, ky, kz;    // set by triangleShear (no defaults: the BVH keeps one per ray unset
    double sx, sy, sz; // until its first triangle); d[kx]/d[kz], d[ky]/d[kz], 1/d[kz]
};
// Inline, one definition for Triangle::intersect and the BVH walk's leaf set-up, which
// it is compiled into (issue 21: an out-of-line call there cost ~2% of a mesh shadow ray's
// instructions); its three divisions round the same in every instruction set.
inline TriangleShear triangleShear(const glm::dvec3& dir) {
    // Woop–Benthin–Wald: kz = dominant axis of the direction; swap kx, ky to keep winding.
    // Components read through a pointer: glm's operator[] is a switch, a branch per read
    // (issue 21: ~7% of a balls 4 eye ray's instructions went to those switches).
    const double d[3] = {dir.x, dir.y, dir.z};
    const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
    TriangleShear s;
    s.kz = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    s.kx = s.kz == 2 ? 0 : s.kz + 1;
    s.ky = s.kx == 2 ? 0 : s.kx + 1;
    if (d[s.kz] < 0) std::swap(s.kx, s.ky);
    s.sx = d[s.kx] / d[s.kz];
    s.sy = d[s.ky] / d[s.kz];
    s.sz = 1.0 / d[s.kz];
    return s;
}

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
    bool solid() const final { return closed_; } // final: intersectSheared passes closed_
    bool planar() const override { return true; }

    glm::dvec3 v0, v1, v2;

  private:
    glm::dvec3 normal_; // unit, (v1−v0)×(v2−v0) (counter-clockwise = front); 0 if degenerate
    bool closed_;
    // normal_ is 0 (n / len of a finite len > 0 has a component of at least 1/√3): one byte
    // to test in every exact test, not three compares (issue 21, ninth session).
    bool degenerate_;
};

} // namespace wb::rt
