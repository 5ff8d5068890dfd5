#pragma once
// Whitted recursion (seed 000 part 2, practical 12, seed 003's termination rules):
// nearest hit; a shadow feeler to every light, attenuated by the kt of every blocker
// between the point and the light (0 as soon as one has kt < 0.01); reflection
// r = e − 2(e·n)n; refraction by seed 000's formula (7),
//   T = η·V + (η·CV − √(1 + η²(CV² − 1)))·N,  CV = −V·N,
// with total internal reflection when the root's argument is <= 0; the ray's medium
// decides η (entering: n_ray/n_body, leaving: n_body/n_air); colour *= exp(−atten·t)
// in an attenuating medium; recursion stops at maxDepth or when the weight < minWeight.
// A child's weight is parent weight × k / max(1, kr + kt) (seed 000's weight × k when
// kr + kt <= 1), so the cut-off bounds the tree for any kr, kt (issue 12), and
// TraceSettings::maxRaysPerSample bounds it when minWeight is 0.
#include "core/raytrace/scene.h"
#include "core/raytrace/shading.h"

#include <atomic>
#include <optional>

namespace wb::rt {

struct TraceSettings {
    int maxDepth = 5;        // rays of depth >= maxDepth spawn no reflected/refracted rays
    double minWeight = 0.01; // a child ray is traced only when its weight >= minWeight (seed 000)
    double opaqueKt = 0.01; // a shadow blocker with kt below this blocks the light fully (seed 000)
    // Reflected + transmitted rays one trace() may spawn in all (issue 12 point 3), the
    // backstop when minWeight is 0 (lab 07's slider allows it; kr = kt = 1 then makes
    // 2^depth rays). With minWeight 0.01 at most 100 rays a level pass the cut-off (see
    // above), so lab 07's deepest tree (depth 20) has at most 2000 < 4096 and the budget
    // never binds. Children past it are skipped (RayBudget), depth first, reflected
    // before transmitted, so the image stays deterministic.
    long maxRaysPerSample = 4096;
};

// Direction of the reflected ray: e − 2(e·n)n, renormalised.
glm::dvec3 reflectDir(const glm::dvec3& e, const glm::dvec3& n);
// Seed 000's formula (7) for a unit view direction v and a unit normal n facing
// against v (v·n <= 0), η = n_from/n_to. Empty on total internal reflection.
std::optional<glm::dvec3> refractDir(const glm::dvec3& v, const glm::dvec3& n, double eta);

// How far along a shadow feeler from surface point p (unit normal n, unit direction dir)
// the feeler starts: where it is as far off the surface as offsetRayOrigin puts a
// reflected ray's origin. The cosine is floored at 1e-3 so that a light at grazing
// incidence cannot push the start past blockers. Public so that a tool listing a
// feeler's blockers (lab 07's inspector) uses the tracer's own segment.
double feelerStart(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& dir);

// Which ray of the recursion an observer event is about.
enum class RayKind { Primary, Reflected, Refracted };
// Why a reflected or transmitted child ray was not traced.
enum class SkipReason { DepthLimit, BelowWeight, TotalInternalReflection, RayBudget };

// Sees the recursion of Tracer::trace(ray, observer) as it happens, so a tool (lab 07's
// ray inspector) can build the ray tree without a second copy of the rules. Events of
// one ray, in order: rayBegin; then missed, or hit followed per child (reflected first,
// then transmitted) by either childSkipped or the child's own events and childResult;
// attenuated when the ray's medium attenuates; rayEnd. Every method is a no-op.
struct TraceObserver {
    virtual ~TraceObserver() = default;
    // `kind` is Primary for the ray given to trace, whatever its depth.
    virtual void rayBegin(const Ray& /*ray*/, RayKind /*kind*/) {}
    // The ray hits nothing: it carries the background.
    virtual void missed(const Color& /*background*/) {}
    // The nearest hit, its material, the surface colour (texel or material colour), the
    // light samples the model was given and the model's direct colour.
    virtual void hit(const Ray& /*ray*/, const Hit& /*hit*/, const Material& /*material*/,
                     const glm::dvec3& /*surface*/, const std::vector<LightSample>& /*lights*/,
                     const Color& /*direct*/) {}
    // A child ray with k > 0 is not traced. DepthLimit is reported for each such child.
    virtual void childSkipped(RayKind /*child*/, SkipReason /*why*/) {}
    // The colour a traced child carried back (after its rayEnd), before it is × k.
    virtual void childResult(RayKind /*child*/, const Color& /*colour*/, double /*k*/) {}
    // The ray's colour is × factor = exp(−atten·t) for the medium it travelled in.
    virtual void attenuated(double /*factor*/) {}
    // What the ray carries back (also after missed).
    virtual void rayEnd(const Color& /*colour*/) {}
};

// Rays one or more trace() calls shot (Tracer::trace(ray, counts)).
struct RayCounts {
    long long primary = 0;   // eye rays (depth 0)
    long long secondary = 0; // reflected + refracted rays
    long long shadow = 0;    // shadow feelers
};

class Tracer {
  public:
    Tracer(const Scene& scene, const ShadingModel& model, TraceSettings settings = {})
        : scene_(scene), model_(model), settings_(settings) {}
    // The tracer keeps references: a temporary model would dangle.
    Tracer(const Scene&, const ShadingModel&&, TraceSettings = {}) = delete;
    Tracer(const Scene&&, const ShadingModel&, TraceSettings = {}) = delete;

    // Colour carried back along `ray`, in the model's units.
    Color trace(const Ray& ray) const;
    // The same colour, its rays added to `counts` instead of the counters below: for a
    // caller that sums them itself (renderParallel, once per tile) — the counters are
    // atomics, and a read-modify-write per ray costs ~3% of a frame.
    Color trace(const Ray& ray, RayCounts& counts) const;
    // The same colour for an eye ray whose nearest hit the caller already found (issue 21:
    // renderParallel traces eye rays in packets): `hit` is what scene.intersect(ray, 0, inf)
    // gave, hit.primitive == nullptr when it missed. The ray is counted as traced.
    Color traceFrom(const Ray& ray, const Hit& hit, RayCounts& counts) const;
    // The same colour, with a shadow cache for the hit's feelers (issue 21: neighbouring
    // eye rays of a packet): lastBlockers[i] (one entry per scene light, null at first) is
    // an opaque primitive that blocked the previous feeler to light i. Its exact test is
    // asked first; if it blocks this feeler too, the transmittance is 0 without a walk —
    // what the walk gives (it stops at an opaque blocker with 0, and its float filters
    // never drop a primitive whose exact test says yes). Each feeler leaves its own opaque
    // blocker there, or null. The rays the hit spawns use the next entries, one level of
    // lights.size() per depth: lastBlockers holds (maxDepth + 1)·lights.size() entries.
    // The same colour bit for bit whatever the entries hold (null or any primitive of the
    // scene: a transparent one or the hit's own flat primitive is not taken as a blocker).
    Color traceFrom(const Ray& ray, const Hit& hit, RayCounts& counts,
                    const Primitive** lastBlockers) const;
    // traceFrom(rays[j], hits[j], counts, lastBlockers) into out[j] for j < n <= kMaxPacket
    // (issue 21: a packet's eye rays, depth 0), the same colours bit for bit. With the
    // phong model on a scene PhongModel::lanesApply accepts, the untextured hits' direct
    // light is computed two hits at a time (PhongModel::directLanes); every other ray, and
    // every feeler and child ray, goes the single path.
    void traceFromPacket(const Ray* rays, const Hit* hits, int n, RayCounts& counts,
                         const Primitive** lastBlockers, Color* out) const;
    // The same colour, reporting the recursion to `observer` (may be null).
    Color trace(const Ray& ray, TraceObserver* observer) const;
    // Direct-light samples of every scene light at a hit (shadow feelers included).
    std::vector<LightSample> sampleLights(const Hit& hit) const;
    // The same samples into `out` (cleared first): lets the tracer reuse one buffer
    // instead of allocating a vector per hit.
    void sampleLights(const Hit& hit, std::vector<LightSample>& out) const;
    // Π kt of the blockers met by origin + t·dir for tMin < t <= dist (dist may be inf),
    // `self` (the flat primitive the feeler starts on, or null) not counted.
    double transmittance(const glm::dvec3& origin, const glm::dvec3& dir, double tMin, double dist,
                         const Primitive* self = nullptr) const;

    // Rays shot by trace() and the public sampleLights/transmittance, for the bench and
    // tests (atomics, thread-safe; trace() adds its rays once, when it returns).
    mutable std::atomic<long long> primaryRays{0}, secondaryRays{0}, shadowRays{0};

  private:
    // sampleLights with offsetRayOrigin(hit.point, hit.normal) given (traceRay needs it
    // for the reflected ray too).
    // lastBlockers: traceFrom's shadow cache, or null.
    void sampleLightsFrom(const Hit& hit, const glm::dvec3& offsetOrigin,
                          std::vector<LightSample>& out, RayCounts& counts,
                          const Primitive** lastBlockers = nullptr) const;
    // transmittance without counting the feeler (the caller counts it); *blocker (if not
    // null) gets the opaque blocker that ended the walk, or null.
    double feelerTransmittance(const glm::dvec3& origin, const glm::dvec3& dir, double tMin,
                               double dist, const Primitive* self,
                               const Primitive** blocker = nullptr) const;
    // The feeler of one sample (not counted): the shadow cache's entry (traceFrom; null
    // without a cache) asked first, then the walk, which leaves its opaque blocker there.
    double cachedFeeler(const glm::dvec3& point, const glm::dvec3& toLight, double t0, double dist,
                        const Primitive* self, const Primitive** cacheEntry) const;
    void add(const RayCounts& counts) const; // to the atomic counters
    // One ray of the recursion; `kind` is only told to the observer (the root is Primary).
    // kObserve = false compiles every event away: trace(ray) costs what it did before.
    // `budget`: child rays this trace() may still spawn (TraceSettings::maxRaysPerSample).
    // `counts`: the rays it shoots are added there (trace() adds them to the atomics).
    // `known`: the ray's nearest hit, found by the caller (primitive null: a miss), or null.
    // `lastBlockers`: the shadow cache of this ray's own feelers (traceFrom), or null.
    template <bool kObserve>
    Color traceRay(const Ray& ray, RayKind kind, TraceObserver* observer, long& budget,
                   RayCounts& counts, const Hit* known = nullptr,
                   const Primitive** lastBlockers = nullptr) const;

    // traceRay's part after the direct colour `c` of the hit: the reflected and transmitted
    // children (offsetOrigin = offsetRayOrigin(hit.point, hit.normal)) and the attenuation
    // along `ray`; the observer's events of those steps, not rayEnd.
    template <bool kObserve>
    Color spawnChildren(const Ray& ray, const Hit& hit, const Material& m,
                        const glm::dvec3& offsetOrigin, Color c, TraceObserver* observer,
                        long& budget, RayCounts& counts, const Primitive** lastBlockers) const;
    const Scene& scene_;
    const ShadingModel& model_;
    TraceSettings settings_;
};

} // namespace wb::rt
