#include "core/raytrace/polyhedron.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wb::rt {

ConvexPolyhedron::ConvexPolyhedron(std::vector<Face> f) : faces(std::move(f)) {
    if (faces.empty()) throw std::invalid_argument("ConvexPolyhedron: no faces");
    for (Face& face : faces) {
        const double len = glm::length(face.normal);
        if (!(len > 0) || !std::isfinite(len) || !std::isfinite(face.d))
            throw std::invalid_argument("ConvexPolyhedron: zero or non-finite face plane");
        face.normal /= len;
        face.d /= len;
    }
    // Unbounded iff some direction w != 0 has n_i·w <= 0 for every face; the extreme
    // rays of that recession cone lie on intersections of two face planes, ±n_i×n_j
    // (or, if all normals are parallel, anything perpendicular to them).
    std::vector<glm::dvec3> cand;
    for (size_t i = 0; i < faces.size(); ++i)
        for (size_t j = i + 1; j < faces.size(); ++j) {
            const glm::dvec3 w = glm::cross(faces[i].normal, faces[j].normal);
            if (glm::length(w) > 1e-12) {
                cand.push_back(glm::normalize(w));
                cand.push_back(-glm::normalize(w));
            }
        }
    if (cand.empty()) {
        bounds_ = Aabb::infinite();
        return;
    }
    for (const glm::dvec3& w : cand) {
        bool recedes = true;
        for (const Face& face : faces)
            if (glm::dot(face.normal, w) > 1e-12) recedes = false;
        if (recedes) {
            bounds_ = Aabb::infinite();
            return;
        }
    }
    // Bounded: the box of the vertices (triples of planes whose point satisfies all).
    const size_t k = faces.size();
    for (size_t a = 0; a < k; ++a)
        for (size_t b = a + 1; b < k; ++b)
            for (size_t c = b + 1; c < k; ++c) {
                const glm::dvec3 &na = faces[a].normal, &nb = faces[b].normal,
                                 &nc = faces[c].normal;
                const double det = glm::dot(na, glm::cross(nb, nc));
                if (std::fabs(det) < 1e-12) continue;
                const glm::dvec3 p =
                    (faces[a].d * glm::cross(nb, nc) + faces[b].d * glm::cross(nc, na) +
                     faces[c].d * glm::cross(na, nb)) /
                    det;
                bool inside = true;
                for (const Face& face : faces)
                    if (glm::dot(face.normal, p) > face.d + 1e-9 * (1 + std::fabs(face.d)))
                        inside = false;
                if (inside) bounds_.extend(p);
            }
}

bool ConvexPolyhedron::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    double fMax = -std::numeric_limits<double>::infinity();
    double bMin = std::numeric_limits<double>::infinity();
    int fi = -1, bi = -1;
    for (size_t i = 0; i < faces.size(); ++i) {
        const double s = glm::dot(ray.direction, faces[i].normal);
        const double num = faces[i].d - glm::dot(ray.origin, faces[i].normal);
        if (s == 0) { // parallel: outside this half-space means no hit at all
            if (num < 0) return false;
            continue;
        }
        const double alpha = num / s;
        if (s < 0) { // entering through the front of plane i
            if (alpha > fMax) {
                fMax = alpha;
                fi = int(i);
            }
        } else if (alpha < bMin) { // leaving through the back
            bMin = alpha;
            bi = int(i);
        }
        if (fMax > bMin) return false;
    }
    double t;
    int face;
    if (fi >= 0 && fMax > tMin && fMax <= tMax) {
        t = fMax;
        face = fi;
    } else if (bi >= 0 && fMax <= tMin && bMin > tMin && bMin <= tMax) {
        t = bMin; // the origin is inside: the ray meets the body from within
        face = bi;
    } else {
        return false;
    }
    const Face& f = faces[size_t(face)];
    glm::dvec3 p = ray.at(t);
    p += (f.d - glm::dot(f.normal, p)) * f.normal;
    hit.t = t;
    hit.point = p;
    hit.outwardNormal = f.normal;
    hit.hasUv = false;
    finishHit(ray, hit);
    return true;
}

Aabb ConvexPolyhedron::bounds() const {
    return bounds_;
}

} // namespace wb::rt
