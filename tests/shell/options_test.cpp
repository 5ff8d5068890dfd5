// Command-line parsing of the lab shell: every flag, and bad input rejected with a clear message.
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
    for (const char* s : {"0x0", "0x10", "10x0", "x", "10", "10x", "-5x5", "5x5x5", "99999x10", "1e3x10", ""}) {
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
