#include "core/raytrace/scene_file.h"

#include "core/raytrace/nff.h"
#include "core/raytrace/obj_file.h"

#include "core/file_read.h"
#include "core/i18n.h"

#include <cstdint>
#include <unordered_map>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace wb::rt {

glm::dvec3 scaledUp(const glm::dvec3& up) {
    const double m = std::max({std::abs(up.x), std::abs(up.y), std::abs(up.z)});
    if (!(m > 0) || !std::isfinite(m)) return up;
    return up * std::ldexp(1.0, -std::ilogb(m));
}

LookAtCamera SceneFile::camera() const {
    // up only gives a direction: scaled by a power of two (exact, so an up of (0, 1, 0)
    // keeps every bit) so that cross(at − from, up) cannot overflow for a far-away
    // from/at and a huge up (issue 12 point 5).
    LookAtCamera cam(view.from, view.at, scaledUp(view.up), view.angle);
    cam.setHither(view.hither); // NFF's near plane (issue 20 point 14)
    return cam;
}

namespace {

// Near-duplicates piled in one spot (issue 20 point 2): 100,000 unit spheres whose
// centres differ by 1e-9 took 9 s at 64x64 (minutes at 512x512): the BVH splits them
// into small leaves, but their boxes all overlap, so every ray through the spot tests
// every one. Exact duplicates are dropped by the readers; this bounds the rest: boxes
// are compared on a grid of 1/64 of their own size (a power of two, so a box's key is
// exact), and more than kScenePileLimit primitives with the same key are refused.
// Returns the message, or "" when no pile passes the bound.
std::string findPile(const Scene& scene) {
    std::unordered_map<std::uint64_t, std::uint32_t> count;
    count.reserve(scene.primitives.size());
    for (const auto& prim : scene.primitives) {
        const Aabb b = prim->bounds();
        if (!b.bounded() || b.empty()) continue;
        const double d = std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
        if (!(d > 0) || !std::isfinite(d)) continue;
        const int e = std::ilogb(d) - 6; // cell: 2^e, between 1/128 and 1/64 of the size
        std::uint64_t h = 1469598103934665603ull;
        auto mix = [&h](std::int64_t v) {
            for (int i = 0; i < 8; ++i) {
                h ^= std::uint64_t(v >> (8 * i)) & 0xff;
                h *= 1099511628211ull;
            }
        };
        mix(e);
        for (int k = 0; k < 3; ++k) {
            mix(std::int64_t(std::floor(std::ldexp(b.lo[k], -e))));
            mix(std::int64_t(std::floor(std::ldexp(b.hi[k], -e))));
        }
        if (++count[h] > kScenePileLimit) {
            const glm::dvec3 c = 0.5 * b.lo + 0.5 * b.hi;
            return trf("more than %zu primitives nearly coincide (boxes equal to 1/64 of "
                       "their size) near (%g, %g, %g): every ray through there would test "
                       "them all (the limit for one spot, see scene_file.h)",
                       kScenePileLimit, c.x, c.y, c.z);
        }
    }
    return {};
}

} // namespace

SceneFile loadSceneFile(const std::string& path) {
    SceneFile sf = loadSceneFileUnchecked(path);
    if (const std::string pile = findPile(*sf.scene); !pile.empty())
        throw SceneFileError(escapeForMessage(path, 4096) + ":0: " + pile);
    return sf;
}

SceneFile loadSceneFileUnchecked(const std::string& path) {
    std::string ext;
    const auto dot = path.find_last_of('.');
    if (dot != std::string::npos) ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    // The path as messages show it: escape bytes and newlines (issue 20 point 16).
    const std::string shown = escapeForMessage(path, 4096);
    if (ext == "nff") {
        try {
            SceneFile sf = toScene(readNffFile(path));
            if (sf.scene->primitives.empty())
                throw SceneFileError(shown +
                                     ":0: nothing to draw: no objects (s, c, p, pp) in the file");
            // toScene names the document "NFF"; give the file name instead.
            for (std::string& w : sf.warnings)
                if (w.rfind("NFF:", 0) == 0) w = shown + w.substr(3);
            return sf;
        } catch (const SceneFileError& e) {
            std::string msg = e.what();
            if (msg.rfind("NFF:", 0) == 0) msg = shown + msg.substr(3);
            throw SceneFileError(msg);
        }
    }
    if (ext == "obj") return loadObjFile(path);
    throw SceneFileError(shown + ":0: unknown scene format (expected .nff or .obj)");
}

SceneView frameScene(const Scene& scene, double angle) {
    Aabb box;
    for (const auto& p : scene.primitives) {
        const Aabb b = p->bounds();
        if (b.bounded() && !b.empty()) {
            box.extend(b.lo);
            box.extend(b.hi);
        }
    }
    SceneView v;
    v.angle = angle;
    if (box.empty()) return v; // nothing bounded: the default view
    const glm::dvec3 c = 0.5 * (box.lo + box.hi);
    double r = 0.5 * glm::length(box.hi - box.lo);
    if (!(r > 0)) r = 1.0;
    // The bounding sphere fills the vertical field of view: distance r / sin(angle/2).
    double dist = r / std::sin(glm::radians(angle) / 2);
    // Far from the origin a small scene vanishes below a double's resolution (fuzz_nff,
    // issue 20: `s 1e150 1100 1e150 110` has an empty box and from == at, and the
    // camera threw). The eye keeps at least 2^-40 of the distance to the origin.
    const double m = std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)});
    dist = std::max(dist, std::ldexp(m, -40));
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, 0.4, 1.0)); // from the front, above
    v.at = c;
    v.from = c + dist * dir;
    v.up = {0, 1, 0};
    v.hither = 1e-3 * r;
    return v;
}

void addDefaultLight(Scene& scene, const SceneView& view) {
    if (!scene.lights.empty()) return;
    // Above and behind the viewer, so the visible side is lit and shadows fall behind.
    const glm::dvec3 back = view.from - view.at;
    const glm::dvec3 up = glm::normalize(view.up);
    scene.lights.push_back(Light::point(view.from + 0.5 * back + glm::length(back) * up));
}

} // namespace wb::rt
