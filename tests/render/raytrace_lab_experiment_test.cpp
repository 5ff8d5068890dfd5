// Lab 07's timing experiment (issue 11.9): both BVH settings as columns, progress, `x`
// cancels it at once, the view stays in the mode the user chose; the trace's ray
// counters move while it runs; --help names every built-in scene.
#include "render_check.h"

#include "lab_scenes.h"
#include "raytrace_lab.h"
#include "trace_job.h"

#include "common/headless_context.h"

#include <chrono>
#include <thread>

namespace {

// An OSMesa context for driving draw() by hand, as a window would (no waiting).
struct Context : wb::HeadlessContext {
    Context(int w, int h) : HeadlessContext(w, h) { REQUIRE(ok()); }
};

constexpr int kW = 320, kH = 240;

wb::View windowView() { return wb::test::windowView(kW, kH); }

} // namespace

TEST_CASE("lab 07 experiment: every scene with and without the BVH, G stays selected", "[gl]") {
    auto lab = wb::makeRaytraceLab();
    wb::raytraceSetExperiment(*lab, {"one-sphere", "balls:1"}, 1e9);
    // G first, then t: the experiment must not flip the view to the raster.
    wb::test::renderLab(*lab, 96, 72, "Gt");
    CHECK(wb::raytraceState(*lab).traced);
    const auto& rows = wb::raytraceTimings(*lab);
    REQUIRE(rows.size() == 2);
    for (const wb::TimingRow& r : rows) {
        INFO(r.scene);
        CHECK(r.traceSeconds > 0);
        CHECK(r.bruteSeconds > 0);
        CHECK_FALSE(r.bruteEstimated);
        CHECK(r.raysPerSecond > 0);
        CHECK(r.bruteRaysPerSecond > 0);
    }
    CHECK(rows[1].bvhBuilt); // balls 1: 91 objects
    // The BVH setting of the view is not what the experiment used: both columns ran
    // whatever `b` says.
    CHECK(wb::raytraceState(*lab).bvh);
}

TEST_CASE("lab 07 experiment: a no-BVH trace estimated over the limit is not run", "[gl]") {
    auto lab = wb::makeRaytraceLab();
    // A tiny limit: balls:1's brute force time, scaled by balls:2's object count, exceeds it.
    wb::raytraceSetExperiment(*lab, {"balls:1", "balls:2"}, 1e-9);
    wb::test::renderLab(*lab, 64, 48, "t");
    const auto& rows = wb::raytraceTimings(*lab);
    REQUIRE(rows.size() == 2);
    CHECK_FALSE(rows[0].bruteEstimated);
    CHECK(rows[1].bruteEstimated);
    // Brute force is linear in the object count: the estimate is the row above, scaled.
    CHECK(rows[1].bruteSeconds ==
          Approx(rows[0].bruteSeconds * double(rows[1].primitives) / double(rows[0].primitives)));
    CHECK(rows[1].traceSeconds > 0); // the BVH column still ran
}

TEST_CASE("lab 07 experiment: progress while it runs, x cancels it at once", "[gl]") {
    Context c(kW, kH);
    auto lab = wb::makeRaytraceLab();
    std::string err;
    REQUIRE(lab->setOption("threads", "1", err));
    // Without the BVH balls 3 (820 spheres) at 320×240 on one thread takes seconds.
    wb::raytraceSetExperiment(*lab, {"balls:3"}, 1e9);
    lab->init();
    const wb::View v = windowView();
    lab->key('G');
    lab->draw(v);
    lab->key('t');
    const auto t0 = std::chrono::steady_clock::now();
    double progress = 0;
    std::string current;
    // Wait until the no-BVH column is being traced and has made progress.
    for (;;) {
        lab->draw(v);
        const wb::ExperimentStatus st = wb::raytraceExperiment(*lab);
        REQUIRE(st.active);
        progress = st.fraction;
        current = st.current;
        if (current.find("no BVH") != std::string::npos && progress > 0.5) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        REQUIRE(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60));
    }
    INFO(current << " at " << progress);
    CHECK(progress < 1.0);
    CHECK(wb::raytraceState(*lab).traced); // G stays G during the experiment
    const auto t1 = std::chrono::steady_clock::now();
    REQUIRE(lab->key('x'));
    // Cancel is polled between 16×16 tiles: one tile of this scene is far under 500 ms.
    CHECK(std::chrono::steady_clock::now() - t1 < std::chrono::milliseconds(500));
    const wb::ExperimentStatus st = wb::raytraceExperiment(*lab);
    CHECK_FALSE(st.active);
    CHECK(st.cancelled);
    // The half-done row (its BVH column) is kept, the no-BVH column is not filled in.
    REQUIRE(wb::raytraceTimings(*lab).size() == 1);
    CHECK(wb::raytraceTimings(*lab)[0].traceSeconds > 0);
    CHECK(wb::raytraceTimings(*lab)[0].bruteSeconds < 0);
    CHECK(wb::raytraceState(*lab).traced);
}

TEST_CASE("lab 07: the ray counters move while a trace runs", "[gl]") {
    wb::LabScene s;
    std::string err;
    REQUIRE(wb::loadLabScene("seed001-table", s, err));
    REQUIRE(wb::setAccel(s, true));
    wb::TraceRequest req;
    req.scene = &s;
    req.model = s.model;
    req.threads = 1;
    req.camera = wb::ViewCamera::make(s.camera, 0, 0, 1, 400, 300);
    wb::TraceJob job;
    job.start(req);
    long long seen = 0;
    bool midway = false;
    while (job.status().running) {
        const wb::TraceStatus st = job.status();
        if (st.running && st.tilesDone > 0 && st.tilesDone < st.tilesTotal) {
            midway = true;
            seen = std::max(seen, st.primaryRays);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const wb::TraceStatus end = job.status();
    REQUIRE(end.finished);
    if (!midway) WARN("the trace finished before a midway status was seen");
    if (midway) {
        CHECK(seen > 0);               // was 0 until the end
        CHECK(seen < end.primaryRays); // a part of the frame
    }
    CHECK(end.primaryRays == 400 * 300);
}

TEST_CASE("lab 07 --help names every built-in scene", "[gl]") {
    auto lab = wb::makeRaytraceLab();
    std::string sceneHelp;
    for (const wb::OptionHelp& o : lab->options())
        if (o.name == "scene") sceneHelp = o.what;
    for (const std::string& n : wb::builtinSceneNames()) {
        if (n.find(':') != std::string::npos) continue; // balls:N, jacks:N are named once
        INFO(n);
        CHECK(sceneHelp.find(n + " ") != std::string::npos);
    }
    CHECK(sceneHelp.find("diffuse-spheres") != std::string::npos);
    CHECK(sceneHelp.find("seed000-part1-lit") != std::string::npos);
}
