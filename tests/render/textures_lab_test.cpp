// Lab 04 - textures, headless: goldens for each key state, the mirror's reflection, the
// sphere map following the viewer, and texture files that are missing or broken.
#include "environment.h"
#include "render/render_check.h"
#include "texture_file.h"
#include "textures_lab.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <fstream>

namespace {

std::string outPath(const std::string& name) {
    return std::string(WB_TEST_OUT_DIR) + "/" + name;
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream f(path, std::ios::binary);
    f << bytes;
}

// How many pixels are the fallback checkerboard's magenta (255, 0, 255) after lighting-free
// drawing.
int magentaPixels(const wb::Image& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.at(x, y);
            if (p[0] > 200 && p[1] < 40 && p[2] > 200) ++n;
        }
    return n;
}

} // namespace

// Goldens: 160×120 renders. On this machine a render is bit-for-bit repeatable (measured
// max diff 0). The allowance (max 48, mean 0.5) is for another Mesa/llvmpipe version
// rounding texture filtering or rasterising an edge differently: a few edge pixels may flip
// between two texels (up to ~48 on the brick/mortar contrast) but the mean stays tiny;
// a wrong wrap mode, filter, seam or mapping changes the mean by far more than 0.5.
TEST_CASE("lab 04 goldens for each key state", "[gl][textures]") {
    const char* cases[][2] = {{"1", "lab04-flat-repeat-mipmap"},
                              {"1w", "lab04-flat-clamp"},
                              {"1f", "lab04-flat-nearest"},
                              {"1ff", "lab04-flat-linear"},
                              {"2", "lab04-sphere"},
                              {"3", "lab04-torus"},
                              {"3t", "lab04-torus-bricks"},
                              {"4", "lab04-mirror-sphere"},
                              {"4o", "lab04-mirror-torus"},
                              {"4b", "lab04-mirror-no-room"},
                              {"5", "lab04-bump"},
                              {"5k", "lab04-bump-smooth"}};
    for (auto& c : cases) {
        SECTION(c[1]) {
            auto lab = wb::makeTexturesLab();
            wb::Image img = wb::test::renderLab(*lab, 160, 120, c[0]);
            wb::test::checkGolden(img, c[1], 48, 0.5);
        }
    }
}

TEST_CASE("lab 04 key states really differ", "[gl][textures]") {
    // Guards against a key that silently does nothing (then its golden would equal another).
    auto render = [](const char* keys) {
        auto lab = wb::makeTexturesLab();
        return wb::test::renderLab(*lab, 160, 120, keys);
    };
    wb::Image repeat = render("1"), clamp = render("1w"), nearest = render("1f"),
              linear = render("1ff");
    CHECK(wb::compareImages(repeat, clamp).meanDiff > 5.0);
    CHECK(wb::compareImages(repeat, nearest).meanDiff > 1.0); // minification: aliasing vs mipmaps
    CHECK(wb::compareImages(nearest, linear).meanDiff > 0.5);
    CHECK(wb::compareImages(render("5"), render("5k")).meanDiff > 1.0);
}

TEST_CASE("bump mapping changes the shading, not the silhouette", "[gl][textures]") {
    // Section 1.5.2: the displacement is imagined, only the normals change, so the torus'
    // outline must be the smooth one pixel for pixel, while the inside is shaded differently.
    wb::TexturesLabState st;
    auto lab = wb::makeTexturesLab(&st);
    wb::Image bumped = wb::test::renderLab(*lab, 200, 150, "5");
    INFO(st.message);
    CHECK(st.message.empty());                                    // the shader compiled and linked
    wb::Image smooth = wb::test::renderLab(*lab, 200, 150, "5k"); // same lab: k toggles back
    CHECK_FALSE(st.bump);
    const uint8_t* bg = bumped.at(0, 0); // the clear colour
    int covered = 0, outlineDiffers = 0, shadingDiffers = 0;
    for (int y = 0; y < bumped.height; ++y)
        for (int x = 0; x < bumped.width; ++x) {
            const uint8_t *a = bumped.at(x, y), *b = smooth.at(x, y);
            const bool inA = a[0] != bg[0] || a[1] != bg[1] || a[2] != bg[2];
            const bool inB = b[0] != bg[0] || b[1] != bg[1] || b[2] != bg[2];
            if (inA != inB) ++outlineDiffers;
            if (inA && inB) {
                ++covered;
                if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 12)
                    ++shadingDiffers;
            }
        }
    WARN("bump: " << covered << " torus pixels, " << shadingDiffers << " shaded differently, "
                  << outlineDiffers << " outline pixels differ");
    CHECK(covered > 5000);
    CHECK(outlineDiffers == 0);
    CHECK(shadingDiffers > covered / 5);
}

namespace {

constexpr double kTwoPi = 6.283185307179586;

// The torus of scene 5 at (s, t), and its smooth normal (makeTorus's parametrisation).
glm::dvec3 torusPoint(double s, double t) {
    const double phi = kTwoPi * s, theta = kTwoPi * t;
    return wb::kBumpTorusMajor * glm::dvec3(std::sin(phi), 0, std::cos(phi)) +
           wb::kBumpTorusMinor * glm::dvec3(std::cos(theta) * std::sin(phi), std::sin(theta),
                                            std::cos(theta) * std::cos(phi));
}
glm::dvec3 torusNormal(double s, double t) {
    const double phi = kTwoPi * s, theta = kTwoPi * t;
    return {std::cos(theta) * std::sin(phi), std::sin(theta), std::cos(theta) * std::cos(phi)};
}

// The height map of assets/textures/make_textures.py as a continuous function of the tile
// coordinates (u, v) ∈ [0,1)²: round bumps of radius 26 texels centred in each 64-texel cell.
double bumpHeight(double u, double v) {
    const double x = std::fmod(u * 128.0, 64.0) - 32.0, y = std::fmod(v * 128.0, 64.0) - 32.0;
    const double q = (x * x + y * y) / (26.0 * 26.0);
    return q < 1.0 ? (1.0 - q) * (1.0 - q) : 0.0;
}

// The normal of the displaced surface p + D·n itself (not the approximation 5.14), by
// central differences of the displaced points: the independent reference.
glm::dvec3 displacedNormal(double s, double t, double depth) {
    auto p = [&](double a, double b) {
        const double u = std::fmod(a * wb::kBumpRepeatS + 10.0, 1.0);
        const double v = std::fmod(b * wb::kBumpRepeatT + 10.0, 1.0);
        return torusPoint(a, b) + depth * bumpHeight(u, v) * torusNormal(a, b);
    };
    const double h = 1e-6;
    const glm::dvec3 ds = p(s + h, t) - p(s - h, t), dt = p(s, t + h) - p(s, t - h);
    return glm::normalize(glm::cross(ds, dt));
}

} // namespace

TEST_CASE("bump mapping: shading follows the displaced surface's own normal", "[gl][textures]") {
    // For pixels on the torus' front, find the (s, t) the pixel centre shows (Newton on the
    // projection of p(s, t)), compute the normal of p + D·n by differences, light it with the
    // lab's four lights and material (the shader's Phong sum, recomputed here), and compare
    // with the pixel. The shader uses (5.14), which drops D·∂n/∂s and D·∂n/∂t, and an 8-bit
    // height map differentiated over two texels: the tolerance below is what those cost.
    wb::TexturesLabState st;
    auto lab = wb::makeTexturesLab(&st);
    const int w = 400, h = 300;
    wb::Image img = wb::test::renderLab(*lab, w, h, "5");
    const glm::dmat4 mv = st.bumpModelview, pr = st.bumpProjection;
    const glm::dvec4 vp(0, 0, w, h);
    const glm::dmat3 nm = glm::transpose(glm::inverse(glm::dmat3(mv)));
    auto window = [&](double s, double t) {
        return glm::dvec2(glm::project(torusPoint(s, t), mv, pr, vp));
    };
    const glm::dvec3 mat(0.85, 0.65, 0.35);
    double worst = 0, sum = 0;
    int n = 0, flank = 0;
    for (double s0 = -0.06; s0 <= 0.06; s0 += 0.004)
        for (double t0 = 0.01; t0 <= 0.24; t0 += 0.01) {
            // The pixel around (s0, t0), then the (s, t) exactly at its centre.
            glm::dvec2 target = glm::floor(window(s0, t0)) + 0.5;
            double s = s0, t = t0;
            for (int it = 0; it < 8; ++it) {
                const double e = 1e-7;
                const glm::dvec2 f = window(s, t) - target;
                const glm::dvec2 fs = (window(s + e, t) - window(s, t)) / e;
                const glm::dvec2 ft = (window(s, t + e) - window(s, t)) / e;
                const double det = fs.x * ft.y - fs.y * ft.x;
                s -= (f.x * ft.y - f.y * ft.x) / det;
                t -= (fs.x * f.y - fs.y * f.x) / det;
            }
            if (glm::length(window(s, t) - target) > 1e-3) continue;
            const glm::dvec3 eyePos(mv * glm::dvec4(torusPoint(s, t), 1.0));
            const glm::dvec3 v = glm::normalize(-eyePos);
            if (glm::dot(glm::normalize(nm * torusNormal(s, t)), v) < 0.4) continue; // no grazing
            const glm::dvec3 m = glm::normalize(nm * displacedNormal(s, t, st.bumpDepth));
            if (glm::dot(m, glm::normalize(nm * torusNormal(s, t))) < 0.98) ++flank; // tilted > 11°
            glm::dvec3 c = 0.12 * mat; // weak global ambient
            for (const auto& lp : wb::kBumpLights) {
                const glm::dvec3 l = glm::normalize(glm::dvec3(lp[0], lp[1], lp[2]) - eyePos);
                const double diffuse = std::max(glm::dot(m, l), 0.0);
                const double spec =
                    diffuse > 0 ? std::pow(std::max(glm::dot(glm::reflect(-l, m), v), 0.0), 40.0)
                                : 0.0;
                c += 0.45 * diffuse * mat + 0.45 * 0.6 * spec * glm::dvec3(1.0);
            }
            const uint8_t* px = img.at(int(target.x), h - 1 - int(target.y));
            for (int k = 0; k < 3; ++k) {
                const double e = std::abs(px[k] - 255.0 * std::min(1.0, c[k]));
                worst = std::max(worst, e);
                sum += e;
            }
            ++n;
        }
    WARN("bump shading vs the displaced surface: "
         << n << " pixels (" << flank << " on steep flanks), mean error " << sum / (3 * n)
         << "/255, worst " << worst << "/255");
    REQUIRE(n > 200);
    CHECK(flank > 50);
    // Measured: mean 0.52/255, worst 8.2/255 (at a flank's steepest texels). Bumps dented
    // instead of raised, or a missing chain-rule factor, cost tens of levels on the flanks.
    CHECK(sum / (3 * n) < 1.5);
    CHECK(worst < 16.0);
}

TEST_CASE("mirror sphere: centre pixel reflects what is behind the viewer", "[gl][textures]") {
    // The ray from the eye to the sphere's centre is reflected straight back, to +z at yaw 0:
    // the yellow pillar, environmentColour((0,0,1)). Spinning the sphere changes nothing (a
    // sphere's reflection depends on the viewer only). ±12/255: texture filtering of the
    // 256² map blends neighbouring texels, all inside the pillar's ±8° there.
    wb::TexturesLabState st;
    auto lab = wb::makeTexturesLab(&st);
    const glm::dvec3 expect = wb::environmentColour({0, 0, 1}) * 255.0;
    for (const char* keys : {"4", "4{left}{left}{up}"}) {
        INFO("keys " << keys);
        wb::Image img = wb::test::renderLab(*lab, 161, 121, keys);
        const uint8_t* p = img.at(80, 60);
        for (int k = 0; k < 3; ++k)
            CHECK(std::abs(p[k] - expect[k]) <= 12.0);
    }
    CHECK(st.spinY == -20.0);
    CHECK(st.sphereMapBuilds >= 1);
}

TEST_CASE("sphere map follows the viewer", "[textures]") {
    // The centre texel is f = (0,0,1) in eye space: the direction back to the viewer. After
    // the viewer orbits by yaw, the map must show the world direction Rᵀ(0,0,1).
    for (double yaw : {0.0, 90.0, 180.0, -90.0}) {
        INFO("yaw " << yaw);
        glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(yaw), glm::dvec3(0, 1, 0)));
        wb::Image map = wb::makeSphereMapImage(r, 65); // odd: a texel sits on the centre
        const uint8_t* p = map.at(32, 32);
        glm::dvec3 expect = wb::environmentColour(glm::transpose(r) * glm::dvec3(0, 0, 1)) * 255.0;
        for (int k = 0; k < 3; ++k)
            CHECK(std::abs(p[k] - expect[k]) <= 0.5); // rounding only
    }
    // And the four views see four different pillars.
    glm::dvec3 a = wb::environmentColour({0, 0, 1}), b = wb::environmentColour({1, 0, 0});
    CHECK(glm::length(a - b) > 0.5);
}

TEST_CASE("missing, corrupt, truncated and oversized textures give a checkerboard and a message",
          "[gl][textures]") {
    std::string bricks;
    {
        std::ifstream f(std::string(WB_GOLDEN_DIR) + "/../../assets/textures/bricks.png",
                        std::ios::binary);
        bricks.assign(std::istreambuf_iterator<char>(f), {});
    }
    REQUIRE(bricks.size() > 200);
    // PNG headers that claim 5000×5000 (over kMaxTextureSide) and 60000×60000 (over stb's own
    // limit): both must be refused from the header, before any allocation.
    auto be32 = [](uint32_t v) {
        return std::string{char(v >> 24), char((v >> 16) & 255), char((v >> 8) & 255),
                           char(v & 255)};
    };
    std::string huge = bricks.substr(0, 33), big = huge;
    huge.replace(16, 8, be32(60000) + be32(60000));
    big.replace(16, 8, be32(5000) + be32(5000));
    writeBytes(outPath("tex-big.png"), big + std::string(64, '\0'));
    writeBytes(outPath("tex-corrupt.png"), "this is not a PNG file at all");
    writeBytes(outPath("tex-truncated.png"), bricks.substr(0, 120));
    writeBytes(outPath("tex-huge.png"), huge + std::string(64, '\0'));
    writeBytes(outPath("tex-empty.png"), "");

    struct Case {
        std::string file, reason;
    };
    for (const Case& c : {Case{"/nonexistent-dir/none.png", "none.png"},
                          Case{outPath("tex-corrupt.png"), "tex-corrupt.png"},
                          Case{outPath("tex-truncated.png"), "tex-truncated.png"},
                          Case{outPath("tex-big.png"), "5000x5000 is not a usable texture size"},
                          Case{outPath("tex-huge.png"), "too large"},
                          Case{outPath("tex-empty.png"), "tex-empty.png"}}) {
        INFO(c.file);
        wb::Image img;
        std::string msg;
        CHECK_FALSE(wb::loadTextureImage(c.file, img, msg));
        CHECK_THAT(msg, Catch::Contains(c.reason) && Catch::Contains("checkerboard"));
        CHECK(img.width == 64);
        CHECK(img.height == 64);

        // The lab shows the message and draws the checkerboard on the flat object.
        wb::TexturesLabState st;
        auto lab = wb::makeTexturesLab(&st);
        std::string err;
        REQUIRE(lab->setOption("texture", c.file, err));
        wb::Image shot = wb::test::renderLab(*lab, 160, 120, "1");
        CHECK_THAT(st.message, Catch::Contains(c.reason));
        CHECK(magentaPixels(shot) > 1000);
    }
    // The real file loads, and the default render has no magenta at all.
    wb::Image ok;
    std::string msg;
    CHECK(wb::loadTextureImage(std::string(WB_GOLDEN_DIR) + "/../../assets/textures/bricks.png", ok,
                               msg));
    CHECK(msg.empty());
    wb::TexturesLabState st;
    auto lab = wb::makeTexturesLab(&st);
    CHECK(magentaPixels(wb::test::renderLab(*lab, 160, 120, "1")) == 0);
    CHECK(st.message.empty());
}

// Issue 11: the first frame showed the brick plane alone; it now shows the lab's main
// subject, the sphere-mapped mirror between the textured sphere and torus (key 0).
TEST_CASE("lab 04 first frame is the overview", "[gl][textures]") {
    wb::TexturesLabState st;
    auto lab = wb::makeTexturesLab(&st);
    CHECK(st.scene == wb::TextureScene::Overview);
    wb::Image first = wb::test::renderLab(*lab, 160, 120);
    wb::Image flat = wb::test::renderLab(*wb::makeTexturesLab(), 160, 120, "1");
    wb::Image zero = wb::test::renderLab(*wb::makeTexturesLab(), 160, 120, "10");
    CHECK(wb::compareImages(first, zero).maxDiff == 0); // key 0 goes back to it
    CHECK(wb::compareImages(first, flat).meanDiff > 20.0);
    // The mirror's centre (0, 0.25) at scale 0.8 reflects straight back: the yellow
    // pillar behind the viewer, as in the mirror test (±12/255, filtering of the map).
    // Its pixel: 0.25 up at distance 5 with fovy 45 is 0.25/(5·tan 22.5°)·60 = 7 rows up.
    const glm::dvec3 expect = wb::environmentColour({0, 0, 1}) * 255.0;
    const uint8_t* p = first.at(80, 60 - 7);
    for (int k = 0; k < 3; ++k)
        CHECK(std::abs(p[k] - expect[k]) <= 12.0);
    wb::test::checkGolden(first, "lab04-overview", 48, 0.5); // tolerances as the goldens above
}

// Issue 19, item 14: `t` in the first view changed the panel's texture name only (it chose
// the flat object's texture); there it swaps the sphere's and the torus's textures.
TEST_CASE("lab 04 t changes the first view", "[gl][textures]") {
    wb::Image first = wb::test::renderLab(*wb::makeTexturesLab(), 160, 120);
    wb::Image swapped = wb::test::renderLab(*wb::makeTexturesLab(), 160, 120, "t");
    wb::Image back = wb::test::renderLab(*wb::makeTexturesLab(), 160, 120, "tt");
    // The sphere and torus cover ~15% of the picture; bricks against the uv grid there
    // moves the mean by more than 1/255 (the mirror and room do not change).
    CHECK(wb::compareImages(first, swapped).meanDiff > 1.0);
    CHECK(wb::compareImages(first, back).maxDiff == 0);
}
