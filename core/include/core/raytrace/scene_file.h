#pragma once
// A scene loaded from a file or generated in code, with the view its author meant
// (NFF's `v` block; a framing default for OBJ files and scenes without one).
#include "core/raytrace/camera.h"
#include "core/raytrace/scene.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace wb::rt {

// Bad input: the message is "file:line: problem" (line 0 when no line applies).
class SceneFileError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct SceneView {
    glm::dvec3 from{0, 0, 5}; // eye
    glm::dvec3 at{0.0};       // point looked at (centre of the image)
    glm::dvec3 up{0, 1, 0};   // up hint, not parallel to at − from
    double angle = 45.0;      // NFF angle: full vertical field of view in degrees, (0, 180)
    double hither = 1e-3;     // NFF hither: the near plane's distance; nearer is clipped
                              // (eye rays start on it, ScreenCamera::hither)
    int width = 512;          // NFF resolution (image size the author meant)
    int height = 512;
};

// Most primitives allowed to nearly coincide in one spot (loadSceneFile).
constexpr std::size_t kScenePileLimit = 1000;

// Loader warnings kept with a SceneFile (the count covers all of them).
constexpr std::size_t kSceneMaxKeptWarnings = 10;

struct SceneFile {
    std::unique_ptr<Scene> scene; // never null after a successful load
    SceneView view;               // from the file, or a default that frames the scene
    bool hasView = false;         // the file gave its own view
    // Repairs the loader made (OBJ: faces dropped, missing .mtl, normals repaired), the
    // first kSceneMaxKeptWarnings as "file:line: what", for the front ends to show.
    std::vector<std::string> warnings;
    std::size_t warningCount = 0; // all warnings, kept or not
    // The pinhole camera of `view` (vertical field of view = view.angle).
    LookAtCamera camera() const;
};

// `up` scaled by a power of two so its largest component is in [1, 2) (exact; the
// direction is all a camera needs and cross products with it cannot overflow).
glm::dvec3 scaledUp(const glm::dvec3& up);

// Loads .nff or .obj by extension (case-insensitive). Throws SceneFileError naming the
// file, the line and the problem; never crashes on malformed input. Only regular files
// are read (a directory, FIFO or device is refused); a file with nothing to draw is an
// error.
//
// Piles (issue 20 point 2): exact duplicates are dropped by the readers (and counted in
// the warnings); more than kScenePileLimit primitives whose boxes agree to 1/64 of their
// size are refused, so no spot of a scene makes a ray test more than about that many
// overlapping primitives (64x64 of 100,000 near-coincident spheres took 9 s).
SceneFile loadSceneFile(const std::string& path);
// The same without the pile check (what the readers alone accept).
SceneFile loadSceneFileUnchecked(const std::string& path);

// A view that frames the bounded primitives of `scene` (looking from +z, slightly
// above, with the scene's bounding sphere filling the vertical field of view).
SceneView frameScene(const Scene& scene, double angle = 45.0);
// Adds a white point light above-behind the viewer when the scene has none.
void addDefaultLight(Scene& scene, const SceneView& view);

} // namespace wb::rt
