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

// One row of the timing experiment.
struct TimingRow {
    std::string scene;
    long long primitives = 0, triangles = 0;
    double rasterMs = 0;      // mean of several frames, glFinish included
    double traceSeconds = 0;  // wall time of the whole trace
    double accelSeconds = 0;  // BVH build
    double raysPerSecond = 0; // primary + secondary + shadow rays / trace time
    int width = 0, height = 0;
};

class RaytraceLab;
std::unique_ptr<Lab> makeRaytraceLab();

// Test access to the lab's state (the lab class lives in the .cpp).
RaytraceState& raytraceState(Lab& lab);
const RayTree* raytraceInspected(const Lab& lab);
// Inspects image pixel (x, y) of the traced view as a click there would.
void raytraceInspectPixel(Lab& lab, int x, int y);
const std::vector<TimingRow>& raytraceTimings(const Lab& lab);
// Cancelled traces so far (camera changes during a trace) and the last finished frame's status.
int raytraceCancels(const Lab& lab);
bool raytraceLastTraceFinished(const Lab& lab);

} // namespace wb
