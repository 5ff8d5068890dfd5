#include "bezier_lab.h"

#include "exercise_view.h"

#include "common/gl_util.h"
#include "core/i18n.h"
#include "core/teapot.h"

#include "common/panel.h"
#include "core/i18n.h"

#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>

const wb::ex::LabExercises& wbExercises_lab06();

namespace wb {
namespace {

std::string variantLabel(const std::string& english); // below, with the variants

constexpr int kMinGrid = 2;
constexpr int kMaxGrid = 256;
constexpr double kPi = 3.14159265358979323846;

std::vector<float> toFloats(const std::vector<glm::dvec3>& p) {
    std::vector<float> f;
    f.reserve(p.size() * 3);
    for (const auto& q : p)
        for (int c = 0; c < 3; ++c)
            f.push_back(float(q[c]));
    return f;
}

std::string fmt(const char* format, double a, double b = 0.0) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, a, b);
    return buf;
}

// Colours of successive arcs, so the joins between the Bezier pieces show.
const float kArcColours[2][3] = {{0.95f, 0.3f, 0.25f}, {0.3f, 0.55f, 1.0f}};

class BezierLab : public Lab {
  public:
    explicit BezierLab(BezierLabState* s) : s_(s ? s : &own_), ex_(wbExercises_lab06()) {}
    bool busy() const override { return ex_.busy(); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }
    std::string title() const override { return tr("Lab 06 - Bezier curves and patches"); }
    std::vector<KeyHelp> keys() const override {
        return {{"1", tr("circle: two Bezier curves")},
                {"2", tr("sphere: two Bezier patches")},
                {"c", tr("control polygon / net")},
                {"[", tr("grid halve")},
                {"]", tr("grid double")},
                {"a", tr("next approximation")},
                {"w", tr("sphere wireframe")},
                {"t", tr("true circle / sphere (grey)")},
                {"n", tr("normals: GL_AUTO_NORMAL / core")},
                {"3", tr("Utah teapot: Newell's 32 patches")},
                {"z", tr("zoom on the spot GL leaves unlit")},
                ex_.keyHelp()};
    }
    void init() override {
        bezierCircleVariants(); // the fits take about a second: do them before the first frame
        bezierSphereVariants();
    }
    void draw(const View& view) override;
    bool key(int k) override;
    void gui() override;

  private:
    void drawCircle();
    void drawSphere(const View& view);
    void drawTeapot(const View& view);
    // The patches of the current shape (sphere variant or teapot) and each one's colour.
    const std::vector<BezierPatch>& patches() const;
    void patchColour(size_t p, GLfloat out[4]) const;
    // The current shape's patches lit: glMap2f + glEvalMesh2 with GL_AUTO_NORMAL, or
    // core's grid (n); records the GL time when `time`.
    void drawSurface(bool time);
    // Patch p of the current shape as quad strips with core's points and normals.
    void drawCoreMesh(size_t p);
    // The inset (bottom left) magnifying `focus` (shape coordinates) under the current
    // modelview, and a marker square around it in the main view.
    void drawInset(const View& view, const glm::dvec3& focus);
    // The GL evaluator's time for the current mesh, measured now (the panel asks before
    // the frame is drawn when a key has just changed the grid).
    void measureNow();
    void recordTime(double ms);
    // The GL time of one mesh at the current shape/variant/grid: median of the last frames.
    double medianMs() const;
    // Error of the drawn tessellation at grid n, for the current shape and variant (cached).
    double meshError(int n);

    BezierLabState own_;
    BezierLabState* s_;
    ex::ExerciseMode ex_; // e: your circle and sphere (exercises.cpp), the reference as a ghost
    std::map<std::tuple<int, int, int>, std::vector<double>> times_; // (shape, variant, grid) -> ms
    std::map<std::tuple<int, int, int>, double> errors_; // (shape, variant, grid) -> error
    // Core tessellation of (variant, patch, grid): points then normals.
    std::map<std::tuple<int, int, size_t, int>,
             std::pair<std::vector<glm::dvec3>, std::vector<glm::dvec3>>>
        meshes_;                                 // (shape, variant, patch, grid)
    std::map<int, TeapotGlComparison> teapotGl_; // grid -> GL against core (teapot)
};

int variantOf(const BezierLabState& s) {
    return s.shape == 0 ? s.circleVariant : s.shape == 1 ? s.sphereVariant : 0;
}

std::tuple<int, int, int> keyOf(const BezierLabState& s) {
    return {s.shape, variantOf(s), s.grid};
}

void BezierLab::recordTime(double ms) {
    auto& v = times_[keyOf(*s_)];
    v.push_back(ms);
    if (v.size() > 31) v.erase(v.begin());
}

double BezierLab::medianMs() const {
    auto it = times_.find(keyOf(*s_));
    if (it == times_.end() || it->second.empty()) return -1.0;
    std::vector<double> v = it->second;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

double BezierLab::meshError(int n) {
    const BezierLabState& s = *s_;
    const auto k = std::make_tuple(s.shape, variantOf(s), n);
    auto it = errors_.find(k);
    if (it != errors_.end()) return it->second;
    double e;
    if (s.shape == 2) {
        e = -1.0; // no true shape to compare with: the teapot's table is GL against core
    } else if (s.shape == 0) {
        e = polylineRadialError(bezierCircleVariants()[size_t(s.circleVariant)].arcs, 1.0, n)
                .maxError;
    } else {
        const SphereVariant& v = bezierSphereVariants()[size_t(s.sphereVariant)];
        e = meshRadialError(v.patches, v.error.radius, n).maxError / v.error.radius;
    }
    errors_[k] = e;
    return e;
}

void BezierLab::draw(const View& view) {
    ex_.poll(!view.headless);
    glClearColor(0.97f, 0.97f, 0.95f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    // Orthographic, so that radii on screen are radii in the scene.
    const double h = (s_->shape == 0   ? kBezierViewHalfHeight
                      : s_->shape == 1 ? kBezierSphereViewHalfHeight
                                       : kBezierTeapotViewHalfHeight) /
                     double(view.zoom > 0.0f ? view.zoom : 1.0f);
    const double aspect = double(view.width) / double(view.height > 0 ? view.height : 1);
    glOrtho(-h * aspect, h * aspect, -h, h, -20.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    applyOrbit(view);
    if (s_->shape == 0)
        drawCircle();
    else if (s_->shape == 1)
        drawSphere(view);
    else
        drawTeapot(view);
}

void BezierLab::drawCircle() {
    const BezierLabState& s = *s_;
    if (ex_.on()) { // your curves (e), the reference's as a ghost, the true circle on top
        glPushMatrix();
        glScaled(kBezierCircleRadius, kBezierCircleRadius, kBezierCircleRadius);
        drawCircleExercise(ex_, s.grid, s.showControl);
        glPopMatrix();
        return;
    }
    const CircleVariant& v = bezierCircleVariants()[size_t(s.circleVariant)];
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glPushMatrix();
    glScaled(kBezierCircleRadius, kBezierCircleRadius, kBezierCircleRadius);
    glLineWidth(2.0f);
    glEnable(GL_MAP1_VERTEX_3);
    glFinish(); // time the evaluator alone
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t a = 0; a < v.arcs.size(); ++a) {
        const std::vector<float> pts = toFloats(v.arcs[a]);
        glColor3fv(kArcColours[a % 2]);
        glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, GLint(v.arcs[a].size()), pts.data());
        glMapGrid1f(s.grid, 0.0f, 1.0f);
        glEvalMesh1(GL_LINE, 0, s.grid);
    }
    glFinish();
    recordTime(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    glDisable(GL_MAP1_VERTEX_3);
    if (s.showTrue) { // on top, thin: where the curve leaves the circle both show
        glColor3f(0.25f, 0.25f, 0.25f);
        glLineWidth(1.0f);
        glBegin(GL_LINE_LOOP);
        for (int i = 0; i < 720; ++i)
            glVertex2d(std::cos(i * kPi / 360), std::sin(i * kPi / 360));
        glEnd();
    }
    if (s.showControl) {
        glLineWidth(1.0f);
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(2, 0x5555);
        glColor3f(0.2f, 0.2f, 0.2f);
        for (const auto& arc : v.arcs) {
            glBegin(GL_LINE_STRIP);
            for (const auto& p : arc)
                glVertex3d(p.x, p.y, p.z);
            glEnd();
        }
        glDisable(GL_LINE_STIPPLE);
        glPointSize(6.0f);
        glBegin(GL_POINTS);
        for (const auto& arc : v.arcs)
            for (const auto& p : arc)
                glVertex3d(p.x, p.y, p.z);
        glEnd();
    }
    glPopMatrix();
    glLineWidth(1.0f);
}

const std::vector<BezierPatch>& BezierLab::patches() const {
    if (s_->shape == 2) return teapotPatches();
    return bezierSphereVariants()[size_t(s_->sphereVariant)].patches;
}

void BezierLab::patchColour(size_t p, GLfloat out[4]) const {
    static const GLfloat kSphere[2][4] = {{0.9f, 0.65f, 0.2f, 1.0f}, {0.3f, 0.55f, 0.95f, 1.0f}};
    // Teapot parts: rim and body, handle, spout, lid, bottom.
    static const GLfloat kTeapot[5][4] = {{0.9f, 0.65f, 0.2f, 1.0f},
                                          {0.3f, 0.55f, 0.95f, 1.0f},
                                          {0.35f, 0.75f, 0.35f, 1.0f},
                                          {0.85f, 0.35f, 0.3f, 1.0f},
                                          {0.6f, 0.6f, 0.6f, 1.0f}};
    const GLfloat* c = kSphere[p % 2];
    if (s_->shape == 2) {
        const int part = int(p) / 4; // rim, body, body, handle, spout, lid, lid, bottom
        c = kTeapot[part <= 2 ? 0 : part == 3 ? 1 : part == 4 ? 2 : part <= 6 ? 3 : 4];
    }
    std::copy(c, c + 4, out);
}

void BezierLab::drawSurface(bool time) {
    const BezierLabState& s = *s_;
    const std::vector<BezierPatch>& ps = patches();
    // A light from the upper right front, fixed to the camera: set with the eye's modelview.
    glPushMatrix();
    glLoadIdentity();
    const GLfloat lightPos[] = {1.0f, 1.0f, 2.0f, 0.0f};
    const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLfloat ambient[] = {0.25f, 0.25f, 0.25f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, lightPos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glPopMatrix();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    // GL_AUTO_NORMAL gives du × dv; GL_NORMALIZE makes it unit length for lighting.
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_MAP2_VERTEX_3);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t p = 0; p < ps.size(); ++p) {
        const BezierPatch& patch = ps[p];
        GLfloat colour[4];
        patchColour(p, colour);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour);
        if (s.coreNormals) {
            drawCoreMesh(p);
            continue;
        }
        const std::vector<float> pts = toFloats(patch.points);
        glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, patch.orderU, 0.0f, 1.0f, 3 * patch.orderU,
                patch.orderV, pts.data());
        glMapGrid2f(s.grid, 0.0f, 1.0f, s.grid, 0.0f, 1.0f);
        glEvalMesh2(s.wireframe ? GL_LINE : GL_FILL, 0, s.grid, 0, s.grid);
    }
    glFinish();
    if (time && !s.coreNormals) // the table is about the GL evaluator
        recordTime(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                       .count());
    glDisable(GL_MAP2_VERTEX_3);
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_NORMALIZE);
    glDisable(GL_LIGHTING);
}

void BezierLab::measureNow() {
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    if (s_->shape == 0) {
        const CircleVariant& v = bezierCircleVariants()[size_t(s_->circleVariant)];
        glEnable(GL_MAP1_VERTEX_3);
        glFinish();
        const auto t0 = std::chrono::steady_clock::now();
        for (const auto& arc : v.arcs) {
            const std::vector<float> pts = toFloats(arc);
            glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, GLint(arc.size()), pts.data());
            glMapGrid1f(s_->grid, 0.0f, 1.0f);
            glEvalMesh1(GL_LINE, 0, s_->grid);
        }
        glFinish();
        recordTime(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                       .count());
    } else {
        const bool core = s_->coreNormals;
        s_->coreNormals = false;
        drawSurface(true);
        s_->coreNormals = core;
    }
    glPopMatrix();
    glPopAttrib();
}

glm::dvec3 bezierInsetFocus(int shape) {
    return shape == 2 ? glm::dvec3(0.0, 0.0, kTeapotHeight) : glm::dvec3(2.0, -2.0, 0.0);
}

void BezierLab::drawInset(const View& view, const glm::dvec3& focus) {
    // The focus in eye coordinates, under the shape's modelview (orbit included).
    GLdouble mv[16];
    glGetDoublev(GL_MODELVIEW_MATRIX, mv);
    const glm::dvec4 e = glm::make_mat4(mv) * glm::dvec4(focus, 1.0);
    const double r = kBezierInsetHalfSize;
    // 1. The marker in the main view: a square around the spot, over everything.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glColor3f(0.85f, 0.1f, 0.6f);
    glLineWidth(2.0f);
    glBegin(GL_LINE_LOOP);
    glVertex3d(e.x - r, e.y - r, 10.0);
    glVertex3d(e.x + r, e.y - r, 10.0);
    glVertex3d(e.x + r, e.y + r, 10.0);
    glVertex3d(e.x - r, e.y + r, 10.0);
    glEnd();
    glPopMatrix();
    // 2. The inset: its own viewport in the bottom-left corner, cleared, the same surface
    // under the same modelview seen through a small orthographic window around the spot.
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    const int side = int(kBezierInsetFraction * double(std::min(view.width, view.height)));
    const int margin = 8;
    glViewport(vp[0] + margin, vp[1] + margin, side, side);
    glEnable(GL_SCISSOR_TEST);
    glScissor(vp[0] + margin, vp[1] + margin, side, side);
    glClearColor(0.88f, 0.88f, 0.86f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(e.x - r, e.x + r, e.y - r, e.y + r, -20.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    drawSurface(false);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glColor3f(0.85f, 0.1f, 0.6f); // the frame, in the marker's colour
    glLineWidth(3.0f);
    glBegin(GL_LINE_LOOP);
    glVertex2d(0.004, 0.004);
    glVertex2d(0.996, 0.004);
    glVertex2d(0.996, 0.996);
    glVertex2d(0.004, 0.996);
    glEnd();
    glLineWidth(1.0f);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_SCISSOR_TEST);
    glViewport(vp[0], vp[1], vp[2], vp[3]);
}

void BezierLab::drawTeapot(const View& view) {
    // The data's z up onto the screen's y up, centred on the pot (x from -3 to 3.5).
    glRotated(kBezierTeapotTilt, 1.0, 0.0, 0.0);
    glRotated(kBezierTeapotTurn, 0.0, 1.0, 0.0);
    glRotated(-90.0, 1.0, 0.0, 0.0);
    glTranslated(-0.25, 0.0, -0.5 * kTeapotHeight);
    glEnable(GL_DEPTH_TEST);
    drawSurface(true);
    if (s_->showControl) { // the 306 control points
        glDisable(GL_DEPTH_TEST);
        glPointSize(4.0f);
        glColor3f(0.8f, 0.1f, 0.1f);
        glBegin(GL_POINTS);
        for (const auto& q : teapotControlPoints())
            glVertex3dv(&q.x);
        glEnd();
    }
    if (s_->zoomInset) drawInset(view, bezierInsetFocus(2));
    glDisable(GL_DEPTH_TEST);
}

void BezierLab::drawSphere(const View& view) {
    const BezierLabState& s = *s_;
    const SphereVariant& v = bezierSphereVariants()[size_t(s.sphereVariant)];
    glRotated(kBezierSphereTilt, 1.0, 0.0, 0.0);
    if (ex_.on()) { // your patches (e), the reference's as a ghost
        drawSphereExercise(ex_, s.grid, s.wireframe, s.showControl);
        return;
    }
    glEnable(GL_DEPTH_TEST);
    drawSurface(true);

    if (s.showTrue) { // the true sphere: 12 meridians and 11 parallels
        const double r = v.error.radius;
        glColor3f(0.45f, 0.45f, 0.45f);
        for (int m = 0; m < 12; ++m) {
            glBegin(GL_LINE_STRIP);
            for (int i = 0; i <= 64; ++i) {
                const double th = i * kPi / 64, ph = m * kPi / 6;
                glVertex3d(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                           r * std::cos(th));
            }
            glEnd();
        }
        for (int l = 1; l < 12; ++l) {
            glBegin(GL_LINE_LOOP);
            const double th = l * kPi / 12;
            for (int i = 0; i < 96; ++i) {
                const double ph = i * 2 * kPi / 96;
                glVertex3d(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                           r * std::cos(th));
            }
            glEnd();
        }
    }
    if (s.showControl) { // the nets, drawn over the surface
        glDisable(GL_DEPTH_TEST);
        glColor3f(0.1f, 0.1f, 0.1f);
        for (const auto& patch : v.patches) {
            for (int j = 0; j < patch.orderV; ++j) {
                glBegin(GL_LINE_STRIP);
                for (int i = 0; i < patch.orderU; ++i)
                    glVertex3dv(&patch.at(i, j).x);
                glEnd();
            }
            for (int i = 0; i < patch.orderU; ++i) {
                glBegin(GL_LINE_STRIP);
                for (int j = 0; j < patch.orderV; ++j)
                    glVertex3dv(&patch.at(i, j).x);
                glEnd();
            }
        }
        glPointSize(6.0f);
        glColor3f(0.8f, 0.1f, 0.1f);
        glBegin(GL_POINTS);
        for (const auto& patch : v.patches)
            for (const auto& q : patch.points)
                glVertex3dv(&q.x);
        glEnd();
    }
    if (s.zoomInset) drawInset(view, bezierInsetFocus(1));
    glDisable(GL_DEPTH_TEST);
}

void BezierLab::drawCoreMesh(size_t p) {
    const BezierLabState& s = *s_;
    auto& mesh = meshes_[{s.shape, variantOf(s), p, s.grid}];
    if (mesh.first.empty()) tessellatePatch(patches()[p], s.grid, mesh.first, mesh.second);
    const size_t w = size_t(s.grid) + 1;
    if (s.wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    for (size_t j = 0; j + 1 < w; ++j) {
        glBegin(GL_QUAD_STRIP);
        for (size_t i = 0; i < w; ++i)
            for (size_t r : {j + 1, j}) { // the vertex order glEvalMesh2 uses, so faces match
                glNormal3dv(&mesh.second[r * w + i].x);
                glVertex3dv(&mesh.first[r * w + i].x);
            }
        glEnd();
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

bool BezierLab::key(int k) {
    if (ex_.key(k)) return true;
    BezierLabState& s = *s_;
    switch (k) {
    case '1':
        s.shape = 0;
        return true;
    case '2':
        s.shape = 1;
        return true;
    case '3':
        s.shape = 2;
        return true;
    case 'z':
        s.zoomInset = !s.zoomInset;
        return true;
    case 'c':
        s.showControl = !s.showControl;
        return true;
    case '[':
        s.grid = std::max(kMinGrid, s.grid / 2);
        return true;
    case ']':
        s.grid = std::min(kMaxGrid, s.grid * 2);
        return true;
    case 'a':
        if (s.shape == 0)
            s.circleVariant = (s.circleVariant + 1) % int(bezierCircleVariants().size());
        else if (s.shape == 1)
            s.sphereVariant = (s.sphereVariant + 1) % int(bezierSphereVariants().size());
        return true;
    case 'w':
        s.wireframe = !s.wireframe;
        return true;
    case 't':
        s.showTrue = !s.showTrue;
        return true;
    case 'n':
        s.coreNormals = !s.coreNormals;
        return true;
    default:
        return false;
    }
}

void BezierLab::gui() {
    // The panel is narrow: one short item per line, numbers in monospaced tables.
    BezierLabState& s = *s_;
    ex_.gui();
    ImGui::RadioButton(tr("circle (1)"), &s.shape, 0);
    sameLineIfFits(tr("sphere (2)"));
    ImGui::RadioButton(tr("sphere (2)"), &s.shape, 1);
    sameLineIfFits(tr("teapot (3)"));
    ImGui::RadioButton(tr("teapot (3)"), &s.shape, 2);
    ImGui::Checkbox(tr("control net (c)"), &s.showControl);
    if (s.shape != 2) {
        sameLineIfFits(tr("true shape (t)"));
        ImGui::Checkbox(tr("true shape (t)"), &s.showTrue);
    }
    if (s.shape >= 1) {
        ImGui::Checkbox(tr("wireframe (w)"), &s.wireframe);
        sameLineIfFits(tr("core normals (n)"));
        ImGui::Checkbox(tr("core normals (n)"), &s.coreNormals);
        ImGui::Checkbox(tr("zoom on the unlit spot (z)"), &s.zoomInset);
        if (s.shape == 1)
            ImGui::TextWrapped(tr("At the 4 corners of each patch the boundary curves are tangent, "
                                  "du x dv = 0: GL_AUTO_NORMAL has no normal there, and the grid "
                                  "cells at the corner go dark (the inset, bottom left, magnifies "
                                  "the marked corner 30x). 'core normals' draws the grid from "
                                  "evalPatch, which takes the limit from inside the patch."));
        else
            ImGui::TextWrapped(tr("Newell's teapot: 32 bicubic patches on 306 control points. At "
                                  "the lid's and the bottom's poles a row of the net is one point, "
                                  "du = 0: GL_AUTO_NORMAL has no normal there and the knob's top "
                                  "goes dark (inset); core's evalPatch takes the limit (n)."));
    }
    ImGui::SliderInt("##grid", &s.grid, kMinGrid, kMaxGrid, tr("grid %d ([ ])"));

    if (s.shape != 2) {
        ImGui::Separator();
        ImGui::TextWrapped(
            tr("Control points (a) and the radial error of the exact Bezier shape:"));
    }
    if (s.shape == 0) {
        const auto& vs = bezierCircleVariants();
        for (int i = 0; i < int(vs.size()); ++i) {
            const auto& v = vs[size_t(i)];
            ImGui::RadioButton(variantLabel(v.name).c_str(), &s.circleVariant, i);
            ImGui::Text(tr("      max |r-1| = %.3g"), v.error.maxError);
        }
    } else if (s.shape == 1) {
        const auto& vs = bezierSphereVariants();
        for (int i = 0; i < int(vs.size()); ++i) {
            const auto& v = vs[size_t(i)];
            ImGui::RadioButton(variantLabel(v.name).c_str(), &s.sphereVariant, i);
            ImGui::Text(tr("      max |r-R|/R = %.3g"), v.error.relative());
            ImGui::Text(tr("      r in [%.4f, %.4f]"), v.error.minRadius, v.error.maxRadius);
        }
        ImGui::TextWrapped(tr("R is the minimax radius (min+max)/2: the course's net names none."));
    }

    ImGui::Separator();
    if (medianMs() < 0) measureNow(); // a key just changed the grid: time it before showing
    const double ms = medianMs();
    s.shownMs = ms;
    ImGui::Text(tr("GL time per mesh, grid %d:"), s.grid);
    ImGui::Text("   %s", ms < 0 ? tr("(no GL context)") : trf("%.3f ms", ms).c_str());
    if (s.shape == 2) {
        ImGui::TextWrapped(tr("GL's evaluator (float) against core's de Casteljau (double) on "
                              "the same grid, read back with GL_FEEDBACK; normals through "
                              "lighting:"));
        // Stretched to the panel: fixed-fit columns as wide as a long (translated) header ran
        // past the panel's edge.
        if (ImGui::BeginTable("teapot", 4,
                              ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn(tr("grid"));
            ImGui::TableSetupColumn(tr("max |dp|"));
            ImGui::TableSetupColumn(tr("max angle"));
            ImGui::TableSetupColumn(tr("no GL n"));
            ImGui::TableHeadersRow();
            for (int n = 4; n <= 64; n *= 2) {
                auto it = teapotGl_.find(n);
                if (it == teapotGl_.end()) it = teapotGl_.emplace(n, compareTeapotWithGl(n)).first;
                const TeapotGlComparison& c = it->second;
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::Text("%d%s", n, n == s.grid ? " <" : "");
                ImGui::TableNextColumn();
                ImGui::Text("%.1e", c.maxPointError);
                ImGui::TableNextColumn();
                ImGui::Text("%.1e", c.maxNormalAngle);
                ImGui::TableNextColumn();
                ImGui::Text("%d/%d", c.noNormal, c.vertices);
            }
            ImGui::EndTable();
        }
        ImGui::TextWrapped(tr("Angle in degrees where GL has a normal. 'no GL n': grid vertices "
                              "on the poles (8 patches x (grid+1)), where core takes the limit."));
        return;
    }
    ImGui::TextWrapped(
        tr("Speed against error: drawn line strip / triangles against the true shape "
           "(ms: median GL time seen at that grid; visit it with [ ])."));
    float logErr[7], msBars[7];
    int row = 0;
    if (ImGui::BeginTable("grid", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn(tr("grid"));
        ImGui::TableSetupColumn(s.shape == 0 ? "max |r-1|" : "max |r-R|/R");
        ImGui::TableSetupColumn(tr("ms/mesh"));
        ImGui::TableHeadersRow();
        const int keep = s.grid;
        for (int n = 4; n <= kMaxGrid; n *= 2, ++row) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%d%s", n, n == keep ? " <" : "");
            ImGui::TableNextColumn();
            const double e = meshError(n);
            ImGui::Text("%.3g", e);
            logErr[row] = float(std::log10(std::max(e, 1e-300)));
            ImGui::TableNextColumn();
            s.grid = n;
            const double t = medianMs();
            s.grid = keep;
            msBars[row] = float(std::max(t, 0.0));
            if (t >= 0)
                ImGui::Text("%.3f", t);
            else
                ImGui::TextUnformatted("-");
        }
        ImGui::EndTable();
    }
    // The error falls by 4x per doubling of the grid (second order) until the shape's own
    // error is reached: a straight line of slope -log10(4) in log-log, then flat.
    ImGui::TextWrapped(
        tr("log10 of the error against grid 4, 8, ... 256 (one step per doubling):"));
    const float lo = *std::min_element(logErr, logErr + row),
                hi = *std::max_element(logErr, logErr + row);
    ImGui::PlotLines("##err", logErr, row, 0, fmt("%.1f .. %.1f", double(lo), double(hi)).c_str(),
                     std::floor(lo), std::ceil(hi),
                     ImVec2(ImGui::GetContentRegionAvail().x, 70.0f));
    ImGui::TextWrapped(tr("GL ms per mesh at the same grids (0: not visited yet):"));
    ImGui::PlotHistogram("##ms", msBars, row, 0, nullptr, 0.0f, FLT_MAX,
                         ImVec2(ImGui::GetContentRegionAvail().x, 50.0f));
    ImGui::TextWrapped(tr("Full table: docs/bench/bezier.md (bin/bezier_bench)."));
}

// A variant's name in the user's language: the cached variants keep their English names (the
// tests and --help read them), each built from one of these patterns.
std::string variantLabel(const std::string& english) {
    int n = 0, m = 0;
    double k = 0;
    if (std::sscanf(english.c_str(), "%d arcs, fitted k = %lf", &n, &k) == 2)
        return trf("%d arcs, fitted k = %.5f", n, k);
    if (std::sscanf(english.c_str(), "%d arcs, k = 4/3 tan(pi/%d)", &n, &m) == 2)
        return trf("%d arcs, k = 4/3 tan(pi/%d)", n, m);
    if (std::sscanf(english.c_str(), "%d arcs, k = 4/3 (course", &n) == 1)
        return trf("%d arcs, k = 4/3 (course)", n);
    return tr(english.c_str()); // the sphere's nets (N_ where they are named)
}

} // namespace

const std::vector<CircleVariant>& bezierCircleVariants() {
    static const std::vector<CircleVariant> variants = [] {
        std::vector<CircleVariant> vs;
        auto add = [&](std::string name, int n, double k) {
            CircleVariant v{std::move(name), circleArcs(n, k), {}};
            v.error = curvesRadialError(v.arcs, 1.0);
            vs.push_back(std::move(v));
        };
        add("2 arcs, k = 4/3 (course)", 2, circleHandle(2));
        for (int n : {2, 4, 8}) {
            if (n > 2)
                add(std::to_string(n) + " arcs, k = 4/3 tan(pi/" + std::to_string(2 * n) + ")", n,
                    circleHandle(n));
            const double k = fitCircleHandle(n);
            add(std::to_string(n) + " arcs, fitted k = " + fmt("%.5f", k), n, k);
        }
        return vs;
    }();
    return variants;
}

const std::vector<SphereVariant>& bezierSphereVariants() {
    static const std::vector<SphereVariant> variants = [] {
        std::vector<SphereVariant> vs;
        for (int i = 0; i < 2; ++i) {
            SphereVariant v{i == 0 ? N_("course net (lab 6)") : N_("fitted net"),
                            sphereFromNet(i == 0 ? labHemisphereNet() : fitHemisphereNet()),
                            {}};
            v.error = patchesRadialError(v.patches, 0.0);
            vs.push_back(std::move(v));
        }
        return vs;
    }();
    return variants;
}

std::unique_ptr<Lab> makeBezierLab() {
    return std::make_unique<BezierLab>(nullptr);
}
std::unique_ptr<Lab> makeBezierLab(BezierLabState* observe) {
    return std::make_unique<BezierLab>(observe);
}

} // namespace wb

namespace wb {

namespace {
// The feedback comparison's box: glOrtho(±4) around the pot's middle (x -3..3.5,
// y -2..2, z 0..3.15 shifted down by 1.6) onto a 512² viewport.
constexpr double kCmpBox = 4.0, kCmpShift = 1.6;
constexpr int kCmpSize = 512;
} // namespace

TeapotGlComparison compareTeapotWithGl(int n) {
    const std::vector<BezierPatch>& ps = teapotPatches();
    TeapotGlComparison out;
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(-kCmpBox, kCmpBox, -kCmpBox, kCmpBox, -kCmpBox, kCmpBox);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glTranslated(0.0, 0.0, -kCmpShift);
    glViewport(0, 0, kCmpSize, kCmpSize);
    glDepthRange(0.0, 1.0);
    // Normals through lighting (as tests/render/bezier_render_test.cpp): white diffuse
    // material, three directional lights along ±x, ±y, ±z in red, green and blue, no
    // ambient: the colour is max(0, ±n) per channel; + minus - gives n.
    const GLfloat black[] = {0, 0, 0, 1}, white[] = {1, 1, 1, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
    glEnable(GL_LIGHTING);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_MAP2_VERTEX_3);
    std::vector<GLfloat> buf[2];
    for (int pass = 0; pass < 2; ++pass) {
        const float sign = pass == 0 ? 1.0f : -1.0f;
        for (int l = 0; l < 3; ++l) {
            GLfloat dir[4] = {0, 0, 0, 0}, col[4] = {0, 0, 0, 1};
            dir[l] = sign;
            col[l] = 1;
            glLightfv(GLenum(GL_LIGHT0 + l), GL_POSITION, dir);
            glLightfv(GLenum(GL_LIGHT0 + l), GL_DIFFUSE, col);
            glLightfv(GLenum(GL_LIGHT0 + l), GL_SPECULAR, black);
            glLightfv(GLenum(GL_LIGHT0 + l), GL_AMBIENT, black);
            glEnable(GLenum(GL_LIGHT0 + l));
        }
        // 8 floats per point (token, x y z, r g b a).
        buf[pass].assign(ps.size() * size_t(n + 1) * size_t(n + 1) * 8 + 16, 0.0f);
        glFeedbackBuffer(GLsizei(buf[pass].size()), GL_3D_COLOR, buf[pass].data());
        glRenderMode(GL_FEEDBACK);
        for (const BezierPatch& b : ps) {
            const std::vector<float> pts = toFloats(b.points);
            glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, b.orderU, 0.0f, 1.0f, 3 * b.orderU, b.orderV,
                    pts.data());
            glBegin(GL_POINTS);
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i)
                    glEvalCoord2f(float(i) / float(n), float(j) / float(n));
            glEnd();
        }
        const GLint used = glRenderMode(GL_RENDER);
        buf[pass].resize(used > 0 ? size_t(used) : 0);
    }
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopAttrib();

    const size_t want = ps.size() * size_t(n + 1) * size_t(n + 1) * 8;
    if (buf[0].size() != want || buf[1].size() != want) return out; // no context or overflow
    size_t k = 0;
    for (const BezierPatch& b : ps)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i, k += 8) {
                const PatchSample c =
                    evalPatch(b, double(float(i) / float(n)), double(float(j) / float(n)));
                const GLfloat* f = &buf[0][k];
                const GLfloat* g = &buf[1][k];
                // Window x = (x_ndc + 1)·W/2; depth = (z_ndc + 1)/2 with z_ndc = -z/box.
                const glm::dvec3 p((f[1] / (kCmpSize / 2.0) - 1.0) * kCmpBox,
                                   (f[2] / (kCmpSize / 2.0) - 1.0) * kCmpBox,
                                   -(2.0 * f[3] - 1.0) * kCmpBox + kCmpShift);
                const glm::dvec3 nGl(double(f[4]) - g[4], double(f[5]) - g[5], double(f[6]) - g[6]);
                out.maxPointError = std::max(out.maxPointError, glm::length(p - c.point));
                ++out.vertices;
                out.coreLimit += c.normalKind != 0;
                if (glm::length(nGl) < 0.5) { // a zero normal lights nothing: (0,0,0) both ways
                    ++out.noNormal;
                    continue;
                }
                const double cosA = std::clamp(glm::dot(glm::normalize(nGl), c.normal), -1.0, 1.0);
                out.maxNormalAngle = std::max(out.maxNormalAngle, std::acos(cosA) * 180.0 / kPi);
            }
    return out;
}

} // namespace wb
