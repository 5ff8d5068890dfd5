// The headless path of the shell on the test lab: OSMesa draws, keys replay, busy labs finish.
#include "common/shell.h"
#include "shell/test_lab.h"

#include <catch2/catch.hpp>

TEST_CASE("headless render draws the lab into an image of the asked size", "[gl][shell]") {
    wb::test::TestLabState state;
    auto lab = wb::test::makeTestLab(&state);
    wb::Image img;
    std::string err;
    REQUIRE(wb::renderHeadless(*lab, 40, 30, {}, img, err));
    REQUIRE(img.width == 40);
    REQUIRE(img.height == 30);
    CHECK(state.initCalls == 1);
    CHECK(state.frames == 3); // busy() for two frames, so three draws
    // Top-right corner is background (blue); bottom-left is the triangle (red): row 0 is the top.
    const uint8_t* tr = img.at(39, 0);
    const uint8_t* bl = img.at(0, 29);
    CHECK((tr[0] == 0 && tr[1] == 0 && tr[2] == 255));
    CHECK((bl[0] == 255 && bl[1] == 0 && bl[2] == 0));
}

TEST_CASE("headless render replays keys before drawing", "[gl][shell]") {
    wb::test::TestLabState state;
    auto lab = wb::test::makeTestLab(&state);
    wb::Image img;
    std::string err;
    REQUIRE(wb::renderHeadless(*lab, 8, 8, {'g'}, img, err));
    const uint8_t* bl = img.at(0, 7);
    CHECK((bl[0] == 0 && bl[1] == 255 && bl[2] == 0));
}

TEST_CASE("two headless renders in one process do not disturb each other", "[gl][shell]") {
    wb::Image a, b;
    std::string err;
    auto lab1 = wb::test::makeTestLab();
    auto lab2 = wb::test::makeTestLab();
    REQUIRE(wb::renderHeadless(*lab1, 16, 16, {}, a, err));
    REQUIRE(wb::renderHeadless(*lab2, 16, 16, {}, b, err));
    CHECK(a.data == b.data);
}
