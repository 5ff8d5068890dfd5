#pragma once
// Axis-aligned second-order surfaces with lower and upper cutting planes (seed 001):
// only the part with zLow <= z <= zHigh is kept (no caps: a cut surface is open).
//   ellipsoid:   (x−x0)²/A² + (y−y0)²/B² + (z−z0)²/C² = 1
//   paraboloid:  (x−x0)²/A² + (y−y0)²/B² = (z−z0)/C   (opening towards +z for C > 0)
//   hyperboloid: (x−x0)²/A² + (y−y0)²/B² − (z−z0)²/C² = 1 (one sheet; this is the
//                equation seed 001 prints under the name "paraboloid")
// Texture coordinates: the ellipsoid mapping of seed 001 (longitude, latitude of the
// point on the unit sphere) for the ellipsoid; (angle, height between the cuts) otherwise.
#include "core/raytrace/primitive.h"

namespace wb::rt {

class Quadric : public Primitive {
  public:
    enum class Kind { Ellipsoid, Paraboloid, Hyperboloid };
    // axes A, B, C > 0 and finite; zLow < zHigh (±infinity = no cut). Throws
    // std::invalid_argument otherwise.
    Quadric(Kind kind, const glm::dvec3& centre, const glm::dvec3& axes, double zLow = -1e300,
            double zHigh = 1e300);

    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    glm::dvec2 textureCoords(const Hit& hit) const override;
    Aabb bounds() const override;
    // Only an ellipsoid the cuts do not open is a closed body.
    bool solid() const override;

    Kind kind;
    glm::dvec3 centre, axes;
    double zLow, zHigh;
};

} // namespace wb::rt
