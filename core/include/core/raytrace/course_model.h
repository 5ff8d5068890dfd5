#pragma once
// Seed 000's shading model exactly (formula (3) and the Whitted sum (9)):
//   B = BA·C·KA + Σ_lights [ BL·C·KD·SH·(L·N) + BL·KS·SH·(H·N)^P ] + BR·KR + BT·KT
// with colours in 0..255, SH = distScale/dist · Π kt(blockers), H = normalize(L − V).
// Its worked numbers come out only with its colour arithmetic, which is reproduced
// here: a colour is three integers; colour × colour = c1·c2/255, colour × number and
// every term is converted to an integer by rounding to nearest with ties to even (the
// conversion of the seed's language: 10.5 -> 10, 36.5 -> 36, 3.9375 -> 4) and sums are
// clamped to 0..255.
#include "core/raytrace/shading.h"

namespace wb::rt {

class CourseModel : public ShadingModel {
  public:
    Color background(const Scene& scene) const override;
    Color direct(const Scene& scene, const Ray& view, const Hit& hit, const Material& material,
                 const glm::dvec3& surface, const std::vector<LightSample>& lights) const override;
    Color addScaled(const Color& base, const Color& term, double k) const override;
    Color scale(const Color& c, double s) const override;
    void toRgb8(const Color& c, uint8_t out[3]) const override;

    // The colour arithmetic, public for the worked-example tests.
    static Color fromUnit(const glm::dvec3& c);       // 0..1 -> integer 0..255
    static Color mul(const Color& a, const Color& b); // a·b/255, rounded
    static Color mulBy(const Color& a, double s);     // a·s, rounded, clamped
    static Color add(const Color& a, const Color& b); // clamped to 0..255
    static double roundEven(double x);                // ties to even

    // Intermediate figures of the last direct() call for a single light, for tests
    // and the lab panel (not thread-safe; only filled when `trace` is non-null).
    struct Trace {
        Color ambient{0.0};         // BA·C·KA
        double sh = 0.0;            // distScale/dist · transmittance
        double ln = 0.0;            // L·N
        double diffuseFactor = 0.0; // SH·LN·KD
        Color diffuse{0.0};         // BL·C · (SH·LN·KD)
        Color afterDiffuse{0.0};
        glm::dvec3 halfVector{0.0};  // n = normalize(L − V)
        double nn = 0.0;             // n·N
        double nnp = 0.0;            // (n·N)^P
        double specularFactor = 0.0; // SH·KS·NNP
        Color specular{0.0};         // BL · specularFactor
        Color afterSpecular{0.0};
    };
    mutable Trace* trace = nullptr;
};

} // namespace wb::rt
