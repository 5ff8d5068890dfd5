#pragma once
// The scenes of the ray tracer bench, shared by its own frames and by the Embree
// comparison so both measure the same list.
#include "core/raytrace/obj_file.h"
#include "core/raytrace/scene_file.h"
#include "core/raytrace/spd.h"

#include <functional>
#include <string>
#include <vector>

struct BenchScene {
    std::string name;                        // as printed in the report
    std::function<wb::rt::SceneFile()> make; // builds the scene afresh
};

// One and two spheres, SPD balls and jacks 2-5, and the OBJ mesh at `meshPath`.
inline std::vector<BenchScene> benchScenes(const std::string& meshPath) {
    using namespace wb::rt;
    return {
        {"one sphere", [] { return toScene(oneSphereScene()); }},
        {"two spheres", [] { return toScene(twoSpheresScene()); }},
        {"balls 2", [] { return toScene(spdBalls(2)); }},
        {"balls 3", [] { return toScene(spdBalls(3)); }},
        {"balls 4", [] { return toScene(spdBalls(4)); }},
        {"balls 5", [] { return toScene(spdBalls(5)); }},
        {"jacks 2", [] { return toScene(spdJacks(2)); }},
        {"jacks 3", [] { return toScene(spdJacks(3)); }},
        {"jacks 4", [] { return toScene(spdJacks(4)); }},
        {"jacks 5", [] { return toScene(spdJacks(5)); }},
        {"mesh 9k (OBJ)", [meshPath] { return loadObjFile(meshPath); }},
    };
}
