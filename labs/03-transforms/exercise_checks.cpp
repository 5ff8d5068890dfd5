// Lab 03's tasks and their checks (exercise_check.h). The camera is compared through the
// view it gives (the gluLookAt matrix of the student's parameters against the reference's),
// so any up vector that gives the same view is right. The mirror is checked in OpenGL
// itself: a camera matrix is loaded, the student's calls run, and the modelview matrix read
// back must be the camera times the reflection in the wall, and the calls made must be the
// task's own (glTranslatef, glScalef, glRotatef: wb-check sees every matrix call,
// common/gl_call_log.h).
#include "exercises.h"

#include "common/exercise_check.h"
#include "common/gl_call_log.h"
#include "core/i18n.h"

#include <GL/gl.h>
#include <GL/glu.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>
#include <string>

const void* wbExerciseReference_lab03();

namespace wb::lab03 {
namespace {

using ex::Case;
using ex::Values;
using ex::Verdict;

struct Lcg {
    unsigned long long s;
    double next() {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return double(s >> 11) / double(1ull << 53);
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

std::string fmtVec(const glm::dvec3& v) {
    return ex::showNumbers({v.x, v.y, v.z});
}
glm::dvec3 v3(const Values& v, size_t k) {
    return {v.at(k), v.at(k + 1), v.at(k + 2)};
}

// ----- ③ frustum: in = fovy, aspect, near, far; out = the six, then GL's two matrices -----
std::vector<Case> frustumCases() {
    std::vector<Case> cs = {{N_("the lab's view: 50°, 4:3, near 1, far 60"), {50, 4.0 / 3, 1, 60}},
                            {N_("90°, square"), {90, 1, 0.5, 100}},
                            {N_("narrow 10°, wide screen 16:9"), {10, 16.0 / 9, 2, 20}},
                            {N_("wide 150°, tall window 0.5"), {150, 0.5, 0.1, 10}},
                            {N_("a far near plane 25"), {60, 1.25, 25, 200}}};
    Lcg g{31};
    for (int i = 1; i <= 4; ++i) {
        const double n = g.in(0.1, 10);
        cs.push_back(
            {"seed " + std::to_string(i), {g.in(5, 170), g.in(0.2, 5), n, n * g.in(2, 100)}});
    }
    return cs;
}

Values frustumRun(const void* table, const Values& in) {
    const Frustum f = static_cast<const Table*>(table)->perspectiveAsFrustum(in.at(0), in.at(1),
                                                                             in.at(2), in.at(3));
    Values out{f.left, f.right, f.bottom, f.top, f.zNear, f.zFar};
    // OpenGL's own two matrices: glFrustum with these numbers, gluPerspective with the case's.
    GLfloat m[16];
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(f.left, f.right, f.bottom, f.top, f.zNear, f.zFar);
    glGetFloatv(GL_PROJECTION_MATRIX, m);
    out.insert(out.end(), m, m + 16);
    glLoadIdentity();
    gluPerspective(in.at(0), in.at(1), in.at(2), in.at(3));
    glGetFloatv(GL_PROJECTION_MATRIX, m);
    out.insert(out.end(), m, m + 16);
    glMatrixMode(GL_MODELVIEW);
    return out;
}

Verdict frustumCompare(const Values& in, const Values& expected, const Values& got) {
    for (double v : got)
        if (!std::isfinite(v)) return Verdict::fail(tr("a parameter is not a number"));
    // tan and two products: 1e-12 relative.
    const Values six(got.begin(), got.begin() + 6), want(expected.begin(), expected.begin() + 6);
    if (!ex::allNear(want, six, 1e-12)) {
        if (std::fabs(got[0] + got[1]) > 1e-12 * std::fabs(got[1]) ||
            std::fabs(got[2] + got[3]) > 1e-12 * std::fabs(got[3]))
            return Verdict::fail(
                tr("gluPerspective's view is centred: left = -right, bottom = -top"));
        if (got[4] != in.at(2) || got[5] != in.at(3))
            return Verdict::fail(tr("the near and far planes are gluPerspective's own"));
        const double ratio = got[3] / want[3];
        if (std::fabs(got[1] / got[3] - in.at(1)) > 1e-9 * in.at(1))
            return Verdict::fail(trf("right/top = %.6g: the aspect is width/height, so right = "
                                     "top·aspect",
                                     got[1] / got[3]));
        return Verdict::fail(trf("top is %.6g times the right one: top = zNear·tan(fovy/2) with "
                                 "fovy in degrees turned into radians (·pi/180) and halved",
                                 ratio));
    }
    // And in OpenGL: the two projection matrices read back (float: 1e-5 relative).
    const Values a(got.begin() + 6, got.begin() + 22), b(got.begin() + 22, got.begin() + 38);
    double big = 0;
    for (double v : b)
        big = std::max(big, std::fabs(v));
    for (size_t i = 0; i < 16; ++i)
        if (std::fabs(a[i] - b[i]) > 1e-5 * big)
            return Verdict::fail(tr("OpenGL's glFrustum with your numbers differs from "
                                    "gluPerspective's matrix"));
    return Verdict::pass();
}

// ----- ④ camera: in = eye, centre, up, step -----
std::vector<Case> cameraCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string name, const glm::dvec3& e, const glm::dvec3& c,
                     const glm::dvec3& u, double step) {
        cs.push_back({std::move(name), {e.x, e.y, e.z, c.x, c.y, c.z, u.x, u.y, u.z, step}});
    };
    add(N_("the lab's camera, one step in"), {0, 6.34, 7.59}, {0, 0, -1}, {0, 1, 0}, 1);
    add(N_("the lab's camera, one step out"), {0, 6.34, 7.59}, {0, 0, -1}, {0, 1, 0}, -1);
    add(N_("far from the origin, step 2.5 in"), {105, 20, -40}, {100, 18, -30}, {0, 1, 0}, 2.5);
    add(N_("a step past the centre: the eye stops at distance 1"), {0, 0, 5}, {0, 0, 0}, {0, 1, 0},
        7);
    add(N_("a step out past 60: the eye stops at distance 60"), {0, 3, 55}, {0, 3, 0}, {0, 1, 0},
        -20);
    add(N_("already at distance 1, one step in: it stays"), {1, 0, 0}, {0, 0, 0}, {0, 0, 1}, 1);
    add(N_("up not perpendicular to the line of sight"), {3, 4, 5}, {0, 0, 0}, {0.2, 1, 0.1}, 0.5);
    Lcg g{33};
    for (int i = 1; i <= 6; ++i) {
        const glm::dvec3 c(g.in(-10, 10), g.in(-10, 10), g.in(-10, 10));
        glm::dvec3 d(g.in(-1, 1), g.in(-1, 1), g.in(-1, 1));
        d = glm::normalize(d) * g.in(1.5, 50);
        add("seed " + std::to_string(i), c + d, c, {0, 1, 0}, g.in(-5, 5));
    }
    return cs;
}

Values cameraRun(const void* table, const Values& in) {
    LookAt cam{v3(in, 0), v3(in, 3), v3(in, 6)};
    const LookAt out = static_cast<const Table*>(table)->moveCamera(cam, in.at(9));
    return {out.eye.x,    out.eye.y, out.eye.z, out.centre.x, out.centre.y,
            out.centre.z, out.up.x,  out.up.y,  out.up.z};
}

Verdict cameraCompare(const Values& in, const Values& expected, const Values& got) {
    for (double v : got)
        if (!std::isfinite(v)) return Verdict::fail(tr("a parameter is not a number"));
    const glm::dvec3 e = v3(got, 0), c = v3(got, 3), u = v3(got, 6);
    const glm::dvec3 e0 = v3(in, 0), c0 = v3(in, 3);
    if (glm::length(c - c0) > 1e-12 * (1 + glm::length(c0)))
        return Verdict::fail(tr("the centre moved: moving the camera in and out keeps the point "
                                "it looks at (only the eye moves)"));
    const double d = glm::length(e - c);
    if (d < kMinDistance * (1 - 1e-9) || d > kMaxDistance * (1 + 1e-9))
        return Verdict::fail(trf("the eye is %.6g from the centre: keep it within [%g, %g] (at "
                                 "0 gluLookAt has no direction, past it the view turns round)",
                                 d, kMinDistance, kMaxDistance));
    if (glm::length(glm::cross(u, e - c)) < 1e-12 * glm::length(u) * d)
        return Verdict::fail(tr("the up vector lies along the line of sight: gluLookAt cannot "
                                "tell which way is up"));
    // The view: gluLookAt's matrix (glm::lookAt is the same formula) of both answers. Its
    // entries are O(|eye|) = O(100): 1e-9 relative to the largest.
    const glm::dmat4 mg = glm::lookAt(e, c, u);
    const glm::dmat4 me = glm::lookAt(v3(expected, 0), v3(expected, 3), v3(expected, 6));
    const double* pg = glm::value_ptr(mg);
    const double* pe = glm::value_ptr(me);
    if (ex::allNear(Values(pe, pe + 16), Values(pg, pg + 16), 1e-9)) return Verdict::pass();
    const double d0 = glm::length(e0 - c0), de = glm::length(v3(expected, 0) - c0);
    if (glm::dot(e - c, e0 - c0) < 0)
        return Verdict::fail(tr("the eye passed the centre and looks back: stop it at "
                                "kMinDistance"));
    if (glm::length(glm::normalize(e - c) - glm::normalize(e0 - c0)) > 1e-9)
        return Verdict::fail(tr("the eye left the line of sight: move it along eye - centre"));
    if ((d - d0) * (de - d0) < 0)
        return Verdict::fail(tr("the wrong way: step > 0 moves the eye TOWARDS the centre"));
    return Verdict::fail(trf("the eye is %.9g from the centre, expected %.9g: move it by step "
                             "along the UNIT direction of the line of sight",
                             d, de));
}

// ----- ⑤ mirror: in = wallZ, then the camera's 16 entries; out = the modelview, face mode --
std::vector<Case> mirrorCases() {
    std::vector<Case> cs;
    auto add = [&cs](std::string name, float wallZ, const glm::mat4& camera) {
        Values in{double(wallZ)};
        const float* p = glm::value_ptr(camera);
        in.insert(in.end(), p, p + 16);
        cs.push_back({std::move(name), in});
    };
    const glm::mat4 labCamera =
        glm::lookAt(glm::vec3(0, 6.34f, 7.59f), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    add(N_("the lab's wall z = -6 under the identity"), -6.0f, glm::mat4(1.0f));
    add(N_("the lab's wall z = -6 under the lab's camera"), -6.0f, labCamera);
    add(N_("a wall through the origin z = 0"), 0.0f, labCamera);
    add(N_("a wall behind the viewer z = 3.5"), 3.5f, glm::mat4(1.0f));
    add(N_("a far wall z = -100"), -100.0f, labCamera);
    Lcg g{37};
    for (int i = 1; i <= 3; ++i) {
        const glm::mat4 cam =
            glm::lookAt(glm::vec3(g.in(-10, 10), g.in(0, 10), g.in(-10, 10)),
                        glm::vec3(g.in(-2, 2), 0, g.in(-2, 2)), glm::vec3(0, 1, 0));
        add("seed " + std::to_string(i), float(g.in(-20, 20)), cam);
    }
    return cs;
}

// §2.3 task 5: "with glScalef/glTranslatef/glRotatef calls only" (their double twins too;
// push/pop change nothing that is left when they pair up).
bool allowedInMirror(int call) {
    for (const char* ok : {"glTranslatef", "glTranslated", "glScalef", "glScaled", "glRotatef",
                           "glRotated", "glPushMatrix", "glPopMatrix"})
        if (call == ex::glMatrixCallIndex(ok)) return true;
    return false;
}

Values mirrorRun(const void* table, const Values& in) {
    GLfloat cam[16];
    for (int i = 0; i < 16; ++i)
        cam[i] = GLfloat(in.at(size_t(i + 1)));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(cam);
    ex::GlCallLog log; // the matrix calls the student's code makes (wb-check sees them)
    const unsigned face = static_cast<const Table*>(table)->mirrorInWall(float(in.at(0)));
    const std::vector<int> calls = log.calls();
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    Values out(m, m + 16);
    out.push_back(double(face));
    // The first call the task does not allow (-1: none), as a kGlMatrixCalls index.
    int banned = -1;
    for (int c : calls)
        if (!allowedInMirror(c)) {
            banned = c;
            break;
        }
    out.push_back(double(banned));
    return out;
}

Verdict mirrorCompare(const Values& in, const Values& expected, const Values& got) {
    // The rule first: a right matrix made with another call is still not the task.
    const int banned = got.size() > 17 ? int(got[17]) : -1;
    if (banned >= 0 && banned < ex::kGlMatrixCallCount)
        return Verdict::fail(trf("%s is not allowed here: the task builds the mirror with "
                                 "glTranslatef, glScalef and glRotatef calls only",
                                 ex::kGlMatrixCalls[banned]));
    for (double v : got)
        if (!std::isfinite(v)) return Verdict::fail(tr("the matrix holds a non-number"));
    // What it must be: camera · T(wallZ) · S(1, 1, -1) · T(-wallZ), in double.
    glm::dmat4 cam;
    for (int i = 0; i < 16; ++i)
        glm::value_ptr(cam)[i] = in.at(size_t(i + 1));
    const double z = in.at(0);
    glm::dmat4 r(1.0);
    r[2][2] = -1, r[3][2] = 2 * z;
    const glm::dmat4 want = cam * r;
    // GL keeps its matrices in float: each product rounds entries to ~6e-8 relative of
    // the largest (|2·wallZ| up to 200 times the camera's); 1e-5 relative leaves room for
    // three products and none for a wrong factor.
    const double* w = glm::value_ptr(want);
    const Values wantV(w, w + 16), gotM(got.begin(), got.begin() + 16);
    double big = 0;
    for (double v : wantV)
        big = std::max(big, std::fabs(v));
    bool ok = true;
    for (int i = 0; i < 16; ++i)
        ok = ok && std::fabs(wantV[size_t(i)] - gotM[size_t(i)]) <= 1e-5 * big;
    if (!ok) {
        glm::dmat4 g;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(g)[i] = gotM[size_t(i)];
        const glm::dmat4 mine = glm::inverse(cam) * g; // what the student's calls multiplied by
        // The reflection alone although a camera was loaded: the camera was replaced.
        bool camIdentity = true, isReflection = true;
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k) {
                camIdentity = camIdentity && std::fabs(cam[c][k] - (c == k ? 1 : 0)) < 1e-9;
                isReflection =
                    isReflection && std::fabs(g[c][k] - r[c][k]) <= 1e-5 * (1 + std::fabs(z));
            }
        if (!camIdentity && isReflection)
            return Verdict::fail(tr("the camera's matrix is gone: multiply the current matrix "
                                    "(glTranslatef etc.), do not load the identity"));
        const glm::dvec4 p = mine * glm::dvec4(1, 2, z, 1); // a point of the wall must stay
        if (glm::length(glm::dvec3(p) - glm::dvec3(1, 2, z)) > 1e-3 * (1 + std::fabs(z))) {
            if (std::fabs(mine[0][0] + 1) < 1e-3)
                return Verdict::fail(tr("x is flipped: the blackboard wall is the plane z = wallZ, "
                                        "so z is the coordinate to reverse"));
            return Verdict::fail(trf("a point of the wall (1, 2, %g) moves to (%.4g, %.4g, %.4g): "
                                     "translate the wall to z = 0, flip z, translate back - "
                                     "glTranslatef(0,0,wallZ) first in the code, glTranslatef(0,0,"
                                     "-wallZ) last",
                                     z, p.x, p.y, p.z));
        }
        return Verdict::fail(
            tr("not the reflection in the wall: (x, y, z) -> (x, y, 2·wallZ - z)"));
    }
    (void)expected;
    if (got.at(16) != double(GL_CW))
        return Verdict::fail(tr("a reflection turns counter-clockwise triangles clockwise: the "
                                "mirrored room needs glFrontFace(GL_CW), or culling removes its "
                                "front faces and lighting darkens them"));
    return Verdict::pass();
}

} // namespace

const ex::LabExercises& exercises() {
    static const ex::LabExercises lab = [] {
        ex::LabExercises l;
        l.lab = "03";
        l.title = N_("Lab 03 - transforms and projection");
        l.file = "labs/03-transforms/exercises.cpp";
        l.reference = wbExerciseReference_lab03();
        ex::Task fr;
        fr.id = "03.frustum";
        fr.grade = 3;
        fr.title = N_("gluPerspective as glFrustum");
        fr.section = "§2.3 task 3 (second list)";
        fr.cases = frustumCases;
        fr.run = frustumRun;
        fr.compare = frustumCompare;
        fr.needsGl = true;
        fr.showIn = [](const Values& in) {
            return trf("gluPerspective(%.6g, %.6g, %.6g, %.6g)", in.at(0), in.at(1), in.at(2),
                       in.at(3));
        };
        fr.showOut = [](const Values& out) {
            return trf("glFrustum(%.9g, %.9g, %.9g, %.9g, %.6g, %.6g)", out.at(0), out.at(1),
                       out.at(2), out.at(3), out.at(4), out.at(5));
        };
        ex::Task cam;
        cam.id = "03.camera";
        cam.grade = 4;
        cam.title = N_("The camera moved in and out through gluLookAt's parameters");
        cam.section = "§2.3 task 4 (second list)";
        cam.cases = cameraCases;
        cam.run = cameraRun;
        cam.compare = cameraCompare;
        cam.showIn = [](const Values& in) {
            return trf("eye %s, centre %s, up %s, step %g", fmtVec(v3(in, 0)).c_str(),
                       fmtVec(v3(in, 3)).c_str(), fmtVec(v3(in, 6)).c_str(), in.at(9));
        };
        cam.showOut = [](const Values& out) {
            return trf("eye %s, centre %s, up %s", fmtVec(v3(out, 0)).c_str(),
                       fmtVec(v3(out, 3)).c_str(), fmtVec(v3(out, 6)).c_str());
        };
        ex::Task mir;
        mir.id = "03.mirror";
        mir.grade = 5;
        mir.title = N_(
            "The classroom mirrored in the blackboard wall with glScalef, glTranslatef, glRotatef");
        mir.section = "§2.3 task 5";
        mir.cases = mirrorCases;
        mir.run = mirrorRun;
        mir.compare = mirrorCompare;
        mir.needsGl = true;
        mir.showIn = [](const Values& in) { return trf("wall z = %g, camera loaded", in.at(0)); };
        mir.showOut = [](const Values& out) {
            return ex::showMatrix(Values(out.begin(), out.begin() + 16), 4) +
                   (out.at(16) == double(GL_CW)    ? ", GL_CW"
                    : out.at(16) == double(GL_CCW) ? ", GL_CCW"
                                                   : ", ?");
        };
        l.tasks = {fr, cam, mir};
        l.mutants = {{21, "03.frustum", N_("fovy not halved")},
                     {22, "03.frustum", N_("degrees given to tan")},
                     {23, "03.frustum", N_("aspect inverted")},
                     {1, "03.camera", N_("moved along the unnormalised line of sight")},
                     {2, "03.camera", N_("in and out swapped")},
                     {3, "03.camera", N_("the centre moved with the eye")},
                     {4, "03.camera", N_("no limit: the eye passes the centre")},
                     {11, "03.mirror", N_("one translation only")},
                     {12, "03.mirror", N_("the translations in the wrong order")},
                     {13, "03.mirror", N_("x flipped instead of z")},
                     {14, "03.mirror", N_("front faces not turned (GL_CCW)")},
                     {15, "03.mirror", N_("glLoadIdentity: the camera thrown away")},
                     {16, "03.mirror", N_("glMultMatrixd with the right matrix")}};
        return l;
    }();
    return lab;
}

} // namespace wb::lab03

const wb::ex::LabExercises& wbExercises_lab03() {
    return wb::lab03::exercises();
}
