#include "exercise_view.h"

#include "common/gl.h"
#include "exercises.h"

#include <optional>
#include <vector>

namespace wb {
namespace {

const float kColours[2][3] = {{0.95f, 0.3f, 0.25f}, {0.3f, 0.55f, 1.0f}};

std::vector<float> floats(const std::vector<glm::dvec3>& p) {
    std::vector<float> f;
    for (const auto& q : p)
        f.insert(f.end(), {float(q.x), float(q.y), float(q.z)});
    return f;
}

void curves(const std::vector<lab06::Curve>& cs, int grid, bool colours, bool control) {
    glEnable(GL_MAP1_VERTEX_3);
    for (size_t c = 0; c < cs.size(); ++c) {
        if (cs[c].size() < 2 || cs[c].size() > 8) continue; // what glMap1f cannot take
        const std::vector<float> pts = floats(cs[c]);
        if (colours) glColor3fv(kColours[c % 2]);
        glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, GLint(cs[c].size()), pts.data());
        glMapGrid1f(grid, 0.0f, 1.0f);
        glEvalMesh1(GL_LINE, 0, grid);
    }
    glDisable(GL_MAP1_VERTEX_3);
    if (!control) return;
    glLineWidth(1.0f);
    for (const auto& c : cs) {
        glBegin(GL_LINE_STRIP);
        for (const auto& p : c)
            glVertex3d(p.x, p.y, p.z);
        glEnd();
    }
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (const auto& c : cs)
        for (const auto& p : c)
            glVertex3d(p.x, p.y, p.z);
    glEnd();
}

void patches(const std::vector<lab06::Patch>& ps, int grid, bool fill) {
    glEnable(GL_MAP2_VERTEX_3);
    for (size_t k = 0; k < ps.size(); ++k) {
        const lab06::Patch& p = ps[k];
        if (p.orderU < 2 || p.orderV < 2 || p.orderU > 8 || p.orderV > 8 ||
            p.points.size() != size_t(p.orderU * p.orderV))
            continue;
        if (fill) {
            const GLfloat c[4] = {kColours[k % 2][0], kColours[k % 2][1], kColours[k % 2][2], 1.0f};
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, c);
        }
        const std::vector<float> pts = floats(p.points);
        glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, p.orderU, 0.0f, 1.0f, 3 * p.orderU, p.orderV,
                pts.data());
        glMapGrid2f(grid, 0.0f, 1.0f, grid, 0.0f, 1.0f);
        glEvalMesh2(fill ? GL_FILL : GL_LINE, 0, grid, 0, grid);
    }
    glDisable(GL_MAP2_VERTEX_3);
}

void nets(const std::vector<lab06::Patch>& ps) {
    glColor3f(0.1f, 0.1f, 0.1f);
    for (const auto& p : ps) {
        if (p.points.size() != size_t(p.orderU * p.orderV)) continue;
        for (int j = 0; j < p.orderV; ++j) {
            glBegin(GL_LINE_STRIP);
            for (int i = 0; i < p.orderU; ++i)
                glVertex3dv(&p.points[size_t(j * p.orderU + i)].x);
            glEnd();
        }
        for (int i = 0; i < p.orderU; ++i) {
            glBegin(GL_LINE_STRIP);
            for (int j = 0; j < p.orderV; ++j)
                glVertex3dv(&p.points[size_t(j * p.orderU + i)].x);
            glEnd();
        }
    }
}

} // namespace

bool drawCircleExercise(const ex::ExerciseMode& mode, int grid, bool control) {
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    bool drawn = false;
    if (const auto* t = mode.studentTable<lab06::Table>()) {
        const auto mine = mode.call("06.circle", [t] { return t->circleCurves(1.0); });
        if (mine) {
            glLineWidth(2.0f);
            curves(*mine, grid, true, false);
            if (control) {
                glColor3f(0.2f, 0.2f, 0.2f);
                curves(*mine, grid, false, true);
            }
            drawn = true;
        }
    }
    if (const auto* r = mode.referenceTable<lab06::Table>()) {
        ex::ExerciseMode::ghostBegin();
        glColor3f(0.1f, 0.1f, 0.1f);
        glLineWidth(3.0f);
        curves(r->circleCurves(1.0), grid, false, false);
        ex::ExerciseMode::ghostEnd();
    }
    glLineWidth(1.0f);
    return drawn;
}

bool drawSphereExercise(const ex::ExerciseMode& mode, int grid, bool wireframe, bool control) {
    bool drawn = false;
    if (const auto* t = mode.studentTable<lab06::Table>()) {
        const auto mine = mode.call("06.sphere", [t] { return t->spherePatches(); });
        if (mine) {
            // The lab's light (bezier_lab.cpp drawSurface): from the upper right front.
            glPushMatrix();
            glLoadIdentity();
            const GLfloat lightPos[] = {1.0f, 1.0f, 2.0f, 0.0f};
            glLightfv(GL_LIGHT0, GL_POSITION, lightPos);
            glPopMatrix();
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glEnable(GL_AUTO_NORMAL);
            glEnable(GL_NORMALIZE);
            glEnable(GL_DEPTH_TEST);
            if (wireframe) glDisable(GL_LIGHTING), glColor3f(0.2f, 0.3f, 0.7f);
            patches(*mine, grid, !wireframe);
            glDisable(GL_LIGHTING);
            glDisable(GL_AUTO_NORMAL);
            if (control) {
                glDisable(GL_DEPTH_TEST);
                nets(*mine);
            }
            drawn = true;
        }
    }
    if (const auto* r = mode.referenceTable<lab06::Table>()) {
        glDisable(GL_LIGHTING);
        glDisable(GL_DEPTH_TEST);
        ex::ExerciseMode::ghostBegin();
        glColor3f(0.1f, 0.1f, 0.1f);
        patches(r->spherePatches(), 8, false);
        ex::ExerciseMode::ghostEnd();
    }
    return drawn;
}

} // namespace wb
