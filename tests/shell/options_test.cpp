// Command-line parsing of the lab shell: every flag, and bad input rejected with a clear message.
#include "common/cli_values.h"
#include "common/options.h"
#include "common/shell.h"
#include "launcher/launcher.h"

#include <algorithm>
#include <limits>

#include <catch2/catch.hpp>

using namespace wb;

namespace {
bool parse(std::vector<const char*> args, ShellOptions& o, std::string& err,
           const std::vector<OptionHelp>& labOpts = {}) {
    args.insert(args.begin(), "lab");
    return parseOptions(int(args.size()), args.data(), labOpts, o, err);
}
} // namespace

TEST_CASE("shell flags are parsed", "[options]") {
    ShellOptions o;
    std::string err;
    REQUIRE(parse({"--headless", "--out", "a.png", "--size", "80x60", "--keys", "1g"}, o, err));
    CHECK(o.headless);
    CHECK(o.out == "a.png");
    CHECK(o.width == 80);
    CHECK(o.height == 60);
    CHECK(o.keys == "1g");
}

TEST_CASE("bad sizes are rejected", "[options]") {
    for (const char* s : {"0x0", "0x10", "10x0", "x", "10", "10x", "-5x5", "5x5x5", "99999x10", "1e3x10", "", "10x10junk", " 10x10", "10x 10", "+5x5", "0x10x"}) {
        ShellOptions o;
        std::string err;
        CAPTURE(s);
        CHECK_FALSE(parse({"--size", s}, o, err));
        CHECK(err.find("--size") != std::string::npos);
    }
}

TEST_CASE("unknown flags, stray arguments and missing values are rejected", "[options]") {
    ShellOptions o;
    std::string err;
    CHECK_FALSE(parse({"--frobnicate"}, o, err));
    CHECK(err.find("--frobnicate") != std::string::npos);
    CHECK_FALSE(parse({"stray"}, o, err));
    CHECK_FALSE(parse({"--out"}, o, err));
    CHECK(err.find("needs a value") != std::string::npos);
    CHECK_FALSE(parse({"--headless"}, o, err));
    CHECK(err.find("--out") != std::string::npos);
}

TEST_CASE("a lab's own options are accepted with their values", "[options]") {
    ShellOptions o;
    std::string err;
    std::vector<OptionHelp> labOpts = {{"scene", "FILE", "scene"}, {"fast", "", "a flag"}};
    REQUIRE(parse({"--scene", "balls.nff", "--fast"}, o, err, labOpts));
    REQUIRE(o.labOptions.size() == 2);
    CHECK(o.labOptions[0] == std::make_pair(std::string("scene"), std::string("balls.nff")));
    CHECK(o.labOptions[1].first == "fast");
}

TEST_CASE("key strings name special keys in braces", "[options]") {
    std::vector<int> k;
    std::string err;
    REQUIRE(parseKeys("1g{left}{{{f12}{space}", k, err));
    CHECK(k == std::vector<int>{'1', 'g', kKeyLeft, '{', kKeyF1 + 11, ' '});
    CHECK_FALSE(parseKeys("{left", k, err));
    CHECK(err.find("unclosed") != std::string::npos);
    CHECK_FALSE(parseKeys("{f13}", k, err));
    CHECK_FALSE(parseKeys("{}", k, err));
}

TEST_CASE("a value that starts with a dash is still the value of its flag", "[options]") {
    // CLI11 would read `-+` as a flag; the shell joins it to --keys as the old parser did.
    ShellOptions o;
    std::string err;
    REQUIRE(parse({"--keys", "-+", "--out", "-x.png", "--headless"}, o, err));
    CHECK(o.keys == "-+");
    CHECK(o.out == "-x.png");
    REQUIRE(parse({"--keys=ab"}, o, err));
    CHECK(o.keys == "ab");
}

TEST_CASE("the UI scale flag takes 0.5 to 4", "[options]") {
    ShellOptions o;
    std::string err;
    REQUIRE(parse({"--ui-scale", "2"}, o, err));
    CHECK(o.uiScale == 2.0f);
    for (const char* s : {"0.49", "4.01", "big", "", "nan", "2x"}) {
        CAPTURE(s);
        ShellOptions bad;
        CHECK_FALSE(parse({"--ui-scale", s}, bad, err));
        CHECK(err.find("--ui-scale") != std::string::npos);
    }
}

TEST_CASE("a window fits the screen it opens on, at every UI scale", "[options]") {
    for (const ScreenSize screen : kCheckedScreens)
        for (float scale : {1.0f, 1.5f, 2.0f}) {
            for (bool fills : {false, true}) {
                CAPTURE(screen.width, screen.height, scale, fills);
                ShellOptions o;
                o.uiScale = scale;
                const WindowFit f = fitWindow(o, fills, screen.width, screen.height, scale);
                const int maxW = screen.width - kScreenMarginX;
                CHECK(f.width <= maxW);
                CHECK(f.uiScale <= scale);
                if (fills) { // the launcher: 800x600 x the scale, capped by the screen
                    CHECK(f.width == std::min(maxW, int(800 * scale)));
                    CHECK(f.height == std::min(screen.height - kScreenMarginY, int(600 * scale)));
                    continue;
                }
                // A lab's height uses the screen: all of it but the margin, at every scale.
                CHECK(f.height == screen.height - kScreenMarginY);
                // As wide as a 4:3 scene at that height plus the panel, unless the screen's
                // width stops it.
                const int scene4x3 = int(float(f.height) * 4.0f / 3.0f + 0.5f);
                CHECK(f.width == std::min(maxW, scene4x3 + int(float(kPanelWidth) * scale + 0.5f)));
                // The panel's layout needs kPanelWidth x scale; the scene keeps its share.
                CHECK(f.panelWidth == int(float(kPanelWidth) * f.uiScale + 0.5f));
                CHECK(float(f.width - f.panelWidth) >=
                      (1.0f - kMaxPanelShare) * float(f.width) - 1.0f);
                // The panel shows at least 70% of the lines the old 600-px window showed at
                // scale 1 (a 1280x800 laptop at scale 2 -> 1.65 has 720 px: 436 / 600 = 73%).
                CHECK(float(f.height) / f.uiScale >= 600.0f * 0.7f);
                // At scale 1 the scene is drawn 4:3 in its part of the window, never smaller than
                // the old default's 584 x 438 on a 1024x768 screen.
                if (scale == 1.0f) CHECK(sceneViewHeight(f.width - f.panelWidth, f.height) >= 438);
            }
        }
    ShellOptions o;
    // Scale 1: the screen's height, the scene 4:3 beside the 420-px panel. 1024x768 used to
    // open 1004x600 and leave 88 px of the screen unused; 1920x1080 1220x600.
    WindowFit f = fitWindow(o, false, 1024, 768, 1.0f);
    CHECK((f.width == 1004 && f.height == 688 && f.panelWidth == 420));
    f = fitWindow(o, false, 1280, 800, 1.0f); // scene 840x720, drawn 840x630
    CHECK((f.width == 1260 && f.height == 720));
    f = fitWindow(o, false, 1920, 1080, 1.0f); // scene 1333x1000 exactly 4:3
    CHECK((f.width == 1333 + 420 && f.height == 1000));
    // A projector's 1600x1000 keeps scale 2 (the 1640-px window no longer overflows).
    o.uiScale = 2.0f;
    f = fitWindow(o, false, 1600, 1000, 2.0f);
    CHECK(f.uiScale == 2.0f);
    CHECK(f.width == 1580);
    CHECK(f.height == 920);
    // 1024x768 cannot hold an 840-px panel beside a scene: the largest scale that fits.
    f = fitWindow(o, false, 1024, 768, 2.0f);
    CHECK(f.uiScale == Approx(1.31f));
    // The launcher at scale 1 on 1920x1080 keeps 800x600 (its cards do not grow).
    f = fitWindow(o, true, 1920, 1080, 1.0f);
    CHECK((f.width == 800 && f.height == 600));
    // --size keeps its meaning: the scene's size, the panel beside it, capped by the screen.
    o.uiScale = 1.0f;
    o.sizeGiven = true;
    f = fitWindow(o, false, 1920, 1080, 1.0f);
    CHECK((f.width == kDefaultWidth + kPanelWidth && f.height == kDefaultHeight));
    f = fitWindow(o, true, 1920, 1080, 1.0f);
    CHECK((f.width == kDefaultWidth && f.height == kDefaultHeight));
    o.width = 3000;
    o.height = 2000;
    f = fitWindow(o, false, 1280, 800, 1.0f);
    CHECK((f.width == 1260 && f.height == 720));
    // The scene is never drawn narrower than 4:3; a wide one keeps its height.
    CHECK(sceneViewHeight(600, 900) == 450);
    CHECK(sceneViewHeight(1000, 600) == 600);
}

TEST_CASE("lab options keep their command-line order, flags and values interleaved", "[options]") {
    ShellOptions o;
    std::string err;
    std::vector<OptionHelp> labOpts = {{"scene", "FILE", "scene"}, {"fast", "", "a flag"}};
    REQUIRE(parse({"--fast", "--scene", "a.nff", "--size", "8x8", "--scene", "b.nff"}, o, err, labOpts));
    REQUIRE(o.labOptions.size() == 3);
    CHECK(o.labOptions[0].first == "fast");
    CHECK(o.labOptions[1].second == "a.nff");
    CHECK(o.labOptions[2].second == "b.nff");
    // A lab option that clashes with a shell flag is a programming error, reported, not a crash.
    std::vector<OptionHelp> clash = {{"size", "WxH", "twice"}};
    CHECK_FALSE(parse({}, o, err, clash));
    CHECK(err.find("clash") != std::string::npos);
}

TEST_CASE("shared values: --threads 0 means all cores, sizes are strict", "[options]") {
    int t = -1, w = 0, h = 0;
    std::string err;
    CHECK(cli::parseThreads("--threads", "0", t, err));
    CHECK(t == 0);
    CHECK(cli::parseThreads("--threads", "1024", t, err));
    for (const char* s : {"-1", "1025", "2x", "", " 2"}) {
        CAPTURE(s);
        CHECK_FALSE(cli::parseThreads("--threads", s, t, err));
        CHECK(err.find("--threads") != std::string::npos);
    }
    CHECK(cli::parseSize("16384x1", 16384, w, h));
    CHECK((w == 16384 && h == 1));
    CHECK_FALSE(cli::parseSize("16385x1", 16384, w, h));
    CHECK_FALSE(cli::parseSize("10x10junk", 16384, w, h));
    CHECK((w == 16384 && h == 1)); // untouched on failure
}

TEST_CASE("zoom stays finite and comes back after a thousand + presses", "[options]") {
    View v;
    bool panel = true;
    for (int i = 0; i < 1000; ++i) // unclamped, 1.1^930 overflowed a float to infinity
        CHECK(shellKey('+', v, panel));
    CHECK(v.zoom == kMaxZoom);
    for (int i = 0; i < 48; ++i)
        shellKey('-', v, panel);
    CHECK(v.zoom < 1.05f);
    for (int i = 0; i < 1000; ++i)
        shellKey('-', v, panel);
    CHECK(v.zoom == kMinZoom);
    CHECK(clampZoom(std::numeric_limits<float>::infinity()) == 1.0f);
}

TEST_CASE("the launcher passes its flags on, less those about its own window", "[options]") {
    const char* argv[] = {"workbench", "--ui-scale", "2",    "--size",  "800x600", "--lang", "ru",
                          "--frames",  "3",          "--smoke", "--keys", "1",     "--root", "/r",
                          "--screenshot=s.png", "--future-flag"};
    const std::vector<std::string> flags = labFlagsFrom(int(std::size(argv)), argv);
    CHECK(flags == std::vector<std::string>{"--ui-scale", "2", "--lang", "ru", "--root", "/r",
                                            "--future-flag"});
}
