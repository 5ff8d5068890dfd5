// Lab 06's tasks and their checks (exercise_check.h). Both tasks are graded by the radial
// error the student's Bezier pieces reach against the true circle / sphere, measured with
// core's evaluation (core/bezier_shapes.h), after checks that the pieces join, close
// around the shape once and (for the patches) face outwards.
#include "exercises.h"

#include "common/exercise_check.h"
#include "core/bezier_shapes.h"
#include "core/i18n.h"

#include <cmath>
#include <cstdio>
#include <string>

const void* wbExerciseReference_lab06();

namespace wb::lab06 {
namespace {

// Words of generated case names that caseLabel() (exercise_run.h) translates around their
// number: "seed 3: degree 4" reads "сид 3: степень 4".
[[maybe_unused]] constexpr const char* kCaseNamePieces[] = {N_("degree %s"), N_("radius %s")};

using ex::Case;
using ex::Values;
using ex::Verdict;

constexpr double kPi = 3.14159265358979323846;

// Thresholds, measured with core (fitCircleHandle, patchesRadialError; bezier_shapes_test):
// - two cubic half-circle arcs can do no better than 1.32 % of the radius (the handle
//   k = 1.3157 that makes the error equioscillate); the usual k = 4/3 (the arc's midpoint
//   on the circle) gives 1.84 %. 2 % passes 4/3 and anything within ~1 % of it
//   (k = 1.32..1.345), and fails k = 1 (25 %), the quarter-circle handle 0.5523 (59 %).
//   Higher degrees (glMap1f takes up to 8 points here) only do better.
constexpr double kCircleMaxError = 0.02;
// - the course's 4×4 net (§2.6) reaches 4.60 % against its best sphere (radius 2.704); a
//   fitted net of the same shape reaches 0.43 %. 5 % passes the course's own net.
constexpr double kSphereMaxError = 0.05;
// Ends that should coincide are computed from the same numbers: 1e-9 of the radius leaves
// room for any rounding (a few ulps) and none for a real gap.
constexpr double kJoinTol = 1e-9;
// glMap1f/glMap2f orders: GL guarantees 8 (GL_MAX_EVAL_ORDER); the lab draws with GL.
constexpr int kMaxOrder = 8;
// Coverage: every direction from the centre must have a sampled point of the surface
// within 10° (65×65 samples per patch are ~3° apart on the course's net; a missing half
// leaves directions 90° from any sample).
constexpr double kCoverDegrees = 10.0;

std::string fmtNum(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}
std::string fmtVec(const glm::dvec3& v) {
    return "(" + fmtNum(v.x) + ", " + fmtNum(v.y) + ", " + fmtNum(v.z) + ")";
}

// ----- packing: [count, then per piece its size(s) and xyz...] -----
Values packCurves(const std::vector<Curve>& cs) {
    Values v{double(cs.size())};
    for (const Curve& c : cs) {
        v.push_back(double(c.size()));
        for (const auto& p : c)
            v.insert(v.end(), {p.x, p.y, p.z});
    }
    return v;
}
// Returns false when the Values are not a well-formed list of curves.
bool unpackCurves(const Values& v, std::vector<Curve>& cs) {
    cs.clear();
    size_t k = 0;
    if (v.empty()) return false;
    const double n = v[k++];
    if (!(n >= 0 && n < 1000)) return false;
    for (int c = 0; c < int(n); ++c) {
        if (k >= v.size()) return false;
        const double m = v[k++];
        if (!(m >= 0 && m < 1000) || k + size_t(m) * 3 > v.size()) return false;
        Curve curve;
        for (int i = 0; i < int(m); ++i, k += 3)
            curve.push_back({v[k], v[k + 1], v[k + 2]});
        cs.push_back(curve);
    }
    return k == v.size();
}
Values packPatches(const std::vector<Patch>& ps) {
    Values v{double(ps.size())};
    for (const Patch& p : ps) {
        v.insert(v.end(), {double(p.orderU), double(p.orderV), double(p.points.size())});
        for (const auto& q : p.points)
            v.insert(v.end(), {q.x, q.y, q.z});
    }
    return v;
}
bool unpackPatches(const Values& v, std::vector<Patch>& ps) {
    ps.clear();
    size_t k = 0;
    if (v.empty()) return false;
    const double n = v[k++];
    if (!(n >= 0 && n < 1000)) return false;
    for (int c = 0; c < int(n); ++c) {
        if (k + 3 > v.size()) return false;
        Patch p;
        p.orderU = int(v[k]), p.orderV = int(v[k + 1]);
        const double m = v[k + 2];
        k += 3;
        if (!(m >= 0 && m < 10000) || k + size_t(m) * 3 > v.size()) return false;
        for (int i = 0; i < int(m); ++i, k += 3)
            p.points.push_back({v[k], v[k + 1], v[k + 2]});
        ps.push_back(p);
    }
    return k == v.size();
}

std::string showCurves(const Values& out) {
    if (out.empty()) return std::string(tr("(judged from the input: nothing recorded)"));
    std::vector<Curve> cs;
    if (!unpackCurves(out, cs)) return ex::showNumbers(out);
    std::string s;
    for (size_t c = 0; c < cs.size(); ++c) {
        s += (c ? "; curve " : "curve ") + std::to_string(c + 1) + ":";
        for (const auto& p : cs[c])
            s += " " + fmtVec(p);
    }
    return s;
}
std::string showPatches(const Values& out) {
    if (out.empty()) return std::string(tr("(judged from the input: nothing recorded)"));
    std::vector<Patch> ps;
    if (!unpackPatches(out, ps)) return ex::showNumbers(out);
    std::string s;
    for (size_t c = 0; c < ps.size(); ++c) {
        s += (c ? "; patch " : "patch ") + std::to_string(c + 1) + " (" +
             std::to_string(ps[c].orderU) + "x" + std::to_string(ps[c].orderV) + "):";
        for (const auto& p : ps[c].points)
            s += " " + fmtVec(p);
    }
    return s;
}

// ----- ③ a point by de Casteljau: in = u, then the control points' xyz -----
std::vector<Case> pointCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string n, double u, const Curve& p) {
        Values in{u};
        for (const auto& q : p)
            in.insert(in.end(), {q.x, q.y, q.z});
        cs.push_back({std::move(n), in});
    };
    const Curve cubic = {{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, -1}};
    add(N_("cubic at u = 0.3"), 0.3, cubic);
    add(N_("cubic at u = 0 (q = p0 exactly)"), 0.0, cubic);
    add(N_("cubic at u = 1 (q = p3 exactly)"), 1.0, cubic);
    add(N_("cubic at u = 1e-12"), 1e-12, cubic);
    add(N_("a line (degree 1) at u = 0.25"), 0.25, {{1, 1, 1}, {5, -3, 2}});
    add(N_("one point (degree 0)"), 0.6, {{2, 3, 4}});
    unsigned s = 10u;
    auto rnd = [&s] {
        s = s * 1664525u + 1013904223u;
        return double(s >> 8) / double(1u << 24);
    };
    for (int i = 1; i <= 6; ++i) {
        Curve p(size_t(2 + i));
        for (auto& q : p)
            q = {10 * rnd() - 5, 10 * rnd() - 5, 10 * rnd() - 5};
        add("seed " + std::to_string(i) + ": degree " + std::to_string(i + 1), rnd(), p);
    }
    Curve high(21);
    for (size_t i = 0; i < high.size(); ++i)
        high[i] = {std::cos(0.3 * double(i)) * 1e3, std::sin(0.7 * double(i)) * 1e3, double(i)};
    add(N_("degree 20, coordinates ~1e3, u = 0.7"), 0.7, high);
    return cs;
}

Verdict pointCompare(const Values& in, const Values& expected, const Values& got) {
    const glm::dvec3 e(expected.at(0), expected.at(1), expected.at(2));
    const glm::dvec3 q(got.at(0), got.at(1), got.at(2));
    const double u = in.at(0);
    const size_t n = (in.size() - 1) / 3;
    const glm::dvec3 p0(in.at(1), in.at(2), in.at(3));
    const glm::dvec3 pk(in.at(in.size() - 3), in.at(in.size() - 2), in.at(in.size() - 1));
    if ((u == 0 && q != p0) || (u == 1 && q != pk))
        return Verdict::fail(u == 0 ? tr("q(0) must be p0 exactly (the curve starts at its first "
                                         "control point); u and 1 - u swapped?")
                                    : tr("q(1) must be the last control point exactly; u and "
                                         "1 - u swapped?"));
    // de Casteljau's k rounds of convex combinations: each coordinate off by at most
    // ~2k ulps of max |p_i|; a Bernstein sum does as well. 16(k+1) ε max|p_i| allows both.
    double big = 0;
    for (size_t i = 1; i < in.size(); ++i)
        big = std::max(big, std::fabs(in[i]));
    const double tol = 16.0 * double(n) * 2.2204460492503131e-16 * std::max(big, 1e-300);
    if (glm::length(q - e) <= tol) return Verdict::pass();
    Curve p;
    for (size_t i = 1; i + 2 < in.size(); i += 3)
        p.push_back({in[i], in[i + 1], in[i + 2]});
    if (glm::length(q - evalDeCasteljau(p, 1 - u)) <= tol)
        return Verdict::fail(tr("that is q(1 - u): the curve runs backwards - each round takes "
                                "(1 - u)·p_i + u·p_{i+1}"));
    return Verdict::fail(trf("off by %.3g: k = %d rounds of (1 - u)·p_i + u·p_{i+1} leave one "
                             "point (one round short, or halves instead of u?)",
                             glm::length(q - e), int(n) - 1));
}

// ----- ④ circle -----
std::vector<Case> circleCases() {
    std::vector<Case> cs = {{N_("radius 1"), {1.0}},
                            {N_("radius 2.5 (the handle scales with the radius)"), {2.5}},
                            {N_("radius 0.1 (smallest)"), {0.1}},
                            {N_("radius 10 (largest)"), {10.0}}};
    // Seeded radii in 0.1..10 (a fixed LCG: the same cases on every machine).
    unsigned s = 6u;
    for (int i = 0; i < 4; ++i) {
        s = s * 1664525u + 1013904223u;
        const double r = 0.1 + 9.9 * double(s >> 8) / double(1u << 24);
        cs.push_back({"seed " + std::to_string(i + 1) + ": radius " + fmtNum(r), {r}});
    }
    return cs;
}

Verdict circleCompare(const Values& in, const Values& /*expected*/, const Values& got) {
    const double r = in.at(0);
    std::vector<Curve> cs;
    if (!unpackCurves(got, cs) || cs.size() != 2)
        return Verdict::fail(
            trf("%d curves returned: the task asks for exactly two Bezier curves", int(cs.size())));
    for (size_t c = 0; c < 2; ++c)
        if (cs[c].size() < 2 || int(cs[c].size()) > kMaxOrder)
            return Verdict::fail(trf("curve %d has %d control points: glMap1f draws 2 to %d "
                                     "(a cubic has 4)",
                                     int(c + 1), int(cs[c].size()), kMaxOrder));
    for (size_t c = 0; c < 2; ++c)
        for (const auto& p : cs[c])
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return Verdict::fail(trf("curve %d has a control point that is not a number "
                                         "(a division by zero?)",
                                         int(c + 1)));
            else if (std::fabs(p.z) > kJoinTol * r)
                return Verdict::fail(trf("curve %d leaves the plane z = 0 (control point with "
                                         "z = %g): the circle lies in z = 0",
                                         int(c + 1), p.z));
    const double gap1 = glm::length(cs[0].back() - cs[1].front());
    const double gap2 = glm::length(cs[1].back() - cs[0].front());
    if (gap1 > kJoinTol * r || gap2 > kJoinTol * r)
        return Verdict::fail(trf("the curves do not join (gaps %.3g and %.3g): the last control "
                                 "point of each curve must be the first of the other",
                                 gap1, gap2));
    // Winding number about the centre from densely sampled points: once around.
    double turn = 0.0;
    glm::dvec3 prev = cs[0].front();
    for (const Curve& c : cs)
        for (int i = 1; i <= 512; ++i) {
            const glm::dvec3 p = evalDeCasteljau(c, i / 512.0);
            turn += std::atan2(prev.x * p.y - prev.y * p.x, prev.x * p.x + prev.y * p.y);
            prev = p;
        }
    const long winding = std::lround(turn / (2 * kPi));
    if (winding == 0)
        return Verdict::fail(tr("the two curves do not go around the centre: both cover the "
                                "same half of the circle (check the sign of y in the second)"));
    if (std::labs(winding) != 1)
        return Verdict::fail(
            trf("the curves go %ld times around the centre: once is a circle", std::labs(winding)));
    const RadialError e = curvesRadialError(cs, r, 4096);
    if (!(e.relative() <= kCircleMaxError)) {
        const bool out = e.maxRadius - r > r - e.minRadius;
        return Verdict::fail(trf(
            "radial error %.3g %% of the radius (2 %% passes; the best two cubics reach 1.32 %%): "
            "the curve %s the circle - the inner control points sit %s; a cubic half circle "
            "needs them 4/3 of the radius along the tangents",
            100 * e.relative(), out ? tr("bulges outside") : tr("dips inside"),
            out ? tr("too far out") : tr("too close")));
    }
    return Verdict::pass();
}

// ----- ⑤ sphere -----
Verdict sphereCompare(const Values& /*in*/, const Values& /*expected*/, const Values& got) {
    std::vector<Patch> ps;
    if (!unpackPatches(got, ps) || ps.size() != 2)
        return Verdict::fail(trf("%d patches returned: the task asks for exactly two Bezier "
                                 "patches",
                                 int(ps.size())));
    std::vector<BezierPatch> bp;
    for (size_t k = 0; k < 2; ++k) {
        const Patch& p = ps[k];
        if (p.orderU < 2 || p.orderV < 2 || p.orderU > kMaxOrder || p.orderV > kMaxOrder ||
            p.points.size() != size_t(p.orderU) * size_t(p.orderV))
            return Verdict::fail(trf("patch %d: orders %d x %d with %d points: glMap2f needs "
                                     "orderU·orderV points, orders 2..%d",
                                     int(k + 1), p.orderU, p.orderV, int(p.points.size()),
                                     kMaxOrder));
        for (const auto& q : p.points)
            if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
                return Verdict::fail(
                    trf("patch %d has a control point that is not a number", int(k + 1)));
        bp.push_back(BezierPatch{p.orderU, p.orderV, p.points});
    }
    // Coverage: sampled directions against a Fibonacci set of test directions.
    std::vector<glm::dvec3> dirs;
    constexpr int kGrid = 64;
    for (const BezierPatch& p : bp)
        for (int j = 0; j <= kGrid; ++j)
            for (int i = 0; i <= kGrid; ++i) {
                const glm::dvec3 q = evalPatch(p, double(i) / kGrid, double(j) / kGrid).point;
                if (glm::length(q) > 0) dirs.push_back(glm::normalize(q));
            }
    const double cosCover = std::cos(kCoverDegrees * kPi / 180);
    constexpr int kTests = 1000;
    for (int t = 0; t < kTests; ++t) {
        const double z = 1 - (2 * t + 1.0) / kTests, rho = std::sqrt(1 - z * z);
        const double phi = t * kPi * (3 - std::sqrt(5.0));
        const glm::dvec3 d(rho * std::cos(phi), rho * std::sin(phi), z);
        double best = -2;
        for (const auto& s : dirs)
            best = std::max(best, glm::dot(s, d));
        if (best < cosCover)
            return Verdict::fail(trf("no point of the patches lies within %g° of the direction "
                                     "(%.2f, %.2f, %.2f) from the centre: the two patches do not "
                                     "close around the sphere (did you mirror the second one?)",
                                     kCoverDegrees, d.x, d.y, d.z));
    }
    // Orientation: GL_AUTO_NORMAL's du × dv must point away from the centre.
    for (size_t k = 0; k < 2; ++k)
        for (int j = 0; j <= 16; ++j)
            for (int i = 0; i <= 16; ++i) {
                const PatchSample s = evalPatch(bp[k], i / 16.0, j / 16.0);
                if (s.normalKind == 2 || glm::length(s.point) == 0) continue;
                if (glm::dot(s.normal, s.point) < 0)
                    return Verdict::fail(
                        trf("patch %d: du x dv points into the sphere at u = %.3g, v = %.3g, so "
                            "GL_AUTO_NORMAL lights it from inside: a mirrored patch needs its rows "
                            "(or columns) in reverse order",
                            int(k + 1), i / 16.0, j / 16.0));
            }
    const RadialError e = patchesRadialError(bp, 0.0, 128);
    if (!(e.relative() <= kSphereMaxError))
        return Verdict::fail(trf("radial error %.3g %% of the best sphere's radius %.4g (5 %% "
                                 "passes; the course's net reaches 4.6 %%): the surface is too "
                                 "far from a sphere - compare your net with §2.6's",
                                 100 * e.relative(), e.radius));
    return Verdict::pass();
}

} // namespace

const ex::LabExercises& exercises() {
    static const ex::LabExercises lab = [] {
        ex::LabExercises l;
        l.lab = "06";
        l.title = N_("Lab 06 - Bezier curves and patches");
        l.file = "labs/06-bezier/exercises.cpp";
        l.reference = wbExerciseReference_lab06();
        ex::Task point;
        point.id = "06.point";
        point.grade = 3;
        point.title = N_("A point of a Bezier curve by de Casteljau");
        point.section = "§1.10, Theorem 0.4 (practical 10)";
        point.cases = pointCases;
        point.run = [](const void* table, const Values& in) {
            Curve p;
            for (size_t i = 1; i + 2 < in.size(); i += 3)
                p.push_back({in[i], in[i + 1], in[i + 2]});
            const glm::dvec3 q = static_cast<const Table*>(table)->bezierPoint(p, in.at(0));
            return Values{q.x, q.y, q.z};
        };
        point.compare = pointCompare;
        point.showIn = [](const Values& in) {
            std::string s = "u = " + fmtNum(in.at(0)) + ", points";
            for (size_t i = 1; i + 2 < in.size() && i < 40; i += 3)
                s += " " + fmtVec({in[i], in[i + 1], in[i + 2]});
            return in.size() > 40 ? s + " ..." : s;
        };
        ex::Task circle;
        circle.id = "06.circle";
        circle.grade = 4;
        circle.title = N_("A circle from two Bezier curves");
        circle.section = "§2.6 task 4; §1.10";
        circle.cases = circleCases;
        circle.run = [](const void* table, const Values& in) {
            return packCurves(static_cast<const Table*>(table)->circleCurves(in.at(0)));
        };
        circle.compare = circleCompare;
        circle.needsExpected =
            false; // judged from the input alone: a recording would be the answer
        circle.showIn = [](const Values& in) { return "radius " + fmtNum(in.at(0)); };
        circle.showOut = showCurves;
        ex::Task sphere;
        sphere.id = "06.sphere";
        sphere.grade = 5;
        sphere.title = N_("A sphere from two Bezier patches");
        sphere.section = "§2.6 task 5; §1.10.4";
        sphere.cases = [] { return std::vector<Case>{{N_("the two Bezier patches"), {}}}; };
        sphere.run = [](const void* table, const Values&) {
            return packPatches(static_cast<const Table*>(table)->spherePatches());
        };
        sphere.compare = sphereCompare;
        sphere.needsExpected = false;
        sphere.showIn = [](const Values&) { return std::string("-"); };
        sphere.showOut = showPatches;
        l.tasks = {point, circle, sphere};
        l.mutants = {{21, "06.point", N_("u and 1 - u swapped")},
                     {22, "06.point", N_("one round of de Casteljau short")},
                     {23, "06.point", N_("midpoints instead of (1 - u, u)")},
                     {1, "06.circle", N_("quarter-circle handle 0.5523 for half circles")},
                     {2, "06.circle", N_("second curve over the upper half again (sign of y)")},
                     {3, "06.circle", N_("handle not scaled with the radius")},
                     {4, "06.circle", N_("inner control points in the wrong order")},
                     {11, "06.sphere", N_("mirrored without reversing the rows (lit inside)")},
                     {12, "06.sphere", N_("second patch not mirrored: the upper half twice")},
                     {13, "06.sphere", N_("control net transposed (normals inwards)")}};
        return l;
    }();
    return lab;
}

} // namespace wb::lab06

const wb::ex::LabExercises& wbExercises_lab06() {
    return wb::lab06::exercises();
}
