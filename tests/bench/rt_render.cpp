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
#include "core/file_read.h"
#include "core/i18n.h"
#include "core/image.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/scene_file.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

namespace {

constexpr int kMaxDepth = 64; // reflections per eye ray: 2^64 rays is beyond any budget anyway

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

// Empty when a width x height frame fits; otherwise the message with the figures.
std::string memoryRefusal(int width, int height, const wb::rt::ParallelRenderOptions& opt) {
    const double frame = double(wb::rt::renderMemoryBytes(width, height, opt)) +
                         2.0 * 3.0 * double(width) * double(height); // PNG encoder at worst
    // 4 GB: a plain 16384² frame (2.4 GB with the encoder) fits, the SPD corner grid at
    // that size (8.8 GB) does not; less on a machine with under 8 GB.
    double limit =
        std::min(4e9, 0.5 * double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGESIZE)));
    struct rlimit rl {};
    if (::getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        limit = std::min(limit, 0.9 * double(rl.rlim_cur));
    if (frame <= limit) return {};
    const double image = 3.0 * width * double(height), png = 2.0 * image;
    if (opt.cornerRays)
        return wb::trf("a %dx%d render with --spd needs about %.1f GB (image %.1f GB, SPD corner "
                       "colours %.1f GB, PNG encoding %.1f GB); the limit here is %.1f GB (at "
                       "most 4 GB, half the machine's memory): use a smaller --size",
                       width, height, frame / 1e9, image / 1e9,
                       double(width + 1) * double(height + 1) * 24.0 / 1e9, png / 1e9, limit / 1e9);
    return wb::trf("a %dx%d render needs about %.1f GB (image %.1f GB, PNG encoding %.1f GB); "
                   "the limit here is %.1f GB (at most 4 GB, half the machine's memory): use a "
                   "smaller --size",
                   width, height, frame / 1e9, image / 1e9, png / 1e9, limit / 1e9);
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
    app.allow_extras(); // unknown flags, a second scene, `--`: reported below, in our words
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    std::string valueError;
    app.add_flag("-h,--help", help);
    app.add_option("scene", scenePath);
    app.add_option("--out", out);
    wb::cli::addSizeOption(app, "--size", 16384, width, height, valueError, "");
    wb::cli::addThreadsOption(app, "--threads", threads, valueError, "");
    // Every refused value names the flag, the value and the range (issue 20 point 15):
    // `--depth 65` printed only the usage line.
    app.add_option_function<std::string>("--depth", [&](const std::string& v) {
        if (wb::cli::parseInt(v, 0, kMaxDepth, depth)) return;
        valueError = wb::trf("--depth '%s': expected an integer from 0 to %d",
                             wb::escapeForMessage(v).c_str(), kMaxDepth);
        throw CLI::ValidationError("--depth", valueError);
    });
    app.add_flag("--spd", spd);
    app.add_flag("--no-bvh", noBvh);
    const auto args =
        wb::cli::joinValues(argc, argv, {"--out", "--size", "--threads", "--depth"}, valueError);
    auto refuse = [&](const std::string& why) {
        std::fprintf(stderr, "%s: %s\n", argv[0], why.c_str());
        return usage(argv[0]);
    };
    if (!valueError.empty()) return refuse(valueError);
    try {
        app.parse(
            std::vector<std::string>(args.rbegin(), args.rend())); // CLI11 takes them reversed
    } catch (const CLI::ParseError& e) {
        if (!valueError.empty()) return refuse(valueError);
        // The only other failure left: a value flag last on the line, e.g. `--depth`.
        std::string what = e.what();
        const auto colon = what.find(':');
        return refuse(wb::trf("%s needs a value",
                              (colon != std::string::npos ? what.substr(0, colon) : what).c_str()));
    }
    if (!app.remaining().empty()) {
        const std::string arg = app.remaining().front(); // remaining() returns a copy
        if (arg == "--")
            return refuse(wb::tr("'--' is not an option here (one scene file, then flags)"));
        if (arg.rfind('-', 0) == 0)
            return refuse(wb::trf("unknown option '%s'", wb::escapeForMessage(arg).c_str()));
        return refuse(wb::trf("one scene file only: '%s' after '%s'",
                              wb::escapeForMessage(arg, 200).c_str(),
                              wb::escapeForMessage(scenePath, 200).c_str()));
    }
    if (help) {
        std::printf(kUsage, argv[0]);
        return 0;
    }
    const bool useBvh = !noBvh;
    if (scenePath.empty()) return usage(argv[0]);
    // SPD's "maximum depth 5" counts the eye ray as level 1: 4 reflections.
    if (depth < 0) depth = spd ? 4 : 5;
    // 16384x16384 --spd ended in a bare std::bad_alloc (issue 20 point 6): the frame's
    // memory (image, SPD corner colours, and the PNG encoder's two image-sized buffers,
    // its filtered rows and its output at worst) is estimated from the size alone and
    // compared with half the machine's memory (and the address-space limit, if any)
    // before anything is loaded or allocated.
    if (width > 0) {
        wb::rt::ParallelRenderOptions probe;
        probe.cornerRays = spd;
        if (const std::string why = memoryRefusal(width, height, probe); !why.empty())
            return refuse(why);
    }
    // Paths are printed escaped: a name may hold escape sequences or a newline (point 16).
    const std::string shownPath = wb::escapeForMessage(scenePath, 4096);
    try {
        const auto t0 = std::chrono::steady_clock::now();
        wb::rt::SceneFile sf = wb::rt::loadSceneFile(scenePath);
        const double loadS =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        // The reader's repairs (faces dropped, a missing .mtl, ...): counted, the first lines.
        if (sf.warningCount > 0) {
            std::fprintf(stderr, wb::tr("%s: %zu warning%s:\n"), shownPath.c_str(), sf.warningCount,
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
        {
            wb::rt::ParallelRenderOptions probe; // the size may come from the file's `v` block
            probe.cornerRays = spd;
            if (const std::string why = memoryRefusal(width, height, probe); !why.empty()) {
                std::fprintf(stderr, "%s: %s\n", argv[0], why.c_str());
                return 1;
            }
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
            std::fprintf(stderr,
                         wb::tr("%s: %s: %lld non-finite pixels (NaN/Inf in the colour): not "
                                "writing the image\n"),
                         argv[0], shownPath.c_str(), st.nonFinitePixels);
            return 1;
        }
        std::string err;
        if (!wb::writePng(out, img, &err)) {
            std::fprintf(stderr, "%s: %s\n", argv[0], err.c_str());
            return 1;
        }
        const long long rays = st.primaryRays + st.secondaryRays + st.shadowRays;
        std::printf(wb::tr("%s: %zu primitives, load %.1f ms (BVH build %.1f ms%s)\n"),
                    shownPath.c_str(), sf.scene->primitives.size(), loadS * 1e3,
                    bvh ? bvh->stats().buildSeconds * 1e3 : 0.0, bvh ? "" : ", plain loop");
        std::printf(wb::tr("%dx%d, depth %d, %d threads: %.1f ms; eye %lld, shadow %lld, "
                           "reflection+refraction %lld rays; %.2f M rays/s -> %s\n"),
                    width, height, depth, st.threads, st.seconds * 1e3, st.primaryRays,
                    st.shadowRays, st.secondaryRays, double(rays) / st.seconds / 1e6,
                    wb::escapeForMessage(out, 4096).c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
