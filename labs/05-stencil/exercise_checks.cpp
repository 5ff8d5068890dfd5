// Lab 05's tasks and their checks (exercise_check.h). The matrices are homogeneous: equal to
// the reference up to a non-zero factor (ex::equalUpToFactor); the cases are the lab's own
// planes (the mirror, every tread and riser of the staircase, the floor and the back wall,
// with the lab's light), seeded random planes with normals of any length and the hard case
// of DESIGN.md, the light on the plane. The ellipse is checked by what the stencil needs.
#include "exercises.h"

#include "common/exercise_check.h"
#include "core/i18n.h"
#include "stencil_lab.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>
#include <string>

const void* wbExerciseReference_lab05();

namespace wb::lab05 {
namespace {

using ex::Case;
using ex::Values;
using ex::Verdict;

constexpr double kPi = 3.14159265358979323846;
// Matrix entries are sums of a few products of inputs up to ~10 (planes up to 10 from the
// origin, lights within 10): rounding of some ulps of 100; 1e-9 relative to the largest
// entry leaves room for any correct formula and none for a wrong term.
constexpr double kMatrixTol = 1e-9;

Values pack(const glm::dmat4& m) {
    const double* p = glm::value_ptr(m);
    return Values(p, p + 16);
}
glm::dmat4 unpack(const Values& v) {
    glm::dmat4 m;
    for (int i = 0; i < 16; ++i)
        glm::value_ptr(m)[i] = v.at(size_t(i));
    return m;
}
std::string showPlane(const Values& in) {
    return trf("plane %.6gx %+.6gy %+.6gz %+.6g = 0", in.at(0), in.at(1), in.at(2), in.at(3));
}

struct Lcg {
    unsigned long long s;
    double next() {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return double(s >> 11) / double(1ull << 53);
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

// ----- ③ reflection: in = plane -----
std::vector<Case> reflectionCases() {
    std::vector<Case> cs = {
        {N_("the rectangular mirror's plane z = -2.98"), {0, 0, 1, -kMirrorZ}},
        {N_("the back wall z = -3, normal of length 5"), {0, 0, 5, -5 * kWallZ}},
        {N_("a plane through the origin, y = x"), {1, -1, 0, 0}},
        {N_("a tilted plane far out (D = 40)"), {1, 2, 2, 40}},
        {N_("a tiny normal (1e-6 long)"), {1e-6, 0, 0, -2e-6}}};
    Lcg g{51};
    for (int i = 1; i <= 6; ++i)
        cs.push_back(
            {"seed " + std::to_string(i), {g.in(-3, 3), g.in(-3, 3), g.in(-3, 3), g.in(-10, 10)}});
    return cs;
}

Verdict reflectionCompare(const Values& in, const Values& expected, const Values& got) {
    if (const auto v = ex::compareHomogeneous(
            expected, got, 4, kMatrixTol, tr("the matrix holds a non-number"),
            tr("transposed: OpenGL reads m[column][row] (column-major); the "
               "translation -2d·n belongs in the last column"),
            tr("the zero matrix is no map at all")))
        return *v;
    const glm::dmat4 g = unpack(got), e = unpack(expected);
    // Where does the matrix put a point of the plane and the origin?
    const glm::dvec3 n(in.at(0), in.at(1), in.at(2));
    const double len = glm::length(n);
    const glm::dvec3 onPlane = -in.at(3) / (len * len) * n;
    const glm::dvec4 q = g * glm::dvec4(onPlane, 1);
    if (std::fabs(q.w) > 0 &&
        glm::length(glm::dvec3(q) / q.w - onPlane) > 1e-9 * (1 + glm::length(onPlane)))
        return Verdict::fail(tr("a point of the plane moves: the mirror must leave its own plane "
                                "in place (the sign of D, or the normal not divided by its "
                                "length?)"));
    const glm::dvec4 o = g * glm::dvec4(onPlane + n / len, 1),
                     oe = e * glm::dvec4(onPlane + n / len, 1);
    if (std::fabs(o.w) > 0 &&
        glm::length(glm::dvec3(o) / o.w - onPlane) < 1e-9 * (1 + glm::length(onPlane)))
        return Verdict::fail(tr("a point 1 in front of the plane lands ON it: that projects onto "
                                "the plane (factor 1) instead of reflecting (factor 2)"));
    (void)oe;
    return Verdict::fail(tr("not the reflection: p' = p - 2(n·p + d)n with n, d divided by "
                            "|(A, B, C)|"));
}

// ----- ④ shadow: in = plane, light -----
std::vector<Case> shadowCases() {
    std::vector<Case> cs;
    const glm::dvec4 light(kStencilLight, 1);
    auto add = [&cs](std::string name, const glm::dvec4& pl, const glm::dvec4& l) {
        cs.push_back({std::move(name), {pl.x, pl.y, pl.z, pl.w, l.x, l.y, l.z, l.w}});
    };
    add(N_("the floor y = 0, the lab's light"), {0, 1, 0, 0}, light);
    for (int k = 1; k <= 4; ++k) {
        add("tread " + std::to_string(k) + ": y = " + std::to_string(k * kStepHeight).substr(0, 3),
            {0, 1, 0, -k * kStepHeight}, light);
        const double x = kStairX0 + k * kStepWidth;
        add("riser " + std::to_string(k) + ": x = " + std::to_string(x).substr(0, 4), {-1, 0, 0, x},
            light);
    }
    add(N_("the stairs' front side z = 1.2"), {0, 0, 1, -kStairHalfDepth}, light);
    add(N_("the back wall z = -3"), {0, 0, 1, -kWallZ}, light);
    add(N_("a light at infinity (w = 0) over the floor"), {0, 1, 0, 0}, {1, 3, 0.5, 0});
    add(N_("the light ON the plane (pi·L = 0): the shadow collapses"), {0, 1, 0, -5}, light);
    add(N_("the light below the plane (pi·L < 0)"), {0, 1, 0, -6}, light);
    add(N_("a light at infinity parallel to the plane"), {0, 1, 0, 0}, {1, 0, 0.5, 0});
    Lcg g{55};
    for (int i = 1; i <= 6; ++i)
        add("seed " + std::to_string(i), {g.in(-3, 3), g.in(-3, 3), g.in(-3, 3), g.in(-5, 5)},
            {g.in(-10, 10), g.in(-10, 10), g.in(-10, 10), i % 3 == 0 ? 0.0 : 1.0});
    return cs;
}

Verdict shadowCompare(const Values& in, const Values& expected, const Values& got) {
    if (const auto v = ex::compareHomogeneous(
            expected, got, 4, kMatrixTol, tr("the matrix holds a non-number"),
            tr("transposed: OpenGL reads m[column][row]; M[c][r] = (pi·L)delta_rc - "
               "L_r pi_c"),
            tr("the zero matrix is no map at all: with the light on the plane "
               "M = -L·pi^T")))
        return *v;
    const glm::dmat4 g = unpack(got);
    const glm::dvec4 pl(in.at(0), in.at(1), in.at(2), in.at(3)),
        l(in.at(4), in.at(5), in.at(6), in.at(7));
    if (std::fabs(glm::dot(pl, l)) > 1e-9 * glm::length(pl) * glm::length(l)) {
        // A point of the plane must stay where it is.
        const glm::dvec3 n(pl);
        const glm::dvec3 p0 = -pl.w / glm::dot(n, n) * n;
        const glm::dvec4 q = g * glm::dvec4(p0, 1);
        if (std::fabs(q.w) > 1e-12 &&
            glm::length(glm::dvec3(q) / q.w - p0) > 1e-6 * (1 + glm::length(p0)))
            return Verdict::fail(tr("a point of the plane moves under your matrix: the (pi·L)·I "
                                    "term, or D left out of pi·L"));
    }
    return Verdict::fail(tr("not M = (pi·L)·I - L·pi^T (up to a factor)"));
}

// ----- ⑤ ellipse: in = cx, cy, a, b, z, n -----
std::vector<Case> ellipseCases() {
    std::vector<Case> cs = {
        {N_("the lab's elliptical mirror, 64 points"),
         {kEllipseMirror[0], kEllipseMirror[1], kEllipseMirror[2], kEllipseMirror[3], kMirrorZ,
          64}},
        {N_("the fewest: 8 points"), {0, 0, 2, 1, 0, 8}},
        {N_("a circle (a = b), 100 points"), {1, -1, 0.5, 0.5, 3, 100}},
        {N_("a thin ellipse 100 x 0.01, 1024 points"), {0, 0, 100, 0.01, -1, 1024}},
        {N_("taller than wide, 33 points"), {-2, 5, 0.3, 4, -2.98, 33}}};
    Lcg g{57};
    for (int i = 1; i <= 4; ++i)
        cs.push_back({"seed " + std::to_string(i),
                      {g.in(-5, 5), g.in(-5, 5), g.in(0.1, 5), g.in(0.1, 5), g.in(-5, 5),
                       double(8 + int(g.in(0, 200)))}});
    return cs;
}

Values ellipseRun(const void* table, const Values& in) {
    const auto pts = static_cast<const Table*>(table)->ellipseOutline(
        {in.at(0), in.at(1)}, in.at(2), in.at(3), in.at(4), int(in.at(5)));
    Values v;
    for (const auto& p : pts)
        v.insert(v.end(), {p.x, p.y, p.z});
    return v;
}

Verdict ellipseCompare(const Values& in, const Values& /*expected*/, const Values& got) {
    const double cx = in.at(0), cy = in.at(1), a = in.at(2), b = in.at(3), z = in.at(4);
    const int n = int(in.at(5));
    if (got.size() != size_t(3 * n))
        return Verdict::fail(trf("%d points, the task asks for n = %d (each once: the polygon "
                                 "closes by itself)",
                                 int(got.size() / 3), n));
    const double size = std::max(a, b);
    double area2 = 0;
    for (int k = 0; k < n; ++k) {
        const double x = got[size_t(3 * k)], y = got[size_t(3 * k + 1)],
                     zz = got[size_t(3 * k + 2)];
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(zz))
            return Verdict::fail(trf("point %d is not a number", k));
        // On the ellipse: sin/cos and one product each; 1e-9 relative.
        if (std::fabs(zz - z) > 1e-12 * (1 + std::fabs(z)))
            return Verdict::fail(trf("point %d has z = %.9g: the mirror lies in z = %g", k, zz, z));
        const double e = (x - cx) * (x - cx) / (a * a) + (y - cy) * (y - cy) / (b * b);
        if (std::fabs(e - 1) > 1e-9)
            return Verdict::fail(trf("point %d (%.6g, %.6g) is not on the ellipse ((x-cx)²/a² + "
                                     "(y-cy)²/b² = %.6g): a is the semi-axis along x, b along y",
                                     k, x, y, e));
        const int j = (k + 1) % n;
        area2 += (x - cx) * (got[size_t(3 * j + 1)] - cy) - (got[size_t(3 * j)] - cx) * (y - cy);
    }
    const double areaMax = 0.5 * n * a * b * std::sin(2 * kPi / n);
    if (area2 < 0)
        return Verdict::fail(tr("clockwise seen from +z: the polygon shows its back to the "
                                "viewer (with culling it draws nothing into the stencil)"));
    // The n-gon of largest area inscribed in an ellipse is the one evenly spread in the
    // parameter angle (the affine image of a regular n-gon); any other spread, or a point
    // repeated, has less. 1e-9: the area's rounding.
    if (0.5 * area2 < areaMax * (1 - 1e-9) - 1e-12 * size * size)
        return Verdict::fail(
            trf("the polygon covers %.9g of the %.9g the evenly spread %d points "
                "cover: the points are not evenly spread in the angle, or one is "
                "repeated (the step is 2pi/n, not 2pi/(n-1); radians, not degrees)",
                0.5 * area2, areaMax, n));
    return Verdict::pass();
}

} // namespace

const ex::LabExercises& exercises() {
    static const ex::LabExercises lab = [] {
        ex::LabExercises l;
        l.lab = "05";
        l.title = N_("Lab 05 - stencil buffer");
        l.file = "labs/05-stencil/exercises.cpp";
        l.reference = wbExerciseReference_lab05();
        ex::Task refl;
        refl.id = "05.reflection";
        refl.grade = 3;
        refl.title = N_("The reflection matrix of the rectangular mirror's plane");
        refl.section = "§2.5 task 3; practical 1.3";
        refl.cases = reflectionCases;
        refl.run = [](const void* table, const Values& in) {
            return pack(static_cast<const Table*>(table)->reflectionMatrix(
                {in.at(0), in.at(1), in.at(2), in.at(3)}));
        };
        refl.compare = reflectionCompare;
        refl.showIn = showPlane;
        refl.showOut = [](const Values& out) { return ex::showMatrix(out, 4); };
        ex::Task shadow;
        shadow.id = "05.shadow";
        shadow.grade = 4;
        shadow.title = N_("The shadow matrix onto each plane of the staircase");
        shadow.section = "§2.5 task 4; practicals 1.2-1.3";
        shadow.cases = shadowCases;
        shadow.run = [](const void* table, const Values& in) {
            return pack(static_cast<const Table*>(table)->shadowMatrix(
                {in.at(0), in.at(1), in.at(2), in.at(3)},
                {in.at(4), in.at(5), in.at(6), in.at(7)}));
        };
        shadow.compare = shadowCompare;
        shadow.showIn = [](const Values& in) {
            return showPlane(in) +
                   trf(", light (%.6g, %.6g, %.6g, %g)", in.at(4), in.at(5), in.at(6), in.at(7));
        };
        shadow.showOut = [](const Values& out) { return ex::showMatrix(out, 4); };
        ex::Task ell;
        ell.id = "05.ellipse";
        ell.grade = 5;
        ell.title = N_("The elliptical mirror's outline for the stencil");
        ell.section = "§2.5 task 5";
        ell.cases = ellipseCases;
        ell.run = ellipseRun;
        ell.compare = ellipseCompare;
        ell.needsExpected = false; // judged from the input alone: a recording would be the answer
        ell.showIn = [](const Values& in) {
            return trf("centre (%.4g, %.4g), a = %.4g, b = %.4g, z = %.4g, n = %d", in.at(0),
                       in.at(1), in.at(2), in.at(3), in.at(4), int(in.at(5)));
        };
        ell.showOut = [](const Values& out) {
            if (out.empty()) return std::string(tr("(judged from the input: nothing recorded)"));
            std::string s = trf("%d points:", int(out.size() / 3));
            for (size_t k = 0; k + 2 < out.size() && k < 12; k += 3)
                s += trf(" (%.4g, %.4g, %.4g)", out[k], out[k + 1], out[k + 2]);
            return out.size() > 12 ? s + " ..." : s;
        };
        l.tasks = {refl, shadow, ell};
        l.mutants = {{1, "05.reflection", N_("transposed (row-major)")},
                     {2, "05.reflection", N_("normal not normalised")},
                     {3, "05.reflection", N_("sign of D")},
                     {4, "05.reflection", N_("factor 1: onto the plane, not across")},
                     {11, "05.shadow", N_("transposed")},
                     {12, "05.shadow", N_("the (pi·L)·I term left out")},
                     {13, "05.shadow", N_("D left out of pi·L")},
                     {21, "05.ellipse", N_("a and b swapped")},
                     {22, "05.ellipse", N_("clockwise")},
                     {23, "05.ellipse", N_("step 2pi/(n-1): the last point repeats the first")},
                     {24, "05.ellipse", N_("degrees given to sin/cos")}};
        return l;
    }();
    return lab;
}

} // namespace wb::lab05

const wb::ex::LabExercises& wbExercises_lab05() {
    return wb::lab05::exercises();
}
