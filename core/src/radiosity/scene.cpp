#include "core/radiosity/scene.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wb::rad {

namespace {

glm::dvec3 newell(const std::vector<glm::dvec3>& poly) {
    glm::dvec3 n(0.0);
    const std::size_t m = poly.size();
    for (std::size_t k = 0; k < m; ++k) {
        const glm::dvec3& a = poly[k];
        const glm::dvec3& b = poly[(k + 1) % m];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n; // 2 × area × unit normal
}

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

[[noreturn]] void fail(std::size_t index, const Surface& s, const std::string& what) {
    std::ostringstream msg;
    msg << "radiosity scene: surface " << index;
    if (!s.name.empty()) msg << " (\"" << s.name << "\")";
    msg << ": " << what;
    throw std::invalid_argument(msg.str());
}

} // namespace

double polygonArea(const std::vector<glm::dvec3>& poly) {
    if (poly.size() < 3) return 0.0;
    const double a = 0.5 * glm::length(newell(poly));
    return std::isfinite(a) ? a : 0.0;
}

bool polygonCentroid(const std::vector<glm::dvec3>& poly, glm::dvec3& centroid) {
    glm::dvec3 sum(0.0);
    double wsum = 0.0;
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
        const double a = 0.5 * glm::length(glm::cross(poly[k] - poly[0], poly[k + 1] - poly[0]));
        sum += a * (poly[0] + poly[k] + poly[k + 1]) / 3.0;
        wsum += a;
    }
    if (!(wsum > 0.0)) return false;
    centroid = sum / wsum;
    return true;
}

glm::dvec3 polygonNormal(const std::vector<glm::dvec3>& poly) {
    if (poly.size() < 3) return glm::dvec3(0.0);
    const glm::dvec3 n = newell(poly);
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return glm::dvec3(0.0);
    return n / len;
}

void validate(const Scene& scene) {
    bool emits = false;
    if (scene.surfaces.empty()) throw std::invalid_argument("radiosity scene: no surfaces");
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        const Surface& s = scene.surfaces[i];
        const std::size_t m = s.vertices.size();
        if (m < 3 || m > 4)
            fail(i, s, std::to_string(m) + " vertices (a patch polygon needs 3 or 4)");
        for (std::size_t k = 0; k < m; ++k)
            if (!finite3(s.vertices[k]))
                fail(i, s, "vertex " + std::to_string(k) + " has a NaN or infinite coordinate");
        double extent = 0.0;
        for (std::size_t k = 0; k < m; ++k)
            extent = std::max(extent, glm::length(s.vertices[k] - s.vertices[(k + 1) % m]));
        const double area = polygonArea(s.vertices);
        // Zero area: below 1e-12 of the squared edge scale the normal is rounding noise.
        if (!(area > 1e-12 * extent * extent) || !(extent > 0.0))
            fail(i, s, "zero area (degenerate polygon)");
        const glm::dvec3 n = polygonNormal(s.vertices);
        for (std::size_t k = 0; k < m; ++k) {
            // Planarity: distance from the plane within 1e-9 of the polygon's extent.
            if (std::abs(glm::dot(s.vertices[k] - s.vertices[0], n)) > 1e-9 * extent)
                fail(i, s, "not planar");
            // Convexity: every turn goes the same way as the normal.
            const glm::dvec3 e0 = s.vertices[(k + 1) % m] - s.vertices[k];
            const glm::dvec3 e1 = s.vertices[(k + 2) % m] - s.vertices[(k + 1) % m];
            if (glm::dot(glm::cross(e0, e1), n) <= 0.0) fail(i, s, "not convex");
        }
        for (int c = 0; c < 3; ++c) {
            const double r = s.reflectivity[c];
            if (!std::isfinite(r) || r < 0.0 || r >= 1.0)
                fail(i, s,
                     "reflectivity " + std::to_string(r) +
                         " outside [0, 1) (R >= 1 creates light; the iteration would diverge)");
            const double e = s.emission[c];
            if (!std::isfinite(e) || e < 0.0)
                fail(i, s, "emission " + std::to_string(e) + " is negative or not finite");
            if (e > 0.0) emits = true;
        }
    }
    if (!emits)
        throw std::invalid_argument(
            "radiosity scene \"" + scene.name +
            "\": no surface emits light (E = 0 everywhere), the solution would be black");
}

} // namespace wb::rad
