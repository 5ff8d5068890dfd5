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

using namespace sse2lanes;

bool PhongModel::isExactly(const ShadingModel& model) {
    return typeid(model) == typeid(PhongModel);
}

bool PhongModel::lanesApply(const Scene& scene) {
    for (const Light& l : scene.lights)
        if (l.kind != Light::Kind::Point || l.spotCutoff != 180.0) return false;
    return true;
}

namespace {
// Whether the highlight's pow can reach the colour: direct() adds transmittance ·
// (diffuse·colour + s·ks·colour) with s = pow(cos, shininess), finite and >= 0 for a cos
// >= 0 and a shininess clamped to [0, 128] (a NaN cos needs an infinite or NaN normal,
// whose diffuse term makes the colour non-finite either way). With ks = ±0 the
// product s·ks is the same zero for any such s, and with transmittance = ±0 (shadowed or
// facing away) the whole term is a zero for any s (a NaN or infinity from the colours stays
// one either way): s = 0 then gives the same colour, at most a zero of the other sign, which
// no byte sees. A NaN shininess (clamp keeps it) makes s NaN: pow is called as before.
// The eye hits of balls 4's floor (ks = 0) and its shadowed hits made most of the eye
// level's pow calls.
inline bool specularNeeded(double transmittance, double ks, double shininess) {
    return (transmittance != 0 && ks != 0) || shininess != shininess;
}

// directLanes four hits at a time: the same formula, operation for operation, in AVX's
// lanes (the scalar comments are directLanes' below).
__attribute__((target("avx"))) void directQuads(const Scene& scene, const Ray* views,
                                                const Hit* hits, unsigned lanes,
                                                const double* transmittance, Color* out) {
    using namespace avxlanes;
    for (int i = 0; i < kMaxPacket; i += 4) {
        const unsigned quadMask = (lanes >> i) & 15u;
        if (!quadMask) continue;
        // A lane outside `lanes` computes on the quad's first lane's data.
        const int first = i + __builtin_ctz(quadMask);
        int at[4];
        for (int k = 0; k < 4; ++k)
            at[k] = ((quadMask >> k) & 1u) ? i + k : first;
        const Hit* h[4] = {&hits[at[0]], &hits[at[1]], &hits[at[2]], &hits[at[3]]};
        const Material* m[4];
        double sh[4];
        for (int k = 0; k < 4; ++k) {
            m[k] = &scene.materials[size_t(h[k]->material)];
            sh[k] = std::clamp(m[k]->phongExp, 0.0, 128.0);
        }
        const auto q3 = [&](auto field) { return quad(field(0), field(1), field(2), field(3)); };
        // The material's terms: broadcast when the quad's four lanes share one material (a
        // row of eye hits mostly does: balls 4's spheres, its floor), gathered otherwise.
        const bool oneMaterial = m[0] == m[1] && m[1] == m[2] && m[2] == m[3];
        const auto qm = [&](auto field) { return oneMaterial ? splat4(field(0)) : q3(field); };
        const V4 surface = qm([&](int k) { return m[k]->colour; });
        const V4 ambient = qm([&](int k) { return m[k]->ka; }) * surface,
                 diffuse = qm([&](int k) { return m[k]->kd; }) * surface;
        const D4 ksQuad = qm([&](int k) { return m[k]->ks; });
        const V4 specular{ksQuad, ksQuad, ksQuad};
        // specularNeeded's material terms for the four lanes: ks != 0 (unordered: NaN
        // counts), a NaN shininess.
        const __m256d ksNonZero = _mm256_cmp_pd(ksQuad.v, _mm256_setzero_pd(), _CMP_NEQ_UQ);
        const __m256d shQuad = _mm256_set_pd(sh[3], sh[2], sh[1], sh[0]);
        const __m256d shNaN = _mm256_cmp_pd(shQuad, shQuad, _CMP_UNORD_Q);
        V4 c = qm([&](int k) { return m[k]->emission; }) + ambient * splat4(scene.globalAmbient);
        const V4 origin = q3([&](int k) { return views[at[k]].origin; });
        const V4 pos = q3([&](int k) { return h[k]->point; }) - origin;
        const V4 normal = q3([&](int k) { return h[k]->normal; });
        const D4 zero = splat4(0.0);
        const V4 zero3{zero, zero, zero};
        const V4 toViewer = {-pos.x, -pos.y, -pos.z};
        const D4 eyeLen = sqrt4(dot(toViewer, toViewer));
        const V4 toEye = select(greater(eyeLen, zero), toViewer / eyeLen, zero3);
        for (std::size_t li = 0; li < scene.lights.size(); ++li) {
            const Light& l = scene.lights[li];
            const V4 toLight = (splat4(l.position) - origin) - pos;
            const D4 d = sqrt4(dot(toLight, toLight));
            const V4 vp = select(greater(d, zero), toLight / d, zero3);
            const D4 denom = splat4(l.constantAttenuation) + splat4(l.linearAttenuation) * d +
                             splat4(l.quadraticAttenuation) * d * d;
            const D4 one = splat4(1.0);
            const D4 attenuation =
                select(equal(denom, one), one, one / maxOf(denom, splat4(1e-12)));
            const D4 diffuseFactor = maxOf(dot(normal, vp), zero);
            const double* trLight = &transmittance[li * kMaxPacket];
            const D4 trans{quadMask == 15u ? _mm256_loadu_pd(&trLight[i])
                                           : _mm256_set_pd(trLight[at[3]], trLight[at[2]],
                                                           trLight[at[1]], trLight[at[0]])};
            // The lanes whose pow reaches the colour: the scalar code's dv != 0 && len > 0,
            // and specularNeeded(transmittance, ks, shininess), as one mask; the half vector
            // only when a lane may need it (the floor's quads, ks = 0, and the shadowed ones
            // skip it).
            const __m256d mayNeed = _mm256_and_pd(
                _mm256_cmp_pd(diffuseFactor.v, zero.v, _CMP_NEQ_UQ),
                _mm256_or_pd(_mm256_and_pd(_mm256_cmp_pd(trans.v, zero.v, _CMP_NEQ_UQ), ksNonZero),
                             shNaN));
            alignas(32) double spec[4] = {0.0, 0.0, 0.0, 0.0};
            if (_mm256_movemask_pd(mayNeed)) {
                const V4 half = vp + toEye;
                const D4 len = sqrt4(dot(half, half));
                const D4 cosH = maxOf(dot(normal, half / len), zero);
                const __m256d need =
                    _mm256_and_pd(mayNeed, _mm256_cmp_pd(len.v, zero.v, _CMP_GT_OQ));
                alignas(32) double cv[4];
                _mm256_store_pd(cv, cosH.v);
                for (unsigned powLanes = unsigned(_mm256_movemask_pd(need)); powLanes;
                     powLanes &= powLanes - 1) {
                    const int k = __builtin_ctz(powLanes);
                    spec[k] = std::pow(cv[k], sh[k]);
                }
            }
            const D4 specularFactor{_mm256_load_pd(spec)};
            const V4 lightColour = splat4(l.colour);
            c = c + (attenuation * one) * (ambient * splat4(l.ambient) +
                                           trans * ((diffuseFactor * diffuse) * lightColour +
                                                    (specularFactor * specular) * lightColour));
        }
        alignas(32) double cx[4], cy[4], cz[4];
        _mm256_store_pd(cx, c.x.v);
        _mm256_store_pd(cy, c.y.v);
        _mm256_store_pd(cz, c.z.v);
        for (int k = 0; k < 4; ++k)
            if ((quadMask >> k) & 1u) out[i + k] = Color(cx[k], cy[k], cz[k]);
    }
}
} // namespace

void PhongModel::directLanes(const Scene& scene, const Ray* views, const Hit* hits, unsigned lanes,
                             const double* transmittance, Color* out, LaneWidth width) {
    static const bool avx = __builtin_cpu_supports("avx");
    if (width == LaneWidth::Four || (width == LaneWidth::Best && avx)) {
        directQuads(scene, views, hits, lanes, transmittance, out);
        return;
    }
    // Lanes 2i+1 (low half) and 2i (high half): _mm_set_pd takes the high lane first.
    for (int i = 0; i + 1 < kMaxPacket; i += 2) {
        const unsigned pairMask = (lanes >> i) & 3u;
        if (!pairMask) continue;
        // A lane outside `lanes` computes on its partner's data (never NaN from garbage).
        const int a = (pairMask & 1u) ? i : i + 1, b = (pairMask & 2u) ? i + 1 : i;
        const Hit &ha = hits[a], &hb = hits[b];
        const Material &ma = scene.materials[size_t(ha.material)],
                       &mb = scene.materials[size_t(hb.material)];
        // direct()'s material terms: ambient = ka·colour, diffuse = kd·colour, specular(ks).
        const V2 surface = pair(ma.colour, mb.colour);
        const V2 ambient = pair(ma.ka, mb.ka) * surface, diffuse = pair(ma.kd, mb.kd) * surface;
        const D2 ks = pair(ma.ks, mb.ks);
        const V2 specular{ks, ks, ks};
        const double shA = std::clamp(ma.phongExp, 0.0, 128.0),
                     shB = std::clamp(mb.phongExp, 0.0, 128.0);
        V2 c = pair(ma.emission, mb.emission) + ambient * splat(scene.globalAmbient);
        const V2 origin = pair(views[a].origin, views[b].origin);
        const V2 pos = pair(ha.point, hb.point) - origin;
        const V2 normal = pair(ha.normal, hb.normal);
        const D2 zero = splat(0.0);
        const V2 zero3{zero, zero, zero};
        // eyeDirection(true, pos) = unit(−pos).
        const V2 toViewer = {-pos.x, -pos.y, -pos.z};
        const D2 eyeLen = sqrt2(dot(toViewer, toViewer));
        const V2 toEye = select(_mm_cmpgt_pd(eyeLen.v, zero.v), toViewer / eyeLen, zero3);
        for (std::size_t li = 0; li < scene.lights.size(); ++li) {
            const Light& l = scene.lights[li];
            // lightFactors for a point light (w = 1) without a spot: gl.position =
            // l.position − view.origin.
            const V2 toLight = (splat(l.position) - origin) - pos;
            const D2 d = sqrt2(dot(toLight, toLight));
            const V2 vp = select(_mm_cmpgt_pd(d.v, zero.v), toLight / d, zero3);
            const D2 denom = splat(l.constantAttenuation) + splat(l.linearAttenuation) * d +
                             splat(l.quadraticAttenuation) * d * d;
            const D2 one = splat(1.0);
            const D2 attenuation =
                select(_mm_cmpeq_pd(denom.v, one.v), one, one / maxOf(denom, splat(1e-12)));
            const D2 diffuseFactor = maxOf(dot(normal, vp), zero);
            // The highlight: std::pow per lane where the scalar code calls it.
            const V2 half = vp + toEye;
            const D2 len = sqrt2(dot(half, half));
            const D2 cosH = maxOf(dot(normal, half / len), zero);
            alignas(16) double dv[2], lv[2], cv[2];
            _mm_store_pd(dv, diffuseFactor.v);
            _mm_store_pd(lv, len.v);
            _mm_store_pd(cv, cosH.v);
            // Index 1 is the high lane (a), index 0 the low lane (b).
            const double trA = transmittance[li * kMaxPacket + std::size_t(a)],
                         trB = transmittance[li * kMaxPacket + std::size_t(b)];
            const double specA = dv[1] != 0 && lv[1] > 0 && specularNeeded(trA, ma.ks, shA)
                                     ? std::pow(cv[1], shA)
                                     : 0.0;
            const double specB = dv[0] != 0 && lv[0] > 0 && specularNeeded(trB, mb.ks, shB)
                                     ? std::pow(cv[0], shB)
                                     : 0.0;
            const D2 specularFactor = pair(specA, specB);
            const D2 trans = pair(trA, trB);
            const V2 lightColour = splat(l.colour);
            // attenuation · spot (1 without a cone) · (ambient·l.ambient + shadow ·
            // (diffuse·d·colour + specular·s·colour)), as direct() groups it.
            c = c + (attenuation * one) * (ambient * splat(l.ambient) +
                                           trans * ((diffuseFactor * diffuse) * lightColour +
                                                    (specularFactor * specular) * lightColour));
        }
        alignas(16) double cx[2], cy[2], cz[2];
        _mm_store_pd(cx, c.x.v);
        _mm_store_pd(cy, c.y.v);
        _mm_store_pd(cz, c.z.v);
        if (pairMask & 1u) out[i] = Color(cx[1], cy[1], cz[1]);
        if (pairMask & 2u) out[i + 1] = Color(cx[0], cy[0], cz[0]);
    }
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
