#include "core/raytrace/camera.h"

#include <emmintrin.h>
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

void LookAtCamera::rowRays(int x0, int y, int n, int width, int height, Ray* out) const {
    int k = 0;
    const ScreenCamera& s = screen_;
    // NaN or negative: rayThroughScreen's test, ray by ray.
    if (s.hither == 0 || s.hither > 0) {
        // rayThroughScreen(xs, ys, pixel) of rayAt, lane by lane: p = centre + pixel·(xs·X +
        // ys·Y), direction = (p − eye)·(1 / sqrt(dot)) as glm::normalize (no FMA: each
        // product is rounded before its sum, as in the scalar code); on the hither plane,
        // origin = eye + (hither / dot(direction, f))·direction.
        const bool hither = s.hither > 0;
        const glm::dvec3 f = glm::normalize(s.screenCentre - s.eye);
        const __m128d h = _mm_set1_pd(s.hither);
        const double pixel = 2.0 * dist * tanHalfFov / height;
        const double ys = height / 2.0 - double(y);
        const glm::dvec3 ysY = ys * s.screenY;
        const __m128d halfW = _mm_set1_pd(width / 2.0), pix = _mm_set1_pd(pixel);
        const __m128d one = _mm_set1_pd(1.0);
        for (; k + 1 < n; k += 2) {
            // Element 0 is ray k, element 1 ray k + 1.
            const __m128d xs = _mm_sub_pd(_mm_set_pd(double(x0 + k + 1), double(x0 + k)), halfW);
            __m128d v[3];
            for (int a = 0; a < 3; ++a) {
                const __m128d onScreen =
                    _mm_add_pd(_mm_mul_pd(xs, _mm_set1_pd(s.screenX[a])), _mm_set1_pd(ysY[a]));
                const __m128d p =
                    _mm_add_pd(_mm_set1_pd(s.screenCentre[a]), _mm_mul_pd(pix, onScreen));
                v[a] = _mm_sub_pd(p, _mm_set1_pd(s.eye[a]));
            }
            const __m128d dot = _mm_add_pd(
                _mm_add_pd(_mm_mul_pd(v[0], v[0]), _mm_mul_pd(v[1], v[1])), _mm_mul_pd(v[2], v[2]));
            const __m128d inv = _mm_div_pd(one, _mm_sqrt_pd(dot));
            __m128d dir[3];
            for (int a = 0; a < 3; ++a)
                dir[a] = _mm_mul_pd(v[a], inv);
            alignas(16) double d[3][2], o[3][2];
            for (int a = 0; a < 3; ++a)
                _mm_store_pd(d[a], dir[a]);
            if (hither) {
                const __m128d cosF = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dir[0], _mm_set1_pd(f.x)),
                                                           _mm_mul_pd(dir[1], _mm_set1_pd(f.y))),
                                                _mm_mul_pd(dir[2], _mm_set1_pd(f.z)));
                const __m128d along = _mm_div_pd(h, cosF);
                for (int a = 0; a < 3; ++a)
                    _mm_store_pd(o[a],
                                 _mm_add_pd(_mm_set1_pd(s.eye[a]), _mm_mul_pd(along, dir[a])));
            }
            for (int e = 0; e < 2; ++e) {
                Ray& r = out[k + e];
                r = Ray();
                r.origin = hither ? glm::dvec3(o[0][e], o[1][e], o[2][e]) : s.eye;
                r.direction = glm::dvec3(d[0][e], d[1][e], d[2][e]);
            }
        }
    }
    for (; k < n; ++k) // an odd last ray, or the hither plane's rays
        out[k] = rayAt(x0 + k, y, width, height);
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
