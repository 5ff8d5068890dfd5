#pragma once
// Lab 07: ray tracing versus rasterization (course lab 7, §1.11–1.12, seeds 000, 001,
// 003). One scene, two pictures: `g` draws it with OpenGL Phong (fixed function or the
// per-fragment shader of shaders/phong.*), `G` ray-traces it in the background with the
// project's tracer; both times side by side, a difference heat map, the timing
// experiment (one sphere vs two, SPD balls), and a ray inspector for any pixel.
#include "common/lab.h"
#include "lab_scenes.h"
#include "ray_inspector.h"
#include "view_camera.h"

#include <memory>
#include <string>

namespace wb {

// Everything the keys and the panel change; plain data so tests can read it.
struct RaytraceState {
    std::string sceneName = "two-spheres"; // see loadLabScene
    bool traced = false;                   // G: show the ray-traced image; g: the rasterized one
    bool glsl = false;     // raster with shaders/phong.* (per fragment) instead of fixed function
    bool showDiff = false; // d: |raster − trace| heat map (needs a finished trace)
    ModelKind model = ModelKind::Phong; // tracer model (set from the scene, m switches)
    int maxDepth = 5;                   // tracer depth limit ([ ])
    double minWeight = 0.01;            // tracer weight cut-off
    int threads = 0;                    // 0 = all cores
    bool bvh = true;                    // use the BVH when the scene is large enough
    int divisor = 1;                    // trace at (W/divisor) × (H/divisor)
    float yaw = 0, pitch = 0;           // arrow keys, degrees (added to the mouse orbit)
    bool showRayPath = true;            // draw the inspected ray tree in 3D
};

// One row of the timing experiment: one scene, traced with the BVH and without it.
struct TimingRow {
    std::string scene;
    long long primitives = 0, triangles = 0;
    double rasterMs = 0;           // mean of several frames, glFinish included
    double traceSeconds = -1;      // BVH column: best wall time of the trace (-1: not run)
    double bruteSeconds = -1;      // no-BVH column (-1: not run or cancelled)
    bool bruteEstimated = false;   // bruteSeconds is an estimate (too slow to run: see panel)
    bool bvhBuilt = false;         // false: too few objects, the "BVH" trace was brute force too
    double accelSeconds = 0;       // BVH build
    double raysPerSecond = 0;      // BVH column: all rays / trace time
    double bruteRaysPerSecond = 0; // no-BVH column
    int width = 0, height = 0;
};
// Timing experiment progress, for the panel and tests.
struct ExperimentStatus {
    bool active = false;
    bool cancelled = false; // `x` stopped it; finished rows stay
    double fraction = 0;    // 0..1 of the planned traces
    std::string current;    // "balls:3, no BVH, run 1"
    double seconds = 0;     // since the start
};

class RaytraceLab;
std::unique_ptr<Lab> makeRaytraceLab();

// Test access to the lab's state (the lab class lives in the .cpp).
RaytraceState& raytraceState(Lab& lab);
const RayTree* raytraceInspected(const Lab& lab);
// Inspects image pixel (x, y) of the traced view as a click there would.
void raytraceInspectPixel(Lab& lab, int x, int y);
const std::vector<TimingRow>& raytraceTimings(const Lab& lab);
ExperimentStatus raytraceExperiment(const Lab& lab);
// Test hook: the experiment's scenes (default: the lab's list) and its no-BVH time limit.
void raytraceSetExperiment(Lab& lab, const std::vector<std::string>& scenes,
                           double bruteLimitSeconds);
// Cancelled traces so far (camera changes during a trace) and the last finished frame's status.
int raytraceCancels(const Lab& lab);
bool raytraceLastTraceFinished(const Lab& lab);

} // namespace wb
