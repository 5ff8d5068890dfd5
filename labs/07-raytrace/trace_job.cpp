#include "trace_job.h"

#include "core/raytrace/course_model.h"
#include "core/raytrace/phong_model.h"

#include <chrono>
#include <cmath>

namespace wb {

namespace {
double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

void TraceJob::start(const TraceRequest& req) {
    cancel();
    request_ = req;
    cancel_ = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        image_ = Image(req.camera.width, req.camera.height, 4); // alpha 0: not traced yet
        const int ts = req.tileSize > 0 ? req.tileSize : 16;
        const uint64_t frame = status_.frame + 1;
        status_ = TraceStatus{};
        status_.frame = frame;
        status_.tilesTotal =
            ((req.camera.width + ts - 1) / ts) * ((req.camera.height + ts - 1) / ts);
        status_.running = true;
        ++version_;
        startTime_ = now();
    }
    worker_ = std::thread([this] { run(); });
}

void TraceJob::cancel() {
    cancel_ = true;
    if (worker_.joinable()) worker_.join();
}

void TraceJob::wait() {
    if (worker_.joinable()) worker_.join();
}

TraceStatus TraceJob::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    TraceStatus s = status_;
    if (s.running) s.seconds = now() - startTime_;
    if (s.running && s.tilesDone > 0)
        s.secondsLeft = s.seconds * double(s.tilesTotal - s.tilesDone) / double(s.tilesDone);
    return s;
}

bool TraceJob::fetch(Image& rgba, uint64_t& version) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (version == version_) return false;
    rgba = image_;
    version = version_;
    return true;
}

void TraceJob::run() {
    const TraceRequest& req = request_;
    const rt::Scene& scene = *req.scene->scene;
    rt::CourseModel course;
    rt::PhongModel phong;
    const rt::ShadingModel& model =
        req.model == ModelKind::Course ? static_cast<const rt::ShadingModel&>(course) : phong;
    const PixelCamera camera(req.camera);
    const int w = req.camera.width, h = req.camera.height;
    const int ts = req.tileSize > 0 ? req.tileSize : 16;

    // One worker, tile after tile (the parallel renderer of issue 6 replaces this loop).
    const rt::Tracer tracer(scene, model, req.settings);
    long long bad = 0;
    std::vector<uint8_t> tile(size_t(ts) * ts * 3);
    bool stopped = false;
    for (int y0 = 0; y0 < h && !stopped; y0 += ts)
        for (int x0 = 0; x0 < w; x0 += ts) {
            if (cancel_) {
                stopped = true;
                break;
            }
            const int x1 = std::min(x0 + ts, w), y1 = std::min(y0 + ts, h);
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    rt::Color c = tracer.trace(camera.primaryRay(x, y, w, h));
                    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
                        ++bad;
                        c = rt::Color(0.0);
                    }
                    model.toRgb8(c, &tile[(size_t(y - y0) * ts + size_t(x - x0)) * 3]);
                }
            std::lock_guard<std::mutex> lock(mutex_);
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    uint8_t* p = image_.at(x, y);
                    const uint8_t* q = &tile[(size_t(y - y0) * ts + size_t(x - x0)) * 3];
                    p[0] = q[0];
                    p[1] = q[1];
                    p[2] = q[2];
                    p[3] = 255;
                }
            ++status_.tilesDone;
            ++version_;
        }
    std::lock_guard<std::mutex> lock(mutex_);
    status_.running = false;
    status_.seconds = now() - startTime_;
    status_.secondsLeft = 0;
    status_.finished = status_.tilesDone == status_.tilesTotal;
    status_.cancelled = !status_.finished;
    status_.primaryRays = tracer.primaryRays;
    status_.secondaryRays = tracer.secondaryRays;
    status_.shadowRays = tracer.shadowRays;
    status_.nonFinitePixels = bad;
    status_.threads = 1;
    ++version_;
}

} // namespace wb
