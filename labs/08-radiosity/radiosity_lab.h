#pragma once
// Lab 08: radiosity (course practicals 13-15, §1.13-1.15). The scene is cut into patches
// (core/radiosity/mesh.h), form factors come from rays (§1.15.1), the CPU hemicube or the
// hemicube drawn by OpenGL (§1.15.2, gl_hemicube.h), and B = E + R·F·B is solved by
// progressive refinement (space: one shot, r: to convergence in the background) or by
// Jacobi / Gauss-Seidel sweeps (panel). Flat patches (figure 13.42) or smoothed vertex
// values with Gouraud (figure 13.43). A click on a patch shows its form-factor row as a
// false-colour map over the scene and its hemicube unfolded in a corner.
#include "common/lab.h"

#include "core/radiosity/hemicube.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace wb {

enum class FfMethod { Rays = 0, CpuHemicube = 1, GlHemicube = 2 };

// Everything the keys and the panel change; plain data so tests can read it. The defaults
// are the fast configuration (issue 19 item 7; figures in docs/bench/radiosity.md and
// /work/wt/brief/lab08-defaults.md): ~3.7k patches in the Cornell box, progressive refinement
// shooting from groups of ~11×11 patches, rows by the method of keys 1 2 3.
struct RadiosityState {
    std::string sceneName = "cornell"; // rad::sceneNames(): cornell, classroom, floorlamp
    // Keys 1 2 3. Rays by default: with shooting groups the rays are gathered at the receivers
    // (exact near field, point_rays.h), the fastest method here (0.5 s to a usable picture in
    // a window) and the closest to the answer; the hemicubes shoot from the group's centre.
    FfMethod method = FfMethod::Rays;
    int solver = 0;           // 0 progressive, 1 Jacobi, 2 Gauss-Seidel (panel)
    bool smooth = false;      // s: vertex values + Gouraud (13.43) instead of flat (13.42)
    bool outlines = false;    // p: patch outlines
    bool showItems = false;   // panel: the scene in item colours, as the hemicube draws it
    bool ambient = true;      // progressive: display the ambient term for the unshot light
    double patchSize = 0.0;   // metres, the mesher's longest patch edge ([ ] scale by √2);
                              // 0 before a scene is loaded: sized for ~kDefaultPatches
    double shooterEdge = 0.0; // metres, shooting groups (0: every patch shoots itself)
    int hemicubeRes = 0;      // pixels along a full hemicube face; 0: the method's default
                              // (128 for both: see hemicubeFor())
    int raySamples = 4;       // k rays per patch pair / per group-to-patch pair (method 1): the
                              // group rows' F is exact (point to polygon), k only samples V
    // A solve stops when the residual (unshot power / emitted) is below. 1e-4, not 1e-3: the
    // ambient term standing for the unshot rest spreads it evenly, and at 1e-3 that put the
    // darkest faces (the short block's front, B ≈ 0.013) 1.5-2% too bright against Cycles;
    // the rows are cached by then, so the extra shots cost little (docs/bench/radiosity.md).
    double tolerance = 1e-4;
    bool autoExposure =
        true;              // display: exposure from the picture (90th percentile), else the slider
    float exposure = 1.0f; // display: linear B × exposure, then sRGB encoding
    bool whiteBalance = true; // display: divide by the light's colour (luminance kept)
    int threads = 0;          // form-factor threads, 0 = all cores (capped at the hardware's)
    int maxSteps = -1; // headless: the automatic solve stops after this many steps (-1: tolerance)
    double budget = 60.0; // headless: seconds of work, then the picture of what there is
};

// Patch count the default patch size is chosen for (defaultPatchSize meshes to find it): the
// bench's ~4k goal; the Cornell box gets 3,692 at 0.0286 m with today's mesher.
constexpr int kDefaultPatches = 3700;
// Patch count no way of setting the patch size (flag, key, slider, adaptive) may exceed.
constexpr int kMaxPatches = 40000;
// Edge of a default shooting group in default patch edges, for every method (0.10 m in the
// Cornell box, 252 groups). Rays gather each row at the receivers (exact F to the group's
// outline): larger groups made it worse (0.10 m 2.29%, 0.12 m 2.62%, 0.14 m 2.62% worst surface
// against Cycles, before the plane fit). The hemicubes: 0.14 m groups (133 rows instead of 248)
// were as close as 0.10 m with flat pooling (1.9%), but with the plane fit and the 1e-4 stop
// only 0.10 m keeps every surface within 1% (0.97%; 0.12 m 1.50%, 0.14 m 1.13%, 0.14 m at 256²
// 1.33%: the ceiling left of the light): docs/bench/radiosity.md, "Lab 08 defaults".
constexpr double kShooterPatches = 4.25;
// The preview phase of a run in a window (radiosity_preview.cpp): shooting groups this many
// times the default's edge (0.30 m in the Cornell box), solved to this unshot fraction first.
constexpr double kPreviewGroupScale = 3.0;
constexpr double kPreviewTolerance = 1e-3;
// Hemicube resolution a method uses when none is set (--hemicube or the slider).
int hemicubeFor(const RadiosityState& s);

std::unique_ptr<Lab> makeRadiosityLab();

// Test access (the lab class lives in the .cpp).
RadiosityState& radiosityState(Lab& lab);
// Patches, solver steps and residual of the current solution.
int radiosityPatchCount(const Lab& lab);
int radiosityStepCount(const Lab& lab);
double radiosityResidual(const Lab& lab);
// B per patch (display radiosity: with the ambient term when progressive and on).
std::vector<glm::dvec3> radiosityDisplayB(const Lab& lab);
// The preview's display B against the current one (the converged answer after a run), both
// by luminance, the light left out: area-weighted relative RMS over the patches, and the
// surface whose area mean is the most off (signed: +0.02 = the preview 2% brighter).
struct PreviewError {
    bool ran = false; // a preview ran (--preview on headless)
    double rms = 0, worst = 0;
    std::string surface;
};
PreviewError radiosityPreviewError(const Lab& lab);
// The preview phase's display B when it ended (empty: no preview ran; --preview on headless).
std::vector<glm::dvec3> radiosityPreviewB(const Lab& lab);
// The selected patch (−1: none), its form-factor row and its item buffer (as the current
// method made it: GL for key 3, CPU otherwise).
int radiositySelected(const Lab& lab);
const std::vector<float>& radiositySelectedRow(const Lab& lab);
const rad::ItemBuffer& radiositySelectedItems(const Lab& lab);
// Selects patch `patch` as a click on it would (the row and hemicube are made in the next draw).
void radiositySelect(Lab& lab, int patch);
// Which surface (index into the scene's surfaces) each patch belongs to, and surface names.
std::vector<int> radiosityPatchSurfaces(const Lab& lab);
std::vector<std::string> radiositySurfaceNames(const Lab& lab);
std::vector<glm::dvec3> radiosityPatchCentres(const Lab& lab);
// The headless summary line of the current state (what the next draw prints).
std::string radiositySummary(const Lab& lab);
// True when the last headless run stopped at the budget (--budget) before the tolerance.
bool radiosityBudgetHit(const Lab& lab);
// Display colour (sRGB, 0..1) of patch `i` as drawn flat.
glm::vec3 radiosityPatchColour(const Lab& lab, int i);

} // namespace wb
