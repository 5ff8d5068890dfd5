#include "core/raytrace/parallel_render.h"

#include <tbb/info.h>
#ifdef WB_TSAN_THREADS
#include <thread>
#else
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace wb::rt {

int hardwareThreads() {
    return tbb::info::default_concurrency();
}

namespace {

bool finite(const Color& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

// Runs body(i) for i in [0, count) on `threads` workers, each index once, and returns
// when all are done. With TBB (parallel_for, one index per task, simple partitioner)
// normally; in the ThreadSanitizer build (-DWORKBENCH_TSAN=ON, WB_TSAN_THREADS) on
// std::threads pulling indices from an atomic counter, because Debian's TBB is not
// instrumented and TSan cannot see its hand-offs (every report landed in TBB's headers).
// The tiles and what each does are the same code either way.
template <class Body> void forEachIndex(int threads, int count, const Body& body) {
#ifdef WB_TSAN_THREADS
    std::atomic<int> next{0};
    std::vector<std::thread> workers;
    for (int t = 0; t < std::min(threads, count); ++t)
        workers.emplace_back([&] {
            for (int i = next++; i < count; i = next++)
                body(i);
        });
    for (std::thread& w : workers)
        w.join();
#else
    // More threads than cores (tests ask for 3 on 2 cores) must be allowed explicitly.
    tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                              std::size_t(std::max(threads, hardwareThreads())));
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, count, 1),
            [&](const tbb::blocked_range<int>& r) {
                for (int i = r.begin(); i != r.end(); ++i)
                    body(i);
            },
            tbb::simple_partitioner());
    });
#endif
}

} // namespace

std::size_t renderMemoryBytes(int width, int height, const ParallelRenderOptions& opt) {
    const std::size_t w = std::size_t(std::max(width, 0)), h = std::size_t(std::max(height, 0));
    std::size_t bytes = w * h * 3; // Image(width, height, 3)
    if (opt.cornerRays) bytes += (w + 1) * (h + 1) * sizeof(Color);
    return bytes;
}

Image renderParallel(const Scene& scene, const Camera& camera, const ShadingModel& model, int width,
                     int height, const ParallelRenderOptions& opt, ParallelRenderStats* stats) {
    if (width < 1 || height < 1 || width > 65536 || height > 65536)
        throw std::invalid_argument("renderParallel: image size must be 1..65536");
    if (opt.tileSize < 1) throw std::invalid_argument("renderParallel: tileSize must be >= 1");
    const LookAtCamera* lookAt = dynamic_cast<const LookAtCamera*>(&camera);
    if (opt.cornerRays && !lookAt)
        throw std::invalid_argument("renderParallel: cornerRays needs a LookAtCamera");
    const auto start = std::chrono::steady_clock::now();
    const int threads = opt.threads > 0 ? opt.threads : hardwareThreads();

    Image img(width, height, 3);
    // The grid the tiles cover: pixels, or the (w+1)×(h+1) pixel corners.
    const int gw = opt.cornerRays ? width + 1 : width;
    const int gh = opt.cornerRays ? height + 1 : height;
    // Left uninitialised (6 MB at 512²: zeroing it was serial work in every frame); every
    // corner is written by its tile before it is read, and a cancelled frame reads none
    // but its finished tiles' own.
    static_assert(std::is_trivially_default_constructible_v<Color>);
    const std::unique_ptr<Color[]> corners(
        opt.cornerRays ? new Color[std::size_t(gw) * std::size_t(gh)] : nullptr);
    const int ts = opt.tileSize;
    const int tilesX = (gw + ts - 1) / ts, tilesY = (gh + ts - 1) / ts;
    const int tilesTotal = tilesX * tilesY;

    std::atomic<long long> primary{0}, secondary{0}, shadow{0}, bad{0};
    std::atomic<bool> cancelled{false};
    std::mutex progressMutex;
    int tilesDone = 0; // guarded by progressMutex

    // Corner rays: pixel (x, y) is the mean of its four corners, in the model's units;
    // returns 1 for a non-finite colour (written as 0).
    const auto averagePixel = [&](int x, int y) {
        const auto at = [&](int cx, int cy) {
            return corners[std::size_t(cy) * std::size_t(gw) + std::size_t(cx)];
        };
        Color c = 0.25 * (at(x, y) + at(x + 1, y) + at(x, y + 1) + at(x + 1, y + 1));
        const bool ok = finite(c);
        if (!ok) c = Color(0.0);
        model.toRgb8(c, img.at(x, y));
        return ok ? 0 : 1;
    };

    auto renderTile = [&](int tile) {
        if (opt.cancel && opt.cancel->load(std::memory_order_relaxed)) {
            cancelled = true;
            return;
        }
        const int x0 = (tile % tilesX) * ts, y0 = (tile / tilesX) * ts;
        const int x1 = std::min(gw, x0 + ts), y1 = std::min(gh, y0 + ts);
        // The tile's rays are counted in plain integers and added to the totals once.
        const Tracer tracer(scene, model, opt.trace);
        RayCounts counts;
        long long nBad = 0;
        const Aggregate& agg = scene.aggregate();
        std::vector<const Primitive*> lastBlockers(
            opt.packets ? std::size_t(std::max(opt.trace.maxDepth, 0) + 1) * scene.lights.size()
                        : 0);
        auto rayOf = [&](int x, int y) {
            return opt.cornerRays ? lookAt->rayAt(x, y, width, height)
                                  : camera.primaryRay(x, y, width, height);
        };
        auto store = [&](int x, int y, Color c) {
            if (opt.cornerRays) {
                corners[std::size_t(y) * std::size_t(gw) + std::size_t(x)] = c;
                return;
            }
            if (!finite(c)) {
                ++nBad;
                c = Color(0.0);
            }
            model.toRgb8(c, img.at(x, y));
        };
        for (int y = y0; y < y1; ++y) {
            if (!opt.packets) {
                for (int x = x0; x < x1; ++x) {
                    const Ray r = rayOf(x, y);
                    store(x, y, tracer.trace(r, counts));
                }
                continue;
            }
            // Eye rays of up to kMaxPacket neighbouring pixels share one walk; each is then
            // shaded from its hit as trace() would (the same colour), their feelers to each
            // light through one shadow cache along the two rows (the last
            // opaque blocker: Tracer::traceFrom), their direct light in lanes
            // (Tracer::traceFromPacket).
            std::fill(lastBlockers.begin(), lastBlockers.end(), nullptr);
            // A packet is two rows of kMaxPacket / 2 rays (one row on a tile's odd last row):
            // the 4×2 pixels' rays and their hits' feelers are closer together than a row
            // of 8, so the packet walks visit fewer nodes (balls 4's eye level, 512², avx8:
            // 693.1 -> 679.5 M instructions, the feeler walk 177.5 -> 164.5 M).
            const int rows = y + 1 < y1 ? 2 : 1;
            const int wide = kMaxPacket / rows;
            for (int x = x0; x < x1; x += wide) {
                const int w = std::min(wide, x1 - x);
                const int n = w * rows;
                Ray rays[kMaxPacket];
                Hit hits[kMaxPacket];
                double tMin[kMaxPacket], tMax[kMaxPacket];
                for (int r = 0; r < rows; ++r) {
                    if (opt.cornerRays) lookAt->rowRays(x, y + r, w, width, height, rays + r * w);
                    for (int j = 0; j < w; ++j) {
                        if (!opt.cornerRays)
                            rays[r * w + j] = camera.primaryRay(x + j, y + r, width, height);
                        tMin[r * w + j] = 0.0;
                        tMax[r * w + j] = std::numeric_limits<double>::infinity();
                    }
                }
                const unsigned found = agg.intersectPacket(rays, tMin, tMax, hits, (1u << n) - 1);
                for (int j = 0; j < n; ++j)
                    if (!((found >> j) & 1)) hits[j].primitive = nullptr;
                Color colours[kMaxPacket];
                tracer.traceFromPacket(rays, hits, n, counts, lastBlockers.data(), colours);
                for (int j = 0; j < n; ++j)
                    store(x + j % w, y + j / w, colours[j]);
            }
            y += rows - 1;
        }
        // The pixels whose four corners are all this tile's, at once (in parallel, and
        // while they are in the cache); those on the tile's last corner row or column
        // wait for the neighbour's corners (the pass after the tiles).
        if (opt.cornerRays)
            for (int y = y0; y + 1 < y1; ++y)
                for (int x = x0; x + 1 < x1; ++x)
                    nBad += averagePixel(x, y);
        primary += counts.primary;
        secondary += counts.secondary;
        shadow += counts.shadow;
        bad += nBad;
        if (opt.progress) {
            std::lock_guard<std::mutex> lock(progressMutex);
            TileProgress p;
            p.x0 = x0;
            p.y0 = y0;
            p.x1 = std::min(x1, width);
            p.y1 = std::min(y1, height);
            p.tilesDone = ++tilesDone;
            p.tilesTotal = tilesTotal;
            p.image = opt.cornerRays ? nullptr : &img;
            p.primaryRays = primary.load();
            p.secondaryRays = secondary.load();
            p.shadowRays = shadow.load();
            opt.progress(p);
        }
    };

    forEachIndex(threads, tilesTotal, renderTile);

    if (opt.cornerRays && !cancelled) {
        // The pixels the tiles left: those on a tile's last corner row or column, 6% of
        // them with 32-pixel tiles, so one thread (a second parallel pass cost more in
        // waking the workers than it saved).
        long long nBad = 0;
        for (int y = 0; y < height; ++y) {
            if (y % ts == ts - 1) {
                for (int x = 0; x < width; ++x)
                    nBad += averagePixel(x, y);
            } else {
                for (int x = ts - 1; x < width; x += ts)
                    nBad += averagePixel(x, y);
            }
        }
        bad += nBad;
    }
    if (stats) {
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->primaryRays = primary;
        stats->secondaryRays = secondary;
        stats->shadowRays = shadow;
        stats->nonFinitePixels = bad;
        stats->threads = threads;
        stats->cancelled = cancelled;
    }
    return img;
}

} // namespace wb::rt
