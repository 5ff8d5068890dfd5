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
    // The frame is core's (rt::orbitScreenCamera), the same code rt_render's
    // LookAtCamera uses, so both front ends trace the same rays for the same view.
    const double dist = glm::length(spec.eye - spec.target);
    if (!(dist > 0)) throw std::invalid_argument("ViewCamera: eye == target");
    const double pixel = spec.screenPixel > 0
                             ? spec.screenPixel
                             : 2.0 * dist * std::tan(glm::radians(spec.fovY) / 2) / height;
    ViewCamera v;
    v.screen =
        rt::orbitScreenCamera(spec.eye, spec.target, spec.up, yawDeg, pitchDeg, pixel / zoom);
    v.screen.hither = spec.hither;
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
           screen.pixelSize == o.screen.pixelSize && screen.hither == o.screen.hither &&
           width == o.width && height == o.height && pixelOffset == o.pixelOffset;
}

rt::Ray PixelCamera::primaryRay(int x, int y, int width, int height) const {
    if (width != view_.width || height != view_.height)
        throw std::invalid_argument("PixelCamera: image size differs from the view's");
    return view_.pixelRay(x, y);
}

} // namespace wb
