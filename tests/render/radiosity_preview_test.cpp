// Lab 08's preview (issue 19 item 7, radiosity_preview.cpp): a run in a window first solves the
// same patches shooting from 0.30 m groups by rays and shows that, then the full solve. The
// full solve's answer must not depend on the preview, on timing or on threads; the preview's
// own answer must not depend on threads either; and it must be as close to the converged
// picture as the panel says. Headless, --preview on runs both phases as a window does (the
// worker thread for rays and the CPU hemicube, draw()'s slices for GL).
#include "render_check.h"

#include "radiosity_lab.h"

#include <tbb/global_control.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr int kW = 96, kH = 72;

struct Solved {
    std::vector<glm::dvec3> B, preview;
    wb::PreviewError error;
};

// The Cornell box at 0.05 m patches (~930) shooting from the default 0.10 m groups (2×2
// patches: 230 groups; the preview's 0.30 m groups: 37), hemicube 32²: a second or so a solve.
Solved solve(const char* method, const char* preview, const char* threads, bool small = true) {
#ifdef WB_TSAN_THREADS
    // ThreadSanitizer (.ci/run): Debian's TBB is not instrumented and its threads give false
    // reports; with TBB held to one thread what is checked is the lab's worker (both phases),
    // the solvers' prefetch workers and the thread reading the snapshots.
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
#endif
    auto lab = wb::makeRadiosityLab();
    std::string err;
#ifdef WB_SANITIZED
    // Under the sanitizers (ThreadSanitizer: 200 s at 0.05 m) ~350 patches, 0.2 m groups.
    REQUIRE(lab->setOption("patch-size", small ? "0.08" : "0.05", err));
    if (small) REQUIRE(lab->setOption("shooting-patch", "0.2", err));
#else
    (void)small;
    REQUIRE(lab->setOption("patch-size", "0.05", err));
#endif
    REQUIRE(lab->setOption("hemicube", "32", err));
    REQUIRE(lab->setOption("method", method, err));
    REQUIRE(lab->setOption("preview", preview, err));
    REQUIRE(lab->setOption("threads", threads, err));
    wb::test::renderLab(*lab, kW, kH);
    REQUIRE(wb::radiosityResidual(*lab) < 1e-4); // converged (the lab's default tolerance)
    return {wb::radiosityDisplayB(*lab), wb::radiosityPreviewB(*lab), wb::radiosityPreviewError(*lab)};
}

bool same(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    return a.size() == b.size() && !a.empty() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::dvec3)) == 0;
}

} // namespace

TEST_CASE("lab 08 preview: the converged answer is the same bit for bit with it on or off, and "
          "the preview is the same with 1 thread or all",
          "[gl][preview]") {
#ifdef WB_TSAN_THREADS
    // ThreadSanitizer: the worker's two phases (rays and the CPU hemicube run the same code;
    // GL steps on the calling thread).
    const std::vector<const char*> methods{"rays"};
#else
    const std::vector<const char*> methods{"rays", "cpu", "gl"};
#endif
    for (const char* method : methods) {
        INFO(method);
        const Solved off = solve(method, "off", "0");
        CHECK(off.preview.empty());
        CHECK_FALSE(off.error.ran);
        const Solved on = solve(method, "on", "0");
        REQUIRE(!on.preview.empty()); // the preview ran
        CHECK(same(on.B, off.B));
        CHECK_FALSE(same(on.preview, on.B)); // it is another answer (else the check says nothing)
        // One thread (TBB arena of 1; the prefetch workers still run beside it): the same.
        const Solved one = solve(method, "on", "1");
        CHECK(same(one.B, off.B));
        CHECK(same(one.preview, on.preview));
    }
}

// The panel says "the walls within a few per cent of the answer, the blocks' faces up to ~40%":
// measured at the lab's defaults (3,716 patches) 6.1% RMS and +37.4% on the short block's
// darkest face (B ≈ 0.013), docs/bench/radiosity.md "l08fast". Here on the test's smaller
// mesh, bounds with room for that (measured: see the INFO on failure) but well under what a
// preview missing the indirect light or shooting twice would give (the unlit box: ~100%).
TEST_CASE("lab 08 preview: its picture is within the stated error of the converged one",
          "[gl][preview]") {
    const Solved on = solve("rays", "on", "0", false);
    REQUIRE(on.error.ran);
    INFO("RMS " << on.error.rms << ", worst " << on.error.worst << " on " << on.error.surface);
    CHECK(on.error.rms < 0.08); // measured 5.26% (0.05 m patches, 2026-12-02)
    CHECK(std::fabs(on.error.worst) < 0.45); // measured +29.1% (short block 2)
}
