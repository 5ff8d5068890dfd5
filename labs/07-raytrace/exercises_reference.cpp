// Lab 07 - the reference answers and, behind WB_MUTANT(n), the typical mistakes CI checks
// the grading against (listed with their ids in exercise_checks.cpp).
#include "exercises.h"

#include <cmath>
#include <utility>

namespace wb::lab07 {

bool intersectSphere(const glm::dvec3& origin, const glm::dvec3& direction,
                     const glm::dvec3& centre, double radius, double& t) {
    const glm::dvec3 f = WB_MUTANT(3) ? centre - origin : origin - centre; // 3: sign of f
    const double h = glm::dot(f, direction);
    const glm::dvec3 l = f - h * direction; // the centre's offset from the ray's line
    const double ll = glm::length(l);
    double disc = (radius - ll) * (radius + ll);
    if (WB_MUTANT(4)) disc = std::fabs(disc); // 4: a miss taken for a hit
    if (!(disc >= 0)) return false;
    const double fl = glm::length(f);
    const double c = (fl - radius) * (fl + radius);
    const double q = -(h + std::copysign(std::sqrt(disc), h));
    double t0 = 0, t1 = 0;
    if (q != 0) t0 = q, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    if (WB_MUTANT(1)) std::swap(t0, t1); // 1: the far root first
    if (t0 > 0 || WB_MUTANT(2)) {        // 2: no t > 0 test: a sphere behind is "hit"
        t = t0;
        return true;
    }
    if (t1 > 0) {
        t = t1;
        return true;
    }
    return false;
}

glm::dvec3 sphereNormal(const glm::dvec3& point, const glm::dvec3& centre, double radius) {
    if (WB_MUTANT(11)) return point - centre;            // 11: not divided by the radius
    if (WB_MUTANT(12)) return (centre - point) / radius; // 12: inward
    if (WB_MUTANT(13)) return point / radius;            // 13: centre forgotten
    return (point - centre) / radius;
}

glm::dvec3 shade(const ShadeInput& in, const Feeler& feeler) {
    const Material& m = in.material;
    glm::dvec3 b = mulBy(mul(in.ambient, m.colour), m.ka);
    const glm::dvec3 toLight = in.lightPos - in.point;
    const double dist = glm::length(toLight);
    if (!(dist > 0)) return b;
    const glm::dvec3 l = toLight / dist;
    double sh = in.distScale / dist;
    if (!WB_MUTANT(21)) sh *= feeler(in.point, in.lightPos); // 21: no shadow feeler
    if (WB_MUTANT(23)) sh = 1;                               // 23: no distScale/dist
    const double ln = glm::dot(l, in.normal);
    if (!(sh > 0) || (!(ln > 0) && !WB_MUTANT(24))) return b; // 24: light behind not tested
    b = add(b, mulBy(mul(in.lightColour, m.colour), sh * ln * m.kd));
    const glm::dvec3 hv = WB_MUTANT(22) ? l + in.view : l - in.view; // 22: n = L + V
    const double hl = glm::length(hv);
    if (!(hl > 0)) return b;
    const double nn = glm::dot(hv / hl, in.normal);
    if (!(nn > 0)) return b;
    return add(b, mulBy(in.lightColour, sh * m.ks * std::pow(nn, m.p)));
}

glm::dvec3 reflectDirection(const glm::dvec3& d, const glm::dvec3& n) {
    if (WB_MUTANT(31)) return d + 2 * glm::dot(d, n) * n; // 31: sign
    if (WB_MUTANT(32)) return d - glm::dot(d, n) * n;     // 32: factor 2 forgotten
    if (WB_MUTANT(33)) return 2 * glm::dot(d, n) * n - d; // 33: the reversed ray
    return d - 2 * glm::dot(d, n) * n;
}

} // namespace wb::lab07

WB_EXERCISE_TABLE(wb::lab07::Table, lab07,
                  {&wb::lab07::intersectSphere, &wb::lab07::sphereNormal, &wb::lab07::shade,
                   &wb::lab07::reflectDirection})
