#include "transforms_lab.h"

#include "exercise_view.h"

#include "core/i18n.h"

#include "common/gl.h"
#include "common/gl_util.h"
#include "core/teapot.h"

#include "common/panel.h"
#include "core/i18n.h"

#include <glm/glm.hpp>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>

const wb::ex::LabExercises& wbExercises_lab03();

namespace wb {

std::vector<TableObjects> placeObjects(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.05f, 0.05f), depth(-0.2f, 0.2f),
        angle(0.0f, 360.0f);
    std::vector<TableObjects> out;
    for (int t = 0; t < 12; ++t) {
        // Three slots across the table top, dealt to the three objects in random order,
        // so they never overlap; each is jittered and turned at random inside its slot.
        int slot[3] = {0, 1, 2};
        std::shuffle(slot, slot + 3, rng);
        auto x = [&](int s) { return -0.5f + 0.5f * float(s) + jitter(rng); };
        TableObjects o{};
        o.bookX = x(slot[0]);
        o.bookZ = depth(rng);
        o.bookAngle = angle(rng);
        o.penX = x(slot[1]);
        o.penZ = depth(rng);
        o.penAngle = angle(rng);
        o.potX = x(slot[2]);
        o.potZ = depth(rng);
        o.potAngle = angle(rng);
        out.push_back(o);
    }
    return out;
}

namespace {
// The next value of `grid` (ascending) strictly beyond `v` in direction dir within
// [lo, hi]; `v` itself when there is none. The relative tolerance 1e-4 keeps a value
// dragged in the panel a hair off a grid point from counting as a step.
float stepThrough(const std::vector<float>& grid, float v, float lo, float hi, int dir) {
    if (dir > 0) {
        for (float g : grid)
            if (g > v * 1.0001f && g >= lo && g <= hi) return g;
    } else {
        for (auto it = grid.rbegin(); it != grid.rend(); ++it)
            if (*it < v * 0.9999f && *it >= lo && *it <= hi) return *it;
    }
    return v;
}
} // namespace

const std::vector<float>& nearSteps() {
    static const std::vector<float> grid = [] {
        std::vector<float> g = {0.1f, 0.25f}; // below the first step: depth-precision values
        for (int k = 1; float(k) * kNearStep <= kNearMax; ++k)
            g.push_back(float(k) * kNearStep); // k·0.5 is exact in float
        return g;
    }();
    return grid;
}

const std::vector<float>& farSteps() {
    static const std::vector<float> grid = [] {
        std::vector<float> g;
        for (int k = 1; float(k) * kFarStep <= kFarMax; ++k)
            g.push_back(float(k) * kFarStep);
        return g;
    }();
    return grid;
}

float stepNear(float zNear, float zFar, int dir) {
    return stepThrough(nearSteps(), zNear, 0.0f, zFar - kNearStep, dir);
}

float stepFar(float zFar, float zNear, int dir) {
    return stepThrough(farSteps(), zFar, zNear + kNearStep, kFarMax, dir);
}

namespace {

// One triangle with per-vertex normals, wound counter-clockwise as seen from the side
// the normals point to (checked against the geometric normal, so generators need not care).
void triangle(glm::vec3 a, glm::vec3 na, glm::vec3 b, glm::vec3 nb, glm::vec3 c, glm::vec3 nc) {
    if (glm::dot(glm::cross(b - a, c - a), na + nb + nc) < 0) {
        std::swap(b, c);
        std::swap(nb, nc);
    }
    glNormal3f(na.x, na.y, na.z);
    glVertex3f(a.x, a.y, a.z);
    glNormal3f(nb.x, nb.y, nb.z);
    glVertex3f(b.x, b.y, b.z);
    glNormal3f(nc.x, nc.y, nc.z);
    glVertex3f(c.x, c.y, c.z);
}

// A unit cube centred at the origin with face normals.
void drawUnitBox() {
    static const float f[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    glBegin(GL_TRIANGLES);
    for (const auto& n3 : f) {
        glm::vec3 n(n3[0], n3[1], n3[2]);
        glm::vec3 u = std::abs(n.x) > 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        glm::vec3 v = glm::cross(n, u);
        glm::vec3 c = 0.5f * n;
        glm::vec3 p[4] = {c - 0.5f * u - 0.5f * v, c + 0.5f * u - 0.5f * v, c + 0.5f * u + 0.5f * v,
                          c - 0.5f * u + 0.5f * v};
        triangle(p[0], n, p[1], n, p[2], n);
        triangle(p[0], n, p[2], n, p[3], n);
    }
    glEnd();
}

// A surface of revolution about +y from a profile of (radius, height) points.
void drawLathe(const std::vector<glm::vec2>& profile, int slices) {
    const size_t m = profile.size();
    std::vector<glm::vec2> normal(m);
    for (size_t i = 0; i < m; ++i) { // profile normal from the neighbours' chord, outward
        glm::vec2 d = profile[std::min(i + 1, m - 1)] - profile[i > 0 ? i - 1 : 0];
        glm::vec2 n(d.y, -d.x);
        normal[i] = glm::length(n) > 0 ? glm::normalize(n) : glm::vec2(0, 1);
    }
    auto at = [&](size_t i, int j, glm::vec3& p, glm::vec3& n) {
        float a = 2.0f * float(M_PI) * float(j) / float(slices);
        float c = std::cos(a), s = std::sin(a);
        p = {profile[i].x * c, profile[i].y, -profile[i].x * s};
        n = {normal[i].x * c, normal[i].y, -normal[i].x * s};
    };
    glBegin(GL_TRIANGLES);
    for (size_t i = 0; i + 1 < m; ++i)
        for (int j = 0; j < slices; ++j) {
            glm::vec3 p00, p01, p10, p11, n00, n01, n10, n11;
            at(i, j, p00, n00);
            at(i, j + 1, p01, n01);
            at(i + 1, j, p10, n10);
            at(i + 1, j + 1, p11, n11);
            if (profile[i].x > 0) triangle(p00, n00, p10, n10, p11, n11);
            if (profile[i + 1].x > 0) triangle(p00, n00, p11, n11, p01, n01);
        }
    glEnd();
}

// A closed cylinder of radius 1 and height 1 along +y from the origin.
void drawCylinder(int sides) {
    drawLathe({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}}, sides);
}

// Newell's Utah teapot from core (32 Bezier patches, 6×6 grid each, normals from
// de Casteljau with the pole limits), as float arrays for glDrawElements; built once.
struct TeapotArrays {
    std::vector<float> positions, normals;
    std::vector<GLuint> indices;
};
const TeapotArrays& teapotArrays() {
    static const TeapotArrays arrays = [] {
        const Mesh m = teapotMesh(6);
        TeapotArrays t;
        for (size_t i = 0; i < m.positions.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                t.positions.push_back(float(m.positions[i][c]));
                t.normals.push_back(float(m.normals[i][c]));
            }
        t.indices.assign(m.indices.begin(), m.indices.end());
        return t;
    }();
    return arrays;
}

// The teapot standing on the origin, height 0.85, spout along +x (the lab asks for
// glutSolidTeapot, which needs GLUT; this is the same shape from core's patches).
void drawTeapot() {
    const TeapotArrays& t = teapotArrays();
    glPushMatrix();
    const float s = 0.85f / float(kTeapotHeight);
    glScalef(s, s, s);
    glRotatef(-90.0f, 1, 0, 0); // the data's z up onto the scene's y up (y goes to -z)
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, t.positions.data());
    glNormalPointer(GL_FLOAT, 0, t.normals.data());
    glDrawElements(GL_TRIANGLES, GLsizei(t.indices.size()), GL_UNSIGNED_INT, t.indices.data());
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glPopMatrix();
}

// A closed book: a box 0.24 × 0.05 × 0.32 on the origin, pages lighter than the cover.
void drawBook(float r, float g, float b) {
    glColor3f(r, g, b);
    glPushMatrix();
    glTranslatef(0, 0.025f, 0);
    glScalef(0.24f, 0.05f, 0.32f);
    drawUnitBox();
    glPopMatrix();
    glColor3f(0.92f, 0.9f, 0.82f); // the page block, set in from the cover on three sides
    glPushMatrix();
    glTranslatef(0.006f, 0.025f, 0);
    glScalef(0.232f, 0.036f, 0.3f);
    drawUnitBox();
    glPopMatrix();
}

// A pen lying along x: a long thin cylinder with a conical tip.
void drawPen() {
    glColor3f(0.1f, 0.2f, 0.7f);
    glPushMatrix();
    glTranslatef(-0.07f, 0.008f, 0);
    glRotatef(-90, 0, 0, 1); // the cylinder's +y axis onto +x
    glScalef(0.008f, 0.14f, 0.008f);
    drawCylinder(12);
    glPopMatrix();
    glColor3f(0.8f, 0.8f, 0.8f);
    glPushMatrix();
    glTranslatef(0.07f, 0.008f, 0);
    glRotatef(-90, 0, 0, 1);
    glScalef(0.008f, 0.02f, 0.008f);
    drawLathe({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, 12);
    glPopMatrix();
}

// A table 1.4 × 0.75 × 0.7 standing on the origin: a top and four legs.
void drawTable() {
    glColor3f(0.6f, 0.4f, 0.22f);
    glPushMatrix();
    glTranslatef(0, 0.72f, 0);
    glScalef(1.4f, 0.06f, 0.7f);
    drawUnitBox();
    glPopMatrix();
    glColor3f(0.35f, 0.22f, 0.12f);
    for (float sx : {-1.0f, 1.0f})
        for (float sz : {-1.0f, 1.0f}) {
            glPushMatrix();
            glTranslatef(sx * 0.64f, 0.345f, sz * 0.29f);
            glScalef(0.06f, 0.69f, 0.06f);
            drawUnitBox();
            glPopMatrix();
        }
}

// The table with its book, pen and teapot, placed by `o`.
void drawTableScene(const TableObjects& o, float bookHue) {
    drawTable();
    glPushMatrix();
    glTranslatef(0, 0.75f, 0); // the table top
    glPushMatrix();
    glTranslatef(o.bookX, 0, o.bookZ);
    glRotatef(o.bookAngle, 0, 1, 0);
    drawBook(0.7f * bookHue, 0.15f, 0.7f * (1 - bookHue));
    glPopMatrix();
    glPushMatrix();
    glTranslatef(o.penX, 0, o.penZ);
    glRotatef(o.penAngle, 0, 1, 0);
    glScalef(1.5f, 1.5f, 1.5f); // a marker pen: thick enough to see from the back row
    drawPen();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(o.potX, 0, o.potZ);
    glRotatef(o.potAngle, 0, 1, 0);
    glScalef(0.24f, 0.24f, 0.24f);
    glColor3f(0.85f, 0.85f, 0.8f);
    drawTeapot();
    glPopMatrix();
    glPopMatrix();
}

// Table centres: 3 rows (front row nearest the blackboard) × 4 tables.
glm::vec2 tablePosition(int index) {
    int row = index / 4, col = index % 4;
    return {-4.5f + 3.0f * float(col), kWallZ + 3.0f + 3.0f * float(row)};
}

// Everything of the room except the blackboard wall's glass: floor, side and back
// walls, the blackboard, the tables. Drawn once as it is and once mirrored.
void drawRoomContents(const std::vector<TableObjects>& objects) {
    glColor3f(0.55f, 0.55f, 0.5f); // floor: a flat box so it has a top face
    glPushMatrix();
    glTranslatef(0, -0.05f, 0.5f * (kWallZ + kRoomBack));
    glScalef(2 * kRoomHalfWidth, 0.1f, kRoomBack - kWallZ);
    drawUnitBox();
    glPopMatrix();
    glColor3f(0.75f, 0.72f, 0.6f); // side walls, low so the room can be seen over them
    for (float sx : {-1.0f, 1.0f}) {
        glPushMatrix();
        glTranslatef(sx * (kRoomHalfWidth + 0.05f), 0.6f, 0.5f * (kWallZ + kRoomBack));
        glScalef(0.1f, 1.2f, kRoomBack - kWallZ);
        drawUnitBox();
        glPopMatrix();
    }
    glColor3f(0.1f, 0.3f, 0.15f); // the blackboard, on the wall
    glPushMatrix();
    glTranslatef(0, 1.8f, kWallZ + 0.04f);
    glScalef(6.0f, 1.6f, 0.08f);
    drawUnitBox();
    glPopMatrix();
    glColor3f(0.5f, 0.32f, 0.18f); // the teacher's desk in front of the board
    glPushMatrix();
    glTranslatef(3.5f, 0.4f, kWallZ + 1.2f);
    glScalef(1.6f, 0.8f, 0.7f);
    drawUnitBox();
    glPopMatrix();
    for (int t = 0; t < 12; ++t) {
        glm::vec2 p = tablePosition(t);
        glPushMatrix();
        glTranslatef(p.x, 0, p.y);
        drawTableScene(objects[size_t(t)], float(t % 4) / 3.0f);
        glPopMatrix();
    }
}

// The light of the room: directional, from above the back right.
void setLight() {
    const GLfloat dir[4] = {0.4f, 1.0f, 0.7f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
}

class TransformsLab : public Lab {
  public:
    explicit TransformsLab(TransformsState* s) : s_(s ? s : &own_), ex_(wbExercises_lab03()) {}
    bool busy() const override { return ex_.busy(); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }
    std::string title() const override { return tr("Lab 03 - transforms and projections"); }
    std::vector<KeyHelp> keys() const override {
        return {{"1 2 3", tr("glOrtho / gluPerspective / glFrustum")},
                {"z x", tr("camera in / out (gluLookAt)")},
                {"n N", tr("near plane -/+ 0.5")},
                {"b B", tr("far plane -/+ 2")},
                {"r", tr("new random placement")},
                {"c", tr("classroom / single table")},
                {"m", tr("mirror image in the blackboard wall")},
                {"w", tr("glFrontFace(GL_CW) for the mirror")},
                {"l", tr("mirrored light position")},
                {"t", tr("top view onto the wall")},
                ex_.keyHelp()};
    }
    void init() override { placedSeed_ = s_->seed + 1; } // forces a placement on first draw
    void draw(const View& view) override;
    bool key(int k) override;
    void gui() override;

  private:
    void project(const View& view);
    void drawWorld(bool mirrored, bool reference = false);

    TransformsState own_;
    TransformsState* s_;
    ex::ExerciseMode ex_; // e: your projection, camera and mirror (exercises.cpp)
    std::vector<TableObjects> objects_;
    unsigned placedSeed_ = 0;
};

void TransformsLab::project(const View& view) {
    const TransformsState& s = *s_;
    const double aspect = double(view.width) / double(std::max(view.height, 1));
    const double zoom = view.zoom > 0 ? double(view.zoom) : 1.0;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    switch (s.projection) {
    case Projection::Ortho: {
        double h = double(s.orthoHalfHeight) / zoom;
        glOrtho(-h * aspect, h * aspect, -h, h, s.zNear, s.zFar);
        break;
    }
    case Projection::Perspective:
        if (!exerciseProjection(ex_, std::min(170.0, double(s.fovy) / zoom), aspect, s.zNear,
                                s.zFar))
            gluPerspective(std::min(170.0, double(s.fovy) / zoom), aspect, s.zNear, s.zFar);
        break;
    case Projection::Frustum:
        glFrustum(s.frustum[0] / zoom, s.frustum[1] / zoom, s.frustum[2] / zoom,
                  s.frustum[3] / zoom, s.zNear, s.zFar);
        break;
    }
    glMatrixMode(GL_MODELVIEW);
}

namespace {
// The lab's own mirror (§2.3 task 5's answer): the reflection in the wall plane z = wallZ
// multiplied onto the current matrix; true when done. A student handout has no answers
// (labs/handout_strip.txt): there it multiplies nothing and says false.
bool labMirror(float wallZ) {
    // Move the wall to z = 0, flip z, move it back.
    glTranslatef(0, 0, wallZ);
    glScalef(1, 1, -1);
    glTranslatef(0, 0, -wallZ);
    return true;
}

// The panel's note on how the lab mirrors (the answer too: cut from a handout).
void labMirrorNote() {
    ImGui::TextWrapped(
        tr("Mirror: glTranslatef(0,0,wall) glScalef(1,1,-1) glTranslatef(0,0,-wall). "
           "The flip reverses the winding, so front faces become clockwise; the light "
           "is re-sent under the same matrix so the mirrored room is lit from the "
           "mirrored side."));
}
} // namespace

void TransformsLab::drawWorld(bool mirrored, bool reference) {
    glPushMatrix();
    // Your mirror (e): your calls and your glFrontFace; the lab's below otherwise.
    const std::optional<unsigned> mine =
        mirrored && !reference ? exerciseMirror(ex_, kWallZ) : std::nullopt;
    if (mine) {
        glFrontFace(GLenum(*mine));
        if (s_->mirrorLight) setLight();
    } else if (mirrored) {
        if (!labMirror(kWallZ)) { // a student handout: only your mirror is drawn
            glPopMatrix();
            return;
        }
        // The flip turns counter-clockwise polygons clockwise: front faces are now CW.
        if (s_->mirrorFrontFace) glFrontFace(GL_CW);
        // The light is part of the mirrored world: its direction is reflected too.
        if (s_->mirrorLight) setLight();
    }
    if (s_->classroom) {
        drawRoomContents(objects_);
    } else if (!mirrored) {
        drawTableScene(objects_[0], 0.0f);
    }
    glFrontFace(GL_CCW);
    glPopMatrix();
    setLight();
}

void TransformsLab::draw(const View& view) {
    TransformsState& s = *s_;
    ex_.poll(!view.headless);
    if (placedSeed_ != s.seed || objects_.empty()) {
        objects_ = placeObjects(s.seed);
        placedSeed_ = s.seed;
    }
    glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE); // back faces culled: a wrong glFrontFace in the mirror shows
    glEnable(GL_NORMALIZE); // glScalef changes normal lengths
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    const GLfloat ambient[4] = {0.35f, 0.35f, 0.35f, 1.0f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    const GLfloat white[4] = {0.75f, 0.75f, 0.75f, 1.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    project(view);
    glLoadIdentity();
    if (s.topView) {
        // Straight down onto the wall line: the room below the image centre, its mirror above.
        gluLookAt(0, s.topViewHeight, kWallZ, 0, 0, kWallZ, 0, 0, -1);
    } else {
        const glm::vec3 centre = s.classroom ? glm::vec3(0, 0.8f, -1.0f) : glm::vec3(0, 0.6f, 0);
        const float scale = s.classroom ? 1.0f : 0.25f;
        const float yaw = glm::radians(view.yaw);
        const float pitch = glm::radians(std::clamp(s.elevation + view.pitch, -89.0f, 89.0f));
        glm::vec3 eye = centre + s.distance * scale *
                                     glm::vec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                               std::cos(yaw) * std::cos(pitch));
        gluLookAt(eye.x, eye.y, eye.z, centre.x, centre.y, centre.z, 0, 1, 0);
    }
    setLight();
    if (s.mirror && s.classroom) drawWorld(true);
    drawWorld(false);
    if (ex_.on() && s.mirror && s.classroom) { // the reference's mirrored room, a ghost wireframe
        ex::ExerciseMode::ghostBegin();
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glDisable(GL_CULL_FACE);
        drawWorld(true, true);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        ex::ExerciseMode::ghostEnd();
    }
    if (s.classroom) {
        // The blackboard wall: opaque, or a half-transparent glass when the mirror is on
        // (the mirrored room lies behind it, as the room seen in a mirror).
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        glDisable(GL_LIGHTING);
        glColor4f(0.7f, 0.75f, 0.8f, s.mirror ? 0.25f : 1.0f);
        glBegin(GL_QUADS);
        glVertex3f(-kRoomHalfWidth, 0, kWallZ);
        glVertex3f(kRoomHalfWidth, 0, kWallZ);
        glVertex3f(kRoomHalfWidth, 3.5f, kWallZ);
        glVertex3f(-kRoomHalfWidth, 3.5f, kWallZ);
        glEnd();
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_NORMALIZE);
    glDisable(GL_DEPTH_TEST);
}

bool TransformsLab::key(int k) {
    TransformsState& s = *s_;
    if (ex_.key(k)) return true;
    if (k == 'z' || k == 'x') // your moveCamera (e), one unit in or out
        if (const auto d = exerciseCameraStep(ex_, s.distance, k == 'z' ? 1.0 : -1.0)) {
            s.distance = float(*d);
            return true;
        }
    switch (k) {
    case '1':
        s.projection = Projection::Ortho;
        return true;
    case '2':
        s.projection = Projection::Perspective;
        return true;
    case '3':
        s.projection = Projection::Frustum;
        return true;
    case 'z':
        s.distance = std::max(1.0f, s.distance - 1.0f);
        return true;
    case 'x':
        s.distance = std::min(60.0f, s.distance + 1.0f);
        return true;
    case 'n':
        s.zNear = stepNear(s.zNear, s.zFar, -1);
        return true;
    case 'N':
        s.zNear = stepNear(s.zNear, s.zFar, +1);
        return true;
    case 'b':
        s.zFar = stepFar(s.zFar, s.zNear, -1);
        return true;
    case 'B':
        s.zFar = stepFar(s.zFar, s.zNear, +1);
        return true;
    case 'r':
        ++s.seed;
        return true;
    case 'c':
        s.classroom = !s.classroom;
        return true;
    case 'm':
        s.mirror = !s.mirror;
        return true;
    case 'w':
        s.mirrorFrontFace = !s.mirrorFrontFace;
        return true;
    case 'l':
        s.mirrorLight = !s.mirrorLight;
        return true;
    case 't':
        s.topView = !s.topView;
        return true;
    default:
        return false;
    }
}

void TransformsLab::gui() {
    TransformsState& s = *s_;
    ex_.gui();
    int proj = int(s.projection);
    ImGui::RadioButton(tr("glOrtho (1)"), &proj, 0);
    sameLineIfFits(tr("gluPerspective (2)"));
    ImGui::RadioButton(tr("gluPerspective (2)"), &proj, 1);
    sameLineIfFits(tr("glFrustum (3)"));
    ImGui::RadioButton(tr("glFrustum (3)"), &proj, 2);
    s.projection = Projection(proj);
    switch (s.projection) {
    case Projection::Ortho:
        ImGui::SliderFloat(tr("half height"), &s.orthoHalfHeight, 0.5f, 20.0f);
        break;
    case Projection::Perspective:
        ImGui::SliderFloat(tr("fovy"), &s.fovy, 5.0f, 150.0f);
        break;
    case Projection::Frustum:
        ImGui::TextUnformatted(tr("glFrustum left, right, bottom, top:"));
        ImGui::SetNextItemWidth(-FLT_MIN);
        ImGui::DragFloat4("##frustum", s.frustum, 0.01f);
        break;
    }
    ImGui::DragFloat(tr("near (n N)"), &s.zNear, 0.05f, 0.01f, s.zFar - 0.01f);
    ImGui::DragFloat(tr("far (b B)"), &s.zFar, 0.25f, s.zNear + 0.01f, 200.0f);
    ImGui::TextWrapped(
        tr("Anything nearer than `near` or farther than `far` is clipped: raise near "
           "until the front tables are cut open, lower far until the board vanishes."));
    ImGui::Separator();
    // Long labels sit above full-width sliders, so a narrow or scaled panel never cuts them.
    ImGui::TextUnformatted(tr("camera distance (z x), elevation:"));
    ImGui::SetNextItemWidth(-FLT_MIN);
    ImGui::SliderFloat("##distance", &s.distance, 1.0f, 60.0f, tr("distance %.1f"));
    ImGui::SetNextItemWidth(-FLT_MIN);
    ImGui::SliderFloat("##elevation", &s.elevation, -89.0f, 89.0f, tr("elevation %.0f deg"));
    ImGui::Checkbox(tr("top view (t)"), &s.topView);
    ImGui::Separator();
    ImGui::Checkbox(tr("classroom (c)"), &s.classroom);
    int seed = int(s.seed);
    if (ImGui::InputInt(tr("seed (r)"), &seed)) s.seed = unsigned(std::max(seed, 0));
    ImGui::Checkbox(tr("mirror in the blackboard wall (m)"), &s.mirror);
    ImGui::Checkbox(tr("glFrontFace(GL_CW) (w)"), &s.mirrorFrontFace); // under "mirror"
    ImGui::Checkbox(tr("mirrored light position (l)"), &s.mirrorLight);
    labMirrorNote();
}

} // namespace

std::unique_ptr<Lab> makeTransformsLab() {
    return std::make_unique<TransformsLab>(nullptr);
}
std::unique_ptr<Lab> makeTransformsLab(TransformsState* observe) {
    return std::make_unique<TransformsLab>(observe);
}

} // namespace wb
