// Tests of core/image: PNG round trip and the image comparison used by golden tests.
#include "core/image.h"

#include <catch2/catch.hpp>

using wb::Image;

TEST_CASE("PNG round trip keeps every byte", "[image]") {
    Image img(7, 5, 3); // odd sizes catch row-stride mistakes
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = uint8_t(i * 37 % 256);
    std::string path = std::string(WB_TEST_OUT_DIR) + "/image_roundtrip.png", err;
    REQUIRE(wb::writePng(path, img, &err));
    Image back;
    REQUIRE(wb::readImage(path, back, 3, &err));
    REQUIRE(back.width == 7);
    REQUIRE(back.height == 5);
    CHECK(back.data == img.data);
}

TEST_CASE("compareImages reports max and mean channel difference", "[image]") {
    Image a(2, 1, 3), b(2, 1, 3);
    b.data[0] = 10; // one channel of six differs by 10
    auto d = wb::compareImages(a, b);
    CHECK(d.sameSize);
    CHECK(d.maxDiff == 10);
    CHECK(d.meanDiff == Approx(10.0 / 6.0));
    CHECK_FALSE(wb::compareImages(a, Image(1, 2, 3)).sameSize);
}

TEST_CASE("writing to an unwritable path fails with the path in the message", "[image]") {
    Image img(1, 1, 3);
    std::string err;
    CHECK_FALSE(wb::writePng("/nonexistent-dir/x.png", img, &err));
    CHECK(err.find("/nonexistent-dir/x.png") != std::string::npos);
    CHECK_FALSE(wb::readImage("/nonexistent-dir/x.png", img, 3, &err));
    CHECK(err.find("/nonexistent-dir/x.png") != std::string::npos);
}
