// Profiling driver (not built by CMake; build_driver.sh builds it against build/core/libcore.a):
// one frame of a bench scene, packets or single rays, for callgrind and stage_split.py.
// frame_driver "balls 4" p|s [size] [repeats] [depth] -> prints the image's FNV hash and the time
// (depth 4 by default; depth 0 is the eye level alone: eye rays, their feelers and shading).
// The 9k OBJ is the one raytrace_scale_bench writes (build-bench/bench-out/mesh.obj); another
// path can be given in WB_BENCH_OBJ.
#include "../../../tests/bench/bench_scenes.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
using namespace wb::rt;
int main(int argc, char** argv) {
    const std::string name = argv[1];
    const bool packets = argv[2][0] == 'p';
    const int size = argc > 3 ? std::atoi(argv[3]) : 512;
    const int reps = argc > 4 ? std::atoi(argv[4]) : 1;
    const int depth = argc > 5 ? std::atoi(argv[5]) : 4;
    const char* obj = std::getenv("WB_BENCH_OBJ");
    for (const auto& bs : benchScenes(obj ? obj : "build-bench/bench-out/mesh.obj")) {
        if (bs.name != name) continue;
        SceneFile sf = bs.make();
        auto bvh = makeAggregate(*sf.scene);
        sf.scene->setAggregate(bvh.get());
        const LookAtCamera cam = sf.camera();
        PhongModel model;
        ParallelRenderOptions opt;
        opt.cornerRays = true;
        opt.trace.maxDepth = depth;
        opt.threads = 1;
        opt.packets = packets;
        for (int r = 0; r < reps; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            wb::Image img = renderParallel(*sf.scene, cam, model, size, size, opt);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            unsigned long long h = 1469598103934665603ull;
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    for (int c = 0; c < 3; ++c) { h ^= img.at(x, y)[c]; h *= 1099511628211ull; }
            std::printf("%s %s %016llx %.1f ms\n", name.c_str(), packets ? "packets" : "single", h, s * 1e3);
        }
    }
}
