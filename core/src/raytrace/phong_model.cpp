#include "core/raytrace/phong_model.h"

#include "core/lighting.h"
#include "core/raytrace/scene.h"
#include "lanes_avx.h"
#include "lanes_sse2.h"

#include <algorithm>
#include <cmath>
#include <typeinfo>

namespace wb::rt {

namespace {
double clamp01(double x) {
    return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0;
}
// std::lround for 0 <= v <= 255 (halves away from zero) without the libm call: the
// truncation is the floor there and v − floor(v) is exact.
uint8_t roundByte(double v) {
    const int i = int(v);
    return uint8_t(i + (v - double(i) >= 0.5 ? 1 : 0));
}
} // namespace

Color PhongModel::background(const Scene& scene) const {
    return scene.background;
}

Color PhongModel::direct(const Scene& scene, const Ray& view, const Hit& hit, const Material& m,
                         const glm::dvec3& surface, const std::vector<LightSample>& lights) const {
    // The material as GL would have it (its colours as dvec3: the same values).
    const glm::dvec3 ambient = m.ka * surface, diffuse = m.kd * surface, specular(m.ks);
    const double shininess = std::clamp(m.phongExp, 0.0, 128.0);
    Color c = m.emission + ambient * scene.globalAmbient;
    // Eye space = world translated so that the viewer (the ray's origin) is at 0.
    const glm::dvec3 pos = hit.point - view.origin;
    const glm::dvec3 toEye = wb::eyeDirection(true, pos); // once per hit, not per light
    // Only the fields lightFactors reads are set per light (not its colours).
    wb::Light gl;
    for (const LightSample& s : lights) {
        const Light& l = *s.light;
        gl.position = l.kind == Light::Kind::Point ? glm::dvec4(l.position - view.origin, 1)
                                                   : glm::dvec4(-l.direction, 0);
        gl.spotDirection = l.spotDirection;
        gl.spotExponent = l.spotExponent;
        gl.spotCutoff = l.spotCutoff;
        gl.constantAttenuation = l.constantAttenuation;
        gl.linearAttenuation = l.linearAttenuation;
        gl.quadraticAttenuation = l.quadraticAttenuation;
        // The factors only: lightTerms' colour sum is not used here.
        const wb::LightTerms t = wb::lightFactors(gl, shininess, toEye, pos, hit.normal);
        // The shadow feeler scales what comes from the light directly, not its ambient.
        c += t.attenuation * t.spot *
             (ambient * l.ambient + s.transmittance * (t.diffuse * diffuse * l.colour +
                                                       t.specular * specular * l.colour));
    }
    return c;
}

bool PhongModel::isExactly(const ShadingModel& model) {
    return typeid(model) == typeid(PhongModel);
}

bool PhongModel::lanesApply(const Scene& scene) {
    for (const Light& l : scene.lights)
        if (l.kind != Light::Kind::Point || l.spotCutoff != 180.0) return false;
    return true;
}

// directLanes' loop once per lane width (phong_lanes_impl.h): four lanes compiled for AVX
// alone (no FMA), two in baseline SSE2.
namespace avxlanes {
#pragma GCC push_options
#pragma GCC target("avx")
#include "phong_lanes_impl.h"
#pragma GCC pop_options
} // namespace avxlanes
namespace sse2lanes {
#include "phong_lanes_impl.h"
} // namespace sse2lanes

void PhongModel::directLanes(const Scene& scene, const Ray* views, const Hit* hits, unsigned lanes,
                             const double* transmittance, Color* out, LaneWidth width) {
    static const bool avx = __builtin_cpu_supports("avx");
    if (width == LaneWidth::Four || (width == LaneWidth::Best && avx)) {
        avxlanes::directGroups(scene, views, hits, lanes, transmittance, out);
        return;
    }
    sse2lanes::directGroups(scene, views, hits, lanes, transmittance, out);
}

Color PhongModel::addScaled(const Color& base, const Color& term, double k) const {
    return base + k * term;
}

Color PhongModel::scale(const Color& c, double s) const {
    return c * s;
}

void PhongModel::toRgb8(const Color& c, uint8_t out[3]) const {
    for (int i = 0; i < 3; ++i)
        out[i] = roundByte(clamp01(c[i]) * 255.0);
}

} // namespace wb::rt
