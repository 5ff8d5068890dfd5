#include "environment.h"

#include "core/sphere_map.h"

#include <algorithm>
#include <cmath>

namespace wb {
namespace {
constexpr double kPi = 3.14159265358979323846;

void put(Image& img, int x, int y, const glm::dvec3& c) {
    uint8_t* p = img.at(x, y);
    for (int k = 0; k < 3; ++k)
        p[k] = uint8_t(std::lround(255.0 * std::clamp(c[k], 0.0, 1.0)));
}
} // namespace

glm::dvec3 environmentColour(const glm::dvec3& dir) {
    const double len = glm::length(dir);
    if (!(len > 0.0)) return {0, 0, 0};
    const glm::dvec3 d = dir / len;
    const double azimuth = std::atan2(d.x, d.z) * 180.0 / kPi; // 0 at +z, 90 at +x
    const double elevation = std::asin(std::clamp(d.y, -1.0, 1.0)) * 180.0 / kPi;
    struct Pillar {
        double azimuth;
        glm::dvec3 colour;
    };
    const Pillar pillars[] = {{90, {0.9, 0.15, 0.1}},
                              {-90, {0.1, 0.75, 0.2}},
                              {180, {0.15, 0.25, 0.95}},
                              {0, {0.95, 0.85, 0.1}}};
    for (const Pillar& p : pillars) {
        double da = std::abs(azimuth - p.azimuth);
        da = std::min(da, 360.0 - da);
        if (da < 8.0 && elevation > -15.0 && elevation < 25.0) return p.colour;
    }
    if (d.y < 0.0) {
        // Floor plane y = -2 with 1-unit checkers, fading to their average far away (no aliasing).
        const glm::dvec3 hit = d * (2.0 / -d.y);
        const bool on = (int(std::floor(hit.x)) + int(std::floor(hit.z))) % 2 == 0;
        const glm::dvec3 c = on ? glm::dvec3(0.85, 0.8, 0.7) : glm::dvec3(0.35, 0.25, 0.2);
        const double fade = std::min(1.0, std::hypot(hit.x, hit.z) / 25.0);
        return c * (1.0 - fade) + glm::dvec3(0.6, 0.525, 0.45) * fade;
    }
    return glm::dvec3(0.85, 0.9, 1.0) * (1.0 - d.y) + glm::dvec3(0.2, 0.4, 0.85) * d.y;
}

Image makeSphereMapImage(const glm::dmat3& worldToEye, int size) {
    Image img(size, size, 3);
    const glm::dmat3 eyeToWorld = glm::transpose(worldToEye);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double s = (x + 0.5) / size, t = 1.0 - (y + 0.5) / size;
            // Texels outside the disc are only reached by filtering at the rim: give them
            // the rim's colour (radius pulled in to 0.999) so nothing dark bleeds in.
            const double r = std::hypot(2.0 * s - 1.0, 2.0 * t - 1.0);
            if (r > 0.999) {
                s = 0.5 + (s - 0.5) * 0.999 / r;
                t = 0.5 + (t - 0.5) * 0.999 / r;
            }
            glm::dvec3 f(0, 0, 1);
            sphereMapDirection(s, t, f);
            put(img, x, y, environmentColour(eyeToWorld * f));
        }
    return img;
}

Image makeLatLongImage(int width, int height) {
    Image img(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double s = (x + 0.5) / width, t = 1.0 - (y + 0.5) / height;
            const double lat = kPi * (t - 0.5), phi = 2.0 * kPi * s;
            put(img, x, y,
                environmentColour(
                    {std::cos(lat) * std::sin(phi), std::sin(lat), std::cos(lat) * std::cos(phi)}));
        }
    return img;
}

} // namespace wb
