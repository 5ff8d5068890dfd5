#pragma once
// Multi-threaded tiled rendering (TBB). Each pixel's colour depends only on its own
// rays, so the image is bit-identical for any thread count and tile order. Progress is
// reported per finished tile (serialised: the callback never runs twice at once, and
// the tile's pixels are already in the image when it runs), and a cancel flag is
// polled between tiles.
#include "core/image.h"
#include "core/raytrace/camera.h"
#include "core/raytrace/tracer.h"

#include <atomic>
#include <functional>

namespace wb::rt {

struct TileProgress {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0; // the finished tile: pixels [x0,x1) × [y0,y1)
    int tilesDone = 0;                  // tiles finished so far, including this one
    int tilesTotal = 0;                 // tiles of the frame
    const Image* image = nullptr;       // the image being written (read the tile only)
    // Rays of the tiles finished so far, this one included (live counters for a viewer).
    long long primaryRays = 0, secondaryRays = 0, shadowRays = 0;
};

struct ParallelRenderOptions {
    int threads = 0;   // worker threads; 0 = all cores
    int tileSize = 32; // square tiles of this many pixels (>= 1)
    // SPD benchmark rule: (w+1)·(h+1) eye rays through the pixel corners, each pixel
    // the mean of its four corners (needs a LookAtCamera). Otherwise one ray through
    // each pixel centre (camera.primaryRay).
    bool cornerRays = false;
    TraceSettings trace; // depth limit, weight cut-off
    // Eye rays in packets of 4×2 neighbouring pixels (two rows of 4), one walk per packet
    // (Aggregate::intersectPacket; issue 21); the same picture as one by one (false).
    bool packets = true;
    // Called after each finished tile, from a worker thread, serialised by a mutex.
    // With cornerRays the tiles are tiles of the corner grid and the image is complete
    // only at the end: a tile averages the pixels whose corners are all its own, the
    // rest follow the last tile (tile callbacks then carry image == nullptr).
    std::function<void(const TileProgress&)> progress;
    const std::atomic<bool>* cancel = nullptr; // set to true to stop: tiles not started are skipped
};

struct ParallelRenderStats {
    double seconds = 0.0;          // wall time of the frame
    long long primaryRays = 0;     // eye rays
    long long secondaryRays = 0;   // reflected + refracted rays
    long long shadowRays = 0;      // shadow feelers
    long long nonFinitePixels = 0; // colours with NaN/Inf written as 0; must stay 0
    int threads = 0;               // threads actually allowed
    bool cancelled = false;        // the frame stopped early; unfinished tiles are black
};

// The memory renderParallel allocates for a frame: the 8-bit RGB image and, with
// cornerRays, the (w+1)·(h+1) corner colours (24 bytes each: 16384² with --spd needs
// 6.4 GB for them alone). Front ends compare it with what the machine has before
// rendering (issue 20 point 6) instead of ending in a bare std::bad_alloc.
std::size_t renderMemoryBytes(int width, int height, const ParallelRenderOptions& options);

Image renderParallel(const Scene& scene, const Camera& camera, const ShadingModel& model, int width,
                     int height, const ParallelRenderOptions& options = {},
                     ParallelRenderStats* stats = nullptr);

// Number of hardware threads TBB would use.
int hardwareThreads();

} // namespace wb::rt
