// The phong model's per-hit shading (issue 13: no GL material/colour sum per light; only
// lightFactors, each length taken once, the eye direction once per hit) against the
// formula it replaced, written out here with the GL structs and lightFactors as it was
// before (every unit vector and length recomputed): the same colour bit for bit on
// random hits, materials and lights (point/directional, attenuation, spots, shadowed,
// facing away); lightFactors (both overloads) against that copy on random and
// degenerate vertices (light at the vertex, vertex at the eye, light behind the viewer,
// tiny and huge distances, w != 1, NaN), and against lightTerms' factors.
#include "core/lighting.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/scene.h"

#include "random_scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace wb::rt;
using wb::test::rnd3;

namespace {

double clampedDot(const glm::dvec3& a, const glm::dvec3& b) {
    return std::max(glm::dot(a, b), 0.0);
}
glm::dvec3 unitOrZero(const glm::dvec3& v) {
    double len = glm::length(v);
    return len > 0 ? v / len : glm::dvec3(0);
}

// wb::lightFactors as it was before the per-hit work was cut (commit e6c89b3), verbatim
// but for the helpers' names.
wb::LightTerms referenceFactors(const wb::Light& light, double shininess, bool localViewer,
                                const glm::dvec3& position, const glm::dvec3& normal) {
    wb::LightTerms t;
    const bool positional = light.position.w != 0;
    glm::dvec3 vp;
    if (positional) {
        glm::dvec3 lightPos = glm::dvec3(light.position) / light.position.w;
        glm::dvec3 toLight = lightPos - position;
        double d = glm::length(toLight);
        vp = unitOrZero(toLight);
        double denom = light.constantAttenuation + light.linearAttenuation * d +
                       light.quadraticAttenuation * d * d;
        t.attenuation = 1.0 / std::max(denom, 1e-12);
        if (light.spotCutoff != 180.0) {
            double cosAngle = clampedDot(-vp, unitOrZero(light.spotDirection));
            double cosCutoff = std::cos(light.spotCutoff * (M_PI / 180.0));
            t.spot = cosAngle >= cosCutoff ? std::pow(cosAngle, light.spotExponent) : 0.0;
        }
    } else {
        vp = unitOrZero(glm::dvec3(light.position));
    }
    t.diffuse = clampedDot(normal, vp);
    if (t.diffuse != 0) {
        glm::dvec3 toEye = localViewer ? unitOrZero(-position) : glm::dvec3(0, 0, 1);
        glm::dvec3 h = unitOrZero(vp + toEye);
        t.specular = glm::length(h) > 0 ? std::pow(clampedDot(normal, h), shininess) : 0.0;
    }
    return t;
}

// Bit for bit, or both NaN (a NaN's payload is not the point).
bool same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}
bool sameFactors(const wb::LightTerms& a, const wb::LightTerms& b) {
    return same(a.attenuation, b.attenuation) && same(a.spot, b.spot) &&
           same(a.diffuse, b.diffuse) && same(a.specular, b.specular);
}

// PhongModel::direct as it was before issue 13 (commit 92489dc), with lightTerms'
// factors from the copy above.
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
        const wb::LightTerms t = referenceFactors(gl, gm.shininess, true, pos, hit.normal);
        c += t.attenuation * t.spot *
             (glm::dvec3(gm.ambient) * l.ambient +
              s.transmittance * (t.diffuse * glm::dvec3(gm.diffuse) * l.colour +
                                 t.specular * glm::dvec3(gm.specular) * l.colour));
    }
    return c;
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

TEST_CASE("rt_phong: lightFactors equal the unshortened formula, degenerate vertices too",
          "[raytrace][phong]") {
    std::mt19937_64 g(15);
    std::uniform_real_distribution<double> u(0, 1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    int lit = 0, highlights = 0, cases = 0;
    auto check = [&](const wb::Light& l, double shininess, const glm::dvec3& p,
                     const glm::dvec3& n) {
        for (bool local : {true, false}) {
            const wb::LightTerms ref = referenceFactors(l, shininess, local, p, n);
            const wb::LightTerms a = wb::lightFactors(l, shininess, local, p, n);
            const wb::LightTerms b =
                wb::lightFactors(l, shininess, wb::eyeDirection(local, p), p, n);
            INFO("light " << l.position.x << ' ' << l.position.y << ' ' << l.position.z << ' '
                          << l.position.w << ", vertex " << p.x << ' ' << p.y << ' ' << p.z
                          << ", local " << local);
            REQUIRE(sameFactors(a, ref));
            REQUIRE(sameFactors(b, ref));
            lit += ref.diffuse > 0;
            highlights += ref.specular > 0;
            ++cases;
        }
    };
    for (int i = 0; i < 3000; ++i) {
        wb::Light l;
        l.position = glm::dvec4(rnd3(g, -5, 5), i % 4 == 0 ? 0.0 : (i % 4 == 1 ? 2.5 : 1.0));
        l.spotCutoff = i % 3 ? 180.0 : 10 + 80 * u(g);
        l.spotExponent = 5 * u(g);
        l.spotDirection = rnd3(g, -1, 1);
        l.constantAttenuation = i % 5 == 0 ? 1.0 : u(g); // 1 with k1 = k2 = 0: denominator 1
        l.linearAttenuation = i % 5 == 0 ? 0.0 : u(g);
        l.quadraticAttenuation = i % 5 == 0 ? 0.0 : 0.1 * u(g);
        const double shininess = i % 2 ? double(int(128 * u(g))) : 128 * u(g);
        const glm::dvec3 p = rnd3(g, -5, 5), n = glm::normalize(rnd3(g, -1, 1));
        check(l, shininess, p, n);
    }
    // Degenerate vertices: each where a shortened length test could differ.
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    for (double s : {1e-300, 1e-160, 1e-20, 1.0, 1e20, 1e150, 1e200}) {
        wb::Light l;
        const glm::dvec3 p(0.5 * s, -0.25 * s, -s);
        l.position = glm::dvec4(p, 1); // light at the vertex: VP = 0
        check(l, 10, p, n);
        check(l, 10, glm::dvec3(0.0), n);    // vertex at the eye: toEye = 0
        l.position = glm::dvec4(2.0 * p, 1); // light behind the viewer: VP + toEye = 0
        check(l, 10, p, n);
        l.position = glm::dvec4(-p, 1);
        check(l, 10, p, n);
        l.position = glm::dvec4(s, 0.5 * s, 2 * s, 0); // directional, any length
        check(l, 5, p, n);
        l.position = glm::dvec4(0, 0, 0, 0); // directional, no direction
        check(l, 5, p, n);
        l.position = glm::dvec4(p.x, p.y, p.z + s * 1e-12, 1); // nearly at the vertex
        check(l, 5, p, n);
    }
    wb::Light l;
    l.position = glm::dvec4(1, nan, 0, 1);
    check(l, 3, glm::dvec3(0.2, 0.1, -1), n);
    l.position = glm::dvec4(1, 1, 1, 1);
    check(l, 3, glm::dvec3(nan, 0.1, -1), n);
    check(l, 3, glm::dvec3(0.2, 0.1, -1), glm::dvec3(nan));
    l.position = glm::dvec4(std::numeric_limits<double>::infinity(), 1, 1, 1);
    check(l, 3, glm::dvec3(0.2, 0.1, -1), n);
    CHECK(lit > cases / 3); // not vacuous: many lit vertices with highlights
    CHECK(highlights > cases / 4);
}

TEST_CASE("rt_phong: toRgb8 rounds as lround(clamp(c)·255)", "[raytrace][phong]") {
    PhongModel model;
    const auto expected = [](double v) {
        const double x = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
        return int(std::lround(x * 255.0));
    };
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1.0,
                                  -1e-300,
                                  1e-300,
                                  2.0,
                                  std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(),
                                  std::numeric_limits<double>::quiet_NaN()};
    // Every tie k + 1/2 (as far as (k + 0.5)/255 lands on one) and its neighbours.
    for (int k = 0; k < 256; ++k)
        for (double v : {(k + 0.5) / 255, double(k) / 255}) {
            values.push_back(v);
            values.push_back(std::nextafter(v, 0.0));
            values.push_back(std::nextafter(v, 2.0));
        }
    std::mt19937_64 g(16);
    std::uniform_real_distribution<double> u(-0.1, 1.1);
    for (int i = 0; i < 100000; ++i)
        values.push_back(u(g));
    int ties = 0;
    for (double v : values) {
        ties +=
            std::clamp(v, 0.0, 1.0) * 255.0 - std::floor(std::clamp(v, 0.0, 1.0) * 255.0) == 0.5;
        uint8_t out[3];
        model.toRgb8(Color(v, 0.5, 1.0), out);
        INFO("v = " << v);
        REQUIRE(int(out[0]) == expected(v));
        REQUIRE(int(out[1]) == 128); // 127.5: the tie goes up
        REQUIRE(int(out[2]) == 255);
    }
    CHECK(ties > 100); // the ties were really tested
}

// PhongModel::directLanes (issue 21: a packet's eye hits shaded two at a time in SSE2's
// double lanes, four in AVX's) against direct() lane by lane, bit for bit: random hits, materials
// (emission, exponents clamped to 0..128, ka/kd/ks 0 and random), point lights with and
// without attenuation (a denominator of exactly 1, of 0, random), shadowed and lit
// samples, normals facing away, random lane masks (a lane outside the mask is neither
// read nor written), packets whose lanes share one material; and the degenerate lanes: the light at
// the hit point (d = 0), the viewer at the hit point (no eye direction), the light exactly behind
// the viewer (a zero half vector), huge and tiny scales.
TEST_CASE("rt_phong: directLanes equals direct() lane by lane, bit for bit", "[raytrace][phong]") {
    std::mt19937_64 g(21);
    std::uniform_real_distribution<double> u(0, 1);
    PhongModel model;
    // SSE2's pairs everywhere; AVX's quads where the CPU has AVX (directLanes' own choice).
    std::vector<PhongModel::LaneWidth> widths{PhongModel::LaneWidth::Two};
    if (__builtin_cpu_supports("avx")) widths.push_back(PhongModel::LaneWidth::Four);
    int lanesSeen = 0, lit = 0, highlights = 0;
    for (int scale : {0, -30, 25}) {
        const double s = std::ldexp(1.0, scale * 3); // 1, 2^-90, 2^75
        Scene scene;
        scene.globalAmbient = rnd3(g, 0, 0.2);
        for (int i = 0; i < 4; ++i) {
            Light l = Light::point(s * rnd3(g, -10, 10), rnd3(g, 0, 1));
            l.ambient = i == 0 ? glm::dvec3(0.0) : rnd3(g, 0, 0.3);
            if (i == 1) {
                l.constantAttenuation = 0.5 + u(g);
                l.linearAttenuation = 0.1 * u(g) / s;
                l.quadraticAttenuation = 0.01 * u(g) / (s * s);
            } else if (i == 2) {
                l.constantAttenuation = 0; // denominator 0 at the light: 1e-12
                l.linearAttenuation = 0;
                l.quadraticAttenuation = 0;
            }
            scene.lights.push_back(l);
        }
        REQUIRE(PhongModel::lanesApply(scene));
        for (int i = 0; i < 3000; ++i) {
            Ray views[kMaxPacket];
            Hit hits[kMaxPacket];
            double trans[4 * kMaxPacket];
            for (int j = 0; j < kMaxPacket; ++j) {
                Material m;
                m.colour = rnd3(g, 0, 1);
                m.ka = j == 3 ? 0.0 : u(g);
                m.kd = u(g);
                m.ks = j == 5 ? 0.0 : u(g);
                m.phongExp = (i + j) % 4 == 0 ? double(int(200 * u(g))) : 300 * u(g) - 20;
                m.emission = (i + j) % 5 == 0 ? rnd3(g, 0, 0.2) : glm::dvec3(0.0);
                hits[j].material = scene.addMaterial(m);
                hits[j].point = s * rnd3(g, -5, 5);
                hits[j].normal = glm::normalize(rnd3(g, -1, 1));
                views[j].origin = s * rnd3(g, -20, 20);
                switch ((i * kMaxPacket + j) % 23) {
                case 0: // the light at the hit point
                    hits[j].point = scene.lights[size_t(i % 4)].position;
                    break;
                case 1: // the viewer at the hit point
                    views[j].origin = hits[j].point;
                    break;
                case 2: // light 0 exactly behind the viewer, along an axis
                    scene.lights[0].position = {0, 0, -2 * s};
                    hits[j].point = {0, 0, 0};
                    hits[j].normal = {0, 0, -1};
                    views[j].origin = {0, 0, s};
                    break;
                default:
                    break;
                }
                views[j].direction = glm::normalize(hits[j].point - views[j].origin);
                for (int li = 0; li < 4; ++li)
                    trans[li * kMaxPacket + j] = (i + j + li) % 3 == 0 ? 0.0 : u(g);
            }
            // Every third packet's lanes share lane 0's material (directQuads broadcasts a
            // quad's one material instead of gathering four).
            if (i % 3 == 1)
                for (int j = 1; j < kMaxPacket; ++j)
                    hits[j].material = hits[0].material;
            const unsigned lanes = i % 4 == 0 ? 0xFFu : unsigned(g() & 0xFFu);
            for (PhongModel::LaneWidth width : widths) {
                Color out[kMaxPacket];
                const Color poison(std::numeric_limits<double>::quiet_NaN());
                for (Color& c : out)
                    c = poison;
                model.directLanes(scene, views, hits, lanes, trans, out, width);
                for (int j = 0; j < kMaxPacket; ++j) {
                    INFO("scale " << scale << " packet " << i << " lane " << j << " width "
                                  << (width == PhongModel::LaneWidth::Four ? 4 : 2));
                    if (!((lanes >> j) & 1u)) {
                        REQUIRE(std::isnan(out[j].x)); // not written
                        continue;
                    }
                    std::vector<LightSample> samples;
                    for (std::size_t li = 0; li < scene.lights.size(); ++li) {
                        LightSample ls;
                        ls.light = &scene.lights[li];
                        ls.transmittance = trans[li * kMaxPacket + std::size_t(j)];
                        samples.push_back(ls);
                    }
                    const Material& m = scene.materials[size_t(hits[j].material)];
                    const Color want = model.direct(scene, views[j], hits[j], m, m.colour, samples);
                    REQUIRE(std::memcmp(&out[j], &want, sizeof want) == 0);
                    ++lanesSeen;
                    lit += want != m.emission + m.ka * m.colour * scene.globalAmbient;
                    highlights += m.ks > 0;
                }
            }
            scene.materials.clear();
            scene.lights[0].position = s * rnd3(g, -10, 10);
        }
    }
    CHECK(lanesSeen > 3 * 3000 * 4 * int(widths.size())); // about 5 of 8 lanes a packet
    CHECK(lit > lanesSeen / 2);
    CHECK(highlights > lanesSeen / 2);
}

TEST_CASE("rt_phong: lanesApply takes point lights without a spot only", "[raytrace][phong]") {
    Scene scene;
    CHECK(PhongModel::lanesApply(scene));
    scene.lights.push_back(Light::point({1, 2, 3}));
    CHECK(PhongModel::lanesApply(scene));
    scene.lights.back().spotCutoff = 45;
    CHECK_FALSE(PhongModel::lanesApply(scene));
    scene.lights.back() = Light::directional({0, 0, -1});
    CHECK_FALSE(PhongModel::lanesApply(scene));
}
