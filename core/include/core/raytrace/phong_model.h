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
    // direct() for up to kMaxPacket hits at once (issue 21: a packet's eye hits), the
    // vectors and dot products of four hits at a time in AVX's double lanes where the CPU
    // has AVX, else two at a time in SSE2's (`width`): for each lane j of `lanes`, out[j]
    // is direct(scene, views[j], hits[j], its material, the material's colour, samples)
    // bit for bit — the same IEEE operations in the same order (no FMA: the library is
    // built for baseline x86-64 and the AVX code enables AVX alone), std::pow per lane. The samples
    // are given by their transmittances alone, transmittance[li * kMaxPacket + j] for scene light
    // li; every scene light must be a point light without a spot cone and no hit's material
    // textured (lanesApply() says whether a scene qualifies). Other lanes are not read.
    // Static (the model has no state): a call through a PhongModel reference in the tracer
    // made UBSan's vptr check refer to this class's type info (see isExactly).
    // Four hits at a time in AVX's lanes where the CPU has AVX (Best), or as asked (tests:
    // Four only where __builtin_cpu_supports("avx")).
    enum class LaneWidth { Best, Two, Four };
    static void directLanes(const Scene& scene, const Ray* views, const Hit* hits, unsigned lanes,
                            const double* transmittance, Color* out,
                            LaneWidth width = LaneWidth::Best);
    // Whether directLanes() may stand in for direct() on this scene's untextured hits.
    static bool lanesApply(const Scene& scene);
    // Whether `model` is a PhongModel itself (a subclass may shade otherwise). Out of line:
    // a typeid(PhongModel) in the tracer put a reference to this class's type info into the
    // tracer's object, which a student's exercise object loaded by dlopen (the handout
    // test's cheats, in the sanitizer build) could not resolve.
    static bool isExactly(const ShadingModel& model);
};

} // namespace wb::rt
