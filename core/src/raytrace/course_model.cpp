#include "core/raytrace/course_model.h"

#include "core/raytrace/scene.h"

#include <algorithm>
#include <cfenv>
#include <cmath>

namespace wb::rt {

namespace {
// A light at (numerically) zero distance would give SH = distScale/0; the
// distance is floored here so the result stays finite (and simply saturates).
constexpr double kMinLightDistance = 1e-9;

double clamp255(double x) {
    return std::isfinite(x) ? std::clamp(x, 0.0, 255.0) : 0.0;
}
} // namespace

double CourseModel::roundEven(double x) {
    // std::nearbyint rounds in the current mode; the default mode is to nearest, ties to
    // even, which is what the seed's integer conversion does. Set it explicitly anyway.
    const int old = std::fegetround();
    if (old != FE_TONEAREST) std::fesetround(FE_TONEAREST);
    const double r = std::nearbyint(x);
    if (old != FE_TONEAREST) std::fesetround(old);
    return r;
}

Color CourseModel::fromUnit(const glm::dvec3& c) {
    Color r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(roundEven(c[i] * 255.0));
    return r;
}

Color CourseModel::mul(const Color& a, const Color& b) {
    Color r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(roundEven(a[i] * b[i] / 255.0));
    return r;
}

Color CourseModel::mulBy(const Color& a, double s) {
    Color r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(roundEven(a[i] * s));
    return r;
}

Color CourseModel::add(const Color& a, const Color& b) {
    Color r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(a[i] + b[i]);
    return r;
}

Color CourseModel::background(const Scene& scene) const {
    return fromUnit(scene.background);
}

Color CourseModel::direct(const Scene& scene, const Ray& view, const Hit& hit, const Material& m,
                          const glm::dvec3& surface, const std::vector<LightSample>& lights) const {
    const Color c = fromUnit(surface);
    Color b = mulBy(mul(fromUnit(scene.ambient), c), m.ka); // BA·C·KA
    if (trace) *trace = Trace{}, trace->ambient = b;
    const glm::dvec3& n = hit.normal; // faces against the view ray
    for (const LightSample& s : lights) {
        const Color bl = fromUnit(s.light->colour);
        double sh = s.transmittance;
        if (s.light->kind == Light::Kind::Point && scene.distScale > 0)
            sh *= scene.distScale / std::max(s.distance, kMinLightDistance);
        if (trace) trace->sh = sh;
        if (!(sh > 0)) continue;
        const double ln = glm::dot(s.toLight, n);
        if (trace) trace->ln = ln;
        if (!(ln > 0)) continue; // light behind the surface
        // Diffuse: (BL·C)·(SH·LN·KD).
        const double fd = sh * ln * m.kd;
        const Color bd = mulBy(mul(bl, c), fd);
        b = add(b, bd);
        if (trace) trace->diffuseFactor = fd, trace->diffuse = bd, trace->afterDiffuse = b;
        // Specular with the micro-facet normal n = normalize(L − V): BL·(SH·KS·(n·N)^P).
        const glm::dvec3 hv = s.toLight - view.direction;
        const double hl = glm::length(hv);
        if (!(hl > 0)) continue;
        const glm::dvec3 hn = hv / hl;
        const double nn = glm::dot(hn, n);
        if (!(nn > 0)) continue;
        const double nnp = std::pow(nn, m.phongExp);
        const double fs = sh * m.ks * nnp;
        const Color bs = mulBy(bl, fs);
        b = add(b, bs);
        if (trace)
            trace->halfVector = hn, trace->nn = nn, trace->nnp = nnp, trace->specularFactor = fs,
            trace->specular = bs, trace->afterSpecular = b;
    }
    return b;
}

Color CourseModel::addScaled(const Color& base, const Color& term, double k) const {
    return add(base, mulBy(term, k));
}

Color CourseModel::scale(const Color& c, double s) const {
    return mulBy(c, s);
}

void CourseModel::toRgb8(const Color& c, uint8_t out[3]) const {
    for (int i = 0; i < 3; ++i)
        out[i] = uint8_t(clamp255(roundEven(c[i])));
}

} // namespace wb::rt
