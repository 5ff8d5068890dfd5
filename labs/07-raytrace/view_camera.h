#pragma once
// One camera for both pictures: the orbit (yaw/pitch about the scene's target, zoom)
// turns a CameraSpec into an eye, an orthonormal frame and a pixel size on the screen
// plane; the tracer's primary rays and the GL frustum are both derived from it, so a
// traced pixel and a rasterized pixel look along the same line.
#include "lab_scenes.h"

#include "core/raytrace/camera.h"

namespace wb {

struct ViewCamera {
    rt::ScreenCamera screen{{0, 0, 1}, {0, 0, -1}, 1.0, {1, 0, 0}, {0, 1, 0}, 1.0};
    glm::dvec3 target{0.0}; // orbit centre (image centre)
    double dist = 1.0;      // eye to the screen plane through the target
    int width = 1, height = 1;
    double pixelOffset = 0.5; // 0.5: rays through pixel centres; 0: seed 000's corners

    // yaw turns about the spec's up, pitch about the camera's right axis (degrees;
    // pitch is limited to ±89° so up never runs along the view); zoom > 0 shrinks pixels.
    static ViewCamera make(const CameraSpec& spec, double yawDeg, double pitchDeg, double zoom,
                           int width, int height);

    // Screen point (xs, ys) (pixels from the image centre, y up) of pixel (x, y) (row 0 at the
    // top).
    glm::dvec2 screenOfPixel(double x, double y) const {
        return {x + pixelOffset - width / 2.0, height / 2.0 - y - pixelOffset};
    }
    rt::Ray pixelRay(double x, double y) const {
        const glm::dvec2 s = screenOfPixel(x, y);
        return screen.rayThroughScreen(s.x, s.y);
    }
    // glFrustum bounds at distance zNear that put the centre of GL pixel (x, y) on pixelRay.
    void frustum(double zNear, double& l, double& r, double& b, double& t) const;
    glm::dvec3 eye() const { return screen.eye; }
    glm::dvec3 forward() const { return glm::normalize(screen.screenCentre - screen.eye); }
    bool operator==(const ViewCamera& o) const;
};

// The tracer's view of a ViewCamera for images of its size (primaryRay checks the size).
class PixelCamera : public rt::Camera {
  public:
    explicit PixelCamera(const ViewCamera& v) : view_(v) {}
    rt::Ray primaryRay(int x, int y, int width, int height) const override;
    const ViewCamera& view() const { return view_; }

  private:
    ViewCamera view_;
};

} // namespace wb
