#include "core/lighting.h"

#include <algorithm>
#include <cmath>

namespace wb {
namespace {
double clamp01(double v) {
    return v < 0 ? 0 : (v > 1 ? 1 : v);
}
double dotClamped(const glm::dvec3& a, const glm::dvec3& b) {
    return std::max(glm::dot(a, b), 0.0);
}
// Normalises v, or returns zero for a zero vector (no NaN from 0/0).
glm::dvec3 unit(const glm::dvec3& v) {
    double len = glm::length(v);
    return len > 0 ? v / len : glm::dvec3(0);
}
} // namespace

glm::dvec3 eyeDirection(bool localViewer, const glm::dvec3& position) {
    return localViewer ? unit(-position) : glm::dvec3(0, 0, 1);
}

LightTerms lightFactors(const Light& light, double shininess, bool localViewer,
                        const glm::dvec3& position, const glm::dvec3& normal) {
    return lightFactors(light, shininess, eyeDirection(localViewer, position), position, normal);
}

// Each length is taken once (the ray tracer calls this per hit and light): VP is the
// vector over the distance d already known, and the half vector's own length test
// (|ĥ| > 0) is the test of the length it was divided by (|v| > 0 and finite, v = VP +
// toEye a sum of two unit-or-zero vectors, gives |v/|v|| ≈ 1).
LightTerms lightFactors(const Light& light, double shininess, const glm::dvec3& toEye,
                        const glm::dvec3& position, const glm::dvec3& normal) {
    LightTerms t;
    const bool positional = light.position.w != 0;
    glm::dvec3 vp; // VP_pli: unit vector from the vertex towards the light
    if (positional) {
        // x / 1 is x: the ray tracer's lights have w = 1, no division for them.
        const glm::dvec3 lightPos = light.position.w == 1
                                        ? glm::dvec3(light.position)
                                        : glm::dvec3(light.position) / light.position.w;
        const glm::dvec3 toLight = lightPos - position;
        const double d = glm::length(toLight);
        vp = d > 0 ? toLight / d : glm::dvec3(0);
        const double denom = light.constantAttenuation + light.linearAttenuation * d +
                             light.quadraticAttenuation * d * d;
        t.attenuation = denom == 1 ? 1.0 : 1.0 / std::max(denom, 1e-12); // 1/1 is 1
        if (light.spotCutoff != 180.0) {
            double cosAngle = dotClamped(-vp, unit(light.spotDirection));
            double cosCutoff = std::cos(light.spotCutoff * (M_PI / 180.0));
            t.spot = cosAngle >= cosCutoff ? std::pow(cosAngle, light.spotExponent) : 0.0;
        }
    } else {
        vp = unit(glm::dvec3(light.position));
    }
    t.diffuse = dotClamped(normal, vp);
    if (t.diffuse != 0) { // f_i: no highlight on a surface the light does not reach
        const glm::dvec3 v = vp + toEye;
        const double len = glm::length(v);
        // A zero half vector (light exactly behind the viewer): no highlight.
        if (len > 0) t.specular = std::pow(dotClamped(normal, v / len), shininess);
    }
    return t;
}

LightTerms lightTerms(const Light& light, const Material& material, bool localViewer,
                      const glm::dvec3& position, const glm::dvec3& normal) {
    LightTerms t = lightFactors(light, material.shininess, localViewer, position, normal);
    glm::dvec3 sum = glm::dvec3(material.ambient) * glm::dvec3(light.ambient) +
                     t.diffuse * glm::dvec3(material.diffuse) * glm::dvec3(light.diffuse) +
                     t.specular * glm::dvec3(material.specular) * glm::dvec3(light.specular);
    t.color = t.attenuation * t.spot * sum;
    return t;
}

glm::dvec3 shadeVertexUnclamped(const LightModel& model, const std::vector<Light>& lights,
                                const Material& material, const glm::dvec3& position,
                                const glm::dvec3& normal) {
    glm::dvec3 c =
        glm::dvec3(material.emission) + glm::dvec3(material.ambient) * glm::dvec3(model.ambient);
    for (const Light& light : lights)
        if (light.enabled)
            c += lightTerms(light, material, model.localViewer, position, normal).color;
    return c;
}

glm::dvec4 shadeVertex(const LightModel& model, const std::vector<Light>& lights,
                       const Material& front, const glm::dvec3& position, const glm::dvec3& normal,
                       bool backFacing, const Material* back) {
    const bool useBack = model.twoSide && backFacing;
    const Material& m = useBack && back ? *back : front;
    glm::dvec3 c = shadeVertexUnclamped(model, lights, m, position, useBack ? -normal : normal);
    return {clamp01(c.r), clamp01(c.g), clamp01(c.b), clamp01(m.diffuse.a)};
}

std::string validateLight(const Light& light) {
    if (!(light.spotExponent >= 0 && light.spotExponent <= 128))
        return "spot exponent must be in [0, 128]";
    if (!((light.spotCutoff >= 0 && light.spotCutoff <= 90) || light.spotCutoff == 180))
        return "spot cutoff must be in [0, 90] or 180";
    if (!(light.constantAttenuation >= 0 && light.linearAttenuation >= 0 &&
          light.quadraticAttenuation >= 0))
        return "attenuation factors must be >= 0";
    if (light.spotCutoff != 180 && glm::length(light.spotDirection) == 0)
        return "spot direction must not be zero";
    return {};
}

std::string validateMaterial(const Material& material) {
    if (!(material.shininess >= 0 && material.shininess <= 128))
        return "shininess must be in [0, 128]";
    return {};
}

} // namespace wb
