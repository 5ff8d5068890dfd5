// Lab 02's tasks and their checks (issue 18; contract in labs/common/exercise_check.h).
// The cubes are checked face by face against the cube itself (any face order, any first
// corner), so only what the course asks is required: the corners, counter-clockwise from
// outside, and the normals' directions at unit length.
#include "common/exercise_check.h"
#include "core/i18n.h"
#include "exercises.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <random>

const void* wbExerciseReference_lab02();

namespace wb::lab02 {
namespace {

using ex::Case;
using ex::Values;
using ex::Verdict;

// Vertices are centre ± half in each coordinate: one addition, so 1 ulp of |centre| + half;
// 1e-9 relative leaves room for other constructions (a scale and a translation matrix).
constexpr double kPositionTol = 1e-9;
// Unit normals: glm::normalize is within a few ulps of length 1; the directions come from
// one division by a length: 1e-9 is far above that and far below any wrong normal (the
// nearest wrong ones are off by the angle between neighbouring grid points, > 1e-3).
constexpr double kNormalTol = 1e-9;

Values packCube(const Cube& c) {
    Values v{double(c.vertices.size()), double(c.normals.size())};
    for (const glm::dvec3& p : c.vertices)
        v.insert(v.end(), {p.x, p.y, p.z});
    for (const glm::dvec3& n : c.normals)
        v.insert(v.end(), {n.x, n.y, n.z});
    return v;
}

std::string vec(const glm::dvec3& v) {
    return ex::showNumbers({v.x, v.y, v.z});
}

std::vector<Case> cubeCases(unsigned seed) {
    std::vector<Case> cs;
    cs.push_back({N_("the lab's cube: centre 0, half 1"), {0, 0, 0, 1}});
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> uc(-5.0, 5.0), uh(0.1, 3.0);
    for (int i = 0; i < 12; ++i)
        cs.push_back({"seed " + std::to_string(i + 1), {uc(gen), uc(gen), uc(gen), uh(gen)}});
    cs.push_back({N_("tiny cube (half 1e-3) far away (1e2)"), {100, -100, 50, 1e-3}});
    cs.push_back({N_("big cube (half 1e3)"), {1, 2, 3, 1e3}});
    return cs;
}

std::string showCubeIn(const Values& in) {
    return trf("centre = (%.6g, %.6g, %.6g), half = %.6g", in[0], in[1], in[2], in[3]);
}

std::string showCubeOut(const Values& v) {
    if (v.size() < 2) return "-";
    std::string s = trf("%d vertices, %d normals", int(v[0]), int(v[1]));
    const size_t nv = size_t(v[0]);
    if (v.size() == 2 + 6 * nv && nv >= 4) {
        s += tr("; first face:");
        for (size_t i = 0; i < 4; ++i)
            s += " " + vec({v[2 + 3 * i], v[3 + 3 * i], v[4 + 3 * i]});
    }
    return s;
}

Verdict compareCube(const Values& in, const Values& got, bool centreNormals) {
    const glm::dvec3 c(in[0], in[1], in[2]);
    const double h = in[3];
    if (got.size() < 2) return Verdict::fail(tr("no vertices"));
    const size_t nv = size_t(got[0]), nn = size_t(got[1]);
    if (nv != nn)
        return Verdict::fail(
            trf("%zu vertices but %zu normals: give one glNormal before every glVertex", nv, nn));
    if (nv != 24)
        return Verdict::fail(
            trf("%zu vertices: a cube of 6 quads has 24 (a face missing or one too many?)", nv));
    auto vert = [&](size_t i) {
        return glm::dvec3(got[2 + 3 * i], got[3 + 3 * i], got[4 + 3 * i]);
    };
    auto norm = [&](size_t i) {
        return glm::dvec3(got[74 + 3 * i], got[75 + 3 * i], got[76 + 3 * i]);
    };
    const double tol = kPositionTol * std::max(1.0, glm::length(c) + h);
    bool seen[3][2] = {};
    for (size_t f = 0; f < 6; ++f) {
        // Each vertex a corner: every coordinate c ± h. Sign of each coordinate.
        int sgn[4][3];
        for (size_t k = 0; k < 4; ++k) {
            const glm::dvec3 p = vert(4 * f + k);
            for (int a = 0; a < 3; ++a) {
                if (std::abs(p[a] - (c[a] + h)) <= tol)
                    sgn[k][a] = 1;
                else if (std::abs(p[a] - (c[a] - h)) <= tol)
                    sgn[k][a] = -1;
                else
                    return Verdict::fail(trf("face %zu, vertex %zu %s is no corner of the cube "
                                             "(each coordinate must be centre +- half)",
                                             f + 1, k + 1, vec(p).c_str()));
            }
        }
        int axis = -1, side = 0;
        for (int a = 0; a < 3 && axis < 0; ++a)
            if (sgn[0][a] == sgn[1][a] && sgn[0][a] == sgn[2][a] && sgn[0][a] == sgn[3][a])
                axis = a, side = sgn[0][a];
        if (axis < 0)
            return Verdict::fail(
                trf("face %zu: its 4 vertices do not lie on one face of the cube", f + 1));
        if (seen[axis][side > 0])
            return Verdict::fail(trf(
                "face %zu is the same face as an earlier one, so another face is missing", f + 1));
        seen[axis][side > 0] = true;
        const glm::dvec3 out = glm::dvec3(axis == 0, axis == 1, axis == 2) * double(side);
        const glm::dvec3 p0 = vert(4 * f), p1 = vert(4 * f + 1), p2 = vert(4 * f + 2),
                         p3 = vert(4 * f + 3);
        // Around the face (no bow tie): opposite corners p0, p2 and p1, p3 differ in both in-face
        // coordinates.
        if (glm::length(glm::cross(p2 - p0, p3 - p1)) < h * h)
            return Verdict::fail(trf(
                "face %zu: the corners are not in order around the face (the quad crosses itself)",
                f + 1));
        if (glm::dot(glm::cross(p1 - p0, p2 - p0), out) <= 0)
            return Verdict::fail(
                trf("face %zu %s is wound clockwise seen from outside: with "
                    "glFrontFace(GL_CCW) it faces inwards (culled or lit from behind)",
                    f + 1, vec(out).c_str()));
        for (size_t k = 0; k < 4; ++k) {
            const glm::dvec3 p = vert(4 * f + k), n = norm(4 * f + k);
            const double len = glm::length(n);
            const glm::dvec3 radial = glm::normalize(p - c);
            const glm::dvec3 want = centreNormals ? radial : out;
            const std::string where = trf("face %zu, vertex %zu %s: normal %s", f + 1, k + 1,
                                          vec(p).c_str(), vec(n).c_str());
            if (!std::isfinite(len) || len == 0)
                return Verdict::fail(where + ": " + tr("zero or NaN"));
            const glm::dvec3 u = n / len;
            if (glm::dot(u, want) < 1 - kNormalTol) {
                if (glm::dot(u, want) < -1 + kNormalTol)
                    return Verdict::fail(where + ": " + tr("points inwards (the sign is wrong)"));
                if (!centreNormals && glm::dot(u, radial) > 1 - kNormalTol)
                    return Verdict::fail(where + ": " +
                                         tr("that is the centre normal; this cube's normals are "
                                            "perpendicular to the faces"));
                if (centreNormals && glm::dot(u, out) > 1 - kNormalTol)
                    return Verdict::fail(where + ": " +
                                         tr("that is the face normal; this cube's normals point "
                                            "from the centre through the vertex"));
                if (centreNormals && glm::dot(u, glm::normalize(p)) > 1 - kNormalTol)
                    return Verdict::fail(where + ": " +
                                         tr("points from the origin, not from the cube's centre"));
                return Verdict::fail(
                    where + ": " +
                    (centreNormals ? tr("not along centre -> vertex")
                                   : tr("not perpendicular to the face (x, y, z mixed up?)")));
            }
            if (std::abs(len - 1) > kNormalTol)
                return Verdict::fail(
                    where + ": " +
                    trf("|n| = %.6g, not 1: normalise it (OpenGL lights with the normal as given)",
                        len));
        }
    }
    return Verdict::pass();
}

// Grid normal cases: a square face (random size, orientation, place), corner normals
// around its normal, P on the face. Input: A B C D, nA nB nC nD, P (27 numbers).
Case gridCase(std::string name, glm::dvec3 centre, double half, const glm::dmat3& rot,
              const std::array<glm::dvec3, 4>& normalsLocal, double u, double v) {
    std::array<glm::dvec3, 4> corner;
    const glm::dvec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k)
        corner[size_t(k)] =
            centre + rot * glm::dvec3(half * (2 * uv[k].x - 1), half * (2 * uv[k].y - 1), 0);
    Values in;
    for (const glm::dvec3& p : corner)
        in.insert(in.end(), {p.x, p.y, p.z});
    for (const glm::dvec3& n : normalsLocal) {
        const glm::dvec3 w = glm::normalize(rot * n);
        in.insert(in.end(), {w.x, w.y, w.z});
    }
    const glm::dvec3 p = corner[0] + u * (corner[1] - corner[0]) + v * (corner[3] - corner[0]);
    in.insert(in.end(), {p.x, p.y, p.z});
    return {std::move(name), in};
}

std::vector<Case> gridCases() {
    std::vector<Case> cs;
    // The lab's right cube's front face: corner normals from the centre.
    const std::array<glm::dvec3, 4> centreN = {glm::dvec3(-1, -1, 1), glm::dvec3(1, -1, 1),
                                               glm::dvec3(1, 1, 1), glm::dvec3(-1, 1, 1)};
    const glm::dmat3 id(1.0);
    cs.push_back(gridCase(N_("corner A (u = v = 0)"), {0, 0, 1}, 1, id, centreN, 0, 0));
    cs.push_back(gridCase(N_("corner C (u = v = 1)"), {0, 0, 1}, 1, id, centreN, 1, 1));
    cs.push_back(gridCase(N_("centre of the face"), {0, 0, 1}, 1, id, centreN, 0.5, 0.5));
    cs.push_back(
        gridCase(N_("on the edge AB (v = 0, u = 0.25)"), {0, 0, 1}, 1, id, centreN, 0.25, 0));
    cs.push_back(
        gridCase(N_("on the edge AD (u = 0, v = 0.75)"), {0, 0, 1}, 1, id, centreN, 0, 0.75));
    cs.push_back(gridCase(N_("grid point (1/8, 5/8) of an 8x8 grid"), {0, 0, 1}, 1, id, centreN,
                          0.125, 0.625));
    std::mt19937 gen(505);
    std::uniform_real_distribution<double> uc(-5, 5), uh(0.1, 3), ua(-3.14159, 3.14159),
        tilt(-0.6, 0.6);
    std::uniform_int_distribution<int> grid(0, 8);
    for (int i = 0; i < 16; ++i) {
        const glm::dmat3 rot = glm::dmat3(glm::rotate(
            glm::dmat4(1.0), ua(gen),
            glm::normalize(glm::dvec3(uc(gen), uc(gen), uc(gen)) + glm::dvec3(0, 0, 1e-3))));
        std::array<glm::dvec3, 4> n;
        for (glm::dvec3& x : n)
            x = glm::dvec3(tilt(gen), tilt(gen), 1.0); // within ~40 degrees of the face normal
        cs.push_back(gridCase("seed " + std::to_string(i + 1), {uc(gen), uc(gen), uc(gen)}, uh(gen),
                              rot, n, grid(gen) / 8.0, grid(gen) / 8.0));
    }
    cs.push_back(gridCase(N_("tiny face (half 1e-3) at 1e2"), {100, 50, -70}, 1e-3, id, centreN,
                          0.375, 0.875));
    return cs;
}

glm::dvec3 at(const Values& v, size_t i) {
    return {v[i], v[i + 1], v[i + 2]};
}

std::vector<ex::Task> tasks() {
    std::vector<ex::Task> t(3);
    t[0].id = "02.cube-face";
    t[0].grade = 3;
    t[0].title = N_("Cube with normals perpendicular to the faces");
    t[0].section = "\u00a72.2 \u2462, fig. 2.2 a";
    t[0].cases = [] { return cubeCases(201); };
    t[0].run = [](const void* table, const Values& in) {
        return packCube(static_cast<const Table*>(table)->faceNormals(at(in, 0), in[3]));
    };
    t[0].compare = [](const Values& in, const Values&, const Values& g) {
        return compareCube(in, g, false);
    };
    t[0].showIn = showCubeIn;
    t[0].showOut = showCubeOut;
    t[0].needsExpected = false; // judged against the cube itself

    t[1] = t[0];
    t[1].id = "02.cube-centre";
    t[1].title = N_("Cube with normals from the centre through the vertices");
    t[1].section = "\u00a72.2 \u2462, fig. 2.2 b";
    t[1].cases = [] { return cubeCases(202); };
    t[1].run = [](const void* table, const Values& in) {
        return packCube(static_cast<const Table*>(table)->centreNormals(at(in, 0), in[3]));
    };
    t[1].compare = [](const Values& in, const Values&, const Values& g) {
        return compareCube(in, g, true);
    };

    t[2].id = "02.grid-normal";
    t[2].grade = 5;
    t[2].title = N_("Normal at a grid point blended from the corner normals");
    t[2].section = "\u00a72.2 \u2464, fig. 2.3, \u00a71.4";
    t[2].cases = gridCases;
    t[2].run = [](const void* table, const Values& in) {
        std::array<glm::dvec3, 4> c, n;
        for (size_t k = 0; k < 4; ++k) {
            c[k] = at(in, 3 * k);
            n[k] = at(in, 12 + 3 * k);
        }
        const glm::dvec3 r = static_cast<const Table*>(table)->gridNormal(c, n, at(in, 24));
        return Values{r.x, r.y, r.z};
    };
    t[2].compare = [](const Values& in, const Values& e, const Values& g) {
        if (g.size() != 3) return Verdict::fail(tr("not a 3-vector"));
        const glm::dvec3 n = at(g, 0);
        const double len = glm::length(n);
        if (!std::isfinite(len) || len == 0) return Verdict::fail(tr("zero or NaN normal"));
        if (ex::allNear(e, g, kNormalTol)) return Verdict::pass();
        if (ex::equalUpToPositiveFactor(e, g, kNormalTol))
            return Verdict::fail(
                trf("the direction is right but |n| = %.6g: divide by |a nA + b nB + c nC + d nD|",
                    len));
        glm::dvec3 avg(0.0);
        for (size_t k = 0; k < 4; ++k)
            avg += at(in, 12 + 3 * k);
        if (glm::dot(n / len, glm::normalize(avg)) > 1 - kNormalTol)
            return Verdict::fail(tr("that is the plain average of the four normals: the weights a, "
                                    "b, c, d depend on where P is"));
        return Verdict::fail(tr("a different blend: check which weight goes with which corner "
                                "(at P = A the result must be nA, at P = B nB, ...)"));
    };
    t[2].showIn = [](const Values& in) {
        return "A B C D = " + vec(at(in, 0)) + " " + vec(at(in, 3)) + " " + vec(at(in, 6)) + " " +
               vec(at(in, 9)) + "; nA..nD = " + vec(at(in, 12)) + " " + vec(at(in, 15)) + " " +
               vec(at(in, 18)) + " " + vec(at(in, 21)) + "; P = " + vec(at(in, 24));
    };
    return t;
}

} // namespace
} // namespace wb::lab02

const wb::ex::LabExercises& wbExercises_lab02();
const wb::ex::LabExercises& wbExercises_lab02() {
    static const wb::ex::LabExercises lab = [] {
        wb::ex::LabExercises l;
        l.lab = "02";
        l.title = N_("Lab 02 - lighting");
        l.file = "labs/02-lighting/exercises.cpp";
        l.reference = wbExerciseReference_lab02();
        l.tasks = wb::lab02::tasks();
        l.mutants = {{31, "02.cube-face", "normals point inwards"},
                     {32, "02.cube-face", "a face missing (20 vertices)"},
                     {33, "02.cube-face", "a face wound clockwise"},
                     {34, "02.cube-face", "x and y of the normal swapped"},
                     {41, "02.cube-centre", "normal not normalised"},
                     {42, "02.cube-centre", "normal from the origin, not the centre"},
                     {43, "02.cube-centre", "normals point inwards"},
                     {44, "02.cube-centre", "face normals instead"},
                     {51, "02.grid-normal", "not normalised"},
                     {52, "02.grid-normal", "u and v swapped"},
                     {53, "02.grid-normal", "plain average, no weights"},
                     {54, "02.grid-normal", "weights of the edge AB only"}};
        return l;
    }();
    return lab;
}
