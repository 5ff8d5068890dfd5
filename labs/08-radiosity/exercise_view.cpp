#include "exercise_view.h"

#include "common/gl.h"
#include "common/gl_util.h"
#include "core/i18n.h"
#include "core/radiosity/closed_forms.h"
#include "exercises.h"

#include <cmath>
#include <optional>

namespace wb {
namespace {

constexpr double kPlateEdge = 0.013; // as exercise_checks.cpp: no ray midpoint on the edge

lab08::Quad square(double z, bool up) {
    lab08::Quad q;
    q.p[0] = {-0.5, -0.5, z}, q.p[2] = {0.5, 0.5, z};
    q.p[1] = up ? glm::dvec3(0.5, -0.5, z) : glm::dvec3(-0.5, 0.5, z);
    q.p[3] = up ? glm::dvec3(-0.5, 0.5, z) : glm::dvec3(0.5, -0.5, z);
    return q;
}
const lab08::Quad kLow = square(0, true), kHigh = square(2, false);

struct Ray {
    glm::dvec3 a, b;
    bool visible;
};

// The plate z = 1, x < kPlateEdge, |y| < 5: the segment a-b is blocked when it crosses it.
bool visibleThrough(const glm::dvec3& a, const glm::dvec3& b) {
    if ((a.z - 1) * (b.z - 1) > 0 || a.z == b.z) return true;
    const double t = (1 - a.z) / (b.z - a.z);
    const glm::dvec3 p = a + t * (b - a);
    return !(p.x < kPlateEdge && p.x > -5 && std::fabs(p.y) < 5);
}

std::optional<double> raysOf(const ex::ExerciseMode& mode, const lab08::Table* t, bool student,
                             std::vector<Ray>& rays) {
    rays.clear();
    const lab08::Visible v = [&rays](const glm::dvec3& a, const glm::dvec3& b) {
        const bool ok = visibleThrough(a, b);
        if (rays.size() < 4096) rays.push_back({a, b, ok});
        return ok;
    };
    if (!student) return t->formFactorRays(kLow, kHigh, 64, 3, v);
    return mode.call("08.rays", [&] { return t->formFactorRays(kLow, kHigh, 64, 3, v); });
}

void drawQuad(const lab08::Quad& q) {
    glBegin(GL_QUADS);
    for (const auto& p : q.p)
        glVertex3d(p.x, p.y, p.z);
    glEnd();
}

void drawRays(const std::vector<Ray>& rays) {
    glBegin(GL_LINES);
    for (const Ray& r : rays) {
        if (r.visible)
            glColor3f(0.2f, 0.85f, 0.3f);
        else
            glColor3f(0.9f, 0.25f, 0.2f);
        glVertex3d(r.a.x, r.a.y, r.a.z);
        glVertex3d(r.b.x, r.b.y, r.b.z);
    }
    glEnd();
}

std::string num(const std::optional<double>& v) {
    return v ? trf("%.6g", *v) : std::string(tr("not done"));
}

} // namespace

void drawRadiosityExercise(const ex::ExerciseMode& mode, const View& view) {
    glViewport(0, 0, view.width, view.height);
    setPerspective(view, 40.0, 0.1, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslated(0, 0, -6);
    glRotated(-60, 1, 0, 0);
    applyOrbit(view);
    glTranslated(0, 0, -1);
    glDisable(GL_LIGHTING);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glColor3f(0.85f, 0.85f, 0.7f); // the two patches
    drawQuad(kLow);
    glColor3f(0.7f, 0.75f, 0.9f);
    drawQuad(kHigh);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.4f, 0.4f, 0.45f, 0.6f); // the plate
    glBegin(GL_QUADS);
    glVertex3d(-1.2, -0.8, 1), glVertex3d(kPlateEdge, -0.8, 1);
    glVertex3d(kPlateEdge, 0.8, 1), glVertex3d(-1.2, 0.8, 1);
    glEnd();
    glDisable(GL_BLEND);
    std::vector<Ray> rays;
    if (const auto* t = mode.studentTable<lab08::Table>())
        if (raysOf(mode, t, true, rays)) drawRays(rays);
    if (const auto* r = mode.referenceTable<lab08::Table>()) {
        raysOf(mode, r, false, rays);
        ex::ExerciseMode::ghostBegin();
        glLineWidth(3.0f);
        drawRays(rays);
        glLineWidth(1.0f);
        ex::ExerciseMode::ghostEnd();
    }
}

std::vector<std::string> radiosityExerciseLines(const ex::ExerciseMode& mode) {
    std::vector<std::string> out;
    const auto* r = mode.referenceTable<lab08::Table>(); // nullptr in a handout
    const auto* t = mode.studentTable<lab08::Table>();
    const double exact = rad::parallelRectangles(1, 1, 2);
    std::optional<double> f, fRef, frRef;
    if (t) f = mode.call("08.formfactor", [&] { return t->formFactor(kLow, kHigh); });
    std::vector<Ray> rays;
    if (r) fRef = r->formFactor(kLow, kHigh), frRef = raysOf(mode, r, false, rays);
    out.push_back(trf("F by (15.20): yours %s, reference %s, exact %.6g (closed form)",
                      num(f).c_str(), num(fRef).c_str(), exact));
    const std::optional<double> fr = t ? raysOf(mode, t, true, rays) : std::nullopt;
    out.push_back(trf("F by 64 rays past the plate: yours %s, reference %s", num(fr).c_str(),
                      num(frRef).c_str()));
    // Jacobi from B = E on the two squares, the lower one a lamp: 20 sweeps.
    const std::vector<double> e{1, 0}, refl{0.6, 0.8}, F{0, exact, exact, 0};
    auto sweeps = [&](const lab08::Table* tab) {
        std::vector<double> b = e;
        for (int k = 0; k < 20; ++k)
            b = tab->jacobiSweep(b, e, refl, F);
        return b;
    };
    // The exact B of this two-patch system (solved by hand), instead of the reference's.
    const double b1 = 1 / (1 - refl[0] * refl[1] * exact * exact), b2 = refl[1] * exact * b1;
    std::optional<std::vector<double>> bm;
    if (t) bm = mode.call("08.jacobi", [&] { return sweeps(t); });
    out.push_back(
        bm && bm->size() == 2
            ? trf("B after 20 Jacobi sweeps: yours (%.6g, %.6g), exact (%.6g, %.6g)", (*bm)[0],
                  (*bm)[1], b1, b2)
            : trf("B after 20 Jacobi sweeps: yours not done, exact (%.6g, %.6g)", b1, b2));
    return out;
}

} // namespace wb
