#pragma once
// Helpers for the headless render tests ([gl]): render a lab through the shell's
// OSMesa path and compare with a golden PNG in tests/golden/.
//
// Goldens are written only on purpose: run the test binary with WB_UPDATE_GOLDEN=1
// after checking that the change in the picture is the intended one, and say why
// in the commit. Every render also lands in build/test-out/ (actual and, on a
// mismatch, a diff image) for looking at.
#include "common/options.h"
#include "common/shell.h"
#include "core/image.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <memory>
#include <string>

namespace wb::test {

// Renders `lab` at w×h after replaying `keys` (the --keys syntax, e.g. "1g{left}").
// A view as a window gives it: draw() returns at once instead of waiting for background
// work (a trace, an experiment), so a test can watch busy() and the tiles arrive.
inline View windowView(int w, int h) {
    View v;
    v.width = w;
    v.height = h;
    v.headless = false;
    return v;
}

inline Image renderLab(Lab& lab, int w, int h, const std::string& keys = "") {
    std::vector<int> codes;
    std::string err;
    REQUIRE(parseKeys(keys, codes, err));
    Image img;
    INFO(err);
    REQUIRE(renderHeadless(lab, w, h, codes, img, err));
    return img;
}

// Compares `img` with tests/golden/<name>.png. `maxDiff` bounds the largest channel
// difference (0..255) and `meanDiff` the mean over all channels; callers state where
// their numbers come from.
inline void checkGolden(const Image& img, const std::string& name, int maxDiff, double meanDiff) {
    const std::string golden = std::string(WB_GOLDEN_DIR) + "/" + name + ".png";
    const std::string actual = std::string(WB_TEST_OUT_DIR) + "/" + name + ".png";
    std::string err;
    REQUIRE(writePng(actual, img, &err));
    const char* update = std::getenv("WB_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        REQUIRE(writePng(golden, img, &err));
        WARN("golden written: " << golden);
        return;
    }
    Image ref;
    INFO("golden " << golden << " (render: " << actual << "; WB_UPDATE_GOLDEN=1 writes it)");
    REQUIRE(readImage(golden, ref, img.channels, &err));
    ImageDiff d = compareImages(img, ref);
    REQUIRE(d.sameSize);
    if (d.maxDiff > maxDiff || d.meanDiff > meanDiff) { // keep an amplified diff for looking at
        Image diff(img.width, img.height, img.channels);
        for (size_t i = 0; i < diff.data.size(); ++i) {
            int v = std::abs(int(img.data[i]) - int(ref.data[i])) * 8;
            diff.data[i] = uint8_t(v > 255 ? 255 : v);
        }
        writePng(std::string(WB_TEST_OUT_DIR) + "/" + name + ".diff.png", diff, &err);
    }
    CHECK(d.maxDiff <= maxDiff);
    CHECK(d.meanDiff <= meanDiff);
}

} // namespace wb::test
