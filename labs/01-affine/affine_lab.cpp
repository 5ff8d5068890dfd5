#include "affine_lab.h"

#include "common/exercise_mode.h"
#include "common/gl.h"
#include "common/panel.h"
#include "core/homogeneous.h"
#include "core/i18n.h"
#include "exercises.h"

#include "core/i18n.h"

#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>

const wb::ex::LabExercises& wbExercises_lab01();

namespace wb {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A student handout (./wb handout) has no reference answers: core's 2D mirror and shadow
// matrices are stripped from it, so the lab draws and shows only the student's.
#ifdef WB_HANDOUT
constexpr bool kHaveReference = false;
#else
constexpr bool kHaveReference = true;
#endif

// The letter F, counter-clockwise, 1.3 × the unit design, centred near (-1.5, 0.5).
std::vector<glm::dvec2> makePolygon() {
    const glm::dvec2 unit[] = {{-1, -1.5},  {-0.4, -1.5}, {-0.4, -0.1}, {0.6, -0.1}, {0.6, 0.5},
                               {-0.4, 0.5}, {-0.4, 0.9},  {1.0, 0.9},   {1.0, 1.5},  {-1, 1.5}};
    std::vector<glm::dvec2> p;
    for (const glm::dvec2& u : unit)
        p.push_back(1.3 * u + glm::dvec2(-1.5, 0.5));
    return p;
}

glm::dvec2 centroid(const std::vector<glm::dvec2>& p) {
    glm::dvec2 c(0.0);
    for (const glm::dvec2& v : p)
        c += v;
    return c / double(p.size());
}

double radius(const std::vector<glm::dvec2>& p, const glm::dvec2& c) {
    double r = 0;
    for (const glm::dvec2& v : p)
        r = std::max(r, glm::length(v - c));
    return r;
}

double signedDistance(const Line2& line, const glm::dvec2& p) {
    return (line.a * p.x + line.b * p.y + line.c) / std::hypot(line.a, line.b);
}

// Unit normal of Λ pointing to the polygon's side.
glm::dvec2 normalTowardsPolygon(const AffineState& s) {
    const Line2 line = affineLine(s);
    glm::dvec2 n = glm::normalize(glm::dvec2(line.a, line.b));
    if (signedDistance(line, centroid(affinePolygon())) < 0) n = -n;
    return n;
}

void color(const std::array<unsigned char, 3>& c) {
    glColor3ub(c[0], c[1], c[2]);
}

std::string matrixText(const double* colMajor, int n) {
    std::string out;
    char buf[32];
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            std::snprintf(buf, sizeof buf, "%9.4f ", colMajor[c * n + r]);
            out += buf;
        }
        out += '\n';
    }
    return out;
}

// The F extruded to a prism (thickness 0.6), standing on its foot above the plane.
struct Prism {
    std::vector<glm::dvec3> front, back; // polygon at z = +0.3 and z = -0.3
};

Prism makePrism() {
    Prism p;
    for (const glm::dvec2& v : affinePolygon()) {
        // Local F coordinates (undo the 2D placement), then stand it up at y ∈ [1.2, 5].
        const glm::dvec2 u = (v - glm::dvec2(-1.5, 0.5)) / 1.3;
        p.front.push_back({1.4 * u.x, 3.1 + 1.3 * u.y, 0.3});
        p.back.push_back({1.4 * u.x, 3.1 + 1.3 * u.y, -0.3});
    }
    return p;
}

void drawPrism(bool lit) {
    static const Prism p = makePrism();
    const auto& tris = affinePolygonTriangles();
    glBegin(GL_TRIANGLES);
    if (lit) glNormal3d(0, 0, 1);
    for (const auto& t : tris)
        for (int i : t)
            glVertex3dv(glm::value_ptr(p.front[size_t(i)]));
    if (lit) glNormal3d(0, 0, -1);
    for (const auto& t : tris)
        for (int i = 2; i >= 0; --i)
            glVertex3dv(glm::value_ptr(p.back[size_t(t[size_t(i)])]));
    glEnd();
    glBegin(GL_QUADS);
    const size_t n = p.front.size();
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        const glm::dvec3 e = p.front[j] - p.front[i];
        if (lit) glNormal3d(e.y, -e.x, 0); // outward for a counter-clockwise outline
        glVertex3dv(glm::value_ptr(p.front[i]));
        glVertex3dv(glm::value_ptr(p.back[i]));
        glVertex3dv(glm::value_ptr(p.back[j]));
        glVertex3dv(glm::value_ptr(p.front[j]));
    }
    glEnd();
}

class AffineLab : public Lab {
  public:
    explicit AffineLab(AffineState* s) : s_(s ? s : &own_), ex_(wbExercises_lab01()) {
        if (!s) reseed(own_, own_.seed);
        // Exercise 1.1 once: the composite and the closed form, and how far apart they are.
        if (!kHaveReference) return;
        const Line2 ex{3, -2, 1};
        exComposite_ = mirrorLineComposite(ex);
        exClosed_ = mirrorLine(ex);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                exDiff_ = std::max(exDiff_, std::abs(exComposite_[c][r] - exClosed_[c][r]));
    }

    std::string title() const override { return tr("Lab 01 - affine maps"); }
    std::vector<KeyHelp> keys() const override {
        return {{"1", tr("mirror image in the line / plane")},
                {"2", tr("shadow from a light at infinity along l")},
                {"3", tr("shadow from a point light S")},
                {"v", tr("2D view / 3D view")},
                {"r", tr("new random line through K, L (next seed)")},
                {tr("Left Right"), tr("turn l (mode 2) / move S (mode 3)")},
                {tr("Up Down"), tr("move S (mode 3) / tilt l (3D, mode 2)")},
                ex_.keyHelp()};
    }
    bool busy() const override { return ex_.busy(); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }

    void draw(const View& view) override {
        ex_.poll(!view.headless);
        glViewport(0, 0, view.width, view.height);
        if (s_->view3d)
            draw3d(view);
        else
            draw2d(view);
    }

    bool key(int k) override {
        if (ex_.key(k)) return true;
        AffineState& s = *s_;
        const bool pointMode = s.mode == AffineMode::ShadowPoint;
        switch (k) {
        case '1':
            s.mode = AffineMode::Mirror;
            return true;
        case '2':
            s.mode = AffineMode::ShadowDirectional;
            return true;
        case '3':
            s.mode = AffineMode::ShadowPoint;
            return true;
        case 'v':
            s.view3d = !s.view3d;
            return true;
        case 'r':
            reseed(s, s.seed + 1);
            return true;
        case kKeyLeft:
        case kKeyRight: {
            const double sign = k == kKeyLeft ? -1.0 : 1.0;
            if (s.view3d) {
                if (pointMode)
                    s.light3.x += 0.5 * sign;
                else
                    s.lightDir3.x += 0.1 * sign;
            } else if (pointMode) {
                s.light.x += 0.5 * sign;
            } else {
                s.lightAngle = std::clamp(s.lightAngle + 5.0 * sign, -85.0, 85.0);
            }
            return true;
        }
        case kKeyUp:
        case kKeyDown: {
            const double sign = k == kKeyDown ? -1.0 : 1.0;
            if (s.view3d) {
                if (pointMode)
                    s.light3.y += 0.5 * sign;
                else
                    s.lightDir3.z += 0.1 * sign;
            } else {
                s.light.y += 0.5 * sign;
            }
            return true;
        }
        default:
            return false;
        }
    }

    void gui() override {
        AffineState& s = *s_;
        ex_.gui();
        int mode = int(s.mode);
        ImGui::RadioButton(tr("1 mirror image"), &mode, 1);
        ImGui::RadioButton(tr("2 shadow, light at infinity along l"), &mode, 2);
        ImGui::RadioButton(tr("3 shadow, point light S"), &mode, 3);
        s.mode = AffineMode(mode);
        ImGui::Checkbox(tr("3D view (v)"), &s.view3d);
        if (!s.view3d) {
            int seed = int(s.seed);
            if (ImGui::InputInt(tr("seed (r)"), &seed) && seed >= 0) reseed(s, unsigned(seed));
            ImGui::TextWrapped("K = (%.3f, %.3f)  L = (%.3f, %.3f)", s.k.x, s.k.y, s.l.x, s.l.y);
            const Line2 line = affineLine(s);
            ImGui::TextWrapped(tr("line: %.4f x + %.4f y + %.4f = 0"), line.a, line.b, line.c);
            float angle = float(s.lightAngle);
            if (ImGui::SliderFloat(tr("angle of l (deg)"), &angle, -85.f, 85.f))
                s.lightAngle = angle;
            const glm::dvec2 l = affineLightDir(s);
            ImGui::Text("l = (%.3f, %.3f)", l.x, l.y);
            double sxy[2] = {s.light.x, s.light.y};
            if (ImGui::InputScalarN("S", ImGuiDataType_Double, sxy, 2)) s.light = {sxy[0], sxy[1]};
            if (kHaveReference) {
                const glm::dmat3 m = affineMatrix2d(s);
                ImGui::TextWrapped(tr("M (3x3), applied as M [P1 ... P%zu], then / w:"),
                                   affinePolygon().size());
                if (s.mode == AffineMode::ShadowPoint)
                    ImGui::TextWrapped(tr("(homogeneous: any non-zero multiple is the same map)"));
                matrix(glm::value_ptr(m), 3);
            }
            if (ex_.on()) {
                const std::optional<glm::dmat3> mine = studentMatrix();
                ImGui::TextWrapped("%s",
                                   mine ? tr("your M:") : tr("your M: none (not done or failing)"));
                if (mine) matrix(glm::value_ptr(*mine), 3);
            }
            ImGui::TextWrapped(tr("vertices at infinity: %zu, behind the light: %zu"),
                               lastAtInfinity_, lastBehind_);
        } else {
            double pl[4] = {s.plane.n.x, s.plane.n.y, s.plane.n.z, s.plane.d};
            if (ImGui::InputScalarN(tr("plane A B C D"), ImGuiDataType_Double, pl, 4) &&
                (pl[0] != 0 || pl[1] != 0 || pl[2] != 0))
                s.plane = {{pl[0], pl[1], pl[2]}, pl[3]};
            double sl[3] = {s.light3.x, s.light3.y, s.light3.z};
            if (ImGui::InputScalarN("S", ImGuiDataType_Double, sl, 3))
                s.light3 = {sl[0], sl[1], sl[2]};
            double ld[3] = {s.lightDir3.x, s.lightDir3.y, s.lightDir3.z};
            if (ImGui::InputScalarN("l", ImGuiDataType_Double, ld, 3) &&
                (ld[0] != 0 || ld[1] != 0 || ld[2] != 0))
                s.lightDir3 = {ld[0], ld[1], ld[2]};
            if (kHaveReference) {
                const glm::dmat4 m = affineMatrix3d(s);
                ImGui::TextWrapped(tr("M (4x4), given to glMultMatrixd:"));
                matrix(glm::value_ptr(m), 4);
            } else {
                ImGui::TextWrapped(tr("The 3D maps are lab 05's tasks: this handout draws "
                                      "none (your answers are drawn in lab 05)."));
            }
        }
        if (!kHaveReference) return;
        ImGui::Separator();
        ImGui::TextWrapped(tr("Exercise 1.1: mirror in 3x - 2y + 1 = 0"));
        ImGui::TextWrapped(tr("(1) T(0,1/2) R(phi) Mx R(-phi) T(0,-1/2), phi = atan(3/2):"));
        matrix(glm::value_ptr(exComposite_), 3);
        ImGui::TextWrapped(tr("(2) closed form I - 2 n (n, .)/(n, n):"));
        matrix(glm::value_ptr(exClosed_), 3);
        ImGui::TextWrapped(tr("max |(1) - (2)| = %.3g"), exDiff_);
    }

    // A matrix in the panel's monospaced font, so its columns line up.
    static void matrix(const double* m, int n) {
        ImGui::PushFont(panelMonoFont());
        ImGui::TextUnformatted(matrixText(m, n).c_str());
        ImGui::PopFont();
    }

  private:
    void draw2d(const View& view) {
        const AffineState& s = *s_;
        const double hh = kAffineHalfHeight / double(view.zoom > 0 ? view.zoom : 1.0f);
        const double hw = hh * double(view.width) / double(std::max(view.height, 1));
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_LIGHTING);
        glDisable(GL_BLEND);
        glClearColor(1, 1, 1, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-hw, hw, -hh, hh, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();

        // Grid every unit, axes darker.
        glLineWidth(1);
        glBegin(GL_LINES);
        for (int i = -int(std::ceil(hw)); i <= int(std::ceil(hw)); ++i) {
            glColor3ub(i == 0 ? 190 : 232, i == 0 ? 190 : 232, i == 0 ? 190 : 232);
            glVertex2d(i, -hh);
            glVertex2d(i, hh);
        }
        for (int i = -int(std::ceil(hh)); i <= int(std::ceil(hh)); ++i) {
            glColor3ub(i == 0 ? 190 : 232, i == 0 ? 190 : 232, i == 0 ? 190 : 232);
            glVertex2d(-hw, i);
            glVertex2d(hw, i);
        }
        glEnd();

        // The reference's rays under everything else, as the lab always drew them.
        if (!ex_.on() && kHaveReference) drawImage(affineMatrix2d(s), s, true, false);

        // The line Λ, drawn across the whole view, and K, L.
        const glm::dvec2 d = glm::normalize(s.l - s.k) * (4.0 * (hw + hh));
        color(kLineColor);
        glLineWidth(2);
        glBegin(GL_LINES);
        glVertex2dv(glm::value_ptr(glm::dvec2(s.k - d)));
        glVertex2dv(glm::value_ptr(glm::dvec2(s.k + d)));
        glEnd();
        glPointSize(7);
        glColor3ub(0, 90, 0);
        glBegin(GL_POINTS);
        glVertex2dv(glm::value_ptr(s.k));
        glVertex2dv(glm::value_ptr(s.l));
        glEnd();

        // The object, filled, outline darker.
        const std::vector<glm::dvec2>& poly = affinePolygon();
        fillPolygon(poly, std::vector<bool>(poly.size(), true), kPolygonColor);
        outline(poly, std::vector<bool>(poly.size(), true), 20, 50, 140, 2);

        // Your code (e): your matrix's image, and the reference's as a ghost over it.
        if (ex_.on()) {
            if (const std::optional<glm::dmat3> mine = studentMatrix())
                drawImage(*mine, s, true, true);
            if (kHaveReference) {
                ex::ExerciseMode::ghostBegin();
                drawImage(affineMatrix2d(s), s, true, true);
                ex::ExerciseMode::ghostEnd();
            }
        } else {
            drawImage(affineMatrix2d(s), s, false, true);
        }
        if (s.mode != AffineMode::Mirror) drawLight2d(s, hw, hh);
        glLineWidth(1);
        glPointSize(1);
    }

    // The polygon's image under m (mirror image filled, shadow as a thick outline on Λ)
    // with the rays from the light to it.
    void drawImage(const glm::dmat3& m, const AffineState& s, bool rays, bool image) {
        const std::vector<glm::dvec2>& poly = affinePolygon();
        // The lab's point: all vertices in ONE product M·[P1 ... Pn], then divide by w.
        const HomogeneousColumns<3> h = multiply(m, toHomogeneous(poly));
        const ProjectedPoints<glm::dvec2> img = dehomogenize(h);
        lastAtInfinity_ = img.atInfinity;
        lastBehind_ = 0;
        std::vector<bool> usable(poly.size());
        for (size_t i = 0; i < poly.size(); ++i) {
            // Under the point-light matrix w > 0 exactly for vertices nearer the line than S.
            usable[i] = img.kinds[i] == PointKind::Finite && h.at(2, i) > 0;
            if (img.kinds[i] == PointKind::Finite && h.at(2, i) <= 0) ++lastBehind_;
        }

        // Rays from the light through each vertex to its shadow, dotted.
        if (rays && s.mode != AffineMode::Mirror) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(2, 0xAAAA);
            glColor3ub(230, 150, 0);
            glBegin(GL_LINES);
            const glm::dvec2 l = affineLightDir(s);
            for (size_t i = 0; i < poly.size(); ++i) {
                if (!usable[i]) continue;
                const glm::dvec2 from =
                    s.mode == AffineMode::ShadowPoint ? s.light : poly[i] - 3.0 * l;
                glVertex2dv(glm::value_ptr(from));
                glVertex2dv(glm::value_ptr(img.points[i]));
            }
            glEnd();
            glDisable(GL_LINE_STIPPLE);
        }

        if (!image) return;
        if (s.mode == AffineMode::Mirror) {
            fillPolygon(img.points, usable, kImageColor);
            outline(img.points, usable, 140, 20, 20, 2);
        } else {
            // A shadow on a line has no area: its outline collapses onto Λ.
            outline(img.points, usable, kShadowColor[0], kShadowColor[1], kShadowColor[2],
                    float(kShadowLineWidth));
        }
    }

    static void fillPolygon(const std::vector<glm::dvec2>& p, const std::vector<bool>& ok,
                            const std::array<unsigned char, 3>& c) {
        color(c);
        glBegin(GL_TRIANGLES);
        for (const auto& t : affinePolygonTriangles()) {
            if (!ok[size_t(t[0])] || !ok[size_t(t[1])] || !ok[size_t(t[2])]) continue;
            for (int i : t)
                glVertex2dv(glm::value_ptr(p[size_t(i)]));
        }
        glEnd();
    }

    static void outline(const std::vector<glm::dvec2>& p, const std::vector<bool>& ok,
                        unsigned char r, unsigned char g, unsigned char b, float width) {
        glColor3ub(r, g, b);
        glLineWidth(width);
        glBegin(GL_LINES);
        for (size_t i = 0; i < p.size(); ++i) {
            const size_t j = (i + 1) % p.size();
            if (!ok[i] || !ok[j]) continue;
            glVertex2dv(glm::value_ptr(p[i]));
            glVertex2dv(glm::value_ptr(p[j]));
        }
        glEnd();
    }

    static void drawLight2d(const AffineState& s, double hw, double hh) {
        if (s.mode == AffineMode::ShadowPoint) {
            glColor3ub(255, 200, 0);
            glPointSize(13);
            glBegin(GL_POINTS);
            glVertex2dv(glm::value_ptr(s.light));
            glEnd();
            glColor3ub(120, 80, 0);
            glPointSize(5);
            glBegin(GL_POINTS);
            glVertex2dv(glm::value_ptr(s.light));
            glEnd();
            return;
        }
        // A fan of three parallel arrows along l near the top-left corner.
        const glm::dvec2 l = affineLightDir(s), side(-l.y, l.x);
        const glm::dvec2 base(-hw + 2.2, hh - 2.2);
        glColor3ub(230, 150, 0);
        glLineWidth(2);
        glBegin(GL_LINES);
        for (int i = -1; i <= 1; ++i) {
            const glm::dvec2 a = base + 0.8 * double(i) * side - 0.9 * l,
                             b = base + 0.8 * double(i) * side + 0.9 * l;
            glVertex2dv(glm::value_ptr(a));
            glVertex2dv(glm::value_ptr(b));
            for (double sgn : {-1.0, 1.0}) {
                glVertex2dv(glm::value_ptr(b));
                glVertex2dv(glm::value_ptr(glm::dvec2(b - 0.35 * l + sgn * 0.2 * side)));
            }
        }
        glEnd();
    }

    void draw3d(const View& view) {
        const AffineState& s = *s_;
        glClearColor(0.93f, 0.95f, 1.0f, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        const double fovy = std::min(40.0 / double(view.zoom > 0 ? view.zoom : 1.0f), 170.0);
        gluPerspective(fovy, double(view.width) / double(std::max(view.height, 1)), 0.5, 200.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslated(0, -1.5, -21);
        glRotated(22, 1, 0, 0); // look down on the plane by default
        glRotatef(view.pitch, 1, 0, 0);
        glRotatef(view.yaw - 25.0f, 0, 1, 0);

        // Light: GL_LIGHT0 where the lab's light is (w = 0 for the light at infinity).
        glEnable(GL_LIGHT0);
        glEnable(GL_NORMALIZE);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        const glm::dvec3 ld = glm::normalize(s.lightDir3);
        const float pos[4] = {s.mode == AffineMode::ShadowPoint ? float(s.light3.x) : float(-ld.x),
                              s.mode == AffineMode::ShadowPoint ? float(s.light3.y) : float(-ld.y),
                              s.mode == AffineMode::ShadowPoint ? float(s.light3.z) : float(-ld.z),
                              s.mode == AffineMode::ShadowPoint ? 1.0f : 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);

        // A handout has no 3D maps (core's, lab 05's tasks): the plane and the object only.
        const glm::dmat4 m = kHaveReference ? affineMatrix3d(s) : glm::dmat4(1.0);
        if (s.mode == AffineMode::Mirror) {
            // The image first, through the mirror matrix (det −1 turns the winding over).
            if (kHaveReference) {
                glPushMatrix();
                glMultMatrixd(glm::value_ptr(m));
                glFrontFace(GL_CW);
                glEnable(GL_LIGHTING);
                glColor3ub(kImageColor[0], kImageColor[1], kImageColor[2]);
                drawPrism(true);
                glFrontFace(GL_CCW);
                glPopMatrix();
            }
            // The plane, half transparent so the image behind it shows.
            glDisable(GL_LIGHTING);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            drawPlane(s.plane, 0.55f);
            glDisable(GL_BLEND);
        } else {
            glDisable(GL_LIGHTING);
            drawPlane(s.plane, 1.0f);
            // The shadow: the object squashed onto the plane by M; pulled towards the
            // eye in depth so it wins against the plane it lies in.
            if (kHaveReference) {
                glEnable(GL_POLYGON_OFFSET_FILL);
                glPolygonOffset(-1, -2);
                glPushMatrix();
                glMultMatrixd(glm::value_ptr(m));
                glColor3ub(kShadowColor[0], kShadowColor[1], kShadowColor[2]);
                drawPrism(false);
                glPopMatrix();
                glDisable(GL_POLYGON_OFFSET_FILL);
            }
            drawLight3d(s);
        }
        glEnable(GL_LIGHTING);
        glColor3ub(kPolygonColor[0], kPolygonColor[1], kPolygonColor[2]);
        drawPrism(true);
        glDisable(GL_LIGHTING);
        glDisable(GL_COLOR_MATERIAL);
        glDisable(GL_DEPTH_TEST);
    }

    // A 24×24 square of the plane around its point nearest the origin, with a grid.
    static void drawPlane(const Plane& p, float alpha) {
        const glm::dvec3 n = glm::normalize(p.n);
        const glm::dvec3 o = -p.d / glm::dot(p.n, p.n) * p.n;
        const glm::dvec3 t1 = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, {1, 0, 0})
                                                                 : glm::cross(n, {0, 1, 0}));
        const glm::dvec3 t2 = glm::cross(n, t1);
        const double h = 12;
        glColor4f(0.78f, 0.80f, 0.78f, alpha);
        glBegin(GL_QUADS);
        for (const glm::dvec2 c :
             {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
            glVertex3dv(glm::value_ptr(glm::dvec3(o + h * c.x * t1 + h * c.y * t2)));
        glEnd();
        glEnable(GL_POLYGON_OFFSET_LINE);
        glPolygonOffset(-1, -1);
        glColor4f(0.62f, 0.64f, 0.62f, alpha);
        glBegin(GL_LINES);
        for (int i = -12; i <= 12; i += 2) {
            const double x = double(i);
            for (const auto& [a, b] : {std::pair{t1, t2}, std::pair{t2, t1}}) {
                glVertex3dv(glm::value_ptr(glm::dvec3(o + x * a - h * b)));
                glVertex3dv(glm::value_ptr(glm::dvec3(o + x * a + h * b)));
            }
        }
        glEnd();
        glDisable(GL_POLYGON_OFFSET_LINE);
    }

    static void drawLight3d(const AffineState& s) {
        glColor3ub(255, 190, 0);
        if (s.mode == AffineMode::ShadowPoint) {
            glPointSize(10);
            glBegin(GL_POINTS);
            glVertex3dv(glm::value_ptr(s.light3));
            glEnd();
            glPointSize(1);
            return;
        }
        const glm::dvec3 l = glm::normalize(s.lightDir3);
        glLineWidth(2);
        glBegin(GL_LINES);
        for (int i = -1; i <= 1; ++i) {
            // Three parallel rays above the object, ending where they would meet its top.
            const glm::dvec3 end(1.0 * i, 5.6, 0.0);
            glVertex3dv(glm::value_ptr(glm::dvec3(end - 3.0 * l)));
            glVertex3dv(glm::value_ptr(end));
        }
        glEnd();
        glLineWidth(1);
    }

    // Your matrix for the current mode and inputs, when the task's check let it be called.
    std::optional<glm::dmat3> studentMatrix() const {
        const AffineState& s = *s_;
        const lab01::Table* t = ex_.studentTable<lab01::Table>();
        if (!t) return std::nullopt;
        std::optional<glm::dmat3> m;
        switch (s.mode) {
        case AffineMode::Mirror:
            m = ex_.call(
                "01.mirror", [&] { return t->mirror(s.k, s.l); }, s.k, s.l);
            break;
        case AffineMode::ShadowDirectional:
            m = ex_.call(
                "01.shadow-dir", [&] { return t->shadowDirectional(s.k, s.l, affineLightDir(s)); },
                s.k, s.l, affineLightDir(s));
            break;
        case AffineMode::ShadowPoint:
            m = ex_.call(
                "01.shadow-point", [&] { return t->shadowPoint(s.k, s.l, s.light); }, s.k, s.l,
                s.light);
            break;
        }
        if (!m) return m;
        // Any non-zero multiple is the same map; drawn with the reference's sign so that
        // w > 0 marks the same vertices (GL and this lab skip w <= 0). In a handout: the sign
        // that makes w > 0 at the polygon's first vertex (on the light's side).
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                if (!std::isfinite((*m)[c][r])) return std::nullopt;
        double dot = ((*m) * glm::dvec3(affinePolygon()[0], 1.0)).z;
        if (kHaveReference) {
            const glm::dmat3 ref = affineMatrix2d(s);
            dot = 0;
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r)
                    dot += (*m)[c][r] * ref[c][r];
        }
        if (dot < 0) *m = -*m;
        return m;
    }

    AffineState own_;
    AffineState* s_;
    ex::ExerciseMode ex_;
    glm::dmat3 exComposite_{1.0}, exClosed_{1.0};
    double exDiff_ = 0;
    size_t lastAtInfinity_ = 0, lastBehind_ = 0;
};

} // namespace

const std::vector<glm::dvec2>& affinePolygon() {
    static const std::vector<glm::dvec2> p = makePolygon();
    return p;
}

const std::vector<std::array<int, 3>>& affinePolygonTriangles() {
    // Hand triangulation of the F (counter-clockwise triples): stem, middle bar, top bar.
    static const std::vector<std::array<int, 3>> t = {{0, 1, 2}, {0, 2, 5}, {0, 5, 9}, {5, 6, 9},
                                                      {6, 8, 9}, {6, 7, 8}, {2, 3, 4}, {2, 4, 5}};
    return t;
}

void reseed(AffineState& s, unsigned seed) {
    s.seed = seed;
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> ux(-9.0, 9.0), uy(-7.0, 7.0);
    const std::vector<glm::dvec2>& poly = affinePolygon();
    const glm::dvec2 c = centroid(poly);
    const double r = radius(poly, c);
    for (int attempt = 0; attempt < 10000; ++attempt) {
        s.k = {ux(gen), uy(gen)};
        s.l = {ux(gen), uy(gen)};
        if (glm::length(s.l - s.k) < 3.0) continue;
        const Line2 line = affineLine(s);
        const double dist = std::abs(signedDistance(line, c));
        if (dist < r + 0.8 || dist > 6.0) continue;
        if (kHaveReference) {
            const glm::dvec3 mc = mirrorLine(line) * glm::dvec3(c, 1.0);
            if (std::abs(mc.x) > 9.5 - r || std::abs(mc.y) > 8.5 - r) continue;
        }
        // S: beyond the polygon seen from Λ, a little to the side.
        const glm::dvec2 n = normalTowardsPolygon(s), t(-n.y, n.x);
        s.light = c + n * (r + 1.5) + t * 1.0;
        if (std::abs(s.light.x) > 11.0 || std::abs(s.light.y) > 8.5) continue;
        return;
    }
    // Not reached for the view size above; keep a fixed valid layout if it ever is.
    s.k = {-8, -6};
    s.l = {8, -2};
    s.light = c + glm::dvec2(0.5, 4.0);
}

Line2 affineLine(const AffineState& s) {
    return lineThrough(s.k, s.l);
}

glm::dvec2 affineLightDir(const AffineState& s) {
    const glm::dvec2 n = normalTowardsPolygon(s);
    const double a = s.lightAngle * kPi / 180.0;
    // −n (towards Λ) turned by the angle.
    return {-n.x * std::cos(a) + n.y * std::sin(a), -n.x * std::sin(a) - n.y * std::cos(a)};
}

glm::dmat3 affineMatrix2d(const AffineState& s) {
    const Line2 line = affineLine(s);
    switch (s.mode) {
    case AffineMode::Mirror:
        return mirrorLine(line);
    case AffineMode::ShadowDirectional:
        return shadowLineDirectional(line, affineLightDir(s));
    case AffineMode::ShadowPoint:
        return shadowLinePoint(line, s.light);
    }
    return glm::dmat3(1.0);
}

glm::dmat4 affineMatrix3d(const AffineState& s) {
    switch (s.mode) {
    case AffineMode::Mirror:
        return mirrorPlane(s.plane);
    case AffineMode::ShadowDirectional:
        return shadowDirectional(s.plane, s.lightDir3);
    case AffineMode::ShadowPoint:
        return shadowPoint(s.plane, s.light3);
    }
    return glm::dmat4(1.0);
}

glm::dvec2 affinePixelToWorld(int width, int height, float zoom, double px, double py) {
    const double hh = kAffineHalfHeight / double(zoom > 0 ? zoom : 1.0f);
    const double hw = hh * double(width) / double(std::max(height, 1));
    return {-hw + 2.0 * hw * px / double(width), hh - 2.0 * hh * py / double(height)};
}

std::unique_ptr<Lab> makeAffineLab() {
    return std::make_unique<AffineLab>(nullptr);
}
std::unique_ptr<Lab> makeAffineLab(AffineState* observe) {
    return std::make_unique<AffineLab>(observe);
}

} // namespace wb
