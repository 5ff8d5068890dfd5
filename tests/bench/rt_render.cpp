// Renders an NFF or OBJ scene to PNG on all cores with a progress bar (redrawn in place
// on a terminal, one line at the end when stderr is piped) and prints the time and the
// ray counts (the command-line front end of issue 6 next to lab 07's --scene flag; both
// call the same core functions). The reader's warnings go to stderr, counted; non-finite
// pixels and a failed PNG write are errors (exit 1, no image under the name).
//
// Usage: rt_render SCENE.nff|SCENE.obj [--out FILE.png] [--size WxH] [--threads N]
//                  [--depth D] [--spd] [--no-bvh]
//   --size     image size (default: the file's `v` resolution, else 512x512)
//   --threads  worker threads (default and 0: all cores)
//   --depth    reflections/refractions per eye ray (default 5; with --spd 4, which is
//              the SPD's "depth 5" counting the eye ray as level 1)
//   --spd      SPD rules: eye rays through the pixel corners ((w+1)(h+1) rays), depth 4
//   --no-bvh   the plain loop over objects
#include "common/cli_values.h"
#include "core/image.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/scene_file.h"

#include "core/i18n.h"
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace {

constexpr const char* kUsage =
    "usage: %s SCENE.nff|SCENE.obj [--out FILE.png] [--size WxH] [--threads N] "
    "[--depth D] [--spd] [--no-bvh]\n";

int usage(const char* argv0) {
    std::fprintf(stderr, kUsage, argv0);
    return 2;
}

// The 40-column progress bar on stderr; `inPlace` starts with \r (a terminal redraw),
// otherwise the line is written once, whole.
void printBar(int done, int total, bool inPlace) {
    const int percent = total > 0 ? 100 * done / total : 100;
    const int bar = 40, filled = bar * percent / 100;
    std::fprintf(stderr, "%s[%.*s%*s] %3d%%%s", inPlace ? "\r" : "", filled,
                 "########################################", bar - filled, "", percent,
                 inPlace ? "" : "\n");
    std::fflush(stderr);
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage(argv[0]);
    std::string scenePath, out = "render.png";
    int width = 0, height = 0, threads = 0, depth = -1;
    bool spd = false, noBvh = false, help = false;
    // The flags through CLI11, --size and --threads through the shell's shared checks
    // (labs/common/cli_values.h): WxH strictly, threads 0 (all cores) .. 1024.
    CLI::App app{"rt_render"};
    app.set_help_flag();
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    std::string valueError;
    app.add_flag("-h,--help", help);
    app.add_option("scene", scenePath);
    app.add_option("--out", out);
    wb::cli::addSizeOption(app, "--size", 16384, width, height, valueError, "");
    wb::cli::addThreadsOption(app, "--threads", threads, valueError, "");
    app.add_option("--depth", depth)->check(CLI::Range(0, 64));
    app.add_flag("--spd", spd);
    app.add_flag("--no-bvh", noBvh);
    const auto args = wb::cli::joinValues(argc, argv, {"--out", "--size", "--threads", "--depth"});
    try {
        app.parse(
            std::vector<std::string>(args.rbegin(), args.rend())); // CLI11 takes them reversed
    } catch (const CLI::ParseError&) {
        if (!valueError.empty()) std::fprintf(stderr, "%s: %s\n", argv[0], valueError.c_str());
        return usage(argv[0]);
    }
    if (help) {
        std::printf(kUsage, argv[0]);
        return 0;
    }
    const bool useBvh = !noBvh;
    if (scenePath.empty()) return usage(argv[0]);
    // SPD's "maximum depth 5" counts the eye ray as level 1: 4 reflections.
    if (depth < 0) depth = spd ? 4 : 5;
    try {
        const auto t0 = std::chrono::steady_clock::now();
        wb::rt::SceneFile sf = wb::rt::loadSceneFile(scenePath);
        const double loadS =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        // The reader's repairs (faces dropped, a missing .mtl, ...): counted, the first lines.
        if (sf.warningCount > 0) {
            std::fprintf(stderr, wb::tr("%s: %zu warning%s:\n"), scenePath.c_str(), sf.warningCount,
                         sf.warningCount == 1 ? "" : "s");
            for (const std::string& w : sf.warnings)
                std::fprintf(stderr, "  %s\n", w.c_str());
            if (sf.warningCount > sf.warnings.size())
                std::fprintf(stderr, wb::tr("  ... and %zu more\n"),
                             sf.warningCount - sf.warnings.size());
        }
        std::unique_ptr<wb::rt::Bvh> bvh;
        if (useBvh) bvh = wb::rt::makeAggregate(*sf.scene);
        sf.scene->setAggregate(bvh.get());
        if (width == 0) {
            width = sf.view.width;
            height = sf.view.height;
        }
        const wb::rt::LookAtCamera cam = sf.camera();
        wb::rt::PhongModel model;
        wb::rt::ParallelRenderOptions opt;
        opt.threads = threads;
        opt.cornerRays = spd;
        opt.trace.maxDepth = depth;
        // The bar is redrawn in place only on a terminal; piped into a log, the \r updates
        // would pile up on one line, so it is written once at the end instead.
        const bool terminal = ::isatty(STDERR_FILENO) != 0;
        int lastPercent = -1; // redraw the bar only when the percentage changes
        opt.progress = [&lastPercent, terminal](const wb::rt::TileProgress& p) {
            if (!terminal) return;
            const int percent = 100 * p.tilesDone / p.tilesTotal;
            if (percent == lastPercent) return;
            lastPercent = percent;
            printBar(p.tilesDone, p.tilesTotal, true);
        };
        wb::rt::ParallelRenderStats st;
        const wb::Image img =
            wb::rt::renderParallel(*sf.scene, cam, model, width, height, opt, &st);
        if (terminal)
            std::fprintf(stderr, "\n");
        else
            printBar(1, 1, false);
        if (st.nonFinitePixels) {
            // A NaN/Inf colour is written black: the picture would be wrong, not fine.
            std::fprintf(
                stderr,
                wb::tr("%s: %s: %lld non-finite pixels (NaN/Inf in the colour): not writing "
                       "the image\n"),
                argv[0], scenePath.c_str(), st.nonFinitePixels);
            return 1;
        }
        std::string err;
        if (!wb::writePng(out, img, &err)) {
            std::fprintf(stderr, "%s: %s\n", argv[0], err.c_str());
            return 1;
        }
        const long long rays = st.primaryRays + st.secondaryRays + st.shadowRays;
        std::printf(wb::tr("%s: %zu primitives, load %.1f ms (BVH build %.1f ms%s)\n"),
                    scenePath.c_str(), sf.scene->primitives.size(), loadS * 1e3,
                    bvh ? bvh->stats().buildSeconds * 1e3 : 0.0, bvh ? "" : ", plain loop");
        std::printf(wb::tr("%dx%d, depth %d, %d threads: %.1f ms; eye %lld, shadow %lld, "
                           "reflection+refraction %lld rays; %.2f M rays/s -> %s\n"),
                    width, height, depth, st.threads, st.seconds * 1e3, st.primaryRays,
                    st.shadowRays, st.secondaryRays, double(rays) / st.seconds / 1e6, out.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
