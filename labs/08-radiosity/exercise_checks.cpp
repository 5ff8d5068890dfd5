// Lab 08's tasks and their checks (exercise_check.h): the form factor by (15.20), one
// Jacobi sweep, the form factor by rays with visibility. Beside the reference's values
// the checks use the closed forms of core/radiosity/closed_forms.h: (15.20) must approach
// the exact F of two directly opposed squares as they move apart, Jacobi sweeps must
// converge to the exact radiosities of two patches, and the visibility found by rays
// must match the fraction of rays a blocker stops, known exactly for the cases below.
#include "exercises.h"

#include "common/exercise_check.h"
#include "core/i18n.h"
#include "core/radiosity/closed_forms.h"
#include "core/raytrace/rectangle.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

const void* wbExerciseReference_lab08();

namespace wb::lab08 {
namespace {

// Words of generated case names that caseLabel() (exercise_run.h) translates around their
// number: "seed 3: 5 patches".
[[maybe_unused]] constexpr const char* kCaseNamePieces[] = {N_("%s patches")};

using ex::Case;
using ex::Values;
using ex::Verdict;

constexpr double kPi = 3.14159265358979323846;

struct Lcg {
    unsigned long long s;
    double next() {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return double(s >> 11) / double(1ull << 53);
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

void putQuad(Values& v, const Quad& q) {
    for (const auto& p : q.p)
        v.insert(v.end(), {p.x, p.y, p.z});
}
Quad getQuad(const Values& v, size_t k) {
    Quad q;
    for (int c = 0; c < 4; ++c, k += 3)
        q.p[c] = {v.at(k), v.at(k + 1), v.at(k + 2)};
    return q;
}
// A square of side a centred at c, normal +z (up = true) or -z, in the plane z = c.z.
Quad square(const glm::dvec3& c, double a, bool up) {
    const double h = a / 2;
    Quad q;
    q.p[0] = c + glm::dvec3(-h, -h, 0), q.p[2] = c + glm::dvec3(h, h, 0);
    q.p[1] = c + (up ? glm::dvec3(h, -h, 0) : glm::dvec3(-h, h, 0));
    q.p[3] = c + (up ? glm::dvec3(-h, h, 0) : glm::dvec3(h, -h, 0));
    return q;
}
// The quad's corners mapped by a rotation about the axis (unit) through the origin.
Quad rotate(Quad q, const glm::dvec3& axis, double angle, const glm::dvec3& shift) {
    for (auto& p : q.p)
        p = p * std::cos(angle) + glm::cross(axis, p) * std::sin(angle) +
            axis * glm::dot(axis, p) * (1 - std::cos(angle)) + shift;
    return q;
}
std::string showQuad(const Quad& q) {
    char b[256];
    std::snprintf(b, sizeof b,
                  "[(%.4g, %.4g, %.4g) (%.4g, %.4g, %.4g) (%.4g, %.4g, %.4g) (%.4g, %.4g, %.4g)]",
                  q.p[0].x, q.p[0].y, q.p[0].z, q.p[1].x, q.p[1].y, q.p[1].z, q.p[2].x, q.p[2].y,
                  q.p[2].z, q.p[3].x, q.p[3].y, q.p[3].z);
    return b;
}

// ----- ③ (15.20): in = quad i, quad j, side a and distance c of an opposed pair (0: none) --
std::vector<Case> ffCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string n, const Quad& i, const Quad& j, double a = 0, double c = 0) {
        Values in;
        putQuad(in, i);
        putQuad(in, j);
        in.insert(in.end(), {a, c});
        cs.push_back({std::move(n), in});
    };
    add(N_("opposed unit squares 10 apart (the exact F differs by 0.67 %)"),
        square({0, 0, 0}, 1, true), square({0, 0, 10}, 1, false), 1, 10);
    add(N_("opposed squares of side 2, 20 apart"), square({1, 1, 0}, 2, true),
        square({1, 1, 20}, 2, false), 2, 20);
    add(N_("different areas: A_j = 4 A_i"), square({0, 0, 0}, 1, true),
        square({3, 0, 8}, 2, false));
    add(N_("perpendicular, sharing an edge (near: (15.20) is rough, but it is the formula)"),
        square({0, 0, 0}, 1, true),
        rotate(square({0, 0, 0}, 1, true), {1, 0, 0}, kPi / 2, {0, 0.5, 0.5}));
    add(N_("j behind i (cos phi_i < 0): 0"), square({0, 0, 0}, 1, true),
        square({0, 0, -5}, 1, true));
    add(N_("both turned away (both cosines < 0): 0"), square({0, 0, 0}, 1, false),
        square({0, 0, 5}, 1, true));
    add(N_("coincident centres (d = 0): 0"), square({0, 0, 0}, 1, true),
        square({0, 0, 0}, 1, false));
    add(N_("small patches, 1e-2"), square({0, 0, 0}, 1e-2, true),
        square({0.01, 0, 0.05}, 1e-2, false));
    Lcg g{8};
    for (int s = 1; s <= 8; ++s) {
        const glm::dvec3 axisI = glm::normalize(glm::dvec3(g.in(-1, 1), g.in(-1, 1), g.in(-1, 1)));
        const glm::dvec3 axisJ = glm::normalize(glm::dvec3(g.in(-1, 1), g.in(-1, 1), g.in(-1, 1)));
        const Quad i =
            rotate(square({0, 0, 0}, g.in(0.2, 2), true), axisI, g.in(0, 1.2), {0, 0, 0});
        const Quad j = rotate(square({0, 0, 0}, g.in(0.2, 2), false), axisJ, g.in(0, 1.2),
                              {g.in(-3, 3), g.in(-3, 3), g.in(2, 8)});
        add("seed " + std::to_string(s), i, j);
    }
    return cs;
}

Verdict ffCompare(const Values& in, const Values& expected, const Values& got) {
    const double e = expected.at(0), f = got.at(0);
    if (!std::isfinite(f))
        return Verdict::fail(tr("F is not a number: d = 0 or a zero-area patch must give 0"));
    // (15.20) is a closed expression: a few roundings, 1e-12 relative to F.
    if (std::fabs(f - e) > 1e-12 * std::max(std::fabs(e), 1e-300)) {
        if (e == 0)
            return Verdict::fail(tr("F must be 0 here: a patch that sees the other's back (cos phi "
                                    "<= 0), or d = 0, exchanges no light by (15.20)"));
        const double r = f / e;
        if (std::fabs(r - kPi) < 1e-9 * kPi)
            return Verdict::fail(tr("F is pi times too large: (15.20) divides by pi d²"));
        const Quad i = getQuad(in, 0), j = getQuad(in, 12);
        const glm::dvec3 ci = 0.25 * (i.p[0] + i.p[1] + i.p[2] + i.p[3]);
        const glm::dvec3 cj = 0.25 * (j.p[0] + j.p[1] + j.p[2] + j.p[3]);
        const double d = glm::length(cj - ci);
        if (std::fabs(r - d) < 1e-9 * d)
            return Verdict::fail(tr("F is d times too large: (15.20) divides by d², not d"));
        return Verdict::fail(trf("F = %.9g, expected %.9g (ratio %.6g): check A_j (the area of "
                                 "the patch the light arrives at), the cosines at both centres",
                                 f, e, r));
    }
    const double a = in.at(24), c = in.at(25);
    if (a > 0) {
        // Against the exact F of two opposed squares (Howell C-11, closed_forms.h): (15.20)
        // exceeds it by 0.667 (a/c)² relative (measured: 0.641 at c = 2a, 0.666 at 10a);
        // (a/c)² bounds that.
        const double exact = rad::parallelRectangles(a, a, c);
        if (std::fabs(f / exact - 1) > (a / c) * (a / c))
            return Verdict::fail(
                trf("F = %.6g is far from the exact %.6g of two opposed squares", f, exact));
    }
    return Verdict::pass();
}

// ----- ④ Jacobi: in = n, B, E, R, F (n×n), sweeps (1 or many), exact B (when many) -----
std::vector<Case> jacobiCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string name, const std::vector<double>& B, const std::vector<double>& E,
                     const std::vector<double>& R, const std::vector<double>& F, int sweeps,
                     const std::vector<double>& exact = {}) {
        Values in{double(B.size())};
        for (const auto* v : {&B, &E, &R, &F})
            in.insert(in.end(), v->begin(), v->end());
        in.push_back(sweeps);
        in.insert(in.end(), exact.begin(), exact.end());
        cs.push_back({std::move(name), in});
    };
    // Two patches of different areas: F_12 A_1 = F_21 A_2, so F is not symmetric.
    add(N_("two patches, first sweep from B = E"), {1, 0}, {1, 0}, {0.5, 0.8}, {0, 0.2, 0.05, 0},
        1);
    add(N_("two patches, B = (0.3, 0.7)"), {0.3, 0.7}, {1, 0}, {0.5, 0.8}, {0, 0.2, 0.05, 0}, 1);
    add(N_("no patches (n = 0)"), {}, {}, {}, {}, 1);
    Lcg g{5};
    for (int s = 1; s <= 4; ++s) {
        const int n = 3 + s;
        const size_t un = size_t(n);
        std::vector<double> B(un), E(un), R(un), F(un * un, 0.0);
        for (int i = 0; i < n; ++i) {
            B[size_t(i)] = g.in(0, 2),
            E[size_t(i)] = i == 0 ? 1.0 : (g.next() < 0.3 ? g.in(0, 1) : 0);
            R[size_t(i)] = g.in(0.1, 0.9);
            double row = 0;
            for (int j = 0; j < n; ++j)
                if (i != j) row += (F[size_t(i * n + j)] = g.in(0, 1));
            const double total = g.in(0.3, 0.95); // a row sums to at most 1 (energy)
            for (int j = 0; j < n; ++j)
                F[size_t(i * n + j)] *= total / row;
        }
        add("seed " + std::to_string(s) + ": " + std::to_string(n) + " patches", B, E, R, F, 1);
    }
    // Two opposed unit squares 0.5 apart (closed form F), the first a lamp: 200 sweeps
    // from B = E converge to B1 = (E1 + R1 F12 E2)/(1 - R1 R2 F12 F21), B2 = R2 F21 B1 + E2.
    const double f = rad::parallelRectangles(1, 1, 0.5);
    const double r1 = 0.6, r2 = 0.8, e1 = 1, e2 = 0;
    const double b1 = (e1 + r1 * f * e2) / (1 - r1 * r2 * f * f), b2 = e2 + r2 * f * b1;
    add(N_("opposed squares 0.5 apart (F from the closed form): 200 sweeps reach the exact B"),
        {e1, e2}, {e1, e2}, {r1, r2}, {0, f, f, 0}, 200, {b1, b2});
    return cs;
}

struct JacobiIn {
    std::vector<double> B, E, R, F, exact;
    int sweeps = 1;
};
JacobiIn unpackJacobi(const Values& in) {
    JacobiIn j;
    const size_t n = size_t(in.at(0));
    size_t k = 1;
    auto take = [&](std::vector<double>& v, size_t m) {
        v.assign(in.begin() + long(k), in.begin() + long(k + m));
        k += m;
    };
    take(j.B, n), take(j.E, n), take(j.R, n), take(j.F, n * n);
    j.sweeps = int(in.at(k++));
    take(j.exact, in.size() - k);
    return j;
}

Values jacobiRun(const void* table, const Values& in) {
    const JacobiIn j = unpackJacobi(in);
    std::vector<double> b = j.B;
    for (int s = 0; s < j.sweeps; ++s) {
        b = static_cast<const Table*>(table)->jacobiSweep(b, j.E, j.R, j.F);
        if (b.size() != j.B.size()) break;
    }
    return Values(b.begin(), b.end());
}

Verdict jacobiCompare(const Values& in, const Values& expected, const Values& got) {
    const JacobiIn j = unpackJacobi(in);
    const size_t n = j.B.size();
    if (got.size() != n)
        return Verdict::fail(trf("B' has %d values for %d patches", int(got.size()), int(n)));
    // A sweep sums n products of numbers <= ~2: 1e-12 relative leaves room for any order
    // of summation and none for a wrong term.
    if (!ex::allNear(expected, got, 1e-12)) {
        // What the usual mistakes would have given, from the same inputs.
        std::vector<double> gs = j.B, tr_(n), noE(n), noR(n);
        for (size_t i = 0; i < n; ++i) {
            double in1 = 0, inT = 0, inG = 0;
            for (size_t k = 0; k < n; ++k)
                in1 += j.F[i * n + k] * j.B[k], inT += j.F[k * n + i] * j.B[k],
                    inG += j.F[i * n + k] * gs[k];
            gs[i] = j.E[i] + j.R[i] * inG, tr_[i] = j.E[i] + j.R[i] * inT;
            noE[i] = j.R[i] * in1, noR[i] = j.E[i] + in1;
        }
        if (j.sweeps == 1) {
            if (ex::allNear(Values(tr_.begin(), tr_.end()), got, 1e-12))
                return Verdict::fail(tr("F transposed: the light arriving at P_i is sum_j F_ij B_j "
                                        "(row i of F), not F_ji"));
            if (ex::allNear(Values(gs.begin(), gs.end()), got, 1e-12))
                return Verdict::fail(tr("that is a Gauss-Seidel sweep (new B_j used as soon as "
                                        "computed): Jacobi takes every B_j from the old B"));
            if (ex::allNear(Values(noE.begin(), noE.end()), got, 1e-12))
                return Verdict::fail(
                    tr("the emission E_i is missing: B'_i = E_i + R_i sum F_ij B_j"));
            if (ex::allNear(Values(noR.begin(), noR.end()), got, 1e-12))
                return Verdict::fail(tr("the reflectivity R_i is missing: only a fraction R_i of "
                                        "the arriving light leaves P_i again"));
        }
        return Verdict::fail(tr("B' differs from E_i + R_i sum_j F_ij B_j"));
    }
    if (!j.exact.empty()) {
        // 200 sweeps with ρ(RF) <= 0.8·0.25: the error is below 1e-100 of B, so rounding
        // alone remains (1e-12).
        for (size_t i = 0; i < n; ++i)
            if (std::fabs(got[i] - j.exact[i]) > 1e-12 * std::fabs(j.exact[i]))
                return Verdict::fail(
                    trf("after %d sweeps B_%d = %.12g, the exact solution is %.12g", j.sweeps,
                        int(i + 1), got[i], j.exact[i]));
    }
    return Verdict::pass();
}

// ----- ⑤ rays: in = quad i, quad j, k, seed, exact V, then blockers (3 corners each) -----
struct RaysIn {
    Quad i, j;
    int k = 16;
    unsigned seed = 1;
    double exactV = 1;
    std::vector<rt::Rectangle> blockers;
};
RaysIn unpackRays(const Values& in) {
    RaysIn r;
    r.i = getQuad(in, 0), r.j = getQuad(in, 12);
    r.k = int(in.at(24)), r.seed = unsigned(in.at(25)), r.exactV = in.at(26);
    for (size_t k = 27; k + 9 <= in.size(); k += 9)
        r.blockers.emplace_back(glm::dvec3(in[k], in[k + 1], in[k + 2]),
                                glm::dvec3(in[k + 3], in[k + 4], in[k + 5]),
                                glm::dvec3(in[k + 6], in[k + 7], in[k + 8]));
    return r;
}

std::vector<Case> raysCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string name, const Quad& i, const Quad& j, int k, unsigned seed, double v,
                     const std::vector<std::array<glm::dvec3, 3>>& blockers) {
        Values in;
        putQuad(in, i);
        putQuad(in, j);
        in.insert(in.end(), {double(k), double(seed), v});
        for (const auto& b : blockers)
            for (const auto& p : b)
                in.insert(in.end(), {p.x, p.y, p.z});
        cs.push_back({std::move(name), in});
    };
    const Quad lo = square({0, 0, 0}, 1, true), hi = square({0, 0, 2}, 1, false);
    add(N_("nothing in between: V = 1, F = (15.20)"), lo, hi, 16, 1, 1.0, {});
    add(N_("a plate covering both: V = 0"), lo, hi, 16, 2, 0.0,
        {{glm::dvec3(-5, -5, 1), glm::dvec3(5, -5, 1), glm::dvec3(-5, 5, 1)}});
    // A plate over x < x0 in the middle plane z = 1 stops the ray from (x1, .., 0) to
    // (x2, .., 2) when (x1 + x2)/2 < x0: for x1, x2 uniform on [-½, ½] that is
    // P(S < 2·x0) = 1 - (1 - 2x0)²/2 (S's density is triangular): V = (1 - 2x0)²/2.
    // x0 = 0.013 keeps every midpoint of the grids off the plate's edge.
    const double x0 = 0.013, half = (1 - 2 * x0) * (1 - 2 * x0) / 2;
    add(N_("a plate over half of the gap: V = 0.474 (256 rays)"), lo, hi, 256, 3, half,
        {{glm::dvec3(-5, -5, 1), glm::dvec3(x0, -5, 1), glm::dvec3(-5, 5, 1)}});
    add(N_("the same plate, another seed (1024 rays)"), lo, hi, 1024, 4, half,
        {{glm::dvec3(-5, -5, 1), glm::dvec3(x0, -5, 1), glm::dvec3(-5, 5, 1)}});
    add(N_("a plate beside the patches: V = 1"), lo, hi, 64, 5, 1.0,
        {{glm::dvec3(3, -5, 1), glm::dvec3(6, -5, 1), glm::dvec3(3, 5, 1)}});
    add(N_("one ray (k = 1)"), lo, hi, 1, 6, 1.0, {});
    add(N_("facing away: F = 0 whatever V"), lo, square({0, 0, -2}, 1, false), 16, 7, 0.0, {});
    add(N_("different areas, nothing between"), square({0, 0, 0}, 0.5, true),
        square({1, 0.5, 3}, 2, false), 36, 8, 1.0, {});
    return cs;
}

Values raysRun(const void* table, const Values& in) {
    const RaysIn r = unpackRays(in);
    const Visible visible = [&r](const glm::dvec3& a, const glm::dvec3& b) {
        const glm::dvec3 d = b - a;
        const double len = glm::length(d);
        if (!(len > 0)) return true;
        rt::Ray ray;
        ray.origin = a;
        ray.direction = d / len;
        rt::Hit hit;
        for (const auto& q : r.blockers)
            if (q.intersect(ray, 0, len, hit)) return false;
        return true;
    };
    const auto* t = static_cast<const Table*>(table);
    Values out{t->formFactorRays(r.i, r.j, r.k, r.seed, visible)};
    // The reference's run also gives its (15.20) at the centres, which the compare divides
    // by: recorded in a handout, so (15.20) is written nowhere in it but the student's ③.
    if (table && table == wbExerciseReference_lab08()) out.push_back(t->formFactor(r.i, r.j));
    return out;
}

Verdict raysCompare(const Values& in, const Values& expected, const Values& got) {
    const RaysIn r = unpackRays(in);
    if (expected.size() < 2) return Verdict::fail(tr("no (15.20) recorded for this case"));
    const double f = got.at(0), g = expected[1];
    if (!std::isfinite(f)) return Verdict::fail(tr("F is not a number"));
    if (g == 0) {
        if (f == 0) return Verdict::pass();
        return Verdict::fail(tr("F must be 0: the patches do not face each other ((15.20) is 0 "
                                "whatever the rays see)"));
    }
    const double v = f / g; // the visibility the student found
    if (v < -1e-12 || v > 1 + 1e-12)
        return Verdict::fail(trf("F/(15.20) = %.6g: V is a fraction of rays, between 0 and 1 "
                                 "(is the geometric term (15.20) at the centres?)",
                                 v));
    // V counts rays: a multiple of 1/k (to rounding, 1e-9).
    if (std::fabs(v * r.k - std::round(v * r.k)) > 1e-9 * r.k)
        return Verdict::fail(trf("V = F/(15.20) = %.9g is not a whole number of rays out of k = "
                                 "%d: divide the count of visible rays by k",
                                 v, r.k));
    // Every ray blocked or none: exact. Otherwise the estimate of a fraction from k paired
    // points: its standard deviation is at most ½/√k (binomial; the even spread only lowers
    // it), and 4 of those are allowed (0.125 at k = 256, 0.0625 at 1024).
    const double tol = (r.exactV == 0 || r.exactV == 1) ? 1e-12 : 4 * 0.5 / std::sqrt(double(r.k));
    if (std::fabs(v - r.exactV) <= tol) return Verdict::pass();
    if (r.exactV < 1 && v == 1)
        return Verdict::fail(tr("every ray counted as visible: call visible(a, b) for each pair "
                                "of points and count the rays it lets through"));
    if (std::fabs((1 - v) - r.exactV) <= tol)
        return Verdict::fail(tr("V is the fraction of BLOCKED rays: count those visible() "
                                "lets through"));
    return Verdict::fail(
        trf("V = %.4g but %.4g of the rays get through (allowed ±%.3g): spread the "
            "k points evenly over each patch and pair them at random",
            v, r.exactV, tol));
}

} // namespace

const ex::LabExercises& exercises() {
    static const ex::LabExercises lab = [] {
        ex::LabExercises l;
        l.lab = "08";
        l.title = N_("Lab 08 - radiosity");
        l.file = "labs/08-radiosity/exercises.cpp";
        l.reference = wbExerciseReference_lab08();
        ex::Task ff;
        ff.id = "08.formfactor";
        ff.grade = 3;
        ff.title = N_("Form factor of two patches by (15.20)");
        ff.section = "§1.15, (15.20)";
        ff.cases = ffCases;
        ff.run = [](const void* table, const Values& in) {
            return Values{
                static_cast<const Table*>(table)->formFactor(getQuad(in, 0), getQuad(in, 12))};
        };
        ff.compare = ffCompare;
        ff.showIn = [](const Values& in) {
            return "P_i " + showQuad(getQuad(in, 0)) + ", P_j " + showQuad(getQuad(in, 12));
        };
        ex::Task jac;
        jac.id = "08.jacobi";
        jac.grade = 4;
        jac.title = N_("One Jacobi sweep of B = E + R·F·B");
        jac.section = "§1.14, (14.16), (14.18)";
        jac.cases = jacobiCases;
        jac.run = jacobiRun;
        jac.compare = jacobiCompare;
        jac.showIn = [](const Values& in) {
            const JacobiIn j = unpackJacobi(in);
            return trf("n = %d, B = %s, E = %s, R = %s, %d sweep(s)", int(j.B.size()),
                       ex::showNumbers(Values(j.B.begin(), j.B.end())).c_str(),
                       ex::showNumbers(Values(j.E.begin(), j.E.end())).c_str(),
                       ex::showNumbers(Values(j.R.begin(), j.R.end())).c_str(), j.sweeps);
        };
        ex::Task rays;
        rays.id = "08.rays";
        rays.grade = 5;
        rays.title = N_("Form factor by rays with visibility");
        rays.section = "§1.15.1";
        rays.cases = raysCases;
        rays.run = raysRun;
        rays.compare = raysCompare;
        // Judged from the input, the exact V and the reference's (15.20) (recorded in a
        // handout), not from the reference's own rays.
        rays.needsExpected = true;
        rays.showIn = [](const Values& in) {
            const RaysIn r = unpackRays(in);
            return trf("P_i %s, P_j %s, k = %d, seed %u, %d blocker(s)", showQuad(r.i).c_str(),
                       showQuad(r.j).c_str(), r.k, r.seed, int(r.blockers.size()));
        };
        rays.showOut = [](const Values& out) {
            if (out.empty()) return std::string(tr("(judged from the input: nothing recorded)"));
            return trf("F = %.9g", out.at(0));
        };
        l.tasks = {ff, jac, rays};
        l.mutants = {{1, "08.formfactor", N_("pi forgotten")},
                     {2, "08.formfactor", N_("A_i instead of A_j")},
                     {3, "08.formfactor", N_("back sides not tested (both cosines negative)")},
                     {4, "08.formfactor", N_("d instead of d²")},
                     {11, "08.jacobi", N_("F transposed")},
                     {12, "08.jacobi", N_("Gauss-Seidel instead of Jacobi")},
                     {13, "08.jacobi", N_("E forgotten")},
                     {14, "08.jacobi", N_("R forgotten")},
                     {21, "08.rays", N_("visibility ignored")},
                     {22, "08.rays", N_("blocked rays counted")},
                     {23, "08.rays", N_("divided by k + 1")},
                     {24, "08.rays", N_("every ray between the centres")}};
        return l;
    }();
    return lab;
}

} // namespace wb::lab08

const wb::ex::LabExercises& wbExercises_lab08() {
    return wb::lab08::exercises();
}
