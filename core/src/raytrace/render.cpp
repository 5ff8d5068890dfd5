#include "core/raytrace/render.h"

#include <chrono>
#include <cmath>

namespace wb::rt {

Image render(const Scene& scene, const Camera& camera, const ShadingModel& model, int width,
             int height, const TraceSettings& settings, RenderStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    Image img(width, height, 3);
    Tracer tracer(scene, model, settings);
    long long bad = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Color c = tracer.trace(camera.primaryRay(x, y, width, height));
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
                ++bad;
                c = Color(0.0);
            }
            model.toRgb8(c, img.at(x, y));
        }
    if (stats) {
        stats->nonFinitePixels = bad;
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return img;
}

} // namespace wb::rt
