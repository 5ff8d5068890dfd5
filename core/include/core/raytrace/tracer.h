#pragma once
// Whitted recursion (seed 000 part 2, practical 12, seed 003's termination rules):
// nearest hit; a shadow feeler to every light, attenuated by the kt of every blocker
// between the point and the light (0 as soon as one has kt < 0.01); reflection
// r = e − 2(e·n)n; refraction by seed 000's formula (7),
//   T = η·V + (η·CV − √(1 + η²(CV² − 1)))·N,  CV = −V·N,
// with total internal reflection when the root's argument is <= 0; the ray's medium
// decides η (entering: n_ray/n_body, leaving: n_body/n_air); colour *= exp(−atten·t)
// in an attenuating medium; recursion stops at maxDepth or when the weight < minWeight.
#include "core/raytrace/scene.h"
#include "core/raytrace/shading.h"

#include <atomic>
#include <optional>

namespace wb::rt {

struct TraceSettings {
    int maxDepth = 5;        // rays of depth >= maxDepth spawn no reflected/refracted rays
    double minWeight = 0.01; // a child ray is traced only when its weight >= minWeight (seed 000)
    double opaqueKt = 0.01; // a shadow blocker with kt below this blocks the light fully (seed 000)
};

// Direction of the reflected ray: e − 2(e·n)n, renormalised.
glm::dvec3 reflectDir(const glm::dvec3& e, const glm::dvec3& n);
// Seed 000's formula (7) for a unit view direction v and a unit normal n facing
// against v (v·n <= 0), η = n_from/n_to. Empty on total internal reflection.
std::optional<glm::dvec3> refractDir(const glm::dvec3& v, const glm::dvec3& n, double eta);

class Tracer {
  public:
    Tracer(const Scene& scene, const ShadingModel& model, TraceSettings settings = {})
        : scene_(scene), model_(model), settings_(settings) {}
    // The tracer keeps references: a temporary model would dangle.
    Tracer(const Scene&, const ShadingModel&&, TraceSettings = {}) = delete;
    Tracer(const Scene&&, const ShadingModel&, TraceSettings = {}) = delete;

    // Colour carried back along `ray`, in the model's units.
    Color trace(const Ray& ray) const;
    // Direct-light samples of every scene light at a hit (shadow feelers included).
    std::vector<LightSample> sampleLights(const Hit& hit) const;
    // Π kt of the blockers met by origin + t·dir for tMin < t <= dist (dist may be inf).
    double transmittance(const glm::dvec3& origin, const glm::dvec3& dir, double tMin,
                         double dist) const;

    // Counters for the bench and tests (relaxed atomics: cheap, thread-safe).
    mutable std::atomic<long long> primaryRays{0}, secondaryRays{0}, shadowRays{0};

  private:
    const Scene& scene_;
    const ShadingModel& model_;
    TraceSettings settings_;
};

} // namespace wb::rt
