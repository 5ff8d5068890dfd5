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
