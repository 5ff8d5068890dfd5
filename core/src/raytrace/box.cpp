#include "core/raytrace/box.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wb::rt {

Box::Box(const glm::dvec3& l, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
    : loc(l), e1(a), e2(b), e3(c) {
    const double vol = glm::dot(glm::cross(e1, e2), e3);
    if (!(std::fabs(vol) > 0) || !std::isfinite(vol))
        throw std::invalid_argument("Box: edges must be finite and linearly independent");
    centre = loc + 0.5 * (e1 + e2 + e3);
    toEdges_ = glm::inverse(glm::dmat3(e1, e2, e3));
    // Seed 000: N1 = E1×E2 (planes through Loc and Loc+E3), N2 = E1×E3 (Loc, Loc+E2),
    // N3 = E2×E3 (Loc, Loc+E1).
    const glm::dvec3 ns[3] = {glm::cross(e1, e2), glm::cross(e1, e3), glm::cross(e2, e3)};
    const glm::dvec3 far[3] = {e3, e2, e1};
    for (int i = 0; i < 3; ++i) {
        n[i] = glm::normalize(ns[i]);
        d1[i] = glm::dot(n[i], loc);
        d2[i] = glm::dot(n[i], loc + far[i]);
        if (d1[i] > d2[i]) { // seed 000 step 6: orient each pair so that d1 < d2
            n[i] = -n[i];
            d1[i] = -d1[i];
            d2[i] = -d2[i];
        }
    }
}

Box Box::axisAligned(const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 s = hi - lo;
    return Box(lo, {s.x, 0, 0}, {0, s.y, 0}, {0, 0, s.z});
}

bool Box::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    double tNear = -std::numeric_limits<double>::infinity();
    double tFar = std::numeric_limits<double>::infinity();
    int iNear = -1, iFar = -1;
    double sNear = 0, sFar = 0; // sign of the plane's normal along the slab normal
    for (int i = 0; i < 3; ++i) {
        const double vd = glm::dot(ray.direction, n[i]);
        const double vo = glm::dot(ray.origin, n[i]);
        if (vd == 0) { // parallel to the slab: inside it or no hit at all
            if (vo < d1[i] || vo > d2[i]) return false;
            continue;
        }
        double ta = (d1[i] - vo) / vd, tb = (d2[i] - vo) / vd;
        double sa = -1, sb = 1; // plane d1 has outward normal −n, plane d2 has +n
        if (ta > tb) {
            std::swap(ta, tb);
            std::swap(sa, sb);
        }
        if (ta > tNear) {
            tNear = ta;
            iNear = i;
            sNear = sa;
        }
        if (tb < tFar) {
            tFar = tb;
            iFar = i;
            sFar = sb;
        }
        if (tNear > tFar) return false;
    }
    double t;
    glm::dvec3 nrm;
    double plane;
    int face;
    if (iNear >= 0 && tNear > tMin && tNear <= tMax) {
        t = tNear;
        face = iNear;
        nrm = sNear * n[iNear];
        plane = sNear < 0 ? -d1[iNear] : d2[iNear];
    } else if (iFar >= 0 && tFar > tMin && tFar <= tMax) { // origin inside: the exit
        t = tFar;
        face = iFar;
        nrm = sFar * n[iFar];
        plane = sFar < 0 ? -d1[iFar] : d2[iFar];
    } else {
        return false;
    }
    glm::dvec3 p = ray.at(t);
    p += (plane - glm::dot(nrm, p)) * nrm; // onto the face's plane
    hit.t = t;
    hit.point = p;
    hit.outwardNormal = nrm;
    // Texture coordinates: the point's coordinates along the two edges spanning the face.
    const glm::dvec3 abc = toEdges_ * (p - loc);
    hit.uv = face == 0   ? glm::dvec2(abc.x, abc.y)
             : face == 1 ? glm::dvec2(abc.x, abc.z)
                         : glm::dvec2(abc.y, abc.z);
    hit.hasUv = true;
    finishHit(ray, hit);
    return true;
}

Aabb Box::bounds() const {
    Aabb b;
    for (int i = 0; i < 8; ++i)
        b.extend(loc + double(i & 1) * e1 + double((i >> 1) & 1) * e2 + double((i >> 2) & 1) * e3);
    return b;
}

} // namespace wb::rt
