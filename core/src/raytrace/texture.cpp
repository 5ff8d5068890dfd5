#include "core/raytrace/texture.h"

#include <algorithm>
#include <cmath>

namespace wb::rt {

glm::dvec3 sampleTexture(const Image& image, const glm::dvec2& uv) {
    if (image.empty() || image.width <= 0 || image.height <= 0) return glm::dvec3(1.0);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::dvec3(1.0);
    const double u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
    const int x = std::min(image.width - 1, int(u * image.width));
    const int y = std::min(image.height - 1, int((1.0 - v) * image.height));
    const uint8_t* p = image.at(std::max(0, x), std::max(0, y));
    return glm::dvec3(p[0], p[1], p[2]) / 255.0;
}

} // namespace wb::rt
