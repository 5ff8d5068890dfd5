// Lab 07's background trace: a camera change in the middle of a trace cancels it and
// starts the new frame, and the frame that ends is exactly the new camera's (no tile of
// the old one left: "no torn image"); quitting mid-trace joins the worker. Run under the
// sanitizers too (build with -DWORKBENCH_SANITIZE=ON).
#include "render_check.h"

#include "raytrace_lab.h"
#include "trace_job.h"

#include "common/gl_util.h"
#include "core/raytrace/course_model.h"
#include "core/raytrace/render.h"

#include "common/headless_context.h"

#include <chrono>
#include <thread>

namespace {

// An OSMesa context for driving draw() by hand (renderHeadless would wait for the trace).
struct Context : wb::HeadlessContext {
    Context(int w, int h) : HeadlessContext(w, h) { REQUIRE(ok()); }
};

constexpr int kW = 320, kH = 240;

wb::View windowView() { return wb::test::windowView(kW, kH); }

} // namespace

TEST_CASE("lab 07: a camera change during a trace cancels it and the result is the new view's",
          "[gl]") {
    wb::Image after;
    int cancels = 0;
    {
        Context c(kW, kH);
        auto lab = wb::makeRaytraceLab();
        std::string err;
        REQUIRE(lab->setOption("scene", "seed001-table", err));
        REQUIRE(lab->setOption("threads", "1", err));
        lab->init();
        const wb::View v = windowView();
        lab->key('G');
        lab->draw(v); // starts the trace in the background
        REQUIRE(lab->busy());
        for (int i = 0; i < 3; ++i) { // three camera changes, each mid-trace
            lab->key(wb::kKeyLeft);
            lab->draw(v);
        }
        cancels = wb::raytraceCancels(*lab);
        const auto t0 = std::chrono::steady_clock::now();
        while (lab->busy()) {
            lab->draw(v); // tiles appear while the window keeps drawing
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            REQUIRE(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120));
        }
        lab->draw(v);
        glFinish();
        after = wb::readFramebuffer(kW, kH);
        CHECK(wb::raytraceLastTraceFinished(*lab));
    }
    // A 320×240 trace of this scene takes far longer than a draw() call, so every change
    // normally arrives mid-trace (3). On a loaded machine one llvmpipe draw() can outlast
    // a trace (seen with a parallel sanitizer build: 2), so at least one is required.
    CHECK(cancels >= 1);
    CHECK(cancels <= 3);
    if (cancels != 3) WARN("only " << cancels << " of 3 camera changes arrived mid-trace");
    // The frame shown equals a fresh headless render of the final camera, pixel for pixel.
    auto fresh = wb::makeRaytraceLab();
    std::string err;
    REQUIRE(fresh->setOption("scene", "seed001-table", err));
    const wb::Image ref = wb::test::renderLab(*fresh, kW, kH, "G{left}{left}{left}");
    const wb::ImageDiff d = wb::compareImages(after, ref);
    REQUIRE(d.sameSize);
    CHECK(d.maxDiff == 0);
}

TEST_CASE("lab 07: quitting in the middle of a trace stops and joins the worker", "[gl]") {
    Context c(kW, kH);
    for (int round = 0; round < 3; ++round) {
        auto lab = wb::makeRaytraceLab();
        std::string err;
        REQUIRE(lab->setOption("scene", "glass-cube", err));
        lab->init();
        lab->key('G');
        lab->draw(windowView());
        REQUIRE(lab->busy());
        if (round == 1) std::this_thread::sleep_for(std::chrono::milliseconds(20));
        const auto t0 = std::chrono::steady_clock::now();
        lab.reset(); // what Esc does: the shell destroys the lab
        // Cancel is polled between tiles: one 16×16 tile of this scene is well under 50 ms.
        CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::milliseconds(500));
    }
}

TEST_CASE("lab 07: the tiled background trace equals the single-threaded reference renderer",
          "[gl]") {
    wb::LabScene s;
    std::string err;
    REQUIRE(wb::loadLabScene("glass-cube", s, err));
    const wb::ViewCamera cam = wb::ViewCamera::make(s.camera, 10, -5, 1.2, 97, 61); // odd sizes
    wb::TraceJob job;
    wb::TraceRequest req;
    req.scene = &s;
    req.camera = cam;
    req.model = s.model;
    req.tileSize = 16; // 97 = 6·16 + 1: partial tiles at the right and bottom
    job.start(req);
    job.wait();
    const wb::TraceStatus st = job.status();
    CHECK(st.finished);
    CHECK(st.tilesDone == 7 * 4);
    CHECK(st.nonFinitePixels == 0);
    wb::Image rgba;
    uint64_t version = 0;
    REQUIRE(job.fetch(rgba, version));
    const wb::rt::CourseModel model;
    const wb::Image ref = wb::rt::render(*s.scene, wb::PixelCamera(cam), model, 97, 61);
    int differ = 0;
    for (int y = 0; y < 61; ++y)
        for (int x = 0; x < 97; ++x) {
            differ += rgba.at(x, y)[3] != 255;
            for (int ch = 0; ch < 3; ++ch)
                differ += rgba.at(x, y)[ch] != ref.at(x, y)[ch];
        }
    CHECK(differ == 0);
}

TEST_CASE("lab 07: while a restarted trace runs, every pixel shown is the new camera's", "[gl]") {
    // The torn-image check at any moment, not only at the end: restart the job with a
    // turned camera in the middle of a frame, then compare every traced pixel (alpha 255)
    // of each snapshot taken while it runs with the finished frame.
    wb::LabScene s;
    std::string err;
    REQUIRE(wb::loadLabScene("seed001-table", s, err));
    REQUIRE(wb::setAccel(s, true));
    wb::TraceRequest req;
    req.scene = &s;
    req.model = s.model;
    req.threads = 1;
    // 400×300 on one thread takes long enough (tens of ms) to be seen growing even on a
    // busy machine; at 200×150 it sometimes finished between two 2-ms snapshots.
    req.camera = wb::ViewCamera::make(s.camera, 0, 0, 1, 400, 300);
    wb::TraceJob job;
    job.start(req);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    req.camera = wb::ViewCamera::make(s.camera, 25, 10, 1, 400, 300);
    job.start(req); // cancels and joins the first frame
    std::vector<wb::Image> snapshots;
    uint64_t version = 0;
    wb::Image img;
    while (job.status().running) {
        if (job.fetch(img, version)) snapshots.push_back(img);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    job.fetch(img, version);
    REQUIRE(job.status().finished);
    INFO(snapshots.size() << " snapshots");
    CHECK(snapshots.size() >= 2); // the frame was seen while it grew
    long long traced = 0, wrong = 0;
    for (const wb::Image& snap : snapshots)
        for (int y = 0; y < snap.height; ++y)
            for (int x = 0; x < snap.width; ++x) {
                if (snap.at(x, y)[3] != 255) continue;
                ++traced;
                for (int c = 0; c < 3; ++c)
                    wrong += snap.at(x, y)[c] != img.at(x, y)[c];
            }
    CHECK(traced > 0);
    CHECK(wrong == 0);
}
