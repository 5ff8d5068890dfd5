// Command-line parsing of the lab shell: every flag, and bad input rejected with a clear message.
#include "common/cli_values.h"
#include "common/options.h"

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

TEST_CASE("the window --help names is the window that opens", "[options]") {
    ShellOptions o;
    CHECK(windowWidth(o, false) == kDefaultWidth + kPanelWidth);
    CHECK(windowWidth(o, true) == kDefaultWidth);
    o.uiScale = 2.0f;
    CHECK(windowWidth(o, false) == kDefaultWidth + 2 * kPanelWidth);
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
