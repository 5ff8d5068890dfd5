#pragma once
// A tiny lab for testing the shell: a red triangle on blue; `g` turns it green;
// it reports busy() for its first two frames, like a lab tracing in the background.
#include "common/lab.h"

namespace wb::test {

struct TestLabState {
    bool green = false; // toggled by `g`
    int frames = 0;     // draw() calls so far
    int initCalls = 0;  // init() calls so far
};

std::unique_ptr<Lab> makeTestLab(TestLabState* observe = nullptr);

} // namespace wb::test
