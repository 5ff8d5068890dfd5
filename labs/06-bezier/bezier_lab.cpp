#include "bezier_lab.h"

#include "common/gl_util.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

namespace wb {
namespace {

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
    explicit BezierLab(BezierLabState* s) : s_(s ? s : &own_) {}
    std::string title() const override { return "Lab 06 - Bezier curves and patches"; }
    std::vector<KeyHelp> keys() const override {
        return {{"1", "circle: two Bezier curves"},
                {"2", "sphere: two Bezier patches"},
                {"c", "control polygon / net"},
                {"[", "grid halve"},
                {"]", "grid double"},
                {"a", "next approximation"},
                {"w", "sphere wireframe"},
                {"t", "true circle / sphere (grey)"},
                {"n", "normals: GL_AUTO_NORMAL / core"}};
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
    void drawSphere();
    // Patch p of the current sphere as quad strips with core's points and normals.
    void drawCoreMesh(size_t p);
    void recordTime(double ms);
    // The GL time of one mesh at the current shape/variant/grid: median of the last frames.
    double medianMs() const;
    // Error of the drawn tessellation at grid n, for the current shape and variant (cached).
    double meshError(int n);

    BezierLabState own_;
    BezierLabState* s_;
    std::map<std::tuple<int, int, int>, std::vector<double>> times_; // (shape, variant, grid) -> ms
    std::map<std::tuple<int, int, int>, double> errors_; // (shape, variant, grid) -> error
    // Core tessellation of (variant, patch, grid): points then normals.
    std::map<std::tuple<int, size_t, int>,
             std::pair<std::vector<glm::dvec3>, std::vector<glm::dvec3>>>
        meshes_;
};

std::tuple<int, int, int> keyOf(const BezierLabState& s) {
    return {s.shape, s.shape == 0 ? s.circleVariant : s.sphereVariant, s.grid};
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
    const auto k = std::make_tuple(s.shape, s.shape == 0 ? s.circleVariant : s.sphereVariant, n);
    auto it = errors_.find(k);
    if (it != errors_.end()) return it->second;
    double e;
    if (s.shape == 0) {
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
    glClearColor(0.97f, 0.97f, 0.95f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    // Orthographic, so that radii on screen are radii in the scene.
    const double h = (s_->shape == 0 ? kBezierViewHalfHeight : kBezierSphereViewHalfHeight) /
                     double(view.zoom > 0.0f ? view.zoom : 1.0f);
    const double aspect = double(view.width) / double(view.height > 0 ? view.height : 1);
    glOrtho(-h * aspect, h * aspect, -h, h, -20.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    applyOrbit(view);
    if (s_->shape == 0)
        drawCircle();
    else
        drawSphere();
}

void BezierLab::drawCircle() {
    const BezierLabState& s = *s_;
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

void BezierLab::drawSphere() {
    const BezierLabState& s = *s_;
    const SphereVariant& v = bezierSphereVariants()[size_t(s.sphereVariant)];
    glRotated(kBezierSphereTilt, 1.0, 0.0, 0.0);
    glEnable(GL_DEPTH_TEST);

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
    const GLfloat colours[2][4] = {{0.9f, 0.65f, 0.2f, 1.0f}, {0.3f, 0.55f, 0.95f, 1.0f}};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t p = 0; p < v.patches.size(); ++p) {
        const BezierPatch& patch = v.patches[p];
        const std::vector<float> pts = toFloats(patch.points);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colours[p % 2]);
        if (s.coreNormals) {
            drawCoreMesh(p);
            continue;
        }
        glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, patch.orderU, 0.0f, 1.0f, 3 * patch.orderU,
                patch.orderV, pts.data());
        glMapGrid2f(s.grid, 0.0f, 1.0f, s.grid, 0.0f, 1.0f);
        glEvalMesh2(s.wireframe ? GL_LINE : GL_FILL, 0, s.grid, 0, s.grid);
    }
    glFinish();
    if (!s.coreNormals) // the table is about the GL evaluator
        recordTime(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                       .count());
    glDisable(GL_MAP2_VERTEX_3);
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_NORMALIZE);
    glDisable(GL_LIGHTING);

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
}

void BezierLab::drawCoreMesh(size_t p) {
    const BezierLabState& s = *s_;
    auto& mesh = meshes_[{s.sphereVariant, p, s.grid}];
    if (mesh.first.empty())
        tessellatePatch(bezierSphereVariants()[size_t(s.sphereVariant)].patches[p], s.grid,
                        mesh.first, mesh.second);
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
    BezierLabState& s = *s_;
    switch (k) {
    case '1':
        s.shape = 0;
        return true;
    case '2':
        s.shape = 1;
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
        else
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
    // The panel is narrow: one short item per line, numbers on their own lines.
    BezierLabState& s = *s_;
    ImGui::RadioButton("circle (1)", &s.shape, 0);
    ImGui::SameLine();
    ImGui::RadioButton("sphere (2)", &s.shape, 1);
    ImGui::Checkbox("control net (c)", &s.showControl);
    ImGui::SameLine();
    ImGui::Checkbox("true shape (t)", &s.showTrue);
    if (s.shape == 1) {
        ImGui::Checkbox("wireframe (w)", &s.wireframe);
        ImGui::SameLine();
        ImGui::Checkbox("core normals (n)", &s.coreNormals);
        ImGui::TextWrapped("At the 4 corners of each patch the boundary curves are tangent, "
                           "du x dv = 0: GL_AUTO_NORMAL has no normal there (dark spots on "
                           "the equator). 'core normals' draws the grid from evalPatch, "
                           "which takes the limit from inside the patch.");
    }
    ImGui::SliderInt("grid ([ ])", &s.grid, kMinGrid, kMaxGrid);

    ImGui::Separator();
    ImGui::TextWrapped("Control points (a) and the radial error of the exact Bezier shape:");
    if (s.shape == 0) {
        const auto& vs = bezierCircleVariants();
        for (int i = 0; i < int(vs.size()); ++i) {
            const auto& v = vs[size_t(i)];
            ImGui::RadioButton(v.name.c_str(), &s.circleVariant, i);
            ImGui::Text("      max |r-1| = %.3g", v.error.maxError);
        }
    } else {
        const auto& vs = bezierSphereVariants();
        for (int i = 0; i < int(vs.size()); ++i) {
            const auto& v = vs[size_t(i)];
            ImGui::RadioButton(v.name.c_str(), &s.sphereVariant, i);
            ImGui::Text("      max |r-R|/R = %.3g", v.error.relative());
            ImGui::Text("      r in [%.4f, %.4f]", v.error.minRadius, v.error.maxRadius);
        }
        ImGui::TextWrapped("R is the minimax radius (min+max)/2: the course's net names none.");
    }

    ImGui::Separator();
    const double ms = medianMs();
    ImGui::Text("GL time per mesh, grid %d:", s.grid);
    ImGui::Text("   %s", ms < 0 ? "(not drawn yet)" : fmt("%.3f ms", ms).c_str());
    ImGui::TextWrapped("Speed against error: drawn line strip / triangles against the true shape "
                       "(ms: median GL time seen at that grid; visit it with [ ]).");
    if (ImGui::BeginTable("grid", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("grid");
        ImGui::TableSetupColumn(s.shape == 0 ? "max |r-1|" : "max |r-R|/R");
        ImGui::TableSetupColumn("ms/mesh");
        ImGui::TableHeadersRow();
        const int keep = s.grid;
        for (int n = 4; n <= kMaxGrid; n *= 2) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%d%s", n, n == keep ? " <" : "");
            ImGui::TableNextColumn();
            ImGui::Text("%.3g", meshError(n));
            ImGui::TableNextColumn();
            s.grid = n;
            const double t = medianMs();
            s.grid = keep;
            if (t >= 0)
                ImGui::Text("%.3f", t);
            else
                ImGui::TextUnformatted("-");
        }
        ImGui::EndTable();
    }
    ImGui::TextWrapped("Full table: docs/bench/bezier.md (bin/bezier_bench).");
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
            SphereVariant v{i == 0 ? "course net (lab 6)" : "fitted net",
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
