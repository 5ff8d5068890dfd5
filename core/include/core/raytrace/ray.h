#pragma once
// A ray of the Whitted tracer: where it starts, where it goes, how much it still
// matters (weight) and which medium it travels in (seed 000, part 2).
#include <glm/glm.hpp>

namespace wb::rt {

// The optical medium a ray travels through (seed 000's GREENMedium).
struct Medium {
    double refract = 1.0; // refractive index: 1 = air, 1.5 = glass
    double atten = 0.0;   // attenuation per unit length: colour *= exp(-atten * distance)
};

struct Ray {
    glm::dvec3 origin{0.0};         // start point
    glm::dvec3 direction{0, 0, -1}; // unit direction (constructors of rays normalise)
    double weight = 1.0;            // product of the kr/kt factors along the ray tree
    Medium medium;                  // medium the ray travels in
    int depth = 0;                  // 0 = primary ray, +1 per reflection/refraction

    glm::dvec3 at(double t) const { return origin + t * direction; }
};

// A new ray origin just off the surface at `p` on the side `n` points to, so the
// new ray cannot hit the surface it leaves ("acne"). Ray Tracing Gems ch. 6
// (Wächter & Binder), ported to double: the offset is a fixed number of ULPs of
// each coordinate, i.e. it scales with the point's magnitude; near the origin,
// where ULPs vanish, a small absolute offset is used instead.
glm::dvec3 offsetRayOrigin(const glm::dvec3& p, const glm::dvec3& n);
// offsetRayOrigin of `count` (even) points at once, coordinates in arrays (p: x, y, z, each
// of `count` doubles; n and out alike): out's element k is offsetRayOrigin(p_k, n_k)'s, bit
// for bit, two points at a time in SSE2's lanes (issue 21: the packets' eye hits; the call
// per hit and its branches were ~55 instructions an eye ray).
void offsetRayOrigins(const double* const p[3], const double* const n[3], double* const out[3],
                      int count);

} // namespace wb::rt
