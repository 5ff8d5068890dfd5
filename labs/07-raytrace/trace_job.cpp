#include "trace_job.h"

#include "core/raytrace/course_model.h"
#include "core/raytrace/parallel_render.h"
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
        status_.threads = req.threads > 0 ? req.threads : rt::hardwareThreads();
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

    // Issue 6's TBB tiled renderer: every finished tile is copied into the shown image
    // under our lock (its callback is serialised and the tile's pixels are final), the
    // cancel flag is polled between tiles.
    rt::ParallelRenderOptions opt;
    opt.threads = req.threads;
    opt.tileSize = req.tileSize > 0 ? req.tileSize : 16;
    opt.trace = req.settings;
    opt.cancel = &cancel_;
    opt.progress = [this](const rt::TileProgress& t) {
        if (!t.image) return;
        std::lock_guard<std::mutex> lock(mutex_);
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) {
                const uint8_t* q = t.image->at(x, y);
                uint8_t* p = image_.at(x, y);
                p[0] = q[0];
                p[1] = q[1];
                p[2] = q[2];
                p[3] = 255;
            }
        status_.tilesDone = t.tilesDone;
        status_.tilesTotal = t.tilesTotal;
        // Live counters: the rays of the tiles finished so far (the totals land at the end).
        status_.primaryRays = t.primaryRays;
        status_.secondaryRays = t.secondaryRays;
        status_.shadowRays = t.shadowRays;
        ++version_;
    };
    rt::ParallelRenderStats st;
    rt::renderParallel(scene, camera, model, req.camera.width, req.camera.height, opt, &st);

    std::lock_guard<std::mutex> lock(mutex_);
    status_.running = false;
    status_.seconds = now() - startTime_;
    status_.secondsLeft = 0;
    status_.finished = !st.cancelled && status_.tilesDone == status_.tilesTotal;
    status_.cancelled = !status_.finished;
    status_.primaryRays = st.primaryRays;
    status_.secondaryRays = st.secondaryRays;
    status_.shadowRays = st.shadowRays;
    status_.nonFinitePixels = st.nonFinitePixels;
    status_.threads = st.threads;
    ++version_;
}

} // namespace wb
