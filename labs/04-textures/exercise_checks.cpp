// Lab 04's tasks and their checks (exercise_check.h). The meshes are checked by what they
// must be, whatever their vertex order: every vertex on the surface with its unit normal
// and the (s, t) its position calls for, no triangle across a seam, triangles
// counter-clockwise from outside, and the triangles' total area that of the reference's mesh
// of the same grid (a missing or doubled row of cells changes it; only that area is kept of
// the reference's output, and only it is recorded in a handout). The sphere map is
// checked against the reference and against OpenGL's own GL_SPHERE_MAP texgen, read back
// through GL's feedback mode in the check's OSMesa context.
#include "exercises.h"

#include "common/exercise_check.h"
#include "core/i18n.h"

#include <GL/gl.h>

#include <cmath>
#include <cstdio>
#include <string>

const void* wbExerciseReference_lab04();

namespace wb::lab04 {
namespace {

using ex::Case;
using ex::Values;
using ex::Verdict;

constexpr double kPi = 3.14159265358979323846;
// Positions and normals come from sin/cos and a few products: some ulps of the size.
// 1e-9 of the size leaves room for any correct formula and none for a wrong one.
constexpr double kTol = 1e-9;

Values packMesh(const Mesh& m) {
    Values v{double(m.positions.size()), double(m.normals.size()), double(m.texCoords.size()),
             double(m.indices.size())};
    for (const auto& p : m.positions)
        v.insert(v.end(), {p.x, p.y, p.z});
    for (const auto& p : m.normals)
        v.insert(v.end(), {p.x, p.y, p.z});
    for (const auto& p : m.texCoords)
        v.insert(v.end(), {p.x, p.y});
    for (unsigned i : m.indices)
        v.push_back(double(i));
    return v;
}
bool unpackMesh(const Values& v, Mesh& m) {
    if (v.size() < 4) return false;
    const size_t np = size_t(v[0]), nn = size_t(v[1]), nt = size_t(v[2]), ni = size_t(v[3]);
    if (v.size() != 4 + 3 * np + 3 * nn + 2 * nt + ni) return false;
    size_t k = 4;
    for (size_t i = 0; i < np; ++i, k += 3)
        m.positions.push_back({v[k], v[k + 1], v[k + 2]});
    for (size_t i = 0; i < nn; ++i, k += 3)
        m.normals.push_back({v[k], v[k + 1], v[k + 2]});
    for (size_t i = 0; i < nt; ++i, k += 2)
        m.texCoords.push_back({v[k], v[k + 1]});
    for (size_t i = 0; i < ni; ++i)
        m.indices.push_back(unsigned(v[k++]));
    return true;
}
std::string fmtVec(const glm::dvec3& p) {
    return ex::showNumbers({p.x, p.y, p.z});
}
std::string showMesh(const Values& out) {
    if (out.empty()) return std::string(tr("(judged from the input: nothing recorded)"));
    Mesh m;
    if (!unpackMesh(out, m)) return ex::showNumbers(out);
    return trf("%d vertices, %d triangles", int(m.positions.size()), int(m.indices.size() / 3));
}

// All compare() needs of the reference's mesh: the area its triangles cover (Task::
// expectedDigest; a handout records this number, not the reference's vertices).
Values meshArea(const Values& out) {
    Mesh m;
    if (!unpackMesh(out, m)) return {};
    double a = 0;
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        const unsigned i = m.indices[k], j = m.indices[k + 1], l = m.indices[k + 2];
        if (i >= m.positions.size() || j >= m.positions.size() || l >= m.positions.size())
            return {};
        a += 0.5 * glm::length(glm::cross(m.positions[j] - m.positions[i],
                                          m.positions[l] - m.positions[i]));
    }
    return {a};
}

// The checks both meshes share. `surface(i)` says what is wrong with vertex i (empty: fine),
// `outward(tri)` the outward direction at a triangle; spans are the seam limits.
template <class VertexCheck>
Verdict checkMesh(const Mesh& m, double size, double refArea, double spanS, double spanT,
                  const VertexCheck& vertexWrong, const char* cellsWord) {
    const size_t n = m.positions.size();
    if (n == 0 || m.normals.size() != n || m.texCoords.size() != n)
        return Verdict::fail(trf("%d positions, %d normals, %d texture coordinates: one of each "
                                 "per vertex",
                                 int(n), int(m.normals.size()), int(m.texCoords.size())));
    if (m.indices.empty() || m.indices.size() % 3 != 0)
        return Verdict::fail(trf("%d indices: three per triangle", int(m.indices.size())));
    for (unsigned i : m.indices)
        if (i >= n)
            return Verdict::fail(trf("index %u but only %d vertices (off by one in the grid's "
                                     "row length?)",
                                     i, int(n)));
    for (size_t i = 0; i < n; ++i) {
        const std::string why = vertexWrong(i);
        if (!why.empty())
            return Verdict::fail(
                trf("vertex %d at %s: %s", int(i), fmtVec(m.positions[i]).c_str(), why.c_str()));
    }
    double total = 0;
    for (size_t k = 0; k < m.indices.size(); k += 3) {
        const unsigned a = m.indices[k], b = m.indices[k + 1], c = m.indices[k + 2];
        const glm::dvec2 ta = m.texCoords[a], tb = m.texCoords[b], tc = m.texCoords[c];
        const double ds = std::max({ta.x, tb.x, tc.x}) - std::min({ta.x, tb.x, tc.x});
        const double dt = std::max({ta.y, tb.y, tc.y}) - std::min({ta.y, tb.y, tc.y});
        if (ds > spanS + kTol || dt > spanT + kTol)
            return Verdict::fail(trf(
                "triangle %d spans s %.4g..%.4g, t %.4g..%.4g, more than one cell: it runs across "
                "the seam and smears the whole texture over it - give the last column (row) its "
                "own vertices with s = 1 (t = 1)",
                int(k / 3), std::min({ta.x, tb.x, tc.x}), std::max({ta.x, tb.x, tc.x}),
                std::min({ta.y, tb.y, tc.y}), std::max({ta.y, tb.y, tc.y})));
        const glm::dvec3 cr =
            glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
        const double ar = 0.5 * glm::length(cr);
        total += ar;
        if (ar <= kTol * size * size) continue; // a degenerate triangle at a pole: no side
        if (glm::dot(cr, m.normals[a] + m.normals[b] + m.normals[c]) <= 0)
            return Verdict::fail(trf("triangle %d is clockwise seen from outside: with back "
                                     "faces culled it disappears, lit it is dark",
                                     int(k / 3)));
    }
    if (std::fabs(total - refArea) > 1e-9 * refArea)
        return Verdict::fail(trf("the triangles cover an area of %.9g, the %s's grid %.9g (%.3g "
                                 "%%): a row or column of %s missing or drawn twice (off by one?)",
                                 total, cellsWord, refArea, 100 * (total / refArea - 1),
                                 tr("cells")));
    return Verdict::pass();
}

// s and t in [0, 1], finite.
std::string texRange(const glm::dvec2& t) {
    if (!std::isfinite(t.x) || !std::isfinite(t.y)) return tr("texture coordinates not numbers");
    if (t.x < -kTol || t.x > 1 + kTol || t.y < -kTol || t.y > 1 + kTol)
        return trf("(s, t) = (%.6g, %.6g) outside [0, 1]", t.x, t.y);
    return {};
}

// ----- ③ the texel GL_NEAREST picks: in = s, size, repeat -----
std::vector<Case> texelCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string n, double s, int size, bool repeat) {
        cs.push_back({std::move(n), {s, double(size), repeat ? 1.0 : 0.0}});
    };
    add(N_("repeat, s = 0.3 of 8 texels"), 0.3, 8, true);
    add(N_("repeat, s = 2.3 (the third copy)"), 2.3, 8, true);
    add(N_("repeat, s = -0.25 (fraction 0.75)"), -0.25, 8, true);
    add(N_("repeat, s = -2.99 (fraction 0.01)"), -2.99, 16, true);
    add(N_("repeat, s = 1 exactly (the first texel again)"), 1.0, 8, true);
    add(N_("repeat, s just below 1"), 1 - 1e-16, 4096, true);
    add(N_("clamp, s = 1 exactly (the last texel)"), 1.0, 8, false);
    add(N_("clamp, s = 1.7"), 1.7, 8, false);
    add(N_("clamp, s = -0.4"), -0.4, 8, false);
    add(N_("clamp, s = 0.5 of 1 texel"), 0.5, 1, false);
    add(N_("repeat, s on a texel edge (0.375 of 8)"), 0.375, 8, true);
    unsigned g = 3u;
    auto rnd = [&g] {
        g = g * 1664525u + 1013904223u;
        return double(g >> 8) / double(1u << 24);
    };
    for (int i = 1; i <= 8; ++i)
        add("seed " + std::to_string(i), 200 * rnd() - 100, 1 + int(rnd() * 512), i % 2 == 1);
    return cs;
}

Verdict texelCompare(const Values& in, const Values& expected, const Values& got) {
    // Integers: exact.
    if (got.at(0) == expected.at(0)) return Verdict::pass();
    const int size = int(in.at(1));
    if (got.at(0) < 0 || got.at(0) >= size)
        return Verdict::fail(
            trf("texel %d does not exist: a row has texels 0..%d", int(got.at(0)), size - 1));
    if (in.at(2) != 0 && in.at(0) < 0)
        return Verdict::fail(tr("GL_REPEAT keeps the fraction s - floor(s), which is >= 0 also "
                                "for negative s (fmod and int() round towards zero)"));
    return Verdict::fail(in.at(2) != 0 ? tr("GL_REPEAT: i = floor((s - floor(s))·size)")
                                       : tr("GL_CLAMP_TO_EDGE: i = floor(s·size) clamped to "
                                            "0..size-1"));
}

// ----- ④ sphere: in = radius, slices, stacks -----
Verdict sphereCompare(const Values& in, const Values& expected, const Values& got) {
    const double r = in.at(0);
    const int slices = int(in.at(1)), stacks = int(in.at(2));
    Mesh m;
    if (!unpackMesh(got, m)) return Verdict::fail(tr("the mesh could not be read"));
    auto vertex = [&](size_t i) -> std::string {
        const glm::dvec3 p = m.positions[i], n = m.normals[i];
        const glm::dvec2 st = m.texCoords[i];
        if (std::fabs(glm::length(p) - r) > kTol * r)
            return trf("|p| = %.9g, not on the sphere of radius %g", glm::length(p), r);
        if (std::fabs(glm::length(n) - 1) > kTol)
            return trf("|n| = %.6g: normals must be unit (divide by the radius)", glm::length(n));
        if (glm::length(n - p / r) > kTol)
            return trf("normal %s is not the outward direction p/r", fmtVec(n).c_str());
        const std::string range = texRange(st);
        if (!range.empty()) return range;
        if (std::fabs(p.y + r * std::cos(kPi * st.y)) > kTol * r)
            return trf("t = %.6g does not match the latitude (t = 0 at the south pole y = -r, 1 "
                       "at the north pole)",
                       st.y);
        const double rho = std::hypot(p.x, p.z);
        if (rho > kTol * r && std::hypot(p.x - rho * std::sin(2 * kPi * st.x),
                                         p.z - rho * std::cos(2 * kPi * st.x)) > kTol * r)
            return trf("s = %.6g does not match the longitude (s = 0 on +z, growing towards +x)",
                       st.x);
        return {};
    };
    return checkMesh(m, r, expected.empty() ? 0.0 : expected[0], 1.0 / slices, 1.0 / stacks, vertex,
                     "sphere");
}

// ----- ④ torus: in = R, r, rings, sides -----
Verdict torusCompare(const Values& in, const Values& expected, const Values& got) {
    const double R = in.at(0), r = in.at(1);
    const int rings = int(in.at(2)), sides = int(in.at(3));
    Mesh m;
    if (!unpackMesh(got, m)) return Verdict::fail(tr("the mesh could not be read"));
    const double size = R + r;
    auto vertex = [&](size_t i) -> std::string {
        const glm::dvec3 p = m.positions[i], n = m.normals[i];
        const glm::dvec2 st = m.texCoords[i];
        const double rho = std::hypot(p.x, p.z);
        if (!(rho > 0)) return tr("on the axis: not on the torus");
        const glm::dvec3 c =
            glm::dvec3(p.x, 0, p.z) * (R / rho); // nearest point of the centre circle
        if (std::fabs(glm::length(p - c) - r) > kTol * size)
            return trf("%.9g from the tube's centre circle, not r = %g", glm::length(p - c), r);
        if (std::fabs(glm::length(n) - 1) > kTol)
            return trf("|n| = %.6g: normals must be unit", glm::length(n));
        if (glm::length(n - (p - c) / r) > kTol)
            return trf("normal %s does not point from the tube's centre circle to the vertex",
                       fmtVec(n).c_str());
        const std::string range = texRange(st);
        if (!range.empty()) return range;
        if (std::hypot(p.x - rho * std::sin(2 * kPi * st.x), p.z - rho * std::cos(2 * kPi * st.x)) >
            kTol * size)
            return trf("s = %.6g does not match the angle around the y axis (0 on +z, towards +x)",
                       st.x);
        if (std::hypot(rho - R - r * std::cos(2 * kPi * st.y), p.y - r * std::sin(2 * kPi * st.y)) >
            kTol * size)
            return trf("t = %.6g does not match the angle around the tube (0 on the outer equator, "
                       "growing upwards)",
                       st.y);
        return {};
    };
    return checkMesh(m, size, expected.empty() ? 0.0 : expected[0], 1.0 / rings, 1.0 / sides,
                     vertex, "torus");
}

// ----- ⑤ sphere map: in = eye position, unit normal; out = student s, t, GL's s, t, ok -----
// GL's texgen for the same vertex: drawn as a point in feedback mode, which hands back the
// vertex's texture coordinates after texgen (no pixels involved).
glm::dvec2 glSphereMap(const glm::dvec3& p, const glm::dvec3& n, bool& ok) {
    ok = false;
    GLfloat buf[64];
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1e3, 1e3, -1e3, 1e3, -1e3, 1e3); // every case's point lies inside
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity(); // eye space = the coordinates given
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glDisable(GL_NORMALIZE);
    // Mesa computes texture coordinates only for an enabled texture unit: a 1×1 texture.
    static GLuint tex = 0;
    if (!tex) {
        const GLubyte white[4] = {255, 255, 255, 255};
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
    }
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glFeedbackBuffer(64, GL_4D_COLOR_TEXTURE, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glNormal3d(n.x, n.y, n.z);
    glVertex3d(p.x, p.y, p.z);
    glEnd();
    const GLint count = glRenderMode(GL_RENDER);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_2D);
    // GL_POINT_TOKEN, x y z w, r g b a, s t r q.
    if (count < 13 || buf[0] != GLfloat(GL_POINT_TOKEN)) return {0, 0};
    ok = buf[12] != 0;
    return {buf[9] / buf[12], buf[10] / buf[12]};
}

std::vector<Case> mapCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string name, const glm::dvec3& p, const glm::dvec3& n) {
        const glm::dvec3 u = glm::normalize(n);
        cs.push_back({std::move(name), {p.x, p.y, p.z, u.x, u.y, u.z}});
    };
    add(N_("facing the eye on the axis: the disc's centre"), {0, 0, -5}, {0, 0, 1});
    add(N_("off the axis, facing the eye"), {1, 2, -6}, {0, 0, 1});
    add(N_("normal tilted 45° to the side"), {0, 0, -3}, {1, 0, 1});
    add(N_("grazing: normal across the line of sight"), {0.5, 0, -4}, {0, 1, 0});
    add(N_("far vertex, |p| = 900"), {300, -200, -800}, {0.2, 0.3, 0.9});
    add(N_("near the blind spot (m = 0.1)"), {0, 0, -2}, {0.0500, 0, 0.99875});
    add(N_("the blind spot: f = (0, 0, -1), any point of the rim"), {0, 0, -2}, {1, 0, 0});
    unsigned s = 4u;
    auto rnd = [&s] {
        s = s * 1664525u + 1013904223u;
        return double(s >> 8) / double(1u << 24);
    };
    for (int i = 1; i <= 10; ++i)
        add("seed " + std::to_string(i), {4 * rnd() - 2, 4 * rnd() - 2, -0.5 - 20 * rnd()},
            {2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1 + 0.3});
    return cs;
}

Values mapRun(const void* table, const Values& in) {
    const glm::dvec3 p(in.at(0), in.at(1), in.at(2)), n(in.at(3), in.at(4), in.at(5));
    const glm::dvec2 st = static_cast<const Table*>(table)->sphereMap(p, n);
    bool ok = false;
    const glm::dvec2 gl = glSphereMap(p, n, ok);
    return {st.x, st.y, gl.x, gl.y, ok ? 1.0 : 0.0};
}

Verdict mapCompare(const Values& in, const Values& expected, const Values& got) {
    const glm::dvec3 p(in.at(0), in.at(1), in.at(2)), n(in.at(3), in.at(4), in.at(5));
    const glm::dvec2 st(got.at(0), got.at(1)), e(expected.at(0), expected.at(1));
    if (!std::isfinite(st.x) || !std::isfinite(st.y))
        return Verdict::fail(tr("(s, t) is not a number: at the blind spot m = 0, return a point "
                                "of the disc's rim"));
    const glm::dvec3 u = glm::normalize(p), f = u - 2.0 * n * glm::dot(n, u);
    const double m = 2 * std::sqrt(f.x * f.x + f.y * f.y + (f.z + 1) * (f.z + 1));
    if (m < 1e-12) { // the blind spot: the rim
        const double rim = (2 * st.x - 1) * (2 * st.x - 1) + (2 * st.y - 1) * (2 * st.y - 1);
        if (std::fabs(rim - 1) <= 1e-9) return Verdict::pass();
        return Verdict::fail(trf("at the blind spot the answer is the disc's rim, (2s-1)² + "
                                 "(2t-1)² = 1; yours gives %.6g",
                                 rim));
    }
    // The double formula's rounding, magnified by 1/m near the blind spot (m >= 0.1 here).
    const double tol = 1e-12 / m + 1e-12;
    if (glm::length(st - e) > tol) {
        auto variant = [&](const glm::dvec3& uu, bool plus, double one) {
            const glm::dvec3 ff =
                plus ? uu + 2.0 * n * glm::dot(n, uu) : uu - 2.0 * n * glm::dot(n, uu);
            const double mm =
                2 * std::sqrt(ff.x * ff.x + ff.y * ff.y + (ff.z + one) * (ff.z + one));
            return glm::dvec2(ff.x / mm + 0.5, ff.y / mm + 0.5);
        };
        if (glm::length(st - variant(p, false, 1)) <= 1e-9)
            return Verdict::fail(tr("u must be the UNIT vector from the eye to the vertex: "
                                    "divide the eye-space position by its length"));
        if (glm::length(st - variant(u, true, 1)) <= 1e-9)
            return Verdict::fail(tr("the sign of the reflection: f = u - 2n(n·u)"));
        if (glm::length(st - variant(u, false, 0)) <= 1e-9)
            return Verdict::fail(tr("m = 2sqrt(fx² + fy² + (fz + 1)²): the +1 is missing"));
        return Verdict::fail(tr("not OpenGL's sphere map: s = fx/m + ½, t = fy/m + ½"));
    }
    // Against GL's own texgen: llvmpipe computes it in float; tests/render/
    // textures_spheremap_test.cpp measured it within 0.001 texel of 256 (4e-6) of the double
    // formula; near the blind spot 1/m magnifies float rounding, so 4e-6/m (m >= 0.1 here).
    if (got.at(4) != 0) {
        const glm::dvec2 gl(got.at(2), got.at(3));
        if (glm::length(st - gl) > 4e-6 / std::min(1.0, m) + 4e-6)
            return Verdict::fail(
                trf("OpenGL's GL_SPHERE_MAP texgen gives (%.6f, %.6f) here", gl.x, gl.y));
    }
    return Verdict::pass();
}

} // namespace

const ex::LabExercises& exercises() {
    static const ex::LabExercises lab = [] {
        ex::LabExercises l;
        l.lab = "04";
        l.title = N_("Lab 04 - textures");
        l.file = "labs/04-textures/exercises.cpp";
        l.reference = wbExerciseReference_lab04();
        ex::Task texel;
        texel.id = "04.texel";
        texel.grade = 3;
        texel.title = N_("The texel GL_NEAREST samples, with GL_REPEAT and GL_CLAMP_TO_EDGE");
        texel.section = "§2.4 task 3";
        texel.cases = texelCases;
        texel.run = [](const void* table, const Values& in) {
            return Values{double(static_cast<const Table*>(table)->texelIndex(
                in.at(0), int(in.at(1)), in.at(2) != 0))};
        };
        texel.compare = texelCompare;
        texel.showIn = [](const Values& in) {
            return trf("s = %.17g, %d texels, %s", in.at(0), int(in.at(1)),
                       in.at(2) != 0 ? "GL_REPEAT" : "GL_CLAMP_TO_EDGE");
        };
        texel.showOut = [](const Values& out) { return trf("texel %d", int(out.at(0))); };
        ex::Task sphere;
        sphere.id = "04.sphere";
        sphere.grade = 4;
        sphere.title = N_("Sphere: vertices, normals, texture coordinates by hand");
        sphere.section = "§2.4 task 4";
        sphere.cases = [] {
            return std::vector<Case>{{N_("radius 1, 12 slices, 8 stacks"), {1, 12, 8}},
                                     {N_("the coarsest: 3 slices, 2 stacks"), {2.5, 3, 2}},
                                     {N_("radius 0.1, 32 x 16"), {0.1, 32, 16}},
                                     {N_("radius 10, odd grid 7 x 5"), {10, 7, 5}},
                                     {N_("fine: 96 x 64"), {1.5, 96, 64}}};
        };
        sphere.run = [](const void* table, const Values& in) {
            return packMesh(static_cast<const Table*>(table)->sphereMesh(in.at(0), int(in.at(1)),
                                                                         int(in.at(2))));
        };
        sphere.compare = sphereCompare;
        sphere.expectedDigest = meshArea; // the vertices are judged from the input alone
        sphere.showIn = [](const Values& in) {
            return trf("radius %g, %d slices, %d stacks", in.at(0), int(in.at(1)), int(in.at(2)));
        };
        sphere.showOut = showMesh;
        ex::Task torus;
        torus.id = "04.torus";
        torus.grade = 4;
        torus.title = N_("Torus: vertices, normals, texture coordinates by hand");
        torus.section = "§2.4 task 4";
        torus.cases = [] {
            return std::vector<Case>{{N_("R 1, r 0.3, 12 x 8"), {1, 0.3, 12, 8}},
                                     {N_("the coarsest: 3 x 3"), {2, 0.5, 3, 3}},
                                     {N_("a fat torus: R 5, r 4.9, 24 x 16"), {5, 4.9, 24, 16}},
                                     {N_("a thin one: R 1, r 0.01, 16 x 6"), {1, 0.01, 16, 6}},
                                     {N_("fine: 64 x 48"), {3, 1, 64, 48}}};
        };
        torus.run = [](const void* table, const Values& in) {
            return packMesh(static_cast<const Table*>(table)->torusMesh(
                in.at(0), in.at(1), int(in.at(2)), int(in.at(3))));
        };
        torus.compare = torusCompare;
        torus.expectedDigest = meshArea;
        torus.showIn = [](const Values& in) {
            return trf("R %g, r %g, %d rings, %d sides", in.at(0), in.at(1), int(in.at(2)),
                       int(in.at(3)));
        };
        torus.showOut = showMesh;
        ex::Task map;
        map.id = "04.spheremap";
        map.grade = 5;
        map.title = N_("Sphere-map coordinates, as GL_SPHERE_MAP computes them");
        map.section = "§2.4 task 5; §1.5.3";
        map.cases = mapCases;
        map.run = mapRun;
        map.compare = mapCompare;
        map.needsGl = true;
        map.showIn = [](const Values& in) {
            return trf("eye position (%.4g, %.4g, %.4g), normal (%.4g, %.4g, %.4g)", in.at(0),
                       in.at(1), in.at(2), in.at(3), in.at(4), in.at(5));
        };
        map.showOut = [](const Values& out) {
            return trf("(s, t) = (%.9g, %.9g)", out.at(0), out.at(1));
        };
        l.tasks = {texel, sphere, torus, map};
        l.mutants = {{31, "04.texel", N_("fmod for the fraction (negative s)")},
                     {32, "04.texel", N_("GL_REPEAT treated as clamping")},
                     {33, "04.texel", N_("clamped to size instead of size - 1")},
                     {1, "04.sphere", N_("the seam: last column wrapped to s = 0")},
                     {2, "04.sphere", N_("a slice short (off by one)")},
                     {3, "04.sphere", N_("normals not normalised")},
                     {4, "04.sphere", N_("clockwise triangles")},
                     {5, "04.sphere", N_("t from the north pole")},
                     {11, "04.torus", N_("the t seam: last row wrapped to t = 0")},
                     {12, "04.torus", N_("a sphere's normal p/|p|")},
                     {13, "04.torus", N_("a row of cells short (off by one)")},
                     {21, "04.spheremap", N_("u not normalised")},
                     {22, "04.spheremap", N_("sign of the reflection")},
                     {23, "04.spheremap", N_("the +1 in m forgotten")}};
        return l;
    }();
    return lab;
}

} // namespace wb::lab04

const wb::ex::LabExercises& wbExercises_lab04() {
    return wb::lab04::exercises();
}
