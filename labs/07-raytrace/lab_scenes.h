#pragma once
// The scenes of lab 07 by name: in code (the lab's timing experiment, seed 000's worked
// example and glass cube, seed 001's table and glass), generated (SPD balls and jacks)
// and read from .nff / .obj files, each with the camera and shading model it is meant for.
// No GL here: the same scene feeds the rasterizer and the tracer.
#include "core/raytrace/scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace wb {

// Where the eye is and how pixels map to rays (the rasterizer uses the same numbers).
struct CameraSpec {
    glm::dvec3 eye{0, 0, 5};   // eye position, world units
    glm::dvec3 target{0.0};    // the point at the image centre; the orbit turns about it
    glm::dvec3 up{0, 1, 0};    // up hint, not parallel to target − eye
    double fovY = 45.0;        // vertical field of view, degrees (used when screenPixel == 0)
    double screenPixel = 0.0;  // > 0: world size of one pixel on the screen plane through the
                               // target (seed 000: 1 at Dist = 100), so the view grows with
                               // the image instead of keeping its field of view
    double hither = 0.0;       // NFF's near plane: nearer than this along the view is clipped
    bool pixelCorners = false; // seed 000's pixel mapping xs = xx − W/2 (a pixel's corner);
                               // false: rays through pixel centres, as GL samples them
};

enum class ModelKind {
    Course, // seed 000's model: 0..255 integers, distScale, ka/kd/ks/kr/kt
    Phong,  // the OpenGL fixed-function equation of lab 2 (what `g` draws)
};

struct LabScene {
    std::string name;                     // as given to loadLabScene
    std::string about;                    // one line for the panel
    std::unique_ptr<rt::Scene> scene;     // never null after a successful load
    std::unique_ptr<rt::Aggregate> accel; // BVH when built (see useAccel), else null
    CameraSpec camera;                    // the view the scene is meant to be seen from
    ModelKind model = ModelKind::Phong;   // the model the scene is meant for
    double loadSeconds = 0.0;             // building or reading the scene
    double accelSeconds = 0.0;            // building the BVH (0 when none)
    std::vector<std::string> warnings;    // the reader's first warnings, "file:line: text"
    size_t warningCount = 0;              // all of them (kept or not)
};

// "N warning(s):", the kept lines, "... and M more" (empty when there are none): what
// the panel and the headless run show.
std::vector<std::string> warningLines(const LabScene& s);

// Names the panel offers (in-code and generated scenes; files come by path).
std::vector<std::string> builtinSceneNames();

// Builds or loads `name`: one-sphere, two-spheres, diffuse-spheres, seed000-part1, seed000-part2,
// seed000-part1-lit (rectangle 1 removed), glass-cube, seed001-table, balls:N, jacks:N
// (N = 1..5), or a path ending in .nff / .obj. False with a message on a bad name or file.
bool loadLabScene(const std::string& name, LabScene& out, std::string& error);

// Installs (on: when the scene is large enough to pay for it) or removes (off) the BVH
// of a loaded scene; returns false when this build has no BVH. The scene must not be
// traced while this runs.
bool setAccel(LabScene& s, bool on);

} // namespace wb
