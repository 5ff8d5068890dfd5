#pragma once
// Primary rays. Two cameras behind one interface: a look-at pinhole with a vertical
// field of view, and seed 000's screen mapping (eye, screen plane at distance Dist,
// pixel (xx, yy) -> screen point (xs, ys) = (xx − homeX, homeY − yy)).
#include "core/raytrace/ray.h"

namespace wb::rt {

class Camera {
  public:
    virtual ~Camera() = default;
    // The primary ray through pixel (x, y) of a width × height image, row 0 at the top.
    virtual Ray primaryRay(int x, int y, int width, int height) const = 0;
};

class ScreenCamera : public Camera {
  public:
    // The screen plane is perpendicular to `viewDir` at distance `dist` from the eye;
    // screen x runs along `screenX`, screen y along `screenY` (both unit, world units
    // per pixel = pixelSize). Seed 000: eye (0,0,100), looking down −z, Dist = 100,
    // screen x = world x, screen y = world y, so pixel P(50, 0) is the point (50, 0, 0).
    ScreenCamera(const glm::dvec3& eye, const glm::dvec3& viewDir, double dist,
                 const glm::dvec3& screenX, const glm::dvec3& screenY, double pixelSize = 1.0);
    // Seed 000's camera: eye at (0, 0, height) looking straight down, screen at distance dist.
    static ScreenCamera seed000(double height = 100.0, double dist = 100.0);

    // Pixel (xx, yy) with homeX = width/2, homeY = height/2, as seed 000's Tracing().
    Ray primaryRay(int x, int y, int width, int height) const override;
    // The ray through screen point (xs, ys) (origin at the screen centre, y up).
    Ray rayThroughScreen(double xs, double ys) const;

    // The same with pixels of `pixel` world units instead of pixelSize.
    Ray rayThroughScreen(double xs, double ys, double pixel) const;

    glm::dvec3 eye, screenCentre, screenX, screenY;
    double pixelSize;
    // NFF's hither plane: rays start where they cross the plane at this distance from the
    // eye along the view direction, so what is nearer is clipped (0: rays start at the eye).
    double hither = 0.0;
};

// The one look-at frame of the project (issue 12: rt_render and lab 07 rendered the
// same file differently because each built its rays its own way). The eye looks at
// `target`, turned first by yawDeg about `up` and then by pitchDeg about the camera's
// right axis (lab 07's orbit; pitch keeps the view between 1° and 179° from up; both
// 0 for a fixed view, which is then exact: no rotation is applied). The screen plane
// passes through the target (distance |eye − target|), x = normalize(forward × up),
// y = x × forward, pixels of pixelSize. Throws std::invalid_argument when eye == target
// or up runs along the view.
ScreenCamera orbitScreenCamera(const glm::dvec3& eye, const glm::dvec3& target,
                               const glm::dvec3& up, double yawDeg, double pitchDeg,
                               double pixelSize);

// A look-at pinhole with a vertical field of view, for images of any size: the rays of
// orbitScreenCamera(eye, target, up, 0, 0, pixel) with pixel = 2·|eye − target|·tan(fov/2)/h,
// bit for bit what lab 07 traces for the same view (see tests/core/raytrace_scale/
// same_picture_test.cpp).
class LookAtCamera : public Camera {
  public:
    // fovYDegrees in (0, 180); up not parallel to target − eye. Throws
    // std::invalid_argument otherwise. Rays pass through pixel centres.
    LookAtCamera(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                 double fovYDegrees);
    Ray primaryRay(int x, int y, int width, int height) const override;
    // The ray through continuous image coordinates (px, py) in [0, w] × [0, h].
    Ray rayAt(double px, double py, int width, int height) const;
    // rayAt(x0 + k, y, width, height) into out[k] for 0 <= k < n: a packet's row of corner
    // rays (renderParallel), two at a time in SSE2's lanes with rayAt's operations in its
    // order, the same bits (issue 21: rayAt per ray was ~116 instructions of each eye ray).
    void rowRays(int x0, int y, int n, int width, int height, Ray* out) const;

    // The hither (near) plane's distance from the eye (ScreenCamera::hither).
    void setHither(double distance) { screen_.hither = distance; }

    glm::dvec3 eye, forward, right, up; // orthonormal frame (eye as orbitScreenCamera puts it)
    double tanHalfFov;                  // tan(fov/2)
    double dist;                        // |eye − target|: the screen plane's distance

  private:
    ScreenCamera screen_; // pixel size 1; each image size scales it
};

} // namespace wb::rt
