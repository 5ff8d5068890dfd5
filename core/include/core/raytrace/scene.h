#pragma once
// Everything the tracer needs: primitives, materials, lights, background and the
// course model's global parameters. Scenes are built in code; files come later.
// Queries go through an Aggregate so that a BVH can replace the brute-force loop.
#include "core/raytrace/light.h"
#include "core/raytrace/material.h"
#include "core/raytrace/primitive.h"

#include <functional>
#include <memory>
#include <vector>

namespace wb::rt {

class Scene;

// The most rays Aggregate::intersectPacket takes at once.
constexpr int kMaxPacket = 8;

// A set of primitives answering ray queries. The default loops over all of them.
class Aggregate {
  public:
    virtual ~Aggregate() = default;
    // Nearest hit in (tMin, tMax].
    virtual bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const = 0;
    // Calls `visit` with the nearest hit of every primitive the ray meets in (tMin, tMax]
    // (each primitive once, in no particular order); stops early when visit returns false.
    virtual void forEachHit(const Ray& ray, double tMin, double tMax,
                            const std::function<bool(const Hit&)>& visit) const = 0;
    // The same walk for shadow feelers, which need only who blocks (its material):
    // `visit` gets each primitive the ray meets in (tMin, tMax]. The default asks
    // forEachHit; BruteForce and Bvh ask Primitive::occluded, which may skip the hit record.
    // `skip` (issue 21): a FLAT primitive (Primitive::planar) the feeler starts on; it is
    // never asked (a ray leaving a plane meets it again at no t > 0, so its exact test could
    // only say "no" or report rounding error: an exact argument, not an epsilon). Curved
    // primitives must not be passed: a ray leaving a sphere may meet it again.
    virtual void forEachBlocker(const Ray& ray, double tMin, double tMax,
                                const std::function<bool(const Primitive&)>& visit,
                                const Primitive* skip = nullptr) const {
        forEachHit(ray, tMin, tMax,
                   [&](const Hit& h) { return h.primitive == skip || visit(*h.primitive); });
    }
    // Nearest hits of up to kMaxPacket rays at once (issue 21: coherent rays, e.g. a row
    // of eye rays, share one walk in a Bvh): for each bit j of `lanes`, hits[j] and bit j
    // of the result as intersect(rays[j], tMin[j], tMax[j], hits[j]) gives them. The
    // default asks intersect ray by ray.
    virtual unsigned intersectPacket(const Ray* rays, const double* tMin, const double* tMax,
                                     Hit* hits, unsigned lanes) const {
        unsigned found = 0;
        for (int j = 0; j < kMaxPacket; ++j)
            if ((lanes >> j) & 1)
                found |= unsigned(intersect(rays[j], tMin[j], tMax[j], hits[j])) << j;
        return found;
    }
    // Issue 21: whether occludedPacket below walks the rays together (Bvh); false: the
    // default asks forEachBlocker ray by ray, and a caller may as well do that itself. (A
    // virtual, not a dynamic_cast to Bvh in the tracer: a student's object that compiles
    // tracer.cpp in, under -fsanitize=vptr, would need Bvh's typeinfo from core.)
    virtual bool hasOccludedPacket() const { return false; }
    // Bit j, for each bit j of `lanes`: some primitive meets rays[j] in (tMin[j], tMax[j]]
    // (skip[j], when `skip` is given, not asked; the same flat-primitive rule as
    // forEachBlocker's).
    virtual unsigned occludedPacket(const Ray* rays, const double* tMin, const double* tMax,
                                    const Primitive* const* skip, unsigned lanes) const {
        unsigned blocked = 0;
        for (int j = 0; j < kMaxPacket; ++j)
            if ((lanes >> j) & 1) {
                bool any = false;
                forEachBlocker(
                    rays[j], tMin[j], tMax[j],
                    [&](const Primitive&) {
                        any = true;
                        return false;
                    },
                    skip ? skip[j] : nullptr);
                blocked |= unsigned(any) << j;
            }
        return blocked;
    }
};

class BruteForce : public Aggregate {
  public:
    explicit BruteForce(const std::vector<std::unique_ptr<Primitive>>& prims) : prims_(prims) {}
    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const override;
    void forEachHit(const Ray& ray, double tMin, double tMax,
                    const std::function<bool(const Hit&)>& visit) const override;
    void forEachBlocker(const Ray& ray, double tMin, double tMax,
                        const std::function<bool(const Primitive&)>& visit,
                        const Primitive* skip = nullptr) const override;

  private:
    const std::vector<std::unique_ptr<Primitive>>& prims_;
};

class Scene {
  public:
    Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // Adds a material, returns its index. materials[0] is a default Material{} that
    // exists from construction, so index 0 is always valid.
    int addMaterial(const Material& m);
    // Adds a primitive with material index `materialIndex` (must exist: std::out_of_range).
    template <class P> P& add(P prim, int materialIndex) {
        auto p = std::make_unique<P>(std::move(prim));
        P& ref = *p;
        addPrimitive(std::move(p), materialIndex);
        return ref;
    }
    void addPrimitive(std::unique_ptr<Primitive> prim, int materialIndex);
    // Replaces the brute-force loop (nullptr restores it). The aggregate must refer to
    // this scene's primitives and outlive its use.
    void setAggregate(const Aggregate* aggregate) { aggregate_ = aggregate; }

    bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
        return aggregate().intersect(ray, tMin, tMax, hit);
    }
    const Aggregate& aggregate() const { return aggregate_ ? *aggregate_ : bruteForce_; }

    std::vector<std::unique_ptr<Primitive>> primitives;
    std::vector<Material> materials;
    std::vector<Light> lights;
    glm::dvec3 background{128 / 255.0, 207 / 255.0, 1.0}; // seed 000's (128,207,255)
    glm::dvec3 ambient{1.0};       // course model BA, 0..1 (seed 000: (255,255,255))
    double distScale = 30.0;       // course model: SH = distScale/dist for point lights; 0 = SH 1
    glm::dvec3 globalAmbient{0.2}; // phong model GL_LIGHT_MODEL_AMBIENT
    Medium air;                    // medium of primary rays and outside every body

  private:
    BruteForce bruteForce_;
    const Aggregate* aggregate_ = nullptr;
};

} // namespace wb::rt
