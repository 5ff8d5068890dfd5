// The lighting equation of core/lighting.h against OSMesa's fixed-function
// pipeline: lit GL_POINTS at known eye-space positions with known normals, one
// per 8×8 cell, under the lab's combinations 1-4, local and infinite viewer, with
// emission, attenuation and a spot. A point's colour is its vertex colour, so the
// pixel is the lit vertex colour GL computed, quantised to 8 bits.
#include "render_check.h"

#include "common/gl.h"
#include "common/gl_util.h"
#include "lighting_lab.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace {

constexpr int kGrid = 12;            // points per row and column
constexpr int kCell = 8;             // pixels per point cell
constexpr int kSize = kGrid * kCell; // image size
constexpr double kHalf = 3.0;        // the ortho view spans eye x, y in [-3, 3]

struct Sample {
    glm::dvec3 pos;    // eye space
    glm::dvec3 normal; // unit, eye space
    int px, py;        // pixel (x right, y down) of the point's centre
};

std::vector<Sample> makeSamples(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u11(-1, 1), depth(-9, -2);
    std::vector<Sample> out;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            Sample s;
            s.px = i * kCell + kCell / 2;
            s.py = j * kCell + kCell / 2;
            // Pixel centre (px + 0.5, py + 0.5) in eye x, y (ortho: no perspective divide).
            double x = -kHalf + 2 * kHalf * (s.px + 0.5) / kSize;
            double y = kHalf - 2 * kHalf * (s.py + 0.5) / kSize;
            s.pos = {x, y, depth(rng)};
            s.normal = glm::normalize(glm::dvec3(u11(rng), u11(rng), u11(rng) + 0.8));
            out.push_back(s);
        }
    return out;
}

// Draws the samples as 3-pixel lit points with the model, light and material given.
class PointLab : public wb::Lab {
  public:
    wb::LightModel model;
    wb::Light light;
    wb::Material material;
    std::vector<Sample> samples;
    bool glsl = false; // draw through shaders/phong.* instead of the fixed pipeline
    std::string programError;
    GLuint program = 0;
    std::string title() const override { return "points"; }
    void init() override {
        program =
            glsl ? wb::loadProgram("shaders/phong.vert", "shaders/phong.frag", programError) : 0;
    }
    std::vector<wb::KeyHelp> keys() const override { return {}; }
    bool key(int) override { return false; }
    void draw(const wb::View&) override {
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-kHalf, kHalf, -kHalf, kHalf, 0.5, 20);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity(); // object coordinates are eye coordinates, for vertices and the light
        glEnable(GL_LIGHTING);
        wb::glApplyLightModel(model);
        wb::glApplyLight(GL_LIGHT0, light);
        wb::glApplyMaterial(material);
        if (program) {
            glUseProgram(program);
            glUniform1i(glGetUniformLocation(program, "wbLightCount"), 1);
            glUniform1i(glGetUniformLocation(program, "wbLocalViewer"), model.localViewer ? 1 : 0);
        }
        glPointSize(3);
        glBegin(GL_POINTS);
        for (const Sample& s : samples) {
            glNormal3d(s.normal.x, s.normal.y, s.normal.z);
            glVertex3d(s.pos.x, s.pos.y, s.pos.z);
        }
        glEnd();
        if (program) glUseProgram(0);
        glDisable(GL_LIGHTING);
    }
};

// Samples too close to a discontinuity of the equation are skipped: GL evaluates in
// float, so a point within float rounding of the spot cone's edge or of n·L = 0 (where
// f_i switches the highlight off) may fall on the other side. Returns true to compare.
bool awayFromEdges(const wb::Light& l, const Sample& s) {
    glm::dvec3 vp = l.position.w != 0
                        ? glm::normalize(glm::dvec3(l.position) / l.position.w - s.pos)
                        : glm::normalize(glm::dvec3(l.position));
    if (std::abs(glm::dot(vp, s.normal)) < 1e-3) return false;
    if (l.position.w != 0 && l.spotCutoff != 180) {
        double c = glm::dot(-vp, glm::normalize(l.spotDirection));
        if (std::abs(c - std::cos(l.spotCutoff * M_PI / 180)) < 1e-3) return false;
    }
    return true;
}

// Renders the samples and returns the largest channel difference (0..255) between
// OSMesa and core's shadeVertex rounded to 8 bits; `compared` counts the samples used.
int maxDifference(PointLab& lab, int& compared) {
    wb::Image img = wb::test::renderLab(lab, kSize, kSize);
    int worst = 0;
    compared = 0;
    for (const Sample& s : lab.samples) {
        if (!awayFromEdges(lab.light, s)) continue;
        ++compared;
        glm::dvec4 c = wb::shadeVertex(lab.model, {lab.light}, lab.material, s.pos, s.normal);
        const uint8_t* p = img.at(s.px, s.py);
        for (int ch = 0; ch < 3; ++ch) {
            int expected = int(std::lround(c[ch] * 255));
            worst = std::max(worst, std::abs(expected - int(p[ch])));
        }
    }
    return worst;
}

} // namespace

// Tolerance 2/255: the 8-bit framebuffer rounds to the nearest level (0.5/255); GL
// evaluates in float and llvmpipe approximates pow (exp2/log2) and rsqrt, and the
// shininess exponent (12.8) multiplies their relative error into the highlight: we allow
// up to another 1.5/255 for that. Measured (printed): max 0/255 in every case on Mesa
// 22.3 llvmpipe.
TEST_CASE("lighting equation agrees with OSMesa fixed function for keys 1-4 and both viewers",
          "[gl]") {
    PointLab lab;
    lab.samples = makeSamples(7);
    for (int combo = 1; combo <= 4; ++combo)
        for (int local = 0; local < 2; ++local) {
            wb::LightingState s;
            s.combo = combo;
            s.localViewer = local == 1;
            s.lightPos = {0.5f, 1.0f, 1.0f, 1.0f}; // eye space, in front of the points
            lab.model = wb::lightModel(s);
            lab.light = wb::comboLight(s);
            lab.material = wb::comboMaterial(s);
            int compared = 0;
            int d = maxDifference(lab, compared);
            std::printf("lighting vs OSMesa: combo %d, %s viewer: max %d/255 over %d points\n",
                        combo, local ? "local" : "infinite", d, compared);
            INFO("combo " << combo << (local ? " local" : " infinite") << " viewer");
            CHECK(compared > kGrid * kGrid / 2);
            CHECK(d <= 2);
        }
}

TEST_CASE("lighting equation agrees with OSMesa with emission, attenuation, a spot and a "
          "directional light",
          "[gl]") {
    PointLab lab;
    lab.samples = makeSamples(11);
    struct Case {
        const char* name;
        void (*setup)(wb::LightingState&);
    };
    const Case cases[] = {
        {"emission", [](wb::LightingState& s) { s.emissionOn = true; }},
        {"attenuation",
         [](wb::LightingState& s) {
             s.attenuation = {0.3f, 0.2f, 0.05f};
         }},
        {"spot",
         [](wb::LightingState& s) {
             s.spotOn = true;
             s.spotTarget = {0.0f, 0.0f, -5.0f};
             s.spotCutoff = 30;
             s.spotExponent = 4;
         }},
        {"spot + attenuation + emission, local viewer",
         [](wb::LightingState& s) {
             s.spotOn = true;
             s.spotTarget = {-1.0f, 0.5f, -6.0f};
             s.spotCutoff = 40;
             s.spotExponent = 10;
             s.attenuation = {0.5f, 0.1f, 0.02f};
             s.emissionOn = true;
             s.localViewer = true;
         }},
        {"directional light, no global ambient",
         [](wb::LightingState& s) {
             s.lightPos = {1.0f, 1.0f, 2.0f, 0.0f};
             s.globalAmbientOn = false;
         }},
    };
    for (const Case& c : cases)
        for (int combo = 1; combo <= 4; ++combo) {
            wb::LightingState s;
            s.combo = combo;
            s.lightPos = {0.5f, 1.0f, 1.0f, 1.0f};
            c.setup(s);
            lab.model = wb::lightModel(s);
            lab.light = wb::comboLight(s);
            lab.material = wb::comboMaterial(s);
            int compared = 0;
            int d = maxDifference(lab, compared);
            std::printf("lighting vs OSMesa: %s, combo %d: max %d/255 over %d points\n", c.name,
                        combo, d, compared);
            INFO(c.name << ", combo " << combo);
            CHECK(compared > kGrid * kGrid / 2);
            CHECK(d <= 2); // as above
        }
}

TEST_CASE("the comparison can fail: a wrong shininess is caught", "[gl]") {
    PointLab lab;
    lab.samples = makeSamples(7);
    wb::LightingState s;
    s.lightPos = {0.5f, 1.0f, 1.0f, 1.0f};
    lab.model = wb::lightModel(s);
    lab.light = wb::comboLight(s);
    lab.material = wb::comboMaterial(s);
    wb::Image img = wb::test::renderLab(lab, kSize, kSize);
    wb::Material wrong = lab.material;
    wrong.shininess += 2;
    int worst = 0;
    for (const Sample& p : lab.samples) {
        glm::dvec4 c = wb::shadeVertex(lab.model, {lab.light}, wrong, p.pos, p.normal);
        for (int ch = 0; ch < 3; ++ch)
            worst = std::max(worst,
                             std::abs(int(std::lround(c[ch] * 255)) - int(img.at(p.px, p.py)[ch])));
    }
    CHECK(worst > 2);
}

// The per-fragment shader evaluates the same equation from the same fixed-function
// state: on a point every fragment gets the vertex's own position and normal, so it
// must give the fixed pipeline's vertex colour. Same tolerance and reasoning as above.
TEST_CASE("shaders/phong.frag gives core's vertex colours (core = fixed pipeline, above)", "[gl]") {
    PointLab lab;
    lab.glsl = true;
    lab.samples = makeSamples(13);
    for (int combo = 1; combo <= 4; ++combo)
        for (int variant = 0; variant < 3; ++variant) {
            wb::LightingState s;
            s.combo = combo;
            s.lightPos = {0.5f, 1.0f, 1.0f, 1.0f};
            s.localViewer = variant == 1;
            if (variant == 2) {
                s.spotOn = true;
                s.spotTarget = {-1.0f, 0.5f, -6.0f};
                s.spotCutoff = 40;
                s.spotExponent = 10;
                s.attenuation = {0.5f, 0.1f, 0.02f};
                s.emissionOn = true;
            }
            lab.model = wb::lightModel(s);
            lab.light = wb::comboLight(s);
            lab.material = wb::comboMaterial(s);
            int compared = 0;
            int d = maxDifference(lab, compared);
            INFO(lab.programError);
            REQUIRE(lab.program != 0);
            std::printf("GLSL phong vs core: combo %d, variant %d: max %d/255 over %d points\n",
                        combo, variant, d, compared);
            CHECK(compared > kGrid * kGrid / 2);
            CHECK(d <= 2);
        }
}
