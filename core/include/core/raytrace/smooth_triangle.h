#pragma once
// A triangle shaded with interpolated vertex normals (NFF `pp`, OBJ `vn`): the hit is
// the watertight Triangle's; the shading normal is the barycentric blend of the vertex
// normals, turned to the geometric normal's side so a ray never sees a back face.
#include "core/raytrace/triangle.h"

namespace wb::rt {

class SmoothTriangle : public Triangle {
  public:
    // Vertex normals of any non-zero length (normalised here); a zero or non-finite
    // normal is replaced by the geometric normal.
    SmoothTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                   const glm::dvec3& na, const glm::dvec3& nb, const glm::dvec3& nc,
                   bool closedMesh = false);
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;

    glm::dvec3 n0, n1, n2; // unit vertex normals
};

} // namespace wb::rt
