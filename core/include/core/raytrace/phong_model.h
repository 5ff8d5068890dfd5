#pragma once
// The OpenGL fixed-function lighting equation of lab 2 (core/lighting.h, shared with
// the rasterizer) used as the tracer's local model, so lab 7's rasterized and traced
// images of one scene are comparable: emission + global ambient + Σ att·spot·(ambient
// + shadow·(diffuse + specular)), local viewer at the ray's origin, colours 0..1;
// reflected and transmitted light is added before the final clamp.
#include "core/raytrace/shading.h"

namespace wb::rt {

class PhongModel : public ShadingModel {
  public:
    Color background(const Scene& scene) const override;
    Color direct(const Scene& scene, const Ray& view, const Hit& hit, const Material& material,
                 const glm::dvec3& surface, const std::vector<LightSample>& lights) const override;
    Color addScaled(const Color& base, const Color& term, double k) const override;
    Color scale(const Color& c, double s) const override;
    void toRgb8(const Color& c, uint8_t out[3]) const override;
};

} // namespace wb::rt
