// The OpenGL lighting equation of core/lighting.h against values worked out by hand
// from the GL 2.1 spec §2.14.1, and against a second implementation in long double
// that computes the highlight term by a different formula.
#include "core/lighting.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using Catch::Detail::Approx;

namespace {
// The hand-computed values below are exact expressions; double evaluation of them
// and of the equation differ by a few ulps, so 1e-12 is generous and still catches
// any wrong term (the smallest term tested is ~0.01).
constexpr double kEps = 1e-12;

wb::Light directional(glm::dvec3 dir) {
    wb::Light l;
    l.position = glm::dvec4(dir, 0);
    return l;
}
wb::Light positional(glm::dvec3 pos) {
    wb::Light l;
    l.position = glm::dvec4(pos, 1);
    return l;
}
} // namespace

TEST_CASE("GL defaults: light 0 head-on on the default material gives 0.84 grey") {
    // a_cm·a_cs = 0.2·0.2 = 0.04; d_cm·d_cl·(n·VP) = 0.8·1·1; s_cm = 0.
    glm::dvec4 c = wb::shadeVertex({}, {wb::Light{}}, {}, {0, 0, -5}, {0, 0, 1});
    CHECK(c.r == Approx(0.84).epsilon(kEps));
    CHECK(c.g == Approx(0.84).epsilon(kEps));
    CHECK(c.b == Approx(0.84).epsilon(kEps));
    CHECK(c.a == 1.0);
}

TEST_CASE("diffuse and specular at 45 degrees incidence, infinite viewer") {
    wb::Material m;
    m.ambient = {0, 0, 0, 1};
    m.diffuse = {0.5, 0.5, 0.5, 1};
    m.specular = {0.25, 0.25, 0.25, 1};
    m.shininess = 2;
    wb::Light l = directional({1, 0, 1}); // not unit: GL normalises the direction
    wb::LightTerms t = wb::lightTerms(l, m, false, {3, 4, -7}, {0, 0, 1});
    // n·VP = cos 45° = 1/√2; ĥ bisects VP and +z, 22.5° from n: (n·ĥ)² = cos² 22.5° = (2+√2)/4.
    CHECK(t.diffuse == Approx(1 / std::sqrt(2.0)).epsilon(kEps));
    CHECK(t.specular == Approx((2 + std::sqrt(2.0)) / 4).epsilon(kEps));
    CHECK(t.attenuation == 1.0);
    CHECK(t.spot == 1.0);
    double expected = 0.5 / std::sqrt(2.0) + 0.25 * (2 + std::sqrt(2.0)) / 4;
    CHECK(t.color.r == Approx(expected).epsilon(kEps));
}

TEST_CASE("local viewer moves the highlight: half vector uses the direction to the eye") {
    wb::Material m;
    m.specular = {1, 1, 1, 1};
    m.shininess = 1;
    wb::Light l = directional({0, 0, 1});
    // Vertex at (1, 0, -1): the eye is 45° off the normal.
    wb::LightTerms inf = wb::lightTerms(l, m, false, {1, 0, -1}, {0, 0, 1});
    wb::LightTerms loc = wb::lightTerms(l, m, true, {1, 0, -1}, {0, 0, 1});
    CHECK(inf.specular == Approx(1.0).epsilon(kEps));                               // ĥ = +z = n
    CHECK(loc.specular == Approx(std::sqrt(2 + std::sqrt(2.0)) / 2).epsilon(kEps)); // cos 22.5°
    CHECK(inf.diffuse == loc.diffuse);
}

TEST_CASE("attenuation 1/(k0 + k1 d + k2 d^2) for a positional light, none for a directional") {
    wb::Material m;
    m.ambient = {0, 0, 0, 1};
    m.diffuse = {1, 1, 1, 1};
    wb::Light l = positional({0, 0, 1});
    l.constantAttenuation = 1;
    l.linearAttenuation = 0.5;
    l.quadraticAttenuation = 0.25;
    // d = 4: 1 + 2 + 4 = 7.
    wb::LightTerms t = wb::lightTerms(l, m, false, {0, 0, -3}, {0, 0, 1});
    CHECK(t.attenuation == Approx(1.0 / 7).epsilon(kEps));
    CHECK(t.color.g == Approx(1.0 / 7).epsilon(kEps));
    // The homogeneous position (0,0,2,2) is the same point.
    l.position = {0, 0, 2, 2};
    CHECK(wb::lightTerms(l, m, false, {0, 0, -3}, {0, 0, 1}).attenuation ==
          Approx(1.0 / 7).epsilon(kEps));
    l.position = {0, 0, 1, 0};
    CHECK(wb::lightTerms(l, m, false, {0, 0, -3}, {0, 0, 1}).attenuation == 1.0);
}

TEST_CASE("spot: cos^exponent inside the cone and zero outside") {
    wb::Material m;
    m.ambient = {0.5, 0.5, 0.5, 1};
    wb::Light l = positional({0, 0, 0});
    l.ambient = {1, 1, 1, 1};
    l.diffuse = l.specular = {0, 0, 0, 1}; // only the ambient term, to read the factor off
    l.spotDirection = {0, 0, -2};
    l.spotCutoff = 30;
    l.spotExponent = 2;
    auto at = [&](double deg) {
        double a = deg * M_PI / 180;
        return wb::lightTerms(l, m, false, {5 * std::sin(a), 0, -5 * std::cos(a)}, {0, 0, 1});
    };
    CHECK(at(0).spot == Approx(1.0).epsilon(kEps));
    CHECK(at(20).spot == Approx(std::pow(std::cos(20 * M_PI / 180), 2)).epsilon(kEps));
    CHECK(at(29.999).spot > 0.74); // cos² 30° = 0.75
    CHECK(at(30.001).spot == 0.0);
    CHECK(at(40).spot == 0.0);
    CHECK(at(40).color == glm::dvec3(0)); // the spot also removes the light's ambient term
    CHECK(at(20).color.r == Approx(0.5 * std::pow(std::cos(20 * M_PI / 180), 2)).epsilon(kEps));
    // Exponent 0: a hard-edged cone of factor 1.
    l.spotExponent = 0;
    CHECK(at(25).spot == 1.0);
}

TEST_CASE("spot parameters do nothing for a directional light (as Mesa and desktop GL)") {
    wb::Light l = directional({0, 0, 1});
    l.spotCutoff = 5;
    l.spotDirection = {1, 0, 0};
    CHECK(wb::lightTerms(l, {}, false, {0, 0, -1}, {0, 0, 1}).spot == 1.0);
}

TEST_CASE("a face turned away from the light gets neither diffuse nor a highlight (f_i = 0)") {
    wb::Material m;
    m.specular = {1, 1, 1, 1};
    m.shininess = 0; // (n⊙ĥ)^0 would be 1: only f_i removes it
    wb::Light l = directional({0, 0, 1});
    l.ambient = {0.1, 0.1, 0.1, 1};
    wb::LightTerms t = wb::lightTerms(l, m, false, {0, 0, -1}, {0, 0, -1});
    CHECK(t.diffuse == 0.0);
    CHECK(t.specular == 0.0);
    CHECK(t.color.r == Approx(0.2 * 0.1).epsilon(kEps)); // the ambient part stays
    // Grazing light (n·VP = 0 exactly) counts as facing away too.
    wb::LightTerms g = wb::lightTerms(directional({1, 0, 0}), m, false, {0, 0, -1}, {0, 0, 1});
    CHECK(g.specular == 0.0);
}

TEST_CASE("emission and global ambient add, channels clamp to [0,1], alpha is diffuse alpha") {
    wb::Material m;
    m.emission = {2, -1, 0.1, 1};
    m.ambient = {0.5, 0.5, 0.5, 1};
    m.diffuse = {0, 0, 0, 0.25};
    wb::LightModel model;
    model.ambient = {0.2, 0.4, 0.6, 1};
    glm::dvec4 c = wb::shadeVertex(model, {}, m, {0, 0, -1}, {0, 0, 1});
    CHECK(c.r == 1.0);
    CHECK(c.g == 0.0); // -1 + 0.2 clamps to 0
    CHECK(c.b == Approx(0.1 + 0.3).epsilon(kEps));
    CHECK(c.a == 0.25);
    glm::dvec3 u = wb::shadeVertexUnclamped(model, {}, m, {0, 0, -1}, {0, 0, 1});
    CHECK(u.r == Approx(2.1).epsilon(kEps));
    CHECK(u.g == Approx(-0.8).epsilon(kEps));
}

TEST_CASE("disabled lights are skipped and several lights add") {
    wb::Material m;
    m.ambient = {0, 0, 0, 1};
    m.diffuse = {0.25, 0.25, 0.25, 1};
    wb::Light a = directional({0, 0, 1});
    wb::Light b = a;
    wb::LightModel model;
    model.ambient = {0, 0, 0, 1};
    CHECK(wb::shadeVertex(model, {a, b}, m, {0, 0, -1}, {0, 0, 1}).r == Approx(0.5).epsilon(kEps));
    b.enabled = false;
    CHECK(wb::shadeVertex(model, {a, b}, m, {0, 0, -1}, {0, 0, 1}).r == Approx(0.25).epsilon(kEps));
}

TEST_CASE("two-sided lighting: back faces use the back material and the negated normal") {
    wb::Material front, back;
    front.ambient = back.ambient = {0, 0, 0, 1};
    front.diffuse = {1, 0, 0, 1};
    back.diffuse = {0, 0, 1, 1};
    wb::LightModel model;
    model.ambient = {0, 0, 0, 1};
    model.twoSide = true;
    wb::Light l = directional({0, 0, 1});
    // Normal points away from the light; seen from the back the flipped normal faces it.
    glm::dvec4 c = wb::shadeVertex(model, {l}, front, {0, 0, -1}, {0, 0, -1}, true, &back);
    CHECK(c == glm::dvec4(0, 0, 1, 1));
    model.twoSide = false; // one-sided: the front material, unlit
    c = wb::shadeVertex(model, {l}, front, {0, 0, -1}, {0, 0, -1}, true, &back);
    CHECK(c == glm::dvec4(0, 0, 0, 1));
}

TEST_CASE("degenerate input stays finite") {
    wb::Material m;
    m.specular = {1, 1, 1, 1};
    m.shininess = 5;
    // All attenuation factors zero (GL would divide by zero).
    wb::Light l = positional({0, 0, 0});
    l.constantAttenuation = 0;
    glm::dvec4 c = wb::shadeVertex({}, {l}, m, {0, 0, -1}, {0, 0, 1});
    CHECK(std::isfinite(c.r));
    CHECK(c.r == 1.0);
    // Vertex exactly at the light: VP is zero, no diffuse, no highlight, still finite.
    wb::LightTerms t = wb::lightTerms(positional({1, 2, 3}), m, true, {1, 2, 3}, {0, 0, 1});
    CHECK(t.diffuse == 0.0);
    CHECK(std::isfinite(t.color.r));
    // Light exactly opposite the infinite viewer: VP + (0,0,1) = 0, no half vector.
    t = wb::lightTerms(directional({0, 0, -1}), m, false, {0, 0, -1}, {0, 0, -1});
    CHECK(t.diffuse == 1.0);
    CHECK(t.specular == 0.0);
    // Local viewer with the vertex at the eye.
    t = wb::lightTerms(directional({0, 0, 1}), m, true, {0, 0, 0}, {0, 0, 1});
    CHECK(std::isfinite(t.specular));
}

namespace {
// Second implementation in long double: n·ĥ from (n·L + n·V)/|L + V| with
// |L + V| = √(2 + 2 L·V), instead of normalising the sum vector.
long double referenceChannel(const wb::LightModel& model, const wb::Light& l, const wb::Material& m,
                             glm::dvec3 p, glm::dvec3 n, int ch) {
    using LD = long double;
    auto dot = [](const LD* a, const LD* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    LD P[3] = {p.x, p.y, p.z}, N[3] = {n.x, n.y, n.z};
    LD L[3], att = 1, spot = 1;
    if (l.position.w != 0) {
        LD d2 = 0;
        for (int i = 0; i < 3; ++i) {
            L[i] = LD(l.position[i]) / LD(l.position.w) - P[i];
            d2 += L[i] * L[i];
        }
        LD d = std::sqrt(d2);
        for (LD& v : L)
            v /= d;
        att = 1 / (LD(l.constantAttenuation) + LD(l.linearAttenuation) * d +
                   LD(l.quadraticAttenuation) * d2);
        if (l.spotCutoff != 180) {
            LD s[3] = {l.spotDirection.x, l.spotDirection.y, l.spotDirection.z};
            LD sl = std::sqrt(dot(s, s));
            LD c = -dot(L, s) / sl;
            if (c < 0) c = 0;
            spot = c >= std::cos(LD(l.spotCutoff) * 3.14159265358979323846L / 180)
                       ? std::pow(c, LD(l.spotExponent))
                       : 0;
        }
    } else {
        LD len = std::sqrt(LD(l.position.x) * l.position.x + LD(l.position.y) * l.position.y +
                           LD(l.position.z) * l.position.z);
        for (int i = 0; i < 3; ++i)
            L[i] = LD(l.position[i]) / len;
    }
    LD V[3] = {0, 0, 1};
    if (model.localViewer) {
        LD len = std::sqrt(dot(P, P));
        for (int i = 0; i < 3; ++i)
            V[i] = -P[i] / len;
    }
    LD nl = dot(N, L), spec = 0;
    if (nl < 0) nl = 0;
    if (nl > 0) {
        LD nh = (dot(N, L) + dot(N, V)) / std::sqrt(2 + 2 * dot(L, V));
        spec = std::pow(nh < 0 ? 0 : nh, LD(m.shininess));
    }
    LD c = LD(m.emission[ch]) + LD(m.ambient[ch]) * LD(model.ambient[ch]) +
           att * spot *
               (LD(m.ambient[ch]) * LD(l.ambient[ch]) + nl * LD(m.diffuse[ch]) * LD(l.diffuse[ch]) +
                spec * LD(m.specular[ch]) * LD(l.specular[ch]));
    return c < 0 ? 0 : (c > 1 ? 1 : c);
}
} // namespace

TEST_CASE("random configurations agree with a long double second implementation") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u01(0, 1), u11(-1, 1);
    auto rgb = [&](double scale) {
        return glm::dvec4(scale * u01(rng), scale * u01(rng), scale * u01(rng), 1);
    };
    double worst = 0;
    for (int iter = 0; iter < 2000; ++iter) {
        wb::Material m;
        m.emission = rgb(0.2);
        m.ambient = rgb(0.5);
        m.diffuse = rgb(0.7);
        m.specular = rgb(0.7);
        m.shininess = 128 * u01(rng);
        wb::LightModel model;
        model.ambient = rgb(0.3);
        model.localViewer = iter % 2 == 0;
        wb::Light l;
        l.ambient = rgb(0.3);
        l.diffuse = rgb(1);
        l.specular = rgb(1);
        glm::dvec3 lp(4 * u11(rng), 4 * u11(rng), 4 * u11(rng));
        l.position = glm::dvec4(lp, iter % 3 == 0 ? 0.0 : 1.0);
        if (iter % 3 == 1) {
            l.spotDirection = glm::dvec3(u11(rng), u11(rng), u11(rng) - 1.5);
            l.spotCutoff = 90 * u01(rng);
            l.spotExponent = 20 * u01(rng);
        }
        l.constantAttenuation = 0.5 + u01(rng);
        l.linearAttenuation = 0.3 * u01(rng);
        l.quadraticAttenuation = 0.1 * u01(rng);
        glm::dvec3 p(3 * u11(rng), 3 * u11(rng), -2 - 5 * u01(rng));
        glm::dvec3 n = glm::normalize(glm::dvec3(u11(rng), u11(rng), u11(rng) + 0.5));
        glm::dvec4 c = wb::shadeVertex(model, {l}, m, p, n);
        for (int ch = 0; ch < 3; ++ch)
            worst = std::max(
                worst, std::abs(double(c[ch]) - double(referenceChannel(model, l, m, p, n, ch))));
    }
    // Both are rounding-level apart; pow with exponents up to 128 amplifies the
    // relative error of n·ĥ by up to 128, so 1e-11 bounds double's 128·few ulps.
    CHECK(worst < 1e-11);
}

TEST_CASE("validation names the out-of-range field") {
    wb::Light l;
    CHECK(wb::validateLight(l).empty());
    l.spotCutoff = 120;
    CHECK(wb::validateLight(l).find("cutoff") != std::string::npos);
    l.spotCutoff = 45;
    l.spotExponent = 200;
    CHECK(wb::validateLight(l).find("exponent") != std::string::npos);
    l.spotExponent = 1;
    l.linearAttenuation = -1;
    CHECK(wb::validateLight(l).find("attenuation") != std::string::npos);
    wb::Material m;
    CHECK(wb::validateMaterial(m).empty());
    m.shininess = 129;
    CHECK(wb::validateMaterial(m).find("shininess") != std::string::npos);
}
