#include "view_camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wb {

ViewCamera ViewCamera::make(const CameraSpec& spec, double yawDeg, double pitchDeg, double zoom,
                            int width, int height) {
    if (!(width > 0 && height > 0)) throw std::invalid_argument("ViewCamera: empty image");
    if (!(zoom > 0) || !std::isfinite(zoom)) zoom = 1.0;
    const glm::dvec3 up0 = glm::normalize(spec.up);
    glm::dvec3 offset = spec.eye - spec.target;
    const double dist = glm::length(offset);
    if (!(dist > 0)) throw std::invalid_argument("ViewCamera: eye == target");
    // Exact when both angles are 0 (cos 0 = 1, sin 0 = 0): seed 000's rays stay bit-exact.
    if (yawDeg != 0.0)
        offset = glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(yawDeg), up0) *
                            glm::dvec4(offset, 0.0));
    glm::dvec3 forward = -offset / dist;
    glm::dvec3 right = glm::cross(forward, up0);
    if (!(glm::length(right) > 1e-9)) throw std::invalid_argument("ViewCamera: up along the view");
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
    const double pixel = spec.screenPixel > 0
                             ? spec.screenPixel
                             : 2.0 * dist * std::tan(glm::radians(spec.fovY) / 2) / height;
    ViewCamera v;
    v.screen = rt::ScreenCamera(spec.target + offset, forward, dist, right, up, pixel / zoom);
    v.target = spec.target;
    v.dist = dist;
    v.width = width;
    v.height = height;
    v.pixelOffset = spec.pixelCorners ? 0.0 : 0.5;
    return v;
}

void ViewCamera::frustum(double zNear, double& l, double& r, double& b, double& t) const {
    // GL pixel x covers window [x, x+1) and is sampled at x + 0.5; the ray of image pixel x
    // passes through screen xs = x + pixelOffset − W/2. Rows: image row y is GL row H−1−y.
    const double k = screen.pixelSize * zNear / dist;
    const double shift = 0.5 - pixelOffset; // pixels the image is moved right/down
    l = (-width / 2.0 - shift) * k;
    r = (width / 2.0 - shift) * k;
    b = (-height / 2.0 + shift) * k;
    t = (height / 2.0 + shift) * k;
}

bool ViewCamera::operator==(const ViewCamera& o) const {
    return screen.eye == o.screen.eye && screen.screenCentre == o.screen.screenCentre &&
           screen.screenX == o.screen.screenX && screen.screenY == o.screen.screenY &&
           screen.pixelSize == o.screen.pixelSize && width == o.width && height == o.height &&
           pixelOffset == o.pixelOffset;
}

rt::Ray PixelCamera::primaryRay(int x, int y, int width, int height) const {
    if (width != view_.width || height != view_.height)
        throw std::invalid_argument("PixelCamera: image size differs from the view's");
    return view_.pixelRay(x, y);
}

} // namespace wb
