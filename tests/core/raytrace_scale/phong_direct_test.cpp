// The phong model's per-hit shading (issue 13: no GL material/colour sum per light; only
// lightFactors) against the formula it replaced, written out here with the full
// wb::lightTerms and GL structs: the same colour bit for bit on random hits, materials
// and lights (point/directional, attenuation, spots, shadowed, facing away), and
// lightFactors against lightTerms' factors.
#include "core/lighting.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <random>

using namespace wb::rt;

namespace {

// PhongModel::direct as it was before issue 13 (commit 92489dc).
Color referenceDirect(const Scene& scene, const Ray& view, const Hit& hit, const Material& m,
                      const glm::dvec3& surface, const std::vector<LightSample>& lights) {
    wb::Material gm;
    gm.emission = glm::dvec4(m.emission, 1);
    gm.ambient = glm::dvec4(m.ka * surface, 1);
    gm.diffuse = glm::dvec4(m.kd * surface, 1);
    gm.specular = glm::dvec4(glm::dvec3(m.ks), 1);
    gm.shininess = std::clamp(m.phongExp, 0.0, 128.0);
    Color c = m.emission + glm::dvec3(gm.ambient) * scene.globalAmbient;
    const glm::dvec3 pos = hit.point - view.origin;
    for (const LightSample& s : lights) {
        const Light& l = *s.light;
        wb::Light gl;
        gl.ambient = glm::dvec4(l.ambient, 1);
        gl.diffuse = glm::dvec4(l.colour, 1);
        gl.specular = glm::dvec4(l.colour, 1);
        gl.position = l.kind == Light::Kind::Point ? glm::dvec4(l.position - view.origin, 1)
                                                   : glm::dvec4(-l.direction, 0);
        gl.spotDirection = l.spotDirection;
        gl.spotExponent = l.spotExponent;
        gl.spotCutoff = l.spotCutoff;
        gl.constantAttenuation = l.constantAttenuation;
        gl.linearAttenuation = l.linearAttenuation;
        gl.quadraticAttenuation = l.quadraticAttenuation;
        const wb::LightTerms t = wb::lightTerms(gl, gm, true, pos, hit.normal);
        c += t.attenuation * t.spot *
             (glm::dvec3(gm.ambient) * l.ambient +
              s.transmittance * (t.diffuse * glm::dvec3(gm.diffuse) * l.colour +
                                 t.specular * glm::dvec3(gm.specular) * l.colour));
    }
    return c;
}

glm::dvec3 rnd3(std::mt19937_64& g, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(g), u(g), u(g)};
}

} // namespace

TEST_CASE("rt_phong: direct() equals the GL-struct formula bit for bit", "[raytrace][phong]") {
    std::mt19937_64 g(13);
    std::uniform_real_distribution<double> u(0, 1);
    Scene scene;
    for (int i = 0; i < 6; ++i) {
        Light l = (i % 3 == 2) ? Light::directional(rnd3(g, -1, 1), rnd3(g, 0, 1))
                               : Light::point(rnd3(g, -10, 10), rnd3(g, 0, 1));
        l.ambient = rnd3(g, 0, 0.3);
        if (i % 2) {
            l.constantAttenuation = 0.5 + u(g);
            l.linearAttenuation = 0.1 * u(g);
            l.quadraticAttenuation = 0.01 * u(g);
        }
        if (i == 1 || i == 4) {
            l.spotDirection = rnd3(g, -1, 1);
            l.spotCutoff = 20 + 60 * u(g);
            l.spotExponent = 10 * u(g);
        }
        scene.lights.push_back(l);
    }
    PhongModel model;
    int lit = 0;
    for (int i = 0; i < 5000; ++i) {
        Material m;
        m.colour = rnd3(g, 0, 1);
        m.ka = u(g);
        m.kd = u(g);
        m.ks = u(g);
        m.phongExp = i % 4 == 0 ? double(int(200 * u(g))) : 300 * u(g) - 20; // clamped to 0..128
        m.emission = i % 5 == 0 ? rnd3(g, 0, 0.2) : glm::dvec3(0.0);
        Ray view;
        view.origin = rnd3(g, -20, 20);
        Hit hit;
        hit.point = rnd3(g, -5, 5);
        hit.normal = glm::normalize(rnd3(g, -1, 1));
        view.direction = glm::normalize(hit.point - view.origin);
        std::vector<LightSample> samples;
        for (const Light& l : scene.lights) {
            LightSample s;
            s.light = &l;
            s.toLight = l.kind == Light::Kind::Point ? glm::normalize(l.position - hit.point)
                                                     : glm::normalize(-l.direction);
            s.transmittance = (i + int(samples.size())) % 3 == 0 ? 0.0 : u(g);
            samples.push_back(s);
        }
        const glm::dvec3 surface = m.colour;
        const Color a = model.direct(scene, view, hit, m, surface, samples);
        const Color b = referenceDirect(scene, view, hit, m, surface, samples);
        REQUIRE(std::memcmp(&a, &b, sizeof a) == 0);
        lit += a != glm::dvec3(0.0);
    }
    CHECK(lit > 4000); // not vacuous: most points get light
}

TEST_CASE("rt_phong: lightFactors are lightTerms' factors", "[raytrace][phong]") {
    std::mt19937_64 g(14);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 2000; ++i) {
        wb::Light l;
        l.position = glm::dvec4(rnd3(g, -5, 5), i % 3 == 0 ? 0.0 : 1.0);
        l.spotCutoff = i % 2 ? 180.0 : 10 + 80 * u(g);
        l.spotExponent = 5 * u(g);
        l.spotDirection = rnd3(g, -1, 1);
        l.linearAttenuation = u(g);
        wb::Material m;
        m.shininess = 128 * u(g);
        const glm::dvec3 p = rnd3(g, -5, 5), n = glm::normalize(rnd3(g, -1, 1));
        const wb::LightTerms a = wb::lightTerms(l, m, i % 2 == 0, p, n);
        const wb::LightTerms b = wb::lightFactors(l, m.shininess, i % 2 == 0, p, n);
        REQUIRE(a.attenuation == b.attenuation);
        REQUIRE(a.spot == b.spot);
        REQUIRE(a.diffuse == b.diffuse);
        REQUIRE(a.specular == b.specular);
    }
}
