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

class LookAtCamera : public Camera {
  public:
    // fovYDegrees in (0, 180); up not parallel to target − eye. Throws
    // std::invalid_argument otherwise. Rays pass through pixel centres.
    LookAtCamera(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                 double fovYDegrees);
    Ray primaryRay(int x, int y, int width, int height) const override;
    // The ray through continuous image coordinates (px, py) in [0, w] × [0, h].
    Ray rayAt(double px, double py, int width, int height) const;

    glm::dvec3 eye, forward, right, up; // orthonormal frame
    double tanHalfFov;
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

    glm::dvec3 eye, screenCentre, screenX, screenY;
    double pixelSize;
};

} // namespace wb::rt
