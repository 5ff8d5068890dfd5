#include "lighting_lab.h"

#include "common/exercise_mode.h"
#include "common/gl_util.h"
#include "core/i18n.h"
#include "exercises.h"

#include "common/panel.h"
#include "core/i18n.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

const wb::ex::LabExercises& wbExercises_lab02();

namespace wb {

const char* comboName(int combo) {
    switch (combo) {
    case 1:
        return N_("1: specular material + specular light");
    case 2:
        return N_("2: specular material + diffuse light");
    case 3:
        return N_("3: diffuse material + specular light");
    default:
        return N_("4: diffuse material + diffuse light");
    }
}

const char* comboLookFor(int combo) {
    switch (combo) {
    case 1:
        return N_("Look for the grey-white specular reflection: the light has only GL_SPECULAR, "
                  "so elsewhere each cube shows its ambient term alone. The left cube's front "
                  "face turns towards the half-vector as a whole; the right cube's corner "
                  "normals catch it only faintly, near one corner.");
    case 2:
        return N_("Look for faces shaded by their angle to the light, and for the missing "
                  "highlight: the material is shiny, but the light has no GL_SPECULAR, so only "
                  "its dark green diffuse part (0.2) shows.");
    case 3:
        return N_("Look for flat, unlit silhouettes: a matte material (no GL_SPECULAR) under a "
                  "light with only GL_SPECULAR reflects none of it; every face shows the same "
                  "ambient colour.");
    default:
        return N_("Look for bright green faces turned to the light and darker ones turned away: "
                  "matte material, diffuse light, Lambert's cosine and no highlight anywhere.");
    }
}

Material comboMaterial(const LightingState& s) {
    Material m;
    m.ambient = {0.2, 0.2, 0.2, 1};
    if (s.combo <= 2) { // the lab's listing: a dark green with a strong white highlight
        m.diffuse = {0.0, 0.2, 0.0, 1};
        m.specular = {0.6, 0.6, 0.6, 1};
        m.shininess = 0.1 * 128;
    } else { // matte: no GL_SPECULAR at all
        m.diffuse = {0.1, 0.7, 0.1, 1};
        m.specular = {0, 0, 0, 1};
        m.shininess = 0;
    }
    if (s.emissionOn) m.emission = glm::dvec4(glm::dvec3(s.emission), 1);
    return m;
}

Light comboLight(const LightingState& s) {
    Light l;
    l.ambient = {0, 0, 0, 1};
    const glm::dvec4 c(glm::dvec3(s.lightColor), 1);
    const bool specularLight = s.combo == 1 || s.combo == 3;
    l.diffuse = specularLight ? glm::dvec4(0, 0, 0, 1) : c;
    l.specular = specularLight ? c : glm::dvec4(0, 0, 0, 1);
    l.position = glm::dvec4(s.lightPos);
    l.constantAttenuation = s.attenuation.x;
    l.linearAttenuation = s.attenuation.y;
    l.quadraticAttenuation = s.attenuation.z;
    if (s.spotOn) {
        glm::dvec3 from =
            s.lightPos.w != 0.0f ? glm::dvec3(s.lightPos) / double(s.lightPos.w) : glm::dvec3(0);
        glm::dvec3 dir = glm::dvec3(s.spotTarget) - from;
        l.spotDirection = glm::length(dir) > 0 ? dir : glm::dvec3(0, -1, 0);
        l.spotCutoff = s.spotCutoff;
        l.spotExponent = s.spotExponent;
    }
    return l;
}

LightModel lightModel(const LightingState& s) {
    LightModel m;
    m.ambient =
        s.globalAmbientOn ? glm::dvec4(glm::dvec3(s.globalAmbient), 1) : glm::dvec4(0, 0, 0, 1);
    m.localViewer = s.localViewer;
    return m;
}

namespace {
void toFloats(const glm::dvec4& v, GLfloat out[4]) {
    for (int i = 0; i < 4; ++i)
        out[i] = static_cast<GLfloat>(v[i]);
}
} // namespace

void glApplyMaterial(const Material& m) {
    GLfloat v[4];
    toFloats(m.emission, v);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, v);
    toFloats(m.ambient, v);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v);
    toFloats(m.diffuse, v);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, v);
    toFloats(m.specular, v);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, v);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, static_cast<GLfloat>(m.shininess));
}

void glApplyLight(GLenum light, const Light& l) {
    if (!l.enabled) {
        glDisable(light);
        return;
    }
    glEnable(light);
    GLfloat v[4];
    toFloats(l.ambient, v);
    glLightfv(light, GL_AMBIENT, v);
    toFloats(l.diffuse, v);
    glLightfv(light, GL_DIFFUSE, v);
    toFloats(l.specular, v);
    glLightfv(light, GL_SPECULAR, v);
    toFloats(l.position, v);
    glLightfv(light, GL_POSITION, v);
    toFloats(glm::dvec4(l.spotDirection, 0), v);
    glLightfv(light, GL_SPOT_DIRECTION, v);
    glLightf(light, GL_SPOT_CUTOFF, static_cast<GLfloat>(l.spotCutoff));
    glLightf(light, GL_SPOT_EXPONENT, static_cast<GLfloat>(l.spotExponent));
    glLightf(light, GL_CONSTANT_ATTENUATION, static_cast<GLfloat>(l.constantAttenuation));
    glLightf(light, GL_LINEAR_ATTENUATION, static_cast<GLfloat>(l.linearAttenuation));
    glLightf(light, GL_QUADRATIC_ATTENUATION, static_cast<GLfloat>(l.quadraticAttenuation));
}

void glApplyLightModel(const LightModel& m) {
    GLfloat v[4];
    toFloats(m.ambient, v);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, m.localViewer ? GL_TRUE : GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, m.twoSide ? GL_TRUE : GL_FALSE);
}

namespace {

// The six faces of a cube of half-size 1: corners counter-clockwise seen from outside.
struct Face {
    glm::vec3 c[4];
    glm::vec3 n;
};
const Face kFaces[6] = {
    {{{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, {0, 0, 1}},
    {{{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}, {0, 0, -1}},
    {{{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}}, {1, 0, 0}},
    {{{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}, {-1, 0, 0}},
    {{{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}}, {0, 1, 0}},
    {{{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}, {0, -1, 0}},
};

// A cube whose faces are split into an N×N grid. Each grid vertex P gets the lab's
// normal n_P = (a·n_A + b·n_B + c·n_C + d·n_D)/|…| with the bilinear weights of P in
// the face (the barycentric coordinates of P with respect to the corners A, B, C, D).
// centreNormals: the corner normals point from the cube centre through the corner.
void drawCube(bool centreNormals, int n) {
    for (const Face& f : kFaces) {
        glm::vec3 cn[4];
        for (int i = 0; i < 4; ++i)
            cn[i] = centreNormals ? glm::normalize(f.c[i]) : f.n;
        auto vertex = [&](int i, int j) {
            float u = float(i) / float(n), v = float(j) / float(n);
            float w[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
            glm::vec3 p(0), nn(0);
            for (int k = 0; k < 4; ++k) {
                p += w[k] * f.c[k];
                nn += w[k] * cn[k];
            }
            nn = glm::normalize(nn);
            glNormal3f(nn.x, nn.y, nn.z);
            glVertex3f(p.x, p.y, p.z);
        };
        glBegin(GL_QUADS);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                vertex(i, j);
                vertex(i + 1, j);
                vertex(i + 1, j + 1);
                vertex(i, j + 1);
            }
        glEnd();
    }
}

// A box of the given half-sizes with face normals (for the blocker).
void drawBox(glm::vec3 half) {
    glPushMatrix();
    glScalef(half.x, half.y, half.z);
    glEnable(GL_NORMALIZE); // the scale changes the normals' length
    drawCube(false, 1);
    glDisable(GL_NORMALIZE);
    glPopMatrix();
}

// The light's position as an unlit marker: a small star for a positional light, an
// arrow from the scene centre towards a directional one.
void drawMarker(const glm::vec4& pos) {
    glDisable(GL_LIGHTING);
    glColor3f(1.0f, 0.9f, 0.2f);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    if (pos.w != 0.0f) {
        glm::vec3 p = glm::vec3(pos) / pos.w;
        const float r = 0.18f;
        for (int a = 0; a < 3; ++a) {
            glm::vec3 d(0);
            d[a] = r;
            glVertex3f(p.x - d.x, p.y - d.y, p.z - d.z);
            glVertex3f(p.x + d.x, p.y + d.y, p.z + d.z);
        }
    } else {
        glm::vec3 d = glm::normalize(glm::vec3(pos)) * 4.0f;
        glVertex3f(0, 0, 0);
        glVertex3f(d.x, d.y, d.z);
    }
    glEnd();
    glLineWidth(1.0f);
    glEnable(GL_LIGHTING);
}

class LightingLab : public Lab {
  public:
    // 'e' is emission here, so the exercises are on 'E'.
    explicit LightingLab(LightingState* s) : s_(s ? s : &own_), ex_(wbExercises_lab02(), 'E') {}
    std::string title() const override { return tr("Lab 02 - Phong lighting"); }
    std::vector<KeyHelp> keys() const override {
        return {{"1", tr("specular material + specular light")},
                {"2", tr("specular material + diffuse light")},
                {"3", tr("diffuse material + specular light")},
                {"4", tr("diffuse material + diffuse light")},
                {"5", tr("all four combinations side by side (2x2)")},
                {"a", tr("global ambient on/off")},
                {"v", tr("local / infinite viewer")},
                {"e", tr("emission on/off")},
                {"s", tr("smooth / flat shading")},
                {"g", tr("vertex (Gouraud) / per-fragment GLSL Phong")},
                {"[ ]", tr("face grid N down / up")},
                {"w", tr("positional / directional light")},
                {"t", tr("spot on/off")},
                {"k", tr("attenuation on/off")},
                {"m", tr("light marker on/off")},
                {"b", tr("blocker between light and cube")},
                {tr("arrows PgUp PgDn"), tr("move the light")},
                {", .", tr("spin the cubes")},
                ex_.keyHelp()};
    }
    bool busy() const override { return ex_.busy(); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }
    void init() override {
        // init() runs once per context (headless renders make a new one each time).
        program_ = loadProgram("shaders/phong.vert", "shaders/phong.frag", programError_);
    }
    void draw(const View& view) override;
    bool key(int k) override;
    void gui() override;

  private:
    // One view of the two cubes with state `s` into the current viewport.
    void drawScene(const View& view, const LightingState& s);
    void drawDigit(int digit, int w, int h);
    // Your cube (exercises, key E): your vertices and normals, your grid normals for N > 1,
    // your normals as solid hairs and the reference's as a ghost.
    void drawYourCube(bool centreNormals, int n);

    LightingState own_;
    LightingState* s_;
    GLuint program_ = 0;
    std::string programError_;
    ex::ExerciseMode ex_;
};

void LightingLab::drawYourCube(bool centreNormals, int n) {
    const lab02::Table* t = ex_.studentTable<lab02::Table>();
    const lab02::Table* ref = ex_.referenceTable<lab02::Table>();
    const char* task = centreNormals ? "02.cube-centre" : "02.cube-face";
    auto make = [&](const lab02::Table* table) -> std::optional<lab02::Cube> {
        if (!table) return std::nullopt;
        lab02::Cube c =
            centreNormals ? table->centreNormals({0, 0, 0}, 1) : table->faceNormals({0, 0, 0}, 1);
        if (c.vertices.size() != c.normals.size() || c.vertices.size() % 4 != 0)
            return std::nullopt;
        return c;
    };
    const std::optional<lab02::Cube> mine =
        t ? ex_.call(task, [&] { return make(t); }).value_or(std::nullopt) : std::nullopt;
    std::vector<glm::dvec3> hairs; // pairs: point, normal
    if (mine) {
        auto corners = [&](size_t f, std::array<glm::dvec3, 4>& c, std::array<glm::dvec3, 4>& cn) {
            for (size_t k = 0; k < 4; ++k) {
                c[k] = mine->vertices[f + k];
                cn[k] = mine->normals[f + k];
            }
        };
        auto weights = [n](int i, int j, double(&w)[4]) {
            const double u = double(i) / double(n), v = double(j) / double(n);
            w[0] = (1 - u) * (1 - v), w[1] = u * (1 - v), w[2] = u * v, w[3] = (1 - u) * v;
        };
        // Your grid normal (task 5) at every grid point of every face, tried once in a child:
        // one that passes its checks but crashes here fails in the panel, the lab stays up.
        if (n > 1)
            ex_.tryInChild("02.grid-normal",
                           ex::ExerciseMode::inputKey(n, mine->vertices, mine->normals), [&] {
                               std::array<glm::dvec3, 4> c, cn;
                               double w[4];
                               for (size_t f = 0; f + 3 < mine->vertices.size(); f += 4) {
                                   corners(f, c, cn);
                                   for (int j = 0; j <= n; ++j)
                                       for (int i = 0; i <= n; ++i) {
                                           weights(i, j, w);
                                           glm::dvec3 p(0.0);
                                           for (size_t k = 0; k < 4; ++k)
                                               p += w[k] * c[k];
                                           try {
                                               t->gridNormal(c, cn, p);
                                           } catch (...) {
                                           }
                                       }
                               }
                           });
        for (size_t f = 0; f + 3 < mine->vertices.size(); f += 4) {
            std::array<glm::dvec3, 4> c, cn;
            corners(f, c, cn);
            auto vertex = [&](int i, int j) {
                double w[4];
                weights(i, j, w);
                glm::dvec3 p(0.0), nn(0.0);
                for (size_t k = 0; k < 4; ++k) {
                    p += w[k] * c[k];
                    nn += w[k] * cn[k]; // your corner normals as given at the corners (N = 1)
                }
                if (n > 1) {
                    // Your grid normal (task 5) when it can be called, else the lab's own blend.
                    const auto g =
                        ex_.callTried("02.grid-normal", [&] { return t->gridNormal(c, cn, p); });
                    nn = g ? *g : glm::normalize(nn);
                }
                glNormal3d(nn.x, nn.y, nn.z);
                glVertex3d(p.x, p.y, p.z);
                if (n <= 8) hairs.insert(hairs.end(), {p, nn});
            };
            glBegin(GL_QUADS);
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    vertex(i, j);
                    vertex(i + 1, j);
                    vertex(i + 1, j + 1);
                    vertex(i, j + 1);
                }
            glEnd();
        }
    }
    // The hairs: unlit lines, no shader; yours solid yellow, the reference's a ghost.
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glUseProgram(0);
    glDisable(GL_LIGHTING);
    glLineWidth(2.0f);
    auto drawHairs = [](const std::vector<glm::dvec3>& h) {
        glBegin(GL_LINES);
        for (size_t i = 0; i + 1 < h.size(); i += 2) {
            glVertex3d(h[i].x, h[i].y, h[i].z);
            const glm::dvec3 e = h[i] + 0.45 * h[i + 1];
            glVertex3d(e.x, e.y, e.z);
        }
        glEnd();
    };
    glColor3f(1.0f, 0.85f, 0.1f);
    drawHairs(hairs);
    if (const std::optional<lab02::Cube> r = make(ref)) {
        std::vector<glm::dvec3> rh;
        for (size_t i = 0; i < r->vertices.size(); ++i)
            rh.insert(rh.end(), {r->vertices[i], r->normals[i]});
        ex::ExerciseMode::ghostBegin();
        glColor3f(1.0f, 1.0f, 1.0f);
        drawHairs(rh);
        // The reference cube's edges, so a missing or misplaced face shows.
        glBegin(GL_LINES);
        for (size_t f = 0; f + 3 < r->vertices.size(); f += 4)
            for (size_t k = 0; k < 4; ++k) {
                const glm::dvec3 a = r->vertices[f + k], b = r->vertices[f + (k + 1) % 4];
                glVertex3d(a.x, a.y, a.z);
                glVertex3d(b.x, b.y, b.z);
            }
        glEnd();
        ex::ExerciseMode::ghostEnd();
    }
    glLineWidth(1.0f);
    glEnable(GL_LIGHTING);
    glUseProgram(GLuint(program));
}

void LightingLab::draw(const View& view) {
    ex_.poll(!view.headless);
    const LightingState& s = *s_;
    glClearColor(s.background.r, s.background.g, s.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!s.compareAll) {
        drawScene(view, s);
        return;
    }
    // 2×2: combination c in quadrant (c-1)%2, (c-1)/2 from the top left, each with the
    // same state otherwise and the same aspect as the whole view.
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    View quarter = view;
    quarter.width = std::max(1, vp[2] / 2);
    quarter.height = std::max(1, vp[3] / 2);
    for (int c = 1; c <= 4; ++c) {
        const int col = (c - 1) % 2, row = (c - 1) / 2;
        glViewport(vp[0] + col * quarter.width, vp[1] + (1 - row) * quarter.height, quarter.width,
                   quarter.height);
        LightingState one = s;
        one.combo = c;
        drawScene(quarter, one);
        drawDigit(c, quarter.width, quarter.height);
    }
    glViewport(vp[0], vp[1], vp[2], vp[3]);
    // The cross between the quadrants.
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.9f, 0.9f, 0.9f);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    glVertex2f(0.5f, 0.0f);
    glVertex2f(0.5f, 1.0f);
    glVertex2f(0.0f, 0.5f);
    glVertex2f(1.0f, 0.5f);
    glEnd();
    glLineWidth(1.0f);
}

// The combination's number in the top-left corner of a quadrant, drawn with lines so it
// shows in headless renders (and screenshots) too: seven-segment strokes, 24 px high.
void LightingLab::drawDigit(int digit, int w, int h) {
    // Segments a b c d e f g on a 0..1 × 0..2 cell (y up).
    static const float kSeg[7][4] = {{0, 2, 1, 2}, {1, 2, 1, 1}, {1, 1, 1, 0}, {0, 0, 1, 0},
                                     {0, 1, 0, 0}, {0, 2, 0, 1}, {0, 1, 1, 1}};
    static const char* const kOn[5] = {"", "bc", "abged", "abgcd", "fgbc"};
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glColor3f(1.0f, 0.9f, 0.2f);
    glLineWidth(3.0f);
    const float x0 = 10.0f, y0 = float(h) - 10.0f - 24.0f, size = 12.0f;
    glBegin(GL_LINES);
    for (const char* on = kOn[digit]; *on; ++on) {
        const float* g = kSeg[*on - 'a'];
        glVertex2f(x0 + g[0] * size, y0 + g[1] * size);
        glVertex2f(x0 + g[2] * size, y0 + g[3] * size);
    }
    glEnd();
    glLineWidth(1.0f);
}

void LightingLab::drawScene(const View& view, const LightingState& s) {
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    setPerspective(view, kLightingFovy, 1.0, 50.0);
    glLoadIdentity();
    glTranslated(0, 0, -kLightingDistance);
    glRotatef(s.tilt, 1, 0, 0);
    applyOrbit(view);

    glShadeModel(s.smooth ? GL_SMOOTH : GL_FLAT);
    glEnable(GL_LIGHTING);
    glApplyLightModel(lightModel(s));
    // Set in scene coordinates: the light turns with the scene when the mouse rotates it.
    glApplyLight(GL_LIGHT0, comboLight(s));
    glApplyMaterial(comboMaterial(s));

    const bool glsl = s.shading == FaceShading::PhongGlsl && program_ != 0;
    if (glsl) {
        glUseProgram(program_);
        glUniform1i(glGetUniformLocation(program_, "wbLightCount"), 1);
        glUniform1i(glGetUniformLocation(program_, "wbLocalViewer"), s.localViewer ? 1 : 0);
    }
    const int n = std::clamp(s.subdivisions, 1, 64);
    for (int side = 0; side < 2; ++side) {
        glPushMatrix();
        glTranslatef(side == 0 ? -kCubeOffset : kCubeOffset, 0, 0);
        glRotatef(s.cubeSpin, 0, 1, 0);
        if (ex_.on())
            drawYourCube(side == 1, n);
        else
            drawCube(side == 1, n);
        glPopMatrix();
    }
    if (s.showBlocker) { // halfway from the light to the top of the right cube: it casts no shadow
        glm::vec3 light = s.lightPos.w != 0.0f ? glm::vec3(s.lightPos) / s.lightPos.w
                                               : glm::vec3(kCubeOffset, 0, 0) +
                                                     4.0f * glm::normalize(glm::vec3(s.lightPos));
        glm::vec3 mid = 0.5f * (light + glm::vec3(kCubeOffset, 1, 0));
        glPushMatrix();
        glTranslatef(mid.x, mid.y, mid.z);
        drawBox({0.6f, 0.05f, 0.6f});
        glPopMatrix();
    }
    if (glsl) glUseProgram(0);
    if (s.showMarker) drawMarker(s.lightPos);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
}

bool LightingLab::key(int k) {
    if (ex_.key(k)) return true;
    LightingState& s = *s_;
    const float step = 0.25f;
    switch (k) {
    case '1':
    case '2':
    case '3':
    case '4':
        s.combo = k - '0';
        s.compareAll = false;
        return true;
    case '5':
        s.compareAll = !s.compareAll;
        return true;
    case 'a':
        s.globalAmbientOn = !s.globalAmbientOn;
        return true;
    case 'v':
        s.localViewer = !s.localViewer;
        return true;
    case 'e':
        s.emissionOn = !s.emissionOn;
        return true;
    case 's':
        s.smooth = !s.smooth;
        return true;
    case 'g':
        s.shading =
            s.shading == FaceShading::Gouraud ? FaceShading::PhongGlsl : FaceShading::Gouraud;
        return true;
    case '[':
        s.subdivisions = std::max(1, s.subdivisions / 2);
        return true;
    case ']':
        s.subdivisions = std::min(64, s.subdivisions * 2);
        return true;
    case 'w':
        s.lightPos.w = s.lightPos.w != 0.0f ? 0.0f : 1.0f;
        return true;
    case 't':
        s.spotOn = !s.spotOn;
        return true;
    case 'k':
        s.attenuation =
            s.attenuation == glm::vec3(1, 0, 0) ? glm::vec3(0.2f, 0.1f, 0.05f) : glm::vec3(1, 0, 0);
        return true;
    case 'm':
        s.showMarker = !s.showMarker;
        return true;
    case 'b':
        s.showBlocker = !s.showBlocker;
        return true;
    case ',':
        s.cubeSpin -= 10.0f;
        return true;
    case '.':
        s.cubeSpin += 10.0f;
        return true;
    case kKeyLeft:
        s.lightPos.x -= step;
        return true;
    case kKeyRight:
        s.lightPos.x += step;
        return true;
    case kKeyDown:
        s.lightPos.y -= step;
        return true;
    case kKeyUp:
        s.lightPos.y += step;
        return true;
    case kKeyPageUp:
        s.lightPos.z -= step;
        return true;
    case kKeyPageDown:
        s.lightPos.z += step;
        return true;
    default:
        return false;
    }
}

void LightingLab::gui() {
    LightingState& s = *s_;
    ex_.gui();
    ImGui::TextWrapped(tr("Left cube: normals perpendicular to the faces."));
    ImGui::TextWrapped(tr("Right cube: normals from the cube centre through the vertex."));
    ImGui::Separator();
    for (int c = 1; c <= 4; ++c) {
        if (c > 1) ImGui::SameLine();
        if (ImGui::RadioButton(std::to_string(c).c_str(), !s.compareAll && s.combo == c))
            s.combo = c, s.compareAll = false;
    }
    ImGui::SameLine();
    ImGui::Checkbox("2x2 (5)", &s.compareAll);
    if (s.compareAll) {
        ImGui::TextWrapped(
            tr("All four side by side, numbered as the keys: 1 2 on top, 3 4 below."));
        for (int c = 1; c <= 4; ++c)
            ImGui::TextWrapped("%s", tr(comboName(c)));
    } else {
        ImGui::TextWrapped("%s", tr(comboName(s.combo)));
        ImGui::TextWrapped("%s", tr(comboLookFor(s.combo)));
    }
    ImGui::TextWrapped(tr("A specular light only feeds GL_SPECULAR reflection and a diffuse light "
                          "only GL_DIFFUSE."));
    ImGui::Separator();
    ImGui::Checkbox(tr("global ambient (a)"), &s.globalAmbientOn);
    ImGui::SameLine();
    ImGui::ColorEdit3("##ambient", &s.globalAmbient.x, ImGuiColorEditFlags_NoInputs);
    ImGui::Checkbox(tr("local viewer (v)"), &s.localViewer);
    ImGui::Checkbox(tr("emission (e)"), &s.emissionOn);
    ImGui::SameLine();
    ImGui::ColorEdit3("##emission", &s.emission.x, ImGuiColorEditFlags_NoInputs);
    ImGui::Checkbox(tr("smooth shading (s)"), &s.smooth);
    bool glsl = s.shading == FaceShading::PhongGlsl;
    if (ImGui::Checkbox(tr("per-fragment GLSL Phong (g)"), &glsl))
        s.shading = glsl ? FaceShading::PhongGlsl : FaceShading::Gouraud;
    if (!programError_.empty()) ImGui::TextWrapped(tr("shader: %s"), programError_.c_str());
    ImGui::SliderInt(tr("face grid N ([ ])"), &s.subdivisions, 1, 64);
    ImGui::Separator();
    bool positional = s.lightPos.w != 0.0f;
    if (ImGui::Checkbox(tr("positional light (w)"), &positional))
        s.lightPos.w = positional ? 1.0f : 0.0f;
    ImGui::DragFloat3(tr("light position"), &s.lightPos.x, 0.05f);
    ImGui::ColorEdit3(tr("light colour"), &s.lightColor.x);
    ImGui::DragFloat3(tr("kc kl kq (k)"), &s.attenuation.x, 0.01f, 0.0f, 10.0f);
    ImGui::Checkbox(tr("spot (t)"), &s.spotOn);
    ImGui::DragFloat3(tr("spot aims at"), &s.spotTarget.x, 0.05f);
    ImGui::SliderFloat(tr("spot cutoff"), &s.spotCutoff, 0.0f, 90.0f);
    ImGui::SliderFloat(tr("spot exponent"), &s.spotExponent, 0.0f, 128.0f);
    ImGui::Checkbox(tr("light marker (m)"), &s.showMarker);
    sameLineIfFits(tr("blocker (b)"));
    ImGui::Checkbox(tr("blocker (b)"), &s.showBlocker);
    ImGui::SliderFloat(tr("camera tilt"), &s.tilt, -90.0f, 90.0f);
    ImGui::Separator();
    ImGui::TextWrapped(
        tr("The light itself is invisible: hide the marker (m) and nothing shows where "
           "it is. The blocker (b) casts no shadow: GL lighting never asks whether "
           "anything lies between a vertex and the light."));
    ImGui::TextWrapped(
        tr("Highlight inside a face: with 4 vertices Gouraud only interpolates the "
           "vertex colours, so the brightest point is always a corner; split the face "
           "(N > 1) or use GLSL Phong on the right cube."));
    ImGui::TextWrapped(
        tr("Infinite viewer: every vertex sees the eye along +z, so h is the same for "
           "a whole flat face; the highlight needs normals that vary across the face "
           "(the right cube, N > 1)."));
    ImGui::TextWrapped(
        tr("Local viewer: the direction to the eye changes across the face, so h "
           "changes too and even the flat-normal left cube can show a highlight inside "
           "a large subdivided face."));
    if (s.spotOn && s.lightPos.w == 0.0f) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.3f, 1));
        ImGui::TextWrapped("%s", tr("a directional light has no spot cone"));
        ImGui::PopStyleColor();
    }
}

} // namespace

std::unique_ptr<Lab> makeLightingLab() {
    return std::make_unique<LightingLab>(nullptr);
}
std::unique_ptr<Lab> makeLightingLab(LightingState* observe) {
    return std::make_unique<LightingLab>(observe);
}

} // namespace wb
