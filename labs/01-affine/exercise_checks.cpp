// Lab 01's tasks and their checks (issue 18; contract in labs/common/exercise_check.h).
// Each answer is a homogeneous 3x3 matrix: equal to the reference up to a non-zero factor.
#include "common/exercise_check.h"
#include "core/i18n.h"
#include "exercises.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <random>

const void* wbExerciseReference_lab01();

namespace wb::lab01 {
namespace {

using ex::Case;
using ex::Values;
using ex::Verdict;

// Relative tolerance on the matrix entries, scaled by the largest entry (equalUpToFactor):
// the cases keep |K|/|L - K| <= 1e4 (the line's condition), and equivalent formulas
// (composition of rotations with atan2/cos/sin, the closed form, the division-free form)
// differ by a few hundred ulps times that: 1e4 * 1e3 * 2.2e-16 = 2.2e-9 < 1e-8.
constexpr double kMatrixTol = 1e-8;

Values pack(const glm::dmat3& m) {
    const double* p = glm::value_ptr(m);
    return Values(p, p + 9);
}

glm::dvec2 at(const Values& in, size_t i) {
    return {in[i], in[i + 1]};
}

// Inputs K, L, and a third point or vector: 6 numbers. Seeded random ones, then the hard
// cases of the line (vertical, horizontal, through the origin, far away, K and L close).
std::vector<Case> lineCases(unsigned seed, const char* thirdName, bool direction) {
    std::vector<Case> cs;
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-9.0, 9.0);
    for (int i = 0; i < 24; ++i) {
        glm::dvec2 k(u(gen), u(gen)), l(u(gen), u(gen)), t(u(gen), u(gen));
        if (glm::length(l - k) < 0.5) l = k + glm::dvec2(1.0, 0.5);
        if (direction && glm::length(t) < 0.1) t = {0.3, -1.0};
        cs.push_back({"seed " + std::to_string(i + 1), {k.x, k.y, l.x, l.y, t.x, t.y}});
    }
    const glm::dvec2 third = direction ? glm::dvec2(0.3, -1.0) : glm::dvec2(1.5, 6.0);
    cs.push_back({N_("vertical line (K.x = L.x)"), {2, -3, 2, 5, third.x, third.y}});
    cs.push_back({N_("horizontal line (K.y = L.y)"), {-4, 1, 3, 1, third.x, -third.y}});
    cs.push_back({N_("line through the origin"), {-2, -1, 4, 2, third.x, third.y}});
    cs.push_back({N_("K, L far from the origin (|K| = 1e4)"),
                  {1e4, 1e4, 1e4 + 3, 1e4 - 2, 1e4 + third.x, 1e4 + third.y}});
    cs.push_back({N_("K and L 1e-3 apart"), {1, 2, 1.001, 2.0005, third.x, third.y}});
    (void)thirdName;
    return cs;
}

std::string showLineInput(const Values& in, const char* third) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "K = (%.6g, %.6g), L = (%.6g, %.6g), %s = (%.6g, %.6g)", in[0],
                  in[1], in[2], in[3], third, in[4], in[5]);
    return buf;
}

std::string showM(const Values& v) {
    return ex::showMatrix(v, 3);
}

bool finite(const Values& v) {
    for (double x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

// What a difference of this kind usually means, for the three matrices.
Verdict compareMatrix(const Values& expected, const Values& got, const char* degenerateHint) {
    if (const auto v = ex::compareHomogeneous(
            expected, got, 3, kMatrixTol,
            degenerateHint[0] ? degenerateHint
                              : tr("NaN or Inf in the matrix: a division by zero?"),
            tr("your matrix is the transpose of the answer: glm is column-major, "
               "m[c][r] is row r of column c (the translation is column 2)"),
            tr("the zero matrix is no map at all")))
        return *v;
    // Same linear part (top-left 2x2, scaled) but another last column/row?
    return Verdict::fail(tr("a different map: check the signs of the terms and that a point is "
                            "(x, y, 1) and a direction (x, y, 0)"));
}

std::vector<ex::Task> tasks() {
    std::vector<ex::Task> t(3);
    t[0].id = "01.mirror";
    t[0].grade = 3;
    t[0].title = N_("Mirror image in the line KL");
    t[0].section = "\u00a72.1 \u2462, fig. 1.1 a";
    t[0].cases = [] { return lineCases(101, "-", false); };
    t[0].run = [](const void* table, const Values& in) {
        return pack(static_cast<const Table*>(table)->mirror(at(in, 0), at(in, 2)));
    };
    t[0].compare = [](const Values& in, const Values& e, const Values& g) {
        (void)in;
        Verdict v = compareMatrix(e, g, "");
        if (!v.ok && g.size() == 9 && finite(g) &&
            !ex::equalUpToFactor(e, pack(glm::transpose(glm::make_mat3(g.data()))), kMatrixTol)) {
            // A mirror applied twice is the identity; a projection onto Λ is singular.
            const glm::dmat3 m = glm::make_mat3(g.data());
            // 1e-6: a mirror's 2x2 part has |det| = w^2 exactly; rounding is ~1e-15 of that.
            if (std::abs(glm::determinant(glm::dmat2(m))) < 1e-6 * std::abs(m[2][2] * m[2][2]))
                v.why = tr("your matrix is singular: that is a projection onto the line (the "
                           "factor 2 of I - 2 n n^T/(n, n) is missing?), not a mirror");
            else if (!ex::equalUpToFactor(pack(glm::dmat3(1.0)), pack(m * m), kMatrixTol))
                v.why = tr("M M is not the identity, so M is no mirror: is the normal "
                           "normalised by (n, n) (not |n|)?");
            else
                v.why = tr("M is a mirror, but in another line: the translation part (the sign "
                           "of c, or the point p0 of the line) is wrong");
        }
        return v;
    };
    t[0].showIn = [](const Values& in) {
        char buf[120];
        std::snprintf(buf, sizeof buf, "K = (%.6g, %.6g), L = (%.6g, %.6g)", in[0], in[1], in[2],
                      in[3]);
        return std::string(buf);
    };
    t[0].showOut = showM;

    t[1].id = "01.shadow-dir";
    t[1].grade = 4;
    t[1].title = N_("Shadow on the line from a light at infinity along l");
    t[1].section = "\u00a72.1 \u2463, fig. 1.1 b";
    t[1].cases = [] {
        std::vector<Case> cs = lineCases(202, "l", true);
        cs.push_back({N_("light parallel to the line"), {-3, -2, 5, 2, 8, 4}});
        cs.push_back({N_("light perpendicular to the line"), {-3, 0, 5, 0, 0, -2}});
        cs.push_back({N_("light almost parallel (1e-9 rad)"), {0, 0, 1, 0, 1, -1e-9}});
        return cs;
    };
    t[1].run = [](const void* table, const Values& in) {
        return pack(
            static_cast<const Table*>(table)->shadowDirectional(at(in, 0), at(in, 2), at(in, 4)));
    };
    t[1].compare = [](const Values& in, const Values& e, const Values& g) {
        (void)in;
        return compareMatrix(e, g,
                             tr("NaN or Inf: with the light parallel to the line n.l = 0; use the "
                                "form without division, (n.l) I - l pi^T"));
    };
    t[1].showIn = [](const Values& in) { return showLineInput(in, "l"); };
    t[1].showOut = showM;

    t[2].id = "01.shadow-point";
    t[2].grade = 5;
    t[2].title = N_("Shadow on the line from a point light S");
    t[2].section = "\u00a72.1 \u2464, fig. 1.1 c";
    t[2].cases = [] {
        std::vector<Case> cs = lineCases(303, "S", false);
        cs.push_back({N_("S on the line"), {-3, -2, 5, 2, 1, 0}});
        cs.push_back({N_("S 1e-9 from the line"), {-3, 0, 5, 0, 1, 1e-9}});
        cs.push_back({N_("S far away (1e6)"), {-3, 0, 5, 0, 2e5, 1e6}});
        cs.push_back({N_("S on the other side of the line"), {-3, 0, 5, 0, 1, -4}});
        return cs;
    };
    t[2].run = [](const void* table, const Values& in) {
        return pack(static_cast<const Table*>(table)->shadowPoint(at(in, 0), at(in, 2), at(in, 4)));
    };
    t[2].compare = [](const Values& in, const Values& e, const Values& g) {
        (void)in;
        return compareMatrix(e, g,
                             tr("NaN or Inf: with S on the line pi.S = 0; do not divide by it "
                                "(M = (pi.S) I - S pi^T is fine there)"));
    };
    t[2].showIn = [](const Values& in) { return showLineInput(in, "S"); };
    t[2].showOut = showM;
    return t;
}

} // namespace
} // namespace wb::lab01

const wb::ex::LabExercises& wbExercises_lab01();
const wb::ex::LabExercises& wbExercises_lab01() {
    static const wb::ex::LabExercises lab = [] {
        wb::ex::LabExercises l;
        l.lab = "01";
        l.title = N_("Lab 01 - affine maps");
        l.file = "labs/01-affine/exercises.cpp";
        l.reference = wbExerciseReference_lab01();
        l.tasks = wb::lab01::tasks();
        l.mutants = {{1, "01.mirror", "transposed matrix"},
                     {2, "01.mirror", "projection (factor 2 missing)"},
                     {3, "01.mirror", "sign of the translation"},
                     {4, "01.mirror", "divided by |n|, not (n, n)"},
                     {11, "01.shadow-dir", "transposed matrix"},
                     {12, "01.shadow-dir", "sign of l pi^T"},
                     {13, "01.shadow-dir", "l as a point (w = 1)"},
                     {14, "01.shadow-dir", "divides by n.l (parallel light)"},
                     {21, "01.shadow-point", "transposed matrix"},
                     {22, "01.shadow-point", "sign of S pi^T"},
                     {23, "01.shadow-point", "S as a direction (w = 0)"},
                     {24, "01.shadow-point", "divides by pi.S (S on the line)"}};
        return l;
    }();
    return lab;
}
