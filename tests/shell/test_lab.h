#pragma once
// A tiny lab for testing the shell: a red triangle on blue; `g` turns it green;
// it reports busy() for its first two frames, like a lab tracing in the background;
// the unlisted key `B` starts a "background run" that ends right after the frame that
// draws its twelfth running frame (yellow triangle; green-blue background when it has ended):
// the window must draw one more frame by itself to show the end;
// the unlisted key `F` makes its headless render fail (headlessFailed()).
// Its panel has a button (counted) and, after the unlisted key `L`, a label far too long
// for any panel (the clipping check must fail on it) and 60 more lines (the panel scrolls).
#include "common/lab.h"

namespace wb::test {

struct TestLabState {
    bool green = false; // toggled by `g`
    int frames = 0;     // draw() calls so far
    int initCalls = 0;  // init() calls so far
    bool longLabel = false; // `L`: show the too-long label
    int presses = 0;        // clicks on the panel's button
    float buttonX = 0, buttonY = 0; // the button's centre in the last frame, window pixels
};

std::unique_ptr<Lab> makeTestLab(TestLabState* observe = nullptr);

} // namespace wb::test
