// Lab 06 under OSMesa: core's Bezier points and normals against what Mesa's
// evaluators (glEvalCoord, glEvalMesh, GL_AUTO_NORMAL) produce, captured in
// GL_FEEDBACK mode; goldens of the lab's key states; and properties of the picture
// (the drawn circle lies in the band its radial error allows, the sphere's
// silhouette lies between its smallest and largest radius).
#include "bezier_lab.h"
#include "common/gl.h"
#include "core/bezier.h"
#include "core/bezier_shapes.h"
#include "render_check.h"

#include "common/options.h"

#include <imgui.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>

using glm::dvec3;
using wb::BezierCurve;
using wb::BezierPatch;

namespace {

// Mesa evaluates maps in float: about ten roundings of coordinates up to 5
// (ulp 4.8e-7), then float window coordinates (ulp 6e-5 at 800 px = 6e-7 in the
// scene). 1e-5 is twice that bound; a wrong stride, order or layout errs by O(1).
constexpr double kFloatEvalTol = 1e-5;
constexpr int kFeedbackSize = 512; // viewport of the feedback lab, pixels
constexpr double kOrtho = 8.0;     // the scene box [-8, 8]³ maps onto the viewport

// A lab whose draw() runs `body` in GL_FEEDBACK mode with an identity modelview and
// glOrtho(±8), and returns the feedback buffer.
class FeedbackLab : public wb::Lab {
  public:
    FeedbackLab(GLenum type, std::function<void()> body) : type_(type), body_(std::move(body)) {}
    std::string title() const override { return "feedback"; }
    std::vector<wb::KeyHelp> keys() const override { return {}; }
    bool key(int) override { return false; }
    void draw(const wb::View&) override {
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-kOrtho, kOrtho, -kOrtho, kOrtho, -kOrtho, kOrtho);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        buffer.assign(1 << 20, 0.0f);
        glFeedbackBuffer(GLsizei(buffer.size()), type_, buffer.data());
        glRenderMode(GL_FEEDBACK);
        body_();
        const GLint n = glRenderMode(GL_RENDER);
        buffer.resize(n > 0 ? size_t(n) : 0);
        overflow = n < 0;
    }
    std::vector<GLfloat> buffer;
    bool overflow = false;

  private:
    GLenum type_;
    std::function<void()> body_;
};

struct FeedbackVertex {
    dvec3 p;         // back in scene coordinates
    glm::dvec4 rgba; // with GL_3D_COLOR
};

// The vertices of the GL_POINT_TOKENs in a feedback buffer.
std::vector<FeedbackVertex> points(const std::vector<GLfloat>& b, bool colour) {
    std::vector<FeedbackVertex> out;
    const size_t stride = colour ? 7 : 3;
    for (size_t i = 0; i < b.size();) {
        const auto token = GLenum(b[i]);
        REQUIRE(token == GL_POINT_TOKEN); // only points are drawn here
        REQUIRE(i + stride < b.size() + 1);
        FeedbackVertex v;
        // Window x = (x_ndc + 1)·W/2, depth = (z_ndc + 1)/2 with z_ndc = -z/8 for glOrtho.
        v.p = {(b[i + 1] / (kFeedbackSize / 2.0) - 1.0) * kOrtho,
               (b[i + 2] / (kFeedbackSize / 2.0) - 1.0) * kOrtho, -(2.0 * b[i + 3] - 1.0) * kOrtho};
        if (colour) v.rgba = {b[i + 4], b[i + 5], b[i + 6], b[i + 7]};
        out.push_back(v);
        i += 1 + stride;
    }
    return out;
}

std::vector<float> floats(const std::vector<dvec3>& p) {
    std::vector<float> f;
    for (const auto& q : p)
        f.insert(f.end(), {float(q.x), float(q.y), float(q.z)});
    return f;
}

BezierPatch randomPatch(int orderU, int orderV, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-3.0, 3.0);
    BezierPatch p{orderU, orderV, {}};
    for (int i = 0; i < orderU * orderV; ++i)
        p.points.push_back({d(rng), d(rng), d(rng)});
    return p;
}

void mapPatch(const BezierPatch& p, const std::vector<float>& data) {
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, p.orderU, 0.0f, 1.0f, 3 * p.orderU, p.orderV,
            data.data());
    glEnable(GL_MAP2_VERTEX_3);
}

std::vector<FeedbackVertex> capture(GLenum type, std::function<void()> body) {
    FeedbackLab lab(type, std::move(body));
    wb::test::renderLab(lab, kFeedbackSize, kFeedbackSize);
    REQUIRE_FALSE(lab.overflow);
    return points(lab.buffer, type == GL_3D_COLOR);
}

} // namespace

TEST_CASE("glEvalCoord2f points agree with core evalPatch", "[gl][bezier]") {
    for (const BezierPatch& patch :
         {wb::labHemisphereNet(), randomPatch(4, 3, 1), randomPatch(2, 5, 2)}) {
        const std::vector<float> data = floats(patch.points);
        const std::vector<float> us{0.0f, 1e-12f, 0.1f, 0.5f, 0.77f, 1.0f};
        const auto got = capture(GL_3D, [&] {
            mapPatch(patch, data);
            glBegin(GL_POINTS);
            for (float v : us)
                for (float u : us)
                    glEvalCoord2f(u, v);
            glEnd();
        });
        REQUIRE(got.size() == us.size() * us.size());
        size_t k = 0;
        for (float v : us)
            for (float u : us) {
                // Core evaluates at the same float parameters, in double.
                const dvec3 ref = wb::evalPatch(patch, double(u), double(v)).point;
                INFO("u " << u << " v " << v << " orders " << patch.orderU << "x" << patch.orderV);
                CHECK(glm::length(got[k++].p - ref) <= kFloatEvalTol);
            }
    }
}

TEST_CASE("glMapGrid2f + glEvalMesh2 points agree with core's grid", "[gl][bezier]") {
    const BezierPatch patch = wb::labHemisphereNet();
    const std::vector<float> data = floats(patch.points);
    const int n = 16;
    const auto got = capture(GL_3D, [&] {
        mapPatch(patch, data);
        glMapGrid2f(n, 0.0f, 1.0f, n, 0.0f, 1.0f);
        glEvalMesh2(GL_POINT, 0, n, 0, n);
    });
    REQUIRE(got.size() == size_t((n + 1) * (n + 1)));
    std::vector<dvec3> pts, nrm;
    wb::tessellatePatch(patch, n, pts, nrm);
    // Order-free: every GL point has a core grid point within the tolerance, and
    // the nearest core point of each is distinct (a bijection, not all on one point).
    std::vector<int> used(pts.size(), 0);
    for (const auto& g : got) {
        size_t best = 0;
        for (size_t i = 1; i < pts.size(); ++i)
            if (glm::length(pts[i] - g.p) < glm::length(pts[best] - g.p)) best = i;
        CHECK(glm::length(pts[best] - g.p) <= kFloatEvalTol);
        ++used[best];
    }
    CHECK(std::count(used.begin(), used.end(), 1) == int(used.size()));
}

TEST_CASE("glMap1f + glEvalMesh1 points agree with de Casteljau", "[gl][bezier]") {
    for (const BezierCurve& c :
         {wb::circleArcs(2, wb::circleHandle(2))[0],
          BezierCurve{{-3, -1, 2}, {0, 4, -1}, {2, -3, 0}, {3, 3, 3}, {1, 0, -2}}}) {
        const std::vector<float> data = floats(c);
        const int n = 64;
        const auto got = capture(GL_3D, [&] {
            glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, GLint(c.size()), data.data());
            glEnable(GL_MAP1_VERTEX_3);
            glMapGrid1f(n, 0.0f, 1.0f);
            glEvalMesh1(GL_POINT, 0, n);
        });
        REQUIRE(got.size() == size_t(n + 1));
        for (int i = 0; i <= n; ++i) { // the spec's order: i = 0..n
            const double u = double(float(i) * (1.0f / float(n)));
            CHECK(glm::length(got[size_t(i)].p - wb::evalDeCasteljau(c, u)) <= kFloatEvalTol);
        }
    }
}

TEST_CASE("GL_AUTO_NORMAL agrees with core normals except at the tangent corners", "[gl][bezier]") {
    // Normals read back through lighting: three directional lights along +x, +y, +z
    // (then -x, -y, -z) with red, green, blue diffuse colour and a white material give
    // colour = max(0, ±n) per channel, unclamped-safe since |n| = 1 after GL_NORMALIZE.
    const BezierPatch patch = wb::labHemisphereNet();
    const std::vector<float> data = floats(patch.points);
    const std::vector<float> us{0.0f, 0.2f, 0.5f, 0.9f, 1.0f};
    dvec3 sign(1.0);
    auto body = [&] {
        const GLfloat black[] = {0, 0, 0, 1}, white[] = {1, 1, 1, 1};
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, black);
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
        for (int l = 0; l < 3; ++l) {
            GLfloat dir[4] = {0, 0, 0, 0}, col[4] = {0, 0, 0, 1};
            dir[l] = float(sign[l]);
            col[l] = 1;
            glLightfv(GLenum(GL_LIGHT0 + l), GL_POSITION, dir);
            glLightfv(GLenum(GL_LIGHT0 + l), GL_DIFFUSE, col);
            glLightfv(GLenum(GL_LIGHT0 + l), GL_SPECULAR, black);
            glLightfv(GLenum(GL_LIGHT0 + l), GL_AMBIENT, black);
            glEnable(GLenum(GL_LIGHT0 + l));
        }
        glEnable(GL_LIGHTING);
        glEnable(GL_AUTO_NORMAL);
        glEnable(GL_NORMALIZE);
        mapPatch(patch, data);
        glBegin(GL_POINTS);
        for (float v : us)
            for (float u : us)
                glEvalCoord2f(u, v);
        glEnd();
    };
    const auto pos = capture(GL_3D_COLOR, body);
    sign = dvec3(-1.0);
    const auto neg = capture(GL_3D_COLOR, body);
    REQUIRE(pos.size() == us.size() * us.size());
    REQUIRE(neg.size() == pos.size());
    size_t k = 0, corners = 0;
    for (float v : us)
        for (float u : us) {
            const wb::PatchSample s = wb::evalPatch(patch, double(u), double(v));
            const dvec3 gl = dvec3(pos[k].rgba) - dvec3(neg[k].rgba);
            ++k;
            INFO("u " << u << " v " << v << " GL normal " << gl.x << " " << gl.y << " " << gl.z);
            if (s.normalKind == 0) {
                // Float normals and float lighting: ~1e-6; colours are kept as floats in
                // feedback. 1e-4 leaves room for Mesa's normalisation in float.
                CHECK(glm::length(gl - s.normal) <= 1e-4);
            } else {
                // A patch corner where du ∥ dv: GL_AUTO_NORMAL has du × dv = 0, so lighting
                // sees no usable normal, while core returns the limit from inside.
                ++corners;
                CHECK(glm::length(gl - s.normal) > 0.5);
                CHECK(std::abs(glm::length(s.normal) - 1.0) < 1e-12);
            }
        }
    CHECK(corners == 4);
}

namespace {

// The clear colour (0.97, 0.97, 0.95) is (247, 247, 242); the white highlight is brighter.
bool isBackground(const uint8_t* p) {
    return std::abs(p[0] - 247) <= 2 && std::abs(p[1] - 247) <= 2 && std::abs(p[2] - 242) <= 2;
}

wb::Image renderBezier(const std::string& keys, int w, int h, wb::BezierLabState* state = nullptr) {
    wb::BezierLabState own;
    auto lab = wb::makeBezierLab(state ? state : &own);
    return wb::test::renderLab(*lab, w, h, keys);
}

} // namespace

TEST_CASE("Lab 06 goldens", "[gl][bezier]") {
    // llvmpipe renders these bit-exactly run to run on this machine (max diff 0 measured);
    // 16/255 and a mean of 0.3 admit lighting rounding in another Mesa build, not a moved
    // curve, a missing patch or a changed control net (each a full-contrast change of
    // hundreds of pixels, a mean above 1).
    const std::vector<std::pair<std::string, std::string>> shots{
        {"", "lab06-circle"},           {"c", "lab06-circle-control"},
        {"aa]t", "lab06-circle-4arcs"}, {"2", "lab06-sphere"},
        {"2c", "lab06-sphere-net"},     {"2a", "lab06-sphere-fitted"},
        {"2w[", "lab06-sphere-wire-8"}, {"2n", "lab06-sphere-core-normals"},
        {"3", "lab06-teapot"},          {"3n", "lab06-teapot-core-normals"}};
    for (const auto& [keys, name] : shots) {
        INFO("keys '" << keys << "'");
        wb::test::checkGolden(renderBezier(keys, 160, 120), name, 16, 0.3);
    }
}

TEST_CASE("The drawn circle lies in the band of its radial error", "[gl][bezier]") {
    // 240×240, grid 256: the drawn polyline is within 1e-4 of the exact curves.
    const int size = 240;
    for (const std::string& variantKeys : {std::string(""), std::string("aaaa")}) {
        wb::BezierLabState state;
        const wb::Image img = renderBezier(variantKeys + "]]]]", size, size, &state);
        REQUIRE(state.grid == 256);
        const wb::RadialError err = wb::bezierCircleVariants()[size_t(state.circleVariant)].error;
        const double scale = size / 2.0 / wb::kBezierViewHalfHeight; // px per scene unit
        const double rho = wb::kBezierCircleRadius * scale;
        // A 2-pixel line: pixel centres up to 1 px off the curve, plus half a pixel's diagonal.
        const double slack = 1.0 + 0.71;
        const double lo = rho * err.minRadius - slack, hi = rho * err.maxRadius + slack;
        std::vector<int> bins(360, 0);
        int drawn = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                if (isBackground(img.at(x, y))) continue;
                ++drawn;
                const double dx = x + 0.5 - size / 2.0, dy = size / 2.0 - (y + 0.5);
                const double r = std::hypot(dx, dy);
                INFO("pixel " << x << "," << y << " at radius " << r << " not in [" << lo << ", "
                              << hi << "]");
                CHECK(r >= lo);
                CHECK(r <= hi);
                bins[size_t(int(std::floor((std::atan2(dy, dx) + M_PI) / (2 * M_PI) * 360.0)) %
                            360)]++;
            }
        CHECK(drawn > 2 * 2 * M_PI * rho * 0.8); // a closed 2-pixel line, not a few dots
        CHECK(std::count(bins.begin(), bins.end(), 0) == 0); // every degree of the circle drawn
    }
}

TEST_CASE("The control polygon shows the course's k = 4/3 handles", "[gl][bezier]") {
    const int size = 240;
    const wb::Image img = renderBezier("c", size, size);
    const double scale = size / 2.0 / wb::kBezierViewHalfHeight * wb::kBezierCircleRadius;
    // The inner control points of the two half-circle arcs: (±1, ±4/3) on the unit circle's scale.
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const int x = int(size / 2.0 + sx * scale),
                      y = int(size / 2.0 - sy * 4.0 / 3.0 * scale);
            const uint8_t* p = img.at(x, y);
            INFO("control point pixel " << x << "," << y);
            CHECK(int(p[0]) + p[1] + p[2] < 200); // a dark 6-pixel point
        }
}

TEST_CASE("The sphere's silhouette lies between its smallest and largest radius", "[gl][bezier]") {
    const int size = 240;
    for (const std::string& keys : {std::string("2z"), std::string("2az")}) { // z: no inset
        wb::BezierLabState state;
        const wb::Image img = renderBezier(keys, size, size, &state);
        const wb::RadialError err = wb::bezierSphereVariants()[size_t(state.sphereVariant)].error;
        const double scale = size / 2.0 / wb::kBezierSphereViewHalfHeight;
        // A closed surface around the origin between radii rmin and rmax projects
        // (orthographically) onto a region that contains the disc of rmin and lies inside the disc
        // of rmax; one pixel of rasterisation either way.
        int outside = 0, holes = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const double r = std::hypot(x + 0.5 - size / 2.0, size / 2.0 - (y + 0.5));
                const bool bg = isBackground(img.at(x, y));
                if (!bg && r > scale * err.maxRadius + 1.0) ++outside;
                if (bg && r < scale * err.minRadius - 1.0) ++holes;
            }
        INFO("keys " << keys << " rmin " << err.minRadius << " rmax " << err.maxRadius);
        CHECK(outside == 0);
        CHECK(holes == 0);
        // Upper (orange) patch above the equator, lower (blue) below: the two patches.
        const uint8_t* top = img.at(size / 2, size / 2 - int(0.5 * scale * err.radius));
        const uint8_t* bottom = img.at(size / 2, size / 2 + int(0.8 * scale * err.radius));
        CHECK(int(top[0]) > int(top[2]) + 40);
        CHECK(int(bottom[2]) > int(bottom[0]) + 40);
    }
}

namespace {

// Pixels of the inset (bottom-left square, 8 px margin, side 0.42·min(w, h)) and of the
// rest of the picture whose channels differ by more than 40/255 between two renders, and
// the mean difference over the inset (0..255).
struct InsetDiff {
    int inset = 0, outside = 0;
    double insetMean = 0;
};
InsetDiff insetDiff(const wb::Image& a, const wb::Image& b) {
    const int side = int(wb::kBezierInsetFraction * std::min(a.width, a.height));
    InsetDiff d;
    long sum = 0, n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int m = 0;
            for (int ch = 0; ch < 3; ++ch)
                m = std::max(m, std::abs(int(a.at(x, y)[ch]) - int(b.at(x, y)[ch])));
            const bool in = x >= 8 && x < 8 + side && y >= a.height - 8 - side && y < a.height - 8;
            if (in) sum += m, ++n;
            (in ? d.inset : d.outside) += m > 40;
        }
    d.insetMean = double(sum) / double(std::max(n, 1L));
    return d;
}

} // namespace

// Issue 11: the `n` toggle's promised dark spots changed 48 pixels of a 480×360 picture.
// The inset magnifies the spot GL_AUTO_NORMAL leaves unlit 30×, so `n` must change a
// visible share of it; the main view alone changes almost nothing (the old complaint).
TEST_CASE("the n toggle visibly changes the magnified corner and the teapot's pole",
          "[gl][bezier]") {
    const int w = 320, h = 240;
    const int side = int(wb::kBezierInsetFraction * std::min(w, h));
    for (const char* shape : {"2", "3"}) {
        const wb::Image gl = renderBezier(shape, w, h),
                        core = renderBezier(std::string(shape) + "n", w, h);
        const InsetDiff d = insetDiff(gl, core);
        INFO("shape key " << shape << ": inset " << d.inset << " of " << side * side
                          << " px changed, mean " << d.insetMean << ", outside " << d.outside);
        // At least 3% of the inset changes by more than 40/255 (measured: see the WARN),
        // and the mean over the inset moves by at least 3/255: a spot a class can see.
        CHECK(d.inset > side * side * 3 / 100);
        CHECK(d.insetMean > 3.0);
        WARN("shape key " << shape << ": inset " << d.inset << " of " << side * side
                          << " px changed by >40/255, mean " << d.insetMean << "; outside "
                          << d.outside);
        // Without the inset (z) the same toggle changes only a few pixels of the main view.
        const wb::Image glNo = renderBezier(std::string(shape) + "z", w, h),
                        coreNo = renderBezier(std::string(shape) + "zn", w, h);
        const InsetDiff dn = insetDiff(glNo, coreNo);
        CHECK(dn.inset + dn.outside < d.inset);
    }
}

namespace {

// Runs the lab's panel once inside a headless GL context, before the lab has drawn
// anything (as the window does after a key: the panel comes first in a frame).
class PanelFirstLab : public wb::Lab {
  public:
    explicit PanelFirstLab(wb::Lab& inner) : inner_(inner) {}
    std::string title() const override { return "panel first"; }
    std::vector<wb::KeyHelp> keys() const override { return {}; }
    bool key(int) override { return false; }
    void init() override { inner_.init(); }
    void draw(const wb::View&) override {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(400, 2000);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int tw = 0, th = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &tw, &th);
        ImGui::NewFrame();
        ImGui::Begin("panel");
        inner_.gui();
        ImGui::End();
        ImGui::Render();
        ImGui::DestroyContext();
    }

  private:
    wb::Lab& inner_;
};

} // namespace

// Issue 11: "GL time per mesh, grid 64: (not drawn yet)" while the mesh was on screen:
// the panel is laid out before the frame that draws the new grid.
TEST_CASE("the panel shows a GL time for the grid on screen, even before its frame",
          "[gl][bezier]") {
    for (const char* keys : {"", "]]", "2]", "3["}) {
        wb::BezierLabState s;
        auto lab = wb::makeBezierLab(&s);
        std::vector<int> codes;
        std::string err;
        REQUIRE(wb::parseKeys(keys, codes, err));
        for (int k : codes)
            lab->key(k);
        PanelFirstLab panel(*lab);
        wb::test::renderLab(panel, 64, 64);
        INFO("keys '" << keys << "' grid " << s.grid);
        CHECK(s.shownMs > 0.0);
    }
}

// The teapot's GL-against-core table: points agree to float rounding, normals agree
// where GL has one, and GL has none exactly on the two poles' grid rows.
TEST_CASE("teapot: GL evaluator against core, point by point", "[gl][bezier]") {
    struct Cmp : wb::Lab {
        std::string title() const override { return "cmp"; }
        std::vector<wb::KeyHelp> keys() const override { return {}; }
        bool key(int) override { return false; }
        void draw(const wb::View&) override { result = wb::compareTeapotWithGl(8); }
        wb::TeapotGlComparison result;
    } lab;
    wb::test::renderLab(lab, 64, 64);
    const wb::TeapotGlComparison& c = lab.result;
    REQUIRE(c.vertices == 32 * 81);
    // kFloatEvalTol (above): float evaluation and float window coordinates, here with
    // coordinates up to 3.5 in a ±4 box on 512 px.
    CHECK(c.maxPointError <= kFloatEvalTol);
    // 8 pole patches × 9 vertices on the collapsed row, where du = 0 in float as well.
    CHECK(c.noNormal == 8 * 9);
    CHECK(c.coreLimit >= c.noNormal);
    // Float normals through float lighting: 1e-4 in length (as the sphere's test) is
    // about 0.006°; 0.05° leaves room for the rims' sharp curvature in float.
    CHECK(c.maxNormalAngle < 0.05);
}
