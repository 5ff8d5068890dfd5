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

// Everything the keys and the panel change; plain data so tests can read it.
struct RadiosityState {
    std::string sceneName = "cornell";  // rad::sceneNames(): cornell, classroom, floorlamp
    FfMethod method = FfMethod::GlHemicube; // keys 1 2 3 (GL: ~4 ms a 128² row here, CPU ~15)
    int solver = 0;          // 0 progressive, 1 Jacobi, 2 Gauss-Seidel (panel)
    bool smooth = false;     // s: vertex values + Gouraud (13.43) instead of flat (13.42)
    bool outlines = false;   // p: patch outlines
    bool showItems = false;  // panel: the scene in item colours, as the hemicube draws it
    bool ambient = true;     // progressive: display the ambient term for the unshot light
    double patchSize = 0.05; // metres, the mesher's longest patch edge ([ ] scale by √2)
    int hemicubeRes = 128;   // pixels along a full hemicube face (CPU and GL)
    int raySamples = 16;     // k rays per patch pair (method 1)
    double tolerance = 1e-3; // r stops when the residual (unshot power / emitted) is below
    float exposure = 1.0f;   // display: multiplies the scene's automatic exposure
    int threads = 0;         // form-factor threads, 0 = all cores
};

std::unique_ptr<Lab> makeRadiosityLab();

// Test access (the lab class lives in the .cpp).
RadiosityState& radiosityState(Lab& lab);
// Patches, solver steps and residual of the current solution.
int radiosityPatchCount(const Lab& lab);
int radiosityStepCount(const Lab& lab);
double radiosityResidual(const Lab& lab);
// B per patch (display radiosity: with the ambient term when progressive and on).
std::vector<glm::dvec3> radiosityDisplayB(const Lab& lab);
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

} // namespace wb
