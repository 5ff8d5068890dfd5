#include "stencil_lab.h"

#include "exercise_view.h"

#include "core/i18n.h"

#include "common/gl.h"
#include "common/gl_util.h"
#include "core/affine.h"
#include "core/mesh.h"

#include "core/i18n.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

const wb::ex::LabExercises& wbExercises_lab05();

namespace wb {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStepW = kStepWidth, kStepH = kStepHeight, kStairZ = kStairHalfDepth;
const glm::dvec3 kLight = kStencilLight; // also drawn as a small marker

using Quad = std::array<glm::dvec3, 4>; // counter-clockwise seen from the front

// A planar part of the scene that can receive the shadow: its plane (normal towards the
// side it is seen and lit from), its quads, its colour and its stencil value.
struct Receiver {
    Plane plane;
    std::vector<Quad> quads;
    glm::vec3 colour;
    uint8_t stencil;
    bool stairsCast; // the stairs also cast their shadow here (floor, wall); on themselves they
                     // cannot
};

struct Triangle {
    glm::dvec3 p[3], n[3];
};

void drawQuads(const std::vector<Quad>& quads, const glm::dvec3& normal) {
    glBegin(GL_QUADS);
    glNormal3dv(glm::value_ptr(normal));
    for (const Quad& q : quads)
        for (const glm::dvec3& v : q)
            glVertex3dv(glm::value_ptr(v));
    glEnd();
}

// The part of triangle `t` on the positive side of `plane` (Sutherland-Hodgman against one
// plane): 0, 3 or 4 vertices.
std::vector<glm::dvec3> clipToPositive(const Triangle& t, const Plane& plane) {
    std::vector<glm::dvec3> out;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 &a = t.p[i], &b = t.p[(i + 1) % 3];
        const double da = glm::dot(plane.n, a) + plane.d, db = glm::dot(plane.n, b) + plane.d;
        if (da >= 0) out.push_back(a);
        if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// The lab's own answers to §2.5 tasks ③ and ④ (core's matrices). A student handout cuts
// these bodies (labs/handout_strip.txt): there they give nullopt and the lab draws only the
// student's reflection and shadows.
std::optional<glm::dmat4> labReflection(const Plane& plane) {
    return mirrorPlane(plane);
}
std::optional<glm::dmat4> labShadow(const Plane& plane, const glm::dvec3& light) {
    return shadowPoint(plane, light);
}

// An octahedron of radius r with flat normals: the handout's stand-in for the torus (no
// lab's answer; its shadow has no hole).
[[maybe_unused]] Mesh octahedron(double r) {
    Mesh m;
    const glm::dvec3 ax[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int oct = 0; oct < 8; ++oct) {
        const glm::dvec3 a = ax[0] * ((oct & 1) ? -r : r), b = ax[1] * ((oct & 2) ? -r : r),
                         c = ax[2] * ((oct & 4) ? -r : r);
        // Counter-clockwise from outside: (b - a) x (c - a) along a + b + c.
        const bool flip = glm::dot(glm::cross(b - a, c - a), a + b + c) < 0;
        const glm::dvec3 n = glm::normalize(a + b + c);
        for (const glm::dvec3& p : {a, flip ? c : b, flip ? b : c}) {
            m.indices.push_back(uint32_t(m.positions.size()));
            m.positions.push_back(p);
            m.normals.push_back(n);
        }
    }
    return m;
}

// The object on the stairs: the torus (core's, lab 04's task ④). A handout has no torus
// (its vertices are that answer): there the object is the octahedron above.
Mesh labObject() {
    return makeTorus(kTorusMajor, kTorusMinor, 40, 20);
}

// Palette for the raw stencil view: one colour per receiver, the mirrors' colours mixed in
// where their bits are set, everything halved where the shadow bit is set.
void stencilColour(uint8_t v, uint8_t* rgb) {
    static const uint8_t base[][3] = {{0, 0, 0},      {0, 0, 0},       {0, 0, 0},
                                      {150, 110, 60}, {120, 140, 200}, {200, 200, 80},
                                      {90, 220, 90},  {220, 140, 40}};
    const uint8_t receiver = v & kReceiverMask;
    int c[3] = {0, 0, 0};
    if (receiver > 0) {
        const uint8_t* b = base[receiver < 8 ? receiver : 6 + (receiver % 2)];
        const int lighter = receiver >= 8 && (receiver / 2) % 2 == 1 ? 60 : 0; // alternate steps
        for (int k = 0; k < 3; ++k)
            c[k] = std::min(255, b[k] + lighter);
    }
    const int mirror[3] = {(v & kStencilRectMirror) ? 230 : 60, (v & kStencilRectMirror) ? 60 : 200,
                           (v & kStencilRectMirror) ? 60 : 230};
    for (int k = 0; k < 3; ++k) {
        int x = c[k];
        if (v & kMirrorMask) x = receiver ? (x + mirror[k]) / 2 : mirror[k];
        if (v & kShadowBit) x /= 2;
        rgb[k] = uint8_t(x);
    }
}

class StencilLab : public Lab {
  public:
    explicit StencilLab(StencilLabState* s) : s_(s ? s : &own_), ex_(wbExercises_lab05(), 'E') {}
    bool busy() const override { return ex_.busy(); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }
    std::string title() const override { return tr("Lab 05 - stencil buffer"); }
    std::vector<KeyHelp> keys() const override {
        return {{"s", tr("shadow on the stairs on/off")},
                {"n", tr("naive shadow without stencil (leaks, double blending)")},
                {"r", tr("rectangular mirror on/off")},
                {"e", tr("elliptical mirror on/off")},
                {"m", tr("show the raw stencil buffer (scene dimmed where 0)")},
                {tr("Left/Right"), tr("move the object along x")},
                {tr("Up/Down"), tr("move the object along z")},
                {tr("PageUp/PageDown"), tr("move the object up/down")},
                ex_.keyHelp()};
    }

    void init() override { torus_ = labObject(); }

    void draw(const View& view) override {
        ex_.poll(!view.headless);
        buildScene();
        s_->shadowTriangles = 0;
        glViewport(0, 0, view.width, view.height);
        glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        setPerspective(view, 40.0, 0.5, 60.0);
        glLoadIdentity();
        glTranslated(0.0, 0.0, -12.0);
        glRotated(15.0, 1.0, 0.0, 0.0); // a little from above, then the mouse orbit
        applyOrbit(view);
        glTranslated(0.0, -2.0, 0.0);
        recordOutlines(view);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_CULL_FACE); // wrong front faces in the reflection would show as holes
        glEnable(GL_NORMALIZE);

        if (s_->rectMirror || s_->ellipseMirror) drawMirrors();

        // 4th pass: the real scene, no stencil test.
        drawScene();

        if (s_->shadow) {
            if (s_->naiveShadow)
                drawNaiveShadow();
            else
                drawStencilShadow(0);
        }

        // The stencil as the frame leaves it: for the tests, and for `m`.
        s_->width = view.width;
        s_->height = view.height;
        s_->stencil.assign(size_t(view.width) * size_t(view.height), 0);
        std::vector<uint8_t> rows(s_->stencil.size());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, view.width, view.height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE,
                     rows.data());
        for (int y = 0; y < view.height; ++y)
            std::copy_n(&rows[size_t(view.height - 1 - y) * size_t(view.width)], view.width,
                        &s_->stencil[size_t(y) * size_t(view.width)]);
        if (s_->showMask) drawMask(view, rows);
        // Your answers are in the picture (E): the reference's elliptical mirror as a ghost.
        if (ex_.on() && s_->ellipseMirror && !s_->showMask) drawEllipseGhost(referenceEllipse());
    }

    bool key(int k) override {
        const double step = 0.1;
        if (ex_.key(k)) return true; // E: the exercise mode's usual e is the elliptical mirror
        switch (k) {
        case 's':
            s_->shadow = !s_->shadow;
            return true;
        case 'n':
            s_->naiveShadow = !s_->naiveShadow;
            return true;
        case 'r':
            s_->rectMirror = !s_->rectMirror;
            return true;
        case 'e':
            s_->ellipseMirror = !s_->ellipseMirror;
            return true;
        case 'm':
            s_->showMask = !s_->showMask;
            return true;
        case kKeyLeft:
            s_->object.x -= step;
            break;
        case kKeyRight:
            s_->object.x += step;
            break;
        case kKeyUp:
            s_->object.z -= step;
            break;
        case kKeyDown:
            s_->object.z += step;
            break;
        case kKeyPageUp:
            s_->object.y += step;
            break;
        case kKeyPageDown:
            s_->object.y -= step;
            break;
        default:
            return false;
        }
        clampObject();
        return true;
    }

    void gui() override {
        ex_.gui();
        ImGui::Checkbox(tr("shadow (s)"), &s_->shadow);
        ImGui::Checkbox(tr("naive shadow, no stencil (n)"), &s_->naiveShadow);
        ImGui::Checkbox(tr("rectangular mirror (r)"), &s_->rectMirror);
        ImGui::Checkbox(tr("elliptical mirror (e)"), &s_->ellipseMirror);
        ImGui::Checkbox(tr("raw stencil buffer (m)"), &s_->showMask);
        float p[3] = {float(s_->object.x), float(s_->object.y), float(s_->object.z)};
        // The label above its widget: beside a three-field drag it would not fit the panel.
        ImGui::TextUnformatted(tr("object x, y, z (arrows, PgUp/PgDn)"));
        ImGui::SetNextItemWidth(-1.0f);
        if (ImGui::DragFloat3("##object", p, 0.02f)) {
            s_->object = glm::dvec3(p[0], p[1], p[2]);
            clampObject();
        }
        ImGui::SliderInt(tr("steps"), &s_->steps, 1, 6);
        ImGui::Text(tr("shadow: %d clipped triangles"), s_->shadowTriangles);
        ImGui::TextWrapped(
            tr("Stencil bits 0-4: receiver (3 floor, 4 wall, 5 stairs' side, 6+2i "
               "tread i, 7+2i riser i); +32 rectangular mirror, +64 elliptical "
               "mirror (mixed in red / cyan in the mask view); +128 where the shadow "
               "was blended (darker)."));
    }

  private:
    // The object stays below the light and inside the room (a point beyond the light would
    // project through w < 0, see core/affine.h).
    void clampObject() {
        s_->object.x = std::clamp(s_->object.x, -3.0, 3.5);
        s_->object.y = std::clamp(s_->object.y, 0.5, 4.0);
        s_->object.z = std::clamp(s_->object.z, -2.0, 2.5);
    }

    void buildScene() {
        receivers_.clear();
        const int n = std::clamp(s_->steps, 1, 6);
        receivers_.push_back({{{0, 1, 0}, 0.0},
                              {{glm::dvec3(-5, 0, 4), {5, 0, 4}, {5, 0, kWallZ}, {-5, 0, kWallZ}}},
                              {0.75f, 0.65f, 0.5f},
                              kStencilFloor,
                              true});
        receivers_.push_back(
            {{{0, 0, 1}, -kWallZ},
             {{glm::dvec3(-5, 0, kWallZ), {5, 0, kWallZ}, {5, 5, kWallZ}, {-5, 5, kWallZ}}},
             {0.6f, 0.7f, 0.8f},
             kStencilBackWall,
             true});
        Receiver front{{{0, 0, 1}, -kStairZ}, {}, {0.55f, 0.55f, 0.6f}, kStencilStairFront, false};
        stairBack_.clear();
        for (int i = 0; i < n; ++i) {
            const double x0 = kStairX0 + i * kStepW, x1 = x0 + kStepW, top = (i + 1) * kStepH;
            front.quads.push_back({glm::dvec3(x0, 0, kStairZ),
                                   {x1, 0, kStairZ},
                                   {x1, top, kStairZ},
                                   {x0, top, kStairZ}});
            stairBack_.push_back({glm::dvec3(x1, 0, -kStairZ),
                                  {x0, 0, -kStairZ},
                                  {x0, top, -kStairZ},
                                  {x1, top, -kStairZ}});
            receivers_.push_back({{{0, 1, 0}, -top},
                                  {{glm::dvec3(x0, top, kStairZ),
                                    {x1, top, kStairZ},
                                    {x1, top, -kStairZ},
                                    {x0, top, -kStairZ}}},
                                  {0.85f, 0.85f, 0.8f},
                                  uint8_t(kStencilFirstStep + 2 * i),
                                  false});
            receivers_.push_back({{{-1, 0, 0}, x0},
                                  {{glm::dvec3(x0, top - kStepH, kStairZ),
                                    {x0, top, kStairZ},
                                    {x0, top, -kStairZ},
                                    {x0, top - kStepH, -kStairZ}}},
                                  {0.7f, 0.7f, 0.68f},
                                  uint8_t(kStencilFirstStep + 2 * i + 1),
                                  false});
        }
        receivers_.push_back(front);
        const double xe = kStairX0 + n * kStepW, h = n * kStepH;
        stairEnd_ = {
            glm::dvec3(xe, 0, kStairZ), {xe, 0, -kStairZ}, {xe, h, -kStairZ}, {xe, h, kStairZ}};

        // The stairs as triangles, for their shadow on the floor and the wall.
        stairTris_.clear();
        auto addQuad = [&](const Quad& q) {
            stairTris_.push_back({{q[0], q[1], q[2]}, {}});
            stairTris_.push_back({{q[0], q[2], q[3]}, {}});
        };
        for (const Receiver& r : receivers_)
            if (!r.stairsCast)
                for (const Quad& q : r.quads)
                    addQuad(q);
        for (const Quad& q : stairBack_)
            addQuad(q);
        addQuad(stairEnd_);

        // The torus in world space, tilted so its hole shows in the shadow.
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), s_->object);
        m = glm::rotate(m, glm::radians(60.0), glm::dvec3(1, 0, 0.3));
        s_->objectModel = m;
        const glm::dmat3 nm = glm::dmat3(m);
        objectTris_.clear();
        for (size_t k = 0; k + 2 < torus_.indices.size(); k += 3) {
            Triangle t;
            for (int j = 0; j < 3; ++j) {
                const uint32_t idx = torus_.indices[k + size_t(j)];
                t.p[j] = glm::dvec3(m * glm::dvec4(torus_.positions[idx], 1.0));
                t.n[j] = nm * torus_.normals[idx];
            }
            objectTris_.push_back(t);
        }
    }

    void setLight() {
        const GLfloat pos[] = {float(kLight.x), float(kLight.y), float(kLight.z), 1.0f};
        const GLfloat white[] = {0.9f, 0.9f, 0.9f, 1}, ambient[] = {0.3f, 0.3f, 0.3f, 1};
        glLightfv(GL_LIGHT0, GL_POSITION,
                  pos); // under the current modelview: reflected in a mirror
        glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    }

    void drawObject() {
        glColor3f(0.85f, 0.2f, 0.15f);
        glBegin(GL_TRIANGLES);
        for (const Triangle& t : objectTris_)
            for (int j = 0; j < 3; ++j) {
                glNormal3dv(glm::value_ptr(t.n[j]));
                glVertex3dv(glm::value_ptr(t.p[j]));
            }
        glEnd();
    }

    // The room, the stairs, the object and the light marker under the current modelview.
    void drawScene() {
        setLight();
        for (const Receiver& r : receivers_) {
            glColor3fv(glm::value_ptr(r.colour));
            drawQuads(r.quads, r.plane.n);
        }
        glColor3f(0.55f, 0.55f, 0.6f);
        drawQuads(stairBack_, {0, 0, -1});
        drawQuads({stairEnd_}, {1, 0, 0});
        drawObject();
        glDisable(GL_LIGHTING);
        glColor3f(1.0f, 0.95f, 0.3f); // the light itself: a small unlit diamond
        glPushMatrix();
        glTranslated(kLight.x, kLight.y, kLight.z);
        glBegin(GL_TRIANGLES);
        const double r = 0.12;
        const glm::dvec3 tip[2] = {{0, r, 0}, {0, -r, 0}};
        const glm::dvec3 ring[4] = {{r, 0, 0}, {0, 0, -r}, {-r, 0, 0}, {0, 0, r}};
        for (int t = 0; t < 2; ++t)
            for (int i = 0; i < 4; ++i) {
                const glm::dvec3 &a = ring[i], &b = ring[(i + 1) % 4];
                glVertex3dv(glm::value_ptr(tip[t]));
                glVertex3dv(glm::value_ptr(t == 0 ? b : a));
                glVertex3dv(glm::value_ptr(t == 0 ? a : b));
            }
        glEnd();
        glPopMatrix();
    }

    struct Mirror {
        std::vector<glm::dvec3> outline; // convex, counter-clockwise seen from the room (+z)
        uint8_t stencil;
    };

    std::vector<Mirror> mirrors() const {
        std::vector<Mirror> out;
        if (s_->rectMirror) out.push_back({rectangle(), kStencilRectMirror});
        if (s_->ellipseMirror) {
            std::vector<glm::dvec3> e = ellipseOutline(); // empty in a handout until yours is done
            if (e.size() >= 3) out.push_back({std::move(e), kStencilEllipseMirror});
        }
        return out;
    }

    static std::vector<glm::dvec3> rectangle() {
        const double* r = kRectMirror;
        return {{r[0], r[1], kMirrorZ},
                {r[2], r[1], kMirrorZ},
                {r[2], r[3], kMirrorZ},
                {r[0], r[3], kMirrorZ}};
    }

    // The elliptical mirror: your outline under the exercise mode (E), else the lab's.
    std::vector<glm::dvec3> ellipseOutline() const {
        const double* m = kEllipseMirror;
        return exerciseEllipse(ex_, {m[0], m[1]}, m[2], m[3], kMirrorZ, 72, ellipse());
    }
    static std::vector<glm::dvec3> referenceEllipse() { return ellipse(); }

    static std::vector<glm::dvec3> ellipse() {
        std::vector<glm::dvec3> e;
        const int segments = 72;
        for (int i = 0; i < segments; ++i) {
            const double a = 2.0 * kPi * i / segments;
            const double* m = kEllipseMirror;
            e.push_back({m[0] + m[2] * std::cos(a), m[1] + m[3] * std::sin(a), kMirrorZ});
        }
        return e;
    }

    static void drawPolygon(const std::vector<glm::dvec3>& outline) {
        glBegin(GL_POLYGON);
        glNormal3d(0, 0, 1);
        for (const glm::dvec3& v : outline)
            glVertex3dv(glm::value_ptr(v));
        glEnd();
    }

    void recordOutlines(const View& view) {
        GLdouble mv[16], pr[16];
        GLint vp[4];
        glGetDoublev(GL_MODELVIEW_MATRIX, mv);
        glGetDoublev(GL_PROJECTION_MATRIX, pr);
        glGetIntegerv(GL_VIEWPORT, vp);
        s_->modelview = glm::make_mat4(mv);
        s_->projection = glm::make_mat4(pr);
        auto project = [&](const std::vector<glm::dvec3>& pts) {
            std::vector<glm::dvec2> out;
            for (const glm::dvec3& p : pts) {
                GLdouble x = 0, y = 0, z = 0;
                gluProject(p.x, p.y, p.z, mv, pr, vp, &x, &y, &z);
                out.push_back({x, double(view.height) - y});
            }
            return out;
        };
        s_->rectOutline = project(rectangle());
        s_->ellipseOutline = project(ellipseOutline());
    }

    void drawMirrors() {
        const std::vector<Mirror> ms = mirrors();
        // 1st pass: mark each mirror's pixels in the stencil with its own value; no colour,
        // no depth written (the scene is not drawn yet, so the whole mirror is marked).
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        for (const Mirror& m : ms) {
            glStencilFunc(GL_ALWAYS, m.stencil, 0xFF);
            drawPolygon(m.outline);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_TRUE);

        // 2nd pass: the scene reflected through the mirror plane, only where the stencil
        // holds that mirror's value. The reflection reverses orientation, so front faces
        // are clockwise; the light is set inside drawScene() under the mirror matrix, so
        // it is reflected too. A clip plane drops what lies behind the mirror (the wall).
        // Then (b, c) the shadows of the reflected scene: the 5th and 6th passes below,
        // under the mirror matrix, confined to this mirror by its stencil bits.
        const Plane mirrorPlaneEq{{0, 0, 1}, -kMirrorZ};
        const GLdouble behind[4] = {0, 0, -1, kMirrorZ}; // keeps z <= kMirrorZ (after reflecting)
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        for (const Mirror& m : ms) {
            glStencilFunc(GL_EQUAL, m.stencil, 0xFF);
            glClipPlane(GL_CLIP_PLANE0, behind); // in world coordinates: modelview is the camera
            glEnable(GL_CLIP_PLANE0);
            const std::optional<glm::dmat4> reflection =
                exerciseReflection(ex_, mirrorPlaneEq, labReflection(mirrorPlaneEq));
            if (!reflection) { // a student handout before 05.reflection is done: no image
                glDisable(GL_CLIP_PLANE0);
                continue;
            }
            glPushMatrix();
            glMultMatrixd(glm::value_ptr(*reflection));
            glFrontFace(GL_CW);
            drawScene();
            if (s_->shadow && !s_->naiveShadow) {
                drawStencilShadow(m.stencil);
                glEnable(GL_STENCIL_TEST);
                glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            }
            glFrontFace(GL_CCW);
            glPopMatrix();
            glDisable(GL_CLIP_PLANE0);
        }

        // 3rd pass: the mirror surface blended on top (a faint blue glass), writing its
        // depth so the real scene drawn next is hidden behind it exactly as the wall is.
        glDisable(GL_LIGHTING);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glColor4f(0.75f, 0.85f, 1.0f, 0.2f);
        for (const Mirror& m : ms) {
            glStencilFunc(GL_EQUAL, m.stencil, kMirrorMask);
            drawPolygon(m.outline);
        }
        glDisable(GL_BLEND);
        glDisable(GL_STENCIL_TEST);
    }

    // 5th and 6th passes; with mirrorBits != 0 they run inside that mirror's reflection
    // (2nd pass, b and c), under the mirror matrix, keeping the mirror's bits in the stencil.
    void drawStencilShadow(uint8_t mirrorBits) {
        // 5th pass: mark the visible pixels of every receiver with its own value (depth test
        // LEQUAL against the scene just drawn: hidden parts stay unmarked), no colour/depth.
        // In a reflection only pixels of that mirror are marked, and only the receiver bits.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glDisable(GL_LIGHTING);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(mirrorBits ? kReceiverMask : 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        for (const Receiver& r : receivers_) {
            glStencilFunc(mirrorBits ? GL_EQUAL : GL_ALWAYS, mirrorBits | r.stencil, kMirrorMask);
            drawQuads(r.quads, r.plane.n);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

        // 6th pass: per receiver, the casters flattened onto its plane by the point-light
        // shadow matrix, drawn only where the stencil holds that receiver's value. The first
        // blended fragment flips kShadowBit (INVERT with write mask 0x80), so overlapping
        // shadow triangles fail the EQUAL test afterwards: every pixel is darkened once.
        // No depth test: the stencil already holds exactly the visible receiver pixels.
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE); // flattened triangles may face either way
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glColor4f(0.0f, 0.0f, 0.0f, kShadowAlpha);
        glStencilMask(kShadowBit);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
        for (const Receiver& r : receivers_) {
            const double lightSide = glm::dot(r.plane.n, kLight) + r.plane.d;
            if (lightSide <= 0) continue; // the light does not reach this face at all
            glStencilFunc(GL_EQUAL, mirrorBits | r.stencil, 0xFF);
            if (shadowMayReach(r)) drawFlattened(r.plane, objectTris_);
            if (r.stairsCast) drawFlattened(r.plane, stairTris_);
        }
        glStencilMask(0xFF);
        glDisable(GL_BLEND);
        glDisable(GL_STENCIL_TEST);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_CULL_FACE);
        glDepthMask(GL_TRUE);
    }

    // The same projection with no stencil: depth-tested with a polygon offset, so the
    // shadow spills past each step's edge and overlapping triangles darken twice.
    void drawNaiveShadow() {
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(-1.0f, -4.0f);
        glDepthMask(GL_FALSE);
        glColor4f(0.0f, 0.0f, 0.0f, kShadowAlpha);
        for (const Receiver& r : receivers_)
            if (glm::dot(r.plane.n, kLight) + r.plane.d > 0) {
                drawFlattened(r.plane, objectTris_);
                if (r.stairsCast) drawFlattened(r.plane, stairTris_);
            }
        glDepthMask(GL_TRUE);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_BLEND);
        glEnable(GL_CULL_FACE);
    }

    // False when the torus' shadow on r's plane certainly misses r's quads: the corners of
    // the torus' bounding box, flattened by the shadow matrix, bound its shadow (a convex
    // hull maps to a convex hull while every corner is strictly between light and plane).
    // Only a speed-up: when in doubt it says true.
    bool shadowMayReach(const Receiver& r) const {
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const Triangle& t : objectTris_)
            for (const glm::dvec3& p : t.p)
                lo = glm::min(lo, p), hi = glm::max(hi, p);
        const std::optional<glm::dmat4> shadow = labShadow(r.plane, kLight);
        if (!shadow) return true;
        const glm::dmat4 m = *shadow;
        const double lightSide = glm::dot(r.plane.n, kLight) + r.plane.d;
        glm::dvec3 slo(1e300), shi(-1e300);
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 p((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
            const double side = glm::dot(r.plane.n, p) + r.plane.d;
            if (!(side > 0.0 && side < lightSide)) return true; // straddles: no cheap bound
            const glm::dvec4 q = m * glm::dvec4(p, 1.0);
            if (!(q.w > 0.0)) return true;
            slo = glm::min(slo, glm::dvec3(q) / q.w);
            shi = glm::max(shi, glm::dvec3(q) / q.w);
        }
        const double eps = 1e-6; // the receiver is flat: its box has zero thickness along n
        for (const Quad& quad : r.quads) {
            glm::dvec3 qlo(1e300), qhi(-1e300);
            for (const glm::dvec3& v : quad)
                qlo = glm::min(qlo, v), qhi = glm::max(qhi, v);
            if (glm::all(glm::lessThanEqual(slo, qhi + eps)) &&
                glm::all(glm::lessThanEqual(qlo, shi + eps)))
                return true;
        }
        return false;
    }

    // A caster's triangles, clipped to the light's side of `plane` (the part beyond the
    // plane casts nothing on it), drawn through shadowPoint(plane, light).
    void drawFlattened(const Plane& plane, const std::vector<Triangle>& caster) {
        const std::optional<glm::dmat4> shadow =
            exerciseShadow(ex_, plane, kLight, labShadow(plane, kLight));
        if (!shadow) return; // a student handout before 05.shadow is done: no shadow
        glPushMatrix();
        glMultMatrixd(glm::value_ptr(*shadow));
        glBegin(GL_TRIANGLES);
        for (const Triangle& t : caster) {
            const std::vector<glm::dvec3> poly = clipToPositive(t, plane);
            for (size_t i = 1; i + 1 < poly.size(); ++i) {
                glVertex3dv(glm::value_ptr(poly[0]));
                glVertex3dv(glm::value_ptr(poly[i]));
                glVertex3dv(glm::value_ptr(poly[i + 1]));
                ++s_->shadowTriangles;
            }
        }
        glEnd();
        glPopMatrix();
    }

    // `m`: the stencil values as colours over the whole window.
    void drawMask(const View& view, const std::vector<uint8_t>& rows) {
        // Where the stencil is 0 the scene shows through at a quarter of its brightness, for
        // orientation (and so that a stencil that is all 0 is not a black window).
        std::vector<uint8_t> rgb(rows.size() * 3);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, view.width, view.height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        for (size_t i = 0; i < rows.size(); ++i) {
            if (rows[i] == 0)
                for (int k = 0; k < 3; ++k)
                    rgb[i * 3 + size_t(k)] /= 4;
            else
                stencilColour(rows[i], &rgb[i * 3]);
        }
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_LIGHTING);
        glDisable(GL_BLEND);
        glWindowPos2i(0, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glDrawPixels(view.width, view.height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        glEnable(GL_DEPTH_TEST);
    }

    StencilLabState own_;
    StencilLabState* s_;
    ex::ExerciseMode ex_; // E: your matrices and outline (exercises.cpp), the reference as a ghost
    Mesh torus_;
    std::vector<Receiver> receivers_;
    std::vector<Quad> stairBack_;
    Quad stairEnd_{};
    std::vector<Triangle> objectTris_, stairTris_;
};

} // namespace

std::unique_ptr<Lab> makeStencilLab() {
    return std::make_unique<StencilLab>(nullptr);
}

std::unique_ptr<Lab> makeStencilLab(StencilLabState* observe) {
    return std::make_unique<StencilLab>(observe);
}

} // namespace wb
