#pragma once
// The interface every traced object implements (seed 000's IGREENCluster.Intersect),
// shaped so an acceleration structure can be added later: a bounding box, the
// nearest hit inside an interval [tMin, tMax], and an any-hit query for shadow feelers.
#include "core/raytrace/aabb.h"
#include "core/raytrace/hit.h"
#include "core/raytrace/ray.h"

namespace wb::rt {

class Primitive {
  public:
    virtual ~Primitive() = default;

    // Nearest hit with tMin < t <= tMax. On success fills every field of `hit`
    // (t, point, normals, cosVN, entering, solid, hasUv, material, primitive; uv
    // unless the primitive computes it in textureCoords) and returns true; on failure leaves `hit`
    // untouched. Never produces NaN/Inf: degenerate primitives simply report no hit.
    virtual bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const = 0;

    // Any hit in (tMin, tMax]: the shadow-feeler query. The default calls intersect().
    virtual bool occluded(const Ray& ray, double tMin, double tMax) const {
        Hit h;
        return intersect(ray, tMin, tMax, h);
    }

    // Texture coordinates of `hit` (a hit on this primitive with hasUv). Where they cost
    // atan2/asin (sphere, quadric) they are computed here, on demand, from the hit's
    // point or normal, bit for bit as intersect() would have: intersect() runs for every
    // candidate and shadow blocker, but only the shading of a textured material needs uv.
    virtual glm::dvec2 textureCoords(const Hit& hit) const { return hit.uv; }

    // A box enclosing the primitive (infinite for unbounded ones).
    virtual Aabb bounds() const = 0;

    // True for closed bodies (sphere, box, polyhedron, capped cylinder/cone, uncut
    // ellipsoid, closed meshes): a ray crossing their surface changes medium.
    virtual bool solid() const = 0;

    // True for flat primitives (triangle, rectangle, plane): a line meets them at most
    // once, so a shadow feeler starting on one can never be blocked by that same one.
    // The tracer skips it (issue 12): far from the origin the feeler's offset is smaller
    // than the error of its intersection with its own surface (acne from ~1e5 on).
    virtual bool planar() const { return false; }

    // For a shadow feeler from `point` (a hit on this non-flat primitive): false, or true
    // with the terms a caller needs to prove, feeler by feeler, that this primitive's own
    // exact test cannot report it blocking (the Sphere's: f = point − centre and
    // c = |f|² − r² exactly as its test computes them; the tracer's sphereCannotBlock).
    virtual bool feelerSelfTerms(const glm::dvec3& point, glm::dvec3& f, double& c) const {
        (void)point, (void)f, (void)c;
        return false;
    }

    int material = 0; // index into Scene::materials

  protected:
    // Completes a hit given t, point and outward normal: turns the normal against
    // the ray, sets cosVN, entering, solid, material and primitive (seed 000:
    // "the normal must face against the tracing ray").
    void finishHit(const Ray& ray, Hit& hit) const { finishHit(ray, hit, solid()); }
    // The same, for a caller that knows what solid() returns (Triangle's, Sphere's exact
    // tests): no virtual call. Inline: issue 21, ninth session — the call and the virtual
    // solid() were ~40 instructions of every confirmed hit on balls 4.
    void finishHit(const Ray& ray, Hit& hit, bool isSolid) const {
        const double c = glm::dot(ray.direction, hit.outwardNormal);
        if (c < 0) {
            hit.normal = hit.outwardNormal;
            hit.cosVN = c;
        } else {
            hit.normal = -hit.outwardNormal;
            hit.cosVN = -c;
        }
        hit.solid = isSolid;
        hit.entering = isSolid && c < 0;
        hit.material = material;
        hit.primitive = this;
    }
};

} // namespace wb::rt
