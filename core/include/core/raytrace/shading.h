#pragma once
// The shading-model interface the tracer calls. A model decides the colour units
// and the arithmetic (the course model: integers 0..255 rounded after every
// operation; the phong model: doubles 0..1), the tracer decides which rays to shoot.
#include "core/raytrace/hit.h"
#include "core/raytrace/light.h"
#include "core/raytrace/material.h"
#include "core/raytrace/ray.h"

#include <cstdint>
#include <vector>

namespace wb::rt {

class Scene;

using Color = glm::dvec3; // in the model's own units

// What the tracer found out about one light for one hit point.
struct LightSample {
    const Light* light = nullptr;
    glm::dvec3 toLight{0, 0, 1}; // unit vector from the point to the light
    double distance = 0.0;       // to a point light; +infinity for a directional one
    double transmittance = 1.0;  // product of kt of every blocker (0 if one is opaque)
};

class ShadingModel {
  public:
    virtual ~ShadingModel() = default;
    // Colour of a ray that hits nothing.
    virtual Color background(const Scene& scene) const = 0;
    // Direct light at a hit (ambient + every light); `surface` is the material colour
    // (or texel) in 0..1; one sample per scene light, in the scene's order.
    virtual Color direct(const Scene& scene, const Ray& view, const Hit& hit,
                         const Material& material, const glm::dvec3& surface,
                         const std::vector<LightSample>& lights) const = 0;
    // base + k·term (a reflected or transmitted contribution).
    virtual Color addScaled(const Color& base, const Color& term, double k) const = 0;
    // c·s (attenuation in a medium).
    virtual Color scale(const Color& c, double s) const = 0;
    // To 8-bit RGB; non-finite channels become 0.
    virtual void toRgb8(const Color& c, uint8_t out[3]) const = 0;
};

} // namespace wb::rt
