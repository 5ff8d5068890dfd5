#pragma once
// The background trace of lab 07: one frame of the scene traced off the GL thread by
// issue 6's parallel renderer (all cores), tile by tile, so the window keeps drawing while tiles
// appear (progress, time left), and stoppable at any tile boundary (camera change, `x`, Esc).
// Finished tiles land in an RGBA image whose alpha says which pixels are traced; a frame is never a
// mix of two cameras: start() stops and joins the previous frame before the image is reset.
#include "lab_scenes.h"
#include "view_camera.h"

#include "core/image.h"
#include "core/raytrace/tracer.h"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>

namespace wb {

struct TraceRequest {
    const LabScene* scene = nullptr; // must outlive the trace (the lab cancels before replacing it)
    ViewCamera camera;               // image size = camera.width × camera.height
    ModelKind model = ModelKind::Phong;
    rt::TraceSettings settings; // depth limit, weight cut-off
    int threads = 0;            // 0 = all cores
    int tileSize = 16;          // square tiles, pixels
};

struct TraceStatus {
    int tilesDone = 0, tilesTotal = 0;
    double seconds = 0.0;     // since the start (the whole trace once finished)
    double secondsLeft = 0.0; // estimate from the tiles done so far
    bool running = false;
    bool finished = false;                                        // every tile traced
    bool cancelled = false;                                       // stopped before the end
    long long primaryRays = 0, secondaryRays = 0, shadowRays = 0; // so far while running
    long long nonFinitePixels = 0;                                // must stay 0
    int threads = 1;                                              // threads that traced
    uint64_t frame = 0;                                           // counts start() calls
};

class TraceJob {
  public:
    TraceJob() = default;
    TraceJob(const TraceJob&) = delete;
    TraceJob& operator=(const TraceJob&) = delete;
    ~TraceJob() { cancel(); }

    // Stops a running frame, then traces `req` in the background.
    void start(const TraceRequest& req);
    // Stops at the next tile boundary and joins; finished tiles stay in the image.
    void cancel();
    // Blocks until the frame is finished or cancelled.
    void wait();
    TraceStatus status() const;
    // Copies the image when it changed since `version` (updated); RGBA, alpha 255 = traced.
    bool fetch(Image& rgba, uint64_t& version) const;
    const ViewCamera& camera() const { return request_.camera; }
    const TraceRequest& request() const { return request_; }

  private:
    void run();

    TraceRequest request_;
    std::thread worker_;
    std::atomic<bool> cancel_{false};
    mutable std::mutex mutex_; // guards everything below
    Image image_;
    uint64_t version_ = 0;
    TraceStatus status_;
    double startTime_ = 0.0;
};

} // namespace wb
