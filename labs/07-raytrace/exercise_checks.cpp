// Lab 07's tasks and their checks (exercise_check.h): seed 000's steps of a ray tracer.
// The expected values come from the reference answers (or, in a handout, recorded from
// them); the diagnostics and seed 000's worked colours are computed with core's tracer
// (core/raytrace: Sphere, Rectangle, CourseModel, Tracer), which reproduces the seed's
// numbers to the unit (tests/core/raytrace/seed000_test.cpp).
#include "exercises.h"

#include "common/exercise_check.h"
#include "core/i18n.h"
#include "core/raytrace/camera.h"
#include "core/raytrace/course_model.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/scene.h"
#include "core/raytrace/tracer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

const void* wbExerciseReference_lab07();

namespace wb::lab07 {
namespace {

using ex::Case;
using ex::Values;
using ex::Verdict;

constexpr double kEps = DBL_EPSILON;

glm::dvec3 v3(const Values& v, size_t k) {
    return {v.at(k), v.at(k + 1), v.at(k + 2)};
}
void put(Values& v, const glm::dvec3& p) {
    v.insert(v.end(), {p.x, p.y, p.z});
}
std::string fmtVec(const glm::dvec3& v) {
    return ex::showNumbers({v.x, v.y, v.z});
}

// A seeded generator (the same cases on every machine and compiler).
struct Lcg {
    unsigned long long s;
    double next() { // [0, 1)
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return double(s >> 11) / double(1ull << 53);
    }
    double in(double a, double b) { return a + (b - a) * next(); }
    glm::dvec3 unit() {
        for (;;) {
            const glm::dvec3 p(in(-1, 1), in(-1, 1), in(-1, 1));
            const double l = glm::length(p);
            if (l > 0.1 && l <= 1) return p / l;
        }
    }
};

// ----- ③ intersection: in = origin, direction, centre, radius, kind -----
enum Kind { kStrict = 0, kTangent = 1, kGrazing = 2 };

Case rayCase(std::string name, const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c,
             double r, int kind = kStrict) {
    Values in;
    put(in, o);
    put(in, glm::normalize(d));
    put(in, c);
    in.push_back(r);
    in.push_back(kind);
    return {std::move(name), in};
}

std::vector<Case> intersectCases() {
    std::vector<Case> cs;
    Lcg g{7};
    for (int i = 1; i <= 10; ++i) {
        const glm::dvec3 c(g.in(-5, 5), g.in(-5, 5), g.in(-5, 5));
        const double r = g.in(0.5, 3);
        const glm::dvec3 o = c + g.unit() * (r + g.in(1, 10));
        const glm::dvec3 target = c + g.unit() * (1.5 * r * g.next()); // about half hit
        cs.push_back(rayCase("seed " + std::to_string(i), o, target - o, c, r));
    }
    const glm::dvec3 c0(1, 2, 3);
    cs.push_back(rayCase(N_("origin inside the sphere (the far side is the hit)"),
                         c0 + glm::dvec3(0.3, 0, 0), {0.2, 1, 0.1}, c0, 1.5));
    cs.push_back(rayCase(N_("sphere behind the origin (both roots < 0)"), c0 + glm::dvec3(5, 0, 0),
                         {1, 0.1, 0}, c0, 1.5));
    cs.push_back(rayCase(N_("ray pointing away, line through the centre"), {0, 0, 5}, {0, 0, 1},
                         {0, 0, 0}, 1));
    cs.push_back(rayCase(N_("origin 1e6 away from a unit sphere"), {1e6, 3e5, -2e5},
                         glm::dvec3(0.2, -0.1, 0.3) - glm::dvec3(1e6, 3e5, -2e5), {0, 0, 0}, 1));
    cs.push_back(rayCase(N_("hit at t = 1e-7 (origin just outside)"), {0, 0, 2 + 1e-7}, {0, 0, -1},
                         {0, 0, 0}, 2));
    cs.push_back(rayCase(N_("hit at t = 1e7"), {3, -1, 1e7 + 4}, {0, 0, -1}, {3, -1, 0}, 4));
    cs.push_back(rayCase(N_("grazing: the line passes 1e-6·r inside the rim"), {-10, 1 - 1e-6, 0},
                         {1, 0, 0}, {0, 0, 0}, 1, kGrazing));
    cs.push_back(rayCase(N_("grazing: the line passes 1e-6·r outside the rim (a miss)"),
                         {-10, 1 + 1e-6, 0}, {1, 0, 0}, {0, 0, 0}, 1));
    cs.push_back(rayCase(N_("tangent ray (either answer is right)"), {-10, 1, 0}, {1, 0, 0},
                         {0, 0, 0}, 1, kTangent));
    cs.push_back(rayCase(N_("small sphere, r = 1e-3"), {0.01, 0.02, 1}, {-0.01, -0.02, -1},
                         {0, 0, 0}, 1e-3));
    cs.push_back(
        rayCase(N_("large sphere, r = 1e3"), {5000, 10, 20}, {-1, 0.05, 0.01}, {0, 0, 0}, 1e3));
    return cs;
}

Values intersectRun(const void* table, const Values& in) {
    double t = -1;
    const bool hit = static_cast<const Table*>(table)->intersectSphere(v3(in, 0), v3(in, 3),
                                                                       v3(in, 6), in.at(9), t);
    return {hit ? 1.0 : 0.0, hit ? t : 0.0};
}

Verdict intersectCompare(const Values& in, const Values& expected, const Values& got) {
    const glm::dvec3 o = v3(in, 0), d = v3(in, 3), c = v3(in, 6);
    const double r = in.at(9);
    const int kind = int(in.at(10));
    const bool eHit = expected.at(0) != 0, gHit = got.at(0) != 0;
    const double te = expected.at(1), tg = got.at(1);
    const double f = glm::length(o - c);
    if (gHit && !std::isfinite(tg))
        return Verdict::fail(tr("t is not a number: a square root of a negative discriminant "
                                "or a division by zero"));
    if (kind == kTangent) {
        // Either answer; a hit must lie on the sphere, ahead of the origin. The tangent
        // root is ill-conditioned: a relative change ε of the data moves it by ~√ε·|f|,
        // so 1e-6·|f| (√(16 ε) ≈ 6e-8, with margin).
        if (!gHit) return Verdict::pass();
        const double off = std::fabs(glm::length(o + tg * d - c) - r);
        if (tg > 0 && off <= 1e-6 * (f + r)) return Verdict::pass();
        return Verdict::fail(
            trf("a tangent ray: your hit t = %.9g is %.3g off the sphere", tg, off));
    }
    if (eHit && !gHit)
        return Verdict::fail(tr("reported a miss where the ray hits the sphere: check the "
                                "discriminant's sign and, for a far or grazing ray, compute it "
                                "as r² - (distance of the centre from the line)²"));
    if (!eHit && gHit)
        return Verdict::fail(tr("reported a hit where there is none: a negative discriminant "
                                "is a miss, and a sphere behind the origin (both roots <= 0) "
                                "is not hit"));
    if (!eHit) return Verdict::pass();
    // Tolerance: 1e-9 relative for the well-conditioned cases, plus what the textbook
    // h² - c loses for a far origin (h² and c are both ~|f|², rounded to ε·|f|² each; the
    // root moves by that over 2√disc >= 2r... so 16 ε |f|²/r), plus for the grazing case
    // the √-conditioning of a near-double root (√(16 ε)·|f|).
    double tol = 1e-9 * std::max(1.0, std::fabs(te)) + 16 * kEps * f * f / r;
    if (kind == kGrazing) tol += std::sqrt(16 * kEps) * f;
    if (std::fabs(tg - te) <= tol) return Verdict::pass();
    if (tg <= 0)
        return Verdict::fail(tr("t <= 0: that point lies behind the ray's origin; the hit is "
                                "the nearest root t > 0"));
    // The other root: t0·t1 = c.
    const double c2 = (f - r) * (f + r);
    if (te > 0 && std::fabs(tg - c2 / te) <= tol + 1e-9 * std::fabs(tg))
        return Verdict::fail(tr("you took the far root: the ray meets the sphere first at the "
                                "smaller t > 0"));
    return Verdict::fail(trf("t is off by %.3g (allowed %.2g): check h = (origin - centre)·d "
                             "and c = |origin - centre|² - r²",
                             std::fabs(tg - te), tol));
}

// ----- ③ normal: in = point, centre, radius -----
std::vector<Case> normalCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string n, const glm::dvec3& u, const glm::dvec3& c, double r) {
        Values in;
        put(in, c + r * glm::normalize(u));
        put(in, c);
        in.push_back(r);
        cs.push_back({std::move(n), in});
    };
    add(N_("unit sphere at the origin"), {1, 2, 2}, {0, 0, 0}, 1);
    Lcg g{11};
    for (int i = 1; i <= 6; ++i)
        add("seed " + std::to_string(i), g.unit(), {g.in(-5, 5), g.in(-5, 5), g.in(-5, 5)},
            g.in(0.2, 4));
    add(N_("radius 1e-3"), {0, -1, 0}, {2, 2, 2}, 1e-3);
    add(N_("radius 1e3"), {-3, 4, 0}, {10, 0, 0}, 1e3);
    return cs;
}

Verdict normalCompare(const Values& in, const Values& expected, const Values& got) {
    const glm::dvec3 e = v3(expected, 0), n = v3(got, 0);
    const double cl = glm::length(v3(in, 3)), r = in.at(6);
    // The point is c + r·u rounded: its direction from c is off by ~ε(|c| + r)/r.
    const double tol = 1e-9 * (1 + cl / r);
    if (glm::length(n - e) <= tol) return Verdict::pass();
    const double len = glm::length(n);
    if (!std::isfinite(len)) return Verdict::fail(tr("the normal is not a number"));
    if (std::fabs(len - 1) > tol && glm::length(n / len - e) <= tol)
        return Verdict::fail(trf("the direction is right but |N| = %.6g: the lighting needs a "
                                 "unit normal (divide P - C by the radius)",
                                 len));
    if (glm::length(n + e) <= tol || (len > 0 && glm::length(n / len + e) <= tol))
        return Verdict::fail(tr("the normal points into the sphere: the outward normal is "
                                "P - C, not C - P"));
    return Verdict::fail(tr("not the direction from the centre to the point: N = (P - C)/r"));
}

// ----- ④ shading: a scene with one point light and its blockers -----
// in = scene kind, P, N, V, C, ka, kd, ks, p, light pos, BL, BA, distScale, then blocker
// spheres (centre, radius, kt)...
enum SceneKind { kSeedShadow = 0, kSeedLit = 1, kSpheres = 2 };
const glm::dvec3 kRed(234, 21, 21), kGreen(21, 234, 21); // seed 000's colours

struct ShadeCase {
    int kind = kSpheres;
    ShadeInput s;
    std::vector<glm::dvec4> blockers; // centre, radius
    std::vector<double> kts;
};

Values packShade(const ShadeCase& c) {
    Values v{double(c.kind)};
    put(v, c.s.point);
    put(v, c.s.normal);
    put(v, c.s.view);
    put(v, c.s.material.colour);
    v.insert(v.end(), {c.s.material.ka, c.s.material.kd, c.s.material.ks, c.s.material.p});
    put(v, c.s.lightPos);
    put(v, c.s.lightColour);
    put(v, c.s.ambient);
    v.push_back(c.s.distScale);
    for (size_t i = 0; i < c.blockers.size(); ++i)
        v.insert(v.end(),
                 {c.blockers[i].x, c.blockers[i].y, c.blockers[i].z, c.blockers[i].w, c.kts[i]});
    return v;
}
ShadeCase unpackShade(const Values& v) {
    ShadeCase c;
    c.kind = int(v.at(0));
    c.s.point = v3(v, 1);
    c.s.normal = v3(v, 4);
    c.s.view = v3(v, 7);
    c.s.material.colour = v3(v, 10);
    c.s.material.ka = v.at(13), c.s.material.kd = v.at(14), c.s.material.ks = v.at(15);
    c.s.material.p = v.at(16);
    c.s.lightPos = v3(v, 17);
    c.s.lightColour = v3(v, 20);
    c.s.ambient = v3(v, 23);
    c.s.distScale = v.at(26);
    for (size_t k = 27; k + 5 <= v.size(); k += 5) {
        c.blockers.push_back({v[k], v[k + 1], v[k + 2], v[k + 3]});
        c.kts.push_back(v[k + 4]);
    }
    return c;
}

// The case's scene in core: seed 000 part 1's rectangles (the blocker spheres are not in it:
// see blockersFeeler).
std::unique_ptr<rt::Scene> buildScene(const ShadeCase& c) {
    auto s = std::make_unique<rt::Scene>();
    rt::Material m;
    if (c.kind == kSeedShadow || c.kind == kSeedLit) {
        m.kt = 0;
        const int mi = s->addMaterial(m);
        if (c.kind == kSeedShadow) s->add(rt::Rectangle({0, 0, 40}, {20, 0, 40}, {0, 20, 40}), mi);
        s->add(rt::Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), mi);
    }
    return s;
}

// Π kt of the blocker spheres the segment from -> to passes through, without a ray-sphere
// intersection (that is task ③, and a student handout has none in core): a sphere blocks
// when the segment's point nearest its centre lies inside it. The segment starts 1e-9 of the
// scale along, as coreFeeler's does; kt < 0.01 is opaque, as in core's tracer.
double blockersFeeler(const ShadeCase& c, const glm::dvec3& from, const glm::dvec3& to) {
    const glm::dvec3 d = to - from;
    const double dist = glm::length(d);
    if (!(dist > 0)) return 1.0;
    const glm::dvec3 u = d / dist;
    const double t0 = 1e-9 * (1 + glm::length(from));
    double kt = 1.0;
    for (size_t i = 0; i < c.blockers.size(); ++i) {
        const glm::dvec3 centre(c.blockers[i]);
        const double t = std::clamp(glm::dot(centre - from, u), t0, dist);
        if (glm::length(from + t * u - centre) < c.blockers[i].w)
            kt *= c.kts[i] < 0.01 ? 0.0 : c.kts[i];
    }
    return kt;
}

// Π kt along the segment from -> to, from core's tracer (blockers kt < 0.01 are opaque).
double coreFeeler(const rt::Scene& scene, const glm::dvec3& from, const glm::dvec3& to) {
    const glm::dvec3 d = to - from;
    const double dist = glm::length(d);
    if (!(dist > 0)) return 1.0;
    rt::CourseModel model;
    const rt::Tracer tracer(scene, model);
    // Start 1e-9 of the scale along: the point lies on a surface (seed 000's P2 on the green
    // rectangle), which must not shadow itself.
    return tracer.transmittance(from, d / dist, 1e-9 * (1 + glm::length(from)), dist);
}

std::vector<Case> shadeCases() {
    std::vector<Case> cs;
    // Seed 000 part 1: the ray through P(50, 0) hits the green rectangle at P2 = (40, 0, 20).
    const rt::Ray ray = rt::ScreenCamera::seed000().rayThroughScreen(50, 0);
    ShadeCase seed;
    seed.kind = kSeedShadow;
    seed.s.point = {40, 0, 20};
    seed.s.normal = {0, 0, 1};
    seed.s.view = ray.direction;
    seed.s.material = {kGreen, 0.5, 0.5, 0.5, 3};
    seed.s.lightPos = {0, 0, 60};
    cs.push_back(
        {N_("seed 000 part 1: P2 in the shadow of rectangle 1 -> (10,117,10)"), packShade(seed)});
    seed.kind = kSeedLit;
    cs.push_back(
        {N_("seed 000 part 1: P2 lit, rectangle 1 removed -> (50,197,50)"), packShade(seed)});
    Lcg g{23};
    for (int i = 1; i <= 8; ++i) {
        ShadeCase c;
        c.s.point = {g.in(-3, 3), g.in(-3, 3), g.in(-3, 3)};
        c.s.normal = g.unit();
        glm::dvec3 v = g.unit();
        if (glm::dot(v, c.s.normal) > 0) v = -v; // the ray comes from the normal's side
        c.s.view = v;
        c.s.material = {
            {std::round(g.in(0, 255)), std::round(g.in(0, 255)), std::round(g.in(0, 255))},
            g.in(0.1, 0.6),
            g.in(0.3, 0.9),
            g.in(0.3, 0.9),
            std::round(g.in(1, 30))};
        // The light on the normal's side, 10..40 away (SH = 30/dist around 1).
        glm::dvec3 l = g.unit();
        if (glm::dot(l, c.s.normal) < 0.2) l = glm::normalize(l + c.s.normal);
        c.s.lightPos = c.s.point + l * g.in(10, 40);
        c.s.lightColour = {std::round(g.in(100, 255)), std::round(g.in(100, 255)),
                           std::round(g.in(100, 255))};
        c.s.ambient = {std::round(g.in(0, 120)), std::round(g.in(0, 120)),
                       std::round(g.in(0, 120))};
        // Odd seeds: a blocker sphere on the feeler (kt 0 or 0.5); even: one off to the side.
        const glm::dvec3 mid = 0.5 * (c.s.point + c.s.lightPos);
        const glm::dvec3 side = glm::normalize(glm::cross(l, g.unit()));
        c.blockers.push_back(glm::dvec4(i % 2 ? mid : mid + 6.0 * side, 1.0));
        c.kts.push_back(i % 4 == 1 ? 0.0 : 0.5);
        cs.push_back({"seed " + std::to_string(i) +
                          (i % 2 ? std::string(" ") + N_("(a blocker on the feeler)") : ""),
                      packShade(c)});
    }
    // The light behind the surface (L·N < 0) while n = normalize(L - V) still faces N.
    ShadeCase b;
    b.s.point = {0, 0, 0};
    b.s.normal = {0, 0, 1};
    b.s.view = glm::normalize(glm::dvec3(0.6, 0, -0.8));
    b.s.material = {{200, 120, 40}, 0.3, 0.7, 0.8, 2};
    b.s.lightPos = glm::dvec3(0.8, 0, -0.6) * 20.0;
    b.s.ambient = {60, 60, 60};
    cs.push_back({N_("light behind the surface (L·N < 0): ambient only"), packShade(b)});
    return cs;
}

Values shadeRun(const void* table, const Values& in) {
    const ShadeCase c = unpackShade(in);
    const auto scene = buildScene(c);
    const Feeler feeler = [&scene, &c](const glm::dvec3& from, const glm::dvec3& to) {
        return coreFeeler(*scene, from, to) * blockersFeeler(c, from, to);
    };
    Values out;
    put(out, static_cast<const Table*>(table)->shade(c.s, feeler));
    return out;
}

#ifndef WB_HANDOUT // the terms come from core's seed 000 lighting, which a handout has not
// Core's course model on the case (its terms for the message).
rt::CourseModel::Trace coreTerms(const ShadeCase& c, double transmittance) {
    rt::Scene s;
    s.ambient = c.s.ambient / 255.0;
    s.distScale = c.s.distScale;
    s.lights.push_back(rt::Light::point(c.s.lightPos, c.s.lightColour / 255.0));
    rt::Hit hit;
    hit.point = c.s.point;
    hit.normal = hit.outwardNormal = c.s.normal;
    rt::Ray view;
    view.direction = c.s.view;
    rt::Material m;
    m.ka = c.s.material.ka, m.kd = c.s.material.kd, m.ks = c.s.material.ks;
    m.phongExp = c.s.material.p;
    rt::LightSample ls;
    ls.light = &s.lights[0];
    ls.distance = glm::length(c.s.lightPos - c.s.point);
    ls.toLight = (c.s.lightPos - c.s.point) / ls.distance;
    ls.transmittance = transmittance;
    rt::CourseModel model;
    rt::CourseModel::Trace tr;
    model.trace = &tr;
    model.direct(s, view, hit, m, c.s.material.colour / 255.0, {ls});
    return tr;
}
#endif

Verdict shadeCompare(const Values& in, const Values& expected, const Values& got) {
    const glm::dvec3 e = v3(expected, 0), b = v3(got, 0);
    const ShadeCase c = unpackShade(in);
    // Seed 000's cases are its printed integers: exact. Elsewhere ±1 per channel: the
    // factors SH·LN·KD and SH·KS·NN^P multiplied in another order can differ in the last
    // bit and move a .5 tie to the other integer.
    const double tol = c.kind == kSpheres ? 1.0 : 0.0;
    bool ok = true;
    for (int i = 0; i < 3; ++i)
        ok = ok && std::isfinite(b[i]) && std::fabs(b[i] - e[i]) <= tol;
    if (ok) return Verdict::pass();
#ifdef WB_HANDOUT
    // A handout's core has no seed 000 lighting (it is this task): no terms to show.
    if (glm::dot(c.s.lightPos - c.s.point, c.s.normal) <= 0)
        return Verdict::fail(tr("the light is behind the surface (L·N <= 0): no diffuse and no "
                                "specular term, only the ambient"));
    return Verdict::fail(tr("the usual slips: n = normalize(L - V) with V the ray's direction "
                            "(not L + V), SH = distScale/dist times what feeler() returns, "
                            "mul/mulBy in the formula's order"));
#else
    const auto scene = buildScene(c);
    const double kt =
        coreFeeler(*scene, c.s.point, c.s.lightPos) * blockersFeeler(c, c.s.point, c.s.lightPos);
    const rt::CourseModel::Trace t = coreTerms(c, kt);
    const std::string terms =
        trf("expected ambient %s + diffuse %s + specular %s (SH = %.3f, L·N = %.3f, n·N = %.3f)",
            fmtVec(t.ambient).c_str(), fmtVec(t.diffuse).c_str(), fmtVec(t.specular).c_str(), t.sh,
            t.ln, t.nn);
    if (kt < 1) {
        const rt::CourseModel::Trace lit = coreTerms(c, 1.0);
        const glm::dvec3 litColour =
            rt::CourseModel::add(rt::CourseModel::add(lit.ambient, lit.diffuse), lit.specular);
        if (glm::length(b - litColour) < 1.5)
            return Verdict::fail(
                trf("lit as if nothing were in the way: the shadow feeler meets "
                    "a blocker (kt = %.2g), multiply SH by what feeler() returns; %s",
                    kt, terms.c_str()));
    }
    if (glm::dot(c.s.lightPos - c.s.point, c.s.normal) <= 0)
        return Verdict::fail(trf("the light is behind the surface (L·N <= 0): no diffuse and no "
                                 "specular term, only the ambient; %s",
                                 terms.c_str()));
    return Verdict::fail(trf("%s; the usual slips: n = normalize(L - V) with V the ray's "
                             "direction (not L + V), SH = distScale/dist, mul/mulBy in the "
                             "formula's order",
                             terms.c_str()));
#endif
}

// ----- ⑤ reflection: in = d, n, kind (1 = seed 000 part 2: also trace the colour) -----
std::vector<Case> reflectCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string name, const glm::dvec3& d, const glm::dvec3& n, int kind = 0) {
        Values in;
        put(in, glm::normalize(d));
        put(in, glm::normalize(n));
        in.push_back(kind);
        cs.push_back({std::move(name), in});
    };
    add(N_("seed 000 part 2: the reflected ray at P2 and the colour (168,233,86) at P(50,0)"),
        rt::ScreenCamera::seed000().rayThroughScreen(50, 0).direction, {0, 0, 1}, 1);
    add(N_("straight down onto the plane (r = -d)"), {0, 0, -1}, {0, 0, 1});
    add(N_("grazing: d along the surface (r = d)"), {1, 0, 0}, {0, 0, 1});
    add(N_("the normal on the far side (n·d > 0): the same mirror"), {0.6, 0, 0.8}, {0, 0, 1});
    Lcg g{31};
    for (int i = 1; i <= 6; ++i) {
        const glm::dvec3 n = g.unit();
        glm::dvec3 d = g.unit();
        if (glm::dot(d, n) > 0) d = -d;
        add("seed " + std::to_string(i), d, n);
    }
    return cs;
}

Values reflectRun(const void* table, const Values& in) {
    Values out;
    put(out, static_cast<const Table*>(table)->reflectDirection(v3(in, 0), v3(in, 3)));
    return out;
}

#ifndef WB_HANDOUT
// Seed 000 part 2's scene and the colour at P(50, 0) with the reflected direction `r`.
glm::dvec3 seedPart2Colour(const glm::dvec3& r) {
    rt::Scene s;
    s.lights.push_back(rt::Light::point({0, 0, 60}));
    s.distScale = 30;
    rt::Material red, green;
    red.colour = kRed / 255.0, green.colour = kGreen / 255.0;
    red.ka = red.kd = red.ks = green.ka = green.kd = green.ks = 0.5;
    red.phongExp = green.phongExp = 3;
    green.kr = 0.5;
    const int ri = s.addMaterial(red), gi = s.addMaterial(green);
    s.add(rt::Rectangle({50, 0, 20}, {50, 0, 70}, {50, 50, 20}), ri);
    s.add(rt::Rectangle({0, 0, 20}, {50, 0, 20}, {0, 50, 20}), gi);
    const rt::CourseModel model;
    const rt::Tracer tracer(s, model);
    const rt::Ray view = rt::ScreenCamera::seed000().rayThroughScreen(50, 0);
    rt::Hit p2;
    if (!s.intersect(view, 0, 1e30, p2)) return glm::dvec3(-1);
    const rt::Color direct =
        model.direct(s, view, p2, s.materials[size_t(gi)], green.colour, tracer.sampleLights(p2));
    rt::Ray ray;
    ray.origin = p2.point;
    ray.direction = r;
    ray.weight = 0.5;
    ray.depth = 1;
    return rt::CourseModel::add(direct, rt::CourseModel::mulBy(tracer.trace(ray), 0.5));
}
#endif

Verdict reflectCompare(const Values& in, const Values& expected, const Values& got) {
    const glm::dvec3 d = v3(in, 0), n = v3(in, 3), e = v3(expected, 0), r = v3(got, 0);
    // Unit inputs and three roundings: a few ulps; 1e-12 leaves margin and no room for a
    // wrong formula.
    constexpr double kTol = 1e-12;
    if (!(glm::length(r - e) <= kTol)) { // written so that a NaN direction fails too
        const double len = glm::length(r);
        if (!std::isfinite(len)) return Verdict::fail(tr("the direction is not a number"));
        if (glm::length(r + e) <= kTol)
            return Verdict::fail(tr("the reversed ray: r = d - 2(d·n)n goes away from the "
                                    "surface, -r comes back along the way in"));
        if (glm::dot(r, n) * glm::dot(d, n) > 0)
            return Verdict::fail(tr("the ray goes on through the surface: the sign of the "
                                    "2(d·n)n term (r = d - 2(d·n)n)"));
        if (std::fabs(len - 1) > 1e-9)
            return Verdict::fail(trf("|r| = %.6g: for unit d and n, d - 2(d·n)n has length 1 "
                                     "(the factor 2 forgotten?)",
                                     len));
        return Verdict::fail(tr("not the mirror image of d in the plane with normal n: "
                                "r = d - 2(d·n)n"));
    }
#ifndef WB_HANDOUT // a handout's core has no seed 000 lighting; the direction pins the colour
    if (in.at(6) == 1) {
        const glm::dvec3 c = seedPart2Colour(r);
        if (c != glm::dvec3(168, 233, 86))
            return Verdict::fail(trf("with your reflected ray the colour at P(50,0) is %s; seed "
                                     "000 part 2 gets (168,233,86)",
                                     fmtVec(c).c_str()));
    }
#endif
    return Verdict::pass();
}

std::string showVec(const Values& v) {
    return v.size() == 3 ? fmtVec(v3(v, 0)) : ex::showNumbers(v);
}

} // namespace

const ex::LabExercises& exercises() {
    static const ex::LabExercises lab = [] {
        ex::LabExercises l;
        l.lab = "07";
        l.title = N_("Lab 07 - ray tracing (seed 000's steps)");
        l.file = "labs/07-raytrace/exercises.cpp";
        l.reference = wbExerciseReference_lab07();
        ex::Task hit;
        hit.id = "07.intersect";
        hit.grade = 3;
        hit.title = N_("Ray-sphere intersection: the nearest t > 0");
        hit.section = "practical 11.1; seed 000";
        hit.cases = intersectCases;
        hit.run = intersectRun;
        hit.compare = intersectCompare;
        hit.showIn = [](const Values& in) {
            return trf("origin %s, direction %s, centre %s, r = %.6g", fmtVec(v3(in, 0)).c_str(),
                       fmtVec(v3(in, 3)).c_str(), fmtVec(v3(in, 6)).c_str(), in.at(9));
        };
        hit.showOut = [](const Values& out) {
            return out.at(0) != 0 ? trf("hit at t = %.12g", out.at(1)) : std::string(tr("miss"));
        };
        ex::Task normal;
        normal.id = "07.normal";
        normal.grade = 3;
        normal.title = N_("The unit outward normal of the sphere");
        normal.section = "practical 11.1; seed 000";
        normal.cases = normalCases;
        normal.run = [](const void* table, const Values& in) {
            Values out;
            put(out,
                static_cast<const Table*>(table)->sphereNormal(v3(in, 0), v3(in, 3), in.at(6)));
            return out;
        };
        normal.compare = normalCompare;
        normal.showIn = [](const Values& in) {
            return trf("P %s, C %s, r = %.6g", fmtVec(v3(in, 0)).c_str(), fmtVec(v3(in, 3)).c_str(),
                       in.at(6));
        };
        normal.showOut = showVec;
        ex::Task shade;
        shade.id = "07.shade";
        shade.grade = 4;
        shade.title = N_("Lighting at the hit with a shadow feeler");
        shade.section = "seed 000 part 1, formula (3)";
        shade.cases = shadeCases;
        shade.run = shadeRun;
        shade.compare = shadeCompare;
        shade.showIn = [](const Values& in) {
            const ShadeCase c = unpackShade(in);
            return trf("P %s, N %s, V %s, C %s, light at %s", fmtVec(c.s.point).c_str(),
                       fmtVec(c.s.normal).c_str(), fmtVec(c.s.view).c_str(),
                       fmtVec(c.s.material.colour).c_str(), fmtVec(c.s.lightPos).c_str());
        };
        shade.showOut = showVec;
        ex::Task refl;
        refl.id = "07.reflect";
        refl.grade = 5;
        refl.title = N_("The reflected ray");
        refl.section = "seed 000 part 2; practical 12";
        refl.cases = reflectCases;
        refl.run = reflectRun;
        refl.compare = reflectCompare;
        refl.showIn = [](const Values& in) {
            return trf("d %s, n %s", fmtVec(v3(in, 0)).c_str(), fmtVec(v3(in, 3)).c_str());
        };
        refl.showOut = showVec;
        l.tasks = {hit, normal, shade, refl};
        l.mutants = {{1, "07.intersect", N_("the far root taken")},
                     {2, "07.intersect", N_("no t > 0 test (hits behind the origin)")},
                     {3, "07.intersect", N_("sign of origin - centre")},
                     {4, "07.intersect", N_("negative discriminant taken as a hit")},
                     {11, "07.normal", N_("not divided by the radius")},
                     {12, "07.normal", N_("inward normal C - P")},
                     {13, "07.normal", N_("centre forgotten: P / r")},
                     {21, "07.shade", N_("no shadow feeler")},
                     {22, "07.shade", N_("n = normalize(L + V)")},
                     {23, "07.shade", N_("SH = 1 instead of distScale/dist")},
                     {24, "07.shade", N_("light behind the surface not tested (L·N <= 0)")},
                     {31, "07.reflect", N_("sign: d + 2(d·n)n")},
                     {32, "07.reflect", N_("factor 2 forgotten")},
                     {33, "07.reflect", N_("the reversed ray 2(d·n)n - d")}};
        return l;
    }();
    return lab;
}

} // namespace wb::lab07

const wb::ex::LabExercises& wbExercises_lab07() {
    return wb::lab07::exercises();
}
