#pragma once
// Lab 07 - seed 000's steps of a ray tracer as graded tasks: the ray-sphere intersection
// and its normal (practical 11.1), the lighting at the hit with a shadow feeler (seed 000's
// formula (3), part 1) and the reflected ray (part 2). You write the bodies in
// exercises.cpp; with `e` on the lab traces its sphere scene with your functions beside the
// reference, and `./wb check lab07` grades them against seed 000's worked numbers
// ((10,117,10) in shadow, (50,197,50) lit, (168,233,86) with the reflected ray) and
// against the project's tracer on random, grazing and far rays.
#include "common/exercise.h"

#include <glm/glm.hpp>

#include <cmath>
#include <functional>

namespace wb::lab07 {

// ③ Ray-sphere intersection (practical 11.1; DESIGN.md: the cancellation-free roots).
// The ray is origin + t·direction with |direction| = 1; the sphere has `centre` and
// radius > 0 (1e-3 .. 1e3; |origin - centre| up to 1e7). Return true with `t` = the
// NEAREST root t > 0 (a ray starting inside the sphere meets it once, on the far side);
// false when the ray misses or the sphere lies behind the origin (both roots <= 0).
// With a = 1 the roots of t² + 2ht + c = 0 are -h ± √(h² - c); for grazing and far rays
// compute h² - c as r² - |f - h·d|² (f = origin - centre: the squared distance of the
// centre from the ray's line), and take q = -(h + sign(h)√disc), t0 = q, t1 = c/q.
// A tangent ray (disc = 0 up to rounding) may be reported either way.
bool intersectSphere(const glm::dvec3& origin, const glm::dvec3& direction,
                     const glm::dvec3& centre, double radius, double& t);

// ③ The normal at a point of the sphere (practical 11.1): the UNIT outward normal
// (point - centre)/radius. The point lies on the sphere (up to rounding).
glm::dvec3 sphereNormal(const glm::dvec3& point, const glm::dvec3& centre, double radius);

// ---- seed 000's colour arithmetic (given; use it, do not change it) ----------------------
// Colours are three integers 0..255. colour × colour = c1·c2/255, colour × number, and
// every result is rounded to the nearest integer, ties to even (10.5 -> 10, 36.5 -> 36),
// and clamped to 0..255, as seed 000's program does after every operation.
inline double roundEven(double x) {
    return std::nearbyint(x); // the default rounding mode: to nearest, ties to even
}
inline double clamp255(double x) {
    return std::isfinite(x) ? (x < 0 ? 0.0 : (x > 255 ? 255.0 : x)) : 0.0;
}
inline glm::dvec3 mul(const glm::dvec3& a, const glm::dvec3& b) { // a·b/255
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(roundEven(a[i] * b[i] / 255.0));
    return r;
}
inline glm::dvec3 mulBy(const glm::dvec3& a, double s) { // a·s
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(roundEven(a[i] * s));
    return r;
}
inline glm::dvec3 add(const glm::dvec3& a, const glm::dvec3& b) {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = clamp255(a[i] + b[i]);
    return r;
}

// The surface (seed 000's GREENSurface): colour C in 0..255, ka, kd, ks, Phong exponent p.
struct Material {
    glm::dvec3 colour{0.0};
    double ka = 0.5, kd = 0.5, ks = 0.5, p = 3;
};
// What the tracer knows at the hit of a ray with one point light.
struct ShadeInput {
    glm::dvec3 point{0.0};      // the hit point P
    glm::dvec3 normal{0, 0, 1}; // unit normal N at P, on the side the ray came from
    glm::dvec3 view{0, 0, -1};  // unit direction V of the ray that hit P (eye -> P)
    Material material;
    glm::dvec3 lightPos{0.0};      // the point light
    glm::dvec3 lightColour{255.0}; // BL, 0..255
    glm::dvec3 ambient{255.0};     // BA, 0..255
    double distScale = 30;         // seed 000: SH = distScale / distance to the light
};
// The shadow feeler: the product of kt of every object between `from` and `to`
// (1 = nothing in between, 0 = an opaque blocker). Given by the lab (it knows the scene).
using Feeler = std::function<double(const glm::dvec3& from, const glm::dvec3& to)>;

// ④ The colour at the hit (seed 000 part 1, formula (3) for one light):
//   B = BA·C·KA + BL·C·(SH·(L·N)·KD) + BL·(SH·KS·(n·N)^P)
// L = unit vector from P to the light, dist its distance, SH = distScale/dist × feeler(P,
// light); the two light terms only when SH > 0 and L·N > 0 (a light behind the surface
// gives nothing), the specular only when n·N > 0, with the micro-facet normal
// n = normalize(L - V). Every product and sum with mul / mulBy / add above, in this order:
// ambient = mulBy(mul(BA, C), KA); diffuse = mulBy(mul(BL, C), SH·LN·KD);
// specular = mulBy(BL, SH·KS·NN^P); B = add(add(ambient, diffuse), specular).
glm::dvec3 shade(const ShadeInput& in, const Feeler& feeler);

// ⑤ The reflected ray's direction (seed 000 part 2, practical 12): for the unit direction
// d of the incoming ray and the unit normal n at the hit, r = d - 2(d·n)n (unit, whichever
// side n faces). Seed 000: d = (0.447, 0, -0.894), n = (0, 0, 1) give (0.447, 0, 0.894).
glm::dvec3 reflectDirection(const glm::dvec3& d, const glm::dvec3& n);

// The exercise table, in task order.
struct Table {
    bool (*intersectSphere)(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, double,
                            double&);
    glm::dvec3 (*sphereNormal)(const glm::dvec3&, const glm::dvec3&, double);
    glm::dvec3 (*shade)(const ShadeInput&, const Feeler&);
    glm::dvec3 (*reflectDirection)(const glm::dvec3&, const glm::dvec3&);
};

} // namespace wb::lab07
