#pragma once
// Single-threaded reference renderer: one primary ray per pixel, row 0 at the top.
#include "core/image.h"
#include "core/raytrace/camera.h"
#include "core/raytrace/tracer.h"

namespace wb::rt {

struct RenderStats {
    long long nonFinitePixels = 0; // pixels whose colour had a NaN/Inf (written as 0); must stay 0
    double seconds = 0.0;          // wall time
};

Image render(const Scene& scene, const Camera& camera, const ShadingModel& model, int width,
             int height, const TraceSettings& settings = {}, RenderStats* stats = nullptr);

} // namespace wb::rt
