#include "core/raytrace/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wb::rt {

ScreenCamera orbitScreenCamera(const glm::dvec3& eye, const glm::dvec3& target,
                               const glm::dvec3& upHint, double yawDeg, double pitchDeg,
                               double pixelSize) {
    const double upLen = glm::length(upHint);
    if (!(upLen > 0) || !std::isfinite(upLen))
        throw std::invalid_argument("camera: up must be a finite non-zero vector");
    const glm::dvec3 up0 = glm::normalize(upHint);
    glm::dvec3 offset = eye - target;
    const double dist = glm::length(offset);
    if (!(dist > 0) || !std::isfinite(dist)) throw std::invalid_argument("camera: eye == target");
    // Exact when both angles are 0: no rotation, so seed 000's rays stay bit-exact.
    if (yawDeg != 0.0)
        offset = glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(yawDeg), up0) *
                            glm::dvec4(offset, 0.0));
    glm::dvec3 forward = -offset / dist;
    glm::dvec3 right = glm::cross(forward, up0);
    if (!(glm::length(right) > 1e-9)) throw std::invalid_argument("camera: up along the view");
    right = glm::normalize(right);
    if (pitchDeg != 0.0) {
        // Keep the angle between the view and up inside (1°, 179°).
        const double now = glm::degrees(std::acos(std::clamp(glm::dot(forward, up0), -1.0, 1.0)));
        const double pitch = std::clamp(pitchDeg, now - 179.0, now - 1.0);
        offset = glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(-pitch), right) *
                            glm::dvec4(offset, 0.0));
        forward = -offset / dist;
    }
    const glm::dvec3 up = glm::cross(right, forward);
    return ScreenCamera(target + offset, forward, dist, right, up, pixelSize);
}

LookAtCamera::LookAtCamera(const glm::dvec3& e, const glm::dvec3& target, const glm::dvec3& upHint,
                           double fovYDegrees)
    : screen_([&] {
          if (!(fovYDegrees > 0 && fovYDegrees < 180))
              throw std::invalid_argument("LookAtCamera: need 0 < fov < 180");
          try {
              return orbitScreenCamera(e, target, upHint, 0.0, 0.0, 1.0);
          } catch (const std::invalid_argument&) {
              throw std::invalid_argument("LookAtCamera: need target != eye, up not along the "
                                          "view, 0 < fov < 180");
          }
      }()) {
    eye = screen_.eye;
    right = screen_.screenX;
    up = screen_.screenY;
    forward = glm::cross(up, right);
    dist = glm::length(e - target);
    tanHalfFov = std::tan(glm::radians(fovYDegrees) / 2);
}

Ray LookAtCamera::rayAt(double px, double py, int width, int height) const {
    // Lab 07's ViewCamera::make and pixelRay in the same order of operations.
    const double pixel = 2.0 * dist * tanHalfFov / height;
    return screen_.rayThroughScreen(px - width / 2.0, height / 2.0 - py, pixel);
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
    return rayThroughScreen(xs, ys, pixelSize);
}

Ray ScreenCamera::rayThroughScreen(double xs, double ys, double pixel) const {
    const glm::dvec3 p = screenCentre + pixel * (xs * screenX + ys * screenY);
    Ray r;
    r.origin = eye;
    r.direction = glm::normalize(p - eye);
    if (hither > 0) { // start on the hither plane (issue 20 point 14); 0 keeps every bit
        const glm::dvec3 f = glm::normalize(screenCentre - eye);
        r.origin = eye + (hither / glm::dot(r.direction, f)) * r.direction;
    }
    return r;
}

Ray ScreenCamera::primaryRay(int x, int y, int width, int height) const {
    // Seed 000's Tracing(): xs = xx − homeX, ys = homeY − yy.
    return rayThroughScreen(x - width / 2.0, height / 2.0 - y);
}

} // namespace wb::rt
