#include "core/raytrace/camera.h"

#include <cmath>
#include <stdexcept>

namespace wb::rt {

LookAtCamera::LookAtCamera(const glm::dvec3& e, const glm::dvec3& target, const glm::dvec3& upHint,
                           double fovYDegrees)
    : eye(e) {
    const glm::dvec3 f = target - eye;
    const glm::dvec3 r = glm::cross(f, upHint);
    if (!(glm::length(f) > 0) || !(glm::length(r) > 1e-12 * glm::length(f) * glm::length(upHint)) ||
        !(fovYDegrees > 0 && fovYDegrees < 180))
        throw std::invalid_argument("LookAtCamera: need target != eye, up not along the view, "
                                    "0 < fov < 180");
    forward = glm::normalize(f);
    right = glm::normalize(r);
    up = glm::cross(right, forward);
    tanHalfFov = std::tan(glm::radians(fovYDegrees) / 2);
}

Ray LookAtCamera::rayAt(double px, double py, int width, int height) const {
    const double aspect = double(width) / double(height);
    const double sx = (2 * px / width - 1) * tanHalfFov * aspect;
    const double sy = (1 - 2 * py / height) * tanHalfFov;
    Ray r;
    r.origin = eye;
    r.direction = glm::normalize(forward + sx * right + sy * up);
    return r;
}

Ray LookAtCamera::primaryRay(int x, int y, int width, int height) const {
    return rayAt(x + 0.5, y + 0.5, width, height);
}

ScreenCamera::ScreenCamera(const glm::dvec3& e, const glm::dvec3& viewDir, double dist,
                           const glm::dvec3& sx, const glm::dvec3& sy, double px)
    : eye(e), screenX(sx), screenY(sy), pixelSize(px) {
    const double len = glm::length(viewDir);
    if (!(len > 0) || !(dist > 0) || !(px > 0))
        throw std::invalid_argument(
            "ScreenCamera: need a view direction, dist > 0, pixel size > 0");
    screenCentre = eye + dist * (viewDir / len);
}

ScreenCamera ScreenCamera::seed000(double height, double dist) {
    return ScreenCamera({0, 0, height}, {0, 0, -1}, dist, {1, 0, 0}, {0, 1, 0});
}

Ray ScreenCamera::rayThroughScreen(double xs, double ys) const {
    const glm::dvec3 p = screenCentre + pixelSize * (xs * screenX + ys * screenY);
    Ray r;
    r.origin = eye;
    r.direction = glm::normalize(p - eye);
    return r;
}

Ray ScreenCamera::primaryRay(int x, int y, int width, int height) const {
    // Seed 000's Tracing(): xs = xx − homeX, ys = homeY − yy.
    return rayThroughScreen(x - width / 2.0, height / 2.0 - y);
}

} // namespace wb::rt
