// Issue 19 item 12: a second, independent estimate of the Cornell box's per-surface mean
// radiosity, to judge the Cycles reference and our radiosity solver by a third party: a brute
// force Monte Carlo path tracer on the scene's exact polygons (no patches, no form factors, no
// texels). For each surface, points are drawn uniformly over its polygon; points inside a body
// (the floor under a block: the first surface along the normal is met from behind) are
// rejected, so the mean is over the exposed area exactly. At each point
//   B(x) = E(x) + R(x) ⊙ H(x),  H = irradiance,
// H by next-event estimation on the light (uniform area sampling, shadow ray) plus a cosine-
// weighted bounce whose hit y adds R(y) ⊙ H(y) recursively (the light's emission is only
// counted by the next-event term; Russian roulette by max R). Lambertian, one-sided, open front
// (a ray leaving the box finds nothing). Noise: standard error over batches.
//
//   radiosity_mc [--paths N per surface] [--batches K] [--only NAME] [--out mc.json]
#include "core/radiosity/scenes.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/triangle.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace wb;
using V = glm::dvec3;

namespace {

struct Tracer {
    const rad::Scene& scene;
    std::vector<V> normal;
    std::vector<std::unique_ptr<rt::Primitive>> prims;
    std::unique_ptr<rt::Bvh> bvh;
    int light = -1;
    double lightArea = 0.0;

    explicit Tracer(const rad::Scene& s) : scene(s) {
        for (std::size_t i = 0; i < s.surfaces.size(); ++i) {
            const auto& v = s.surfaces[i].vertices;
            normal.push_back(rad::polygonNormal(v));
            for (std::size_t k = 1; k + 1 < v.size(); ++k) {
                prims.push_back(std::make_unique<rt::Triangle>(v[0], v[k], v[k + 1]));
                prims.back()->material = static_cast<int>(i);
            }
            if (glm::length(s.surfaces[i].emission) > 0) {
                light = static_cast<int>(i);
                lightArea = area(static_cast<int>(i));
            }
        }
        bvh = std::make_unique<rt::Bvh>(prims);
    }
    double area(int s) const {
        const auto& v = scene.surfaces[static_cast<std::size_t>(s)].vertices;
        double a = 0;
        for (std::size_t k = 1; k + 1 < v.size(); ++k)
            a += 0.5 * glm::length(glm::cross(v[k] - v[0], v[k + 1] - v[0]));
        return a;
    }
    template <class Rng> V samplePoint(int s, Rng& rng) const {
        std::uniform_real_distribution<double> U(0.0, 1.0);
        const auto& v = scene.surfaces[static_cast<std::size_t>(s)].vertices;
        // Pick a fan triangle by area, then a uniform point in it.
        const double total = area(s);
        double pick = U(rng) * total;
        std::size_t k = 1;
        for (; k + 2 < v.size(); ++k) {
            const double a = 0.5 * glm::length(glm::cross(v[k] - v[0], v[k + 1] - v[0]));
            if (pick < a) break;
            pick -= a;
        }
        double a = U(rng), b = U(rng);
        if (a + b > 1) {
            a = 1 - a;
            b = 1 - b;
        }
        return v[0] + a * (v[k] - v[0]) + b * (v[k + 1] - v[0]);
    }
    // Nearest surface along the ray (front side) and the hit point; -1 for nothing or a back side.
    int trace(const V& o, const V& d, V& at) const {
        rt::Ray ray;
        ray.origin = o;
        ray.direction = d;
        rt::Hit hit;
        if (!bvh->intersect(ray, 1e-7, 1e9, hit)) return -1;
        const int s = hit.material;
        if (glm::dot(normal[static_cast<std::size_t>(s)], d) >= 0) return -1;
        at = o + hit.t * d;
        return s;
    }
    bool exposed(const V& p, int s) const {
        const V n = normal[static_cast<std::size_t>(s)];
        rt::Ray ray;
        ray.origin = p;
        ray.direction = n;
        rt::Hit hit;
        if (!bvh->intersect(ray, 1e-7, 1e9, hit)) return true;
        return glm::dot(normal[static_cast<std::size_t>(hit.material)], n) < 0;
    }
    template <class Rng> V direct(const V& x, const V& n, Rng& rng) const {
        const V y = samplePoint(light, rng);
        V d = y - x;
        const double r2 = glm::dot(d, d);
        const double r = std::sqrt(r2);
        d /= r;
        const double cx = glm::dot(n, d),
                     cl = -glm::dot(normal[static_cast<std::size_t>(light)], d);
        if (cx <= 0 || cl <= 0) return V(0.0);
        rt::Ray ray;
        ray.origin = x;
        ray.direction = d;
        if (bvh->occluded(ray, 1e-7, r * (1 - 1e-9))) return V(0.0);
        return scene.surfaces[static_cast<std::size_t>(light)].emission / M_PI * lightArea * cx *
               cl / r2;
    }
    // Irradiance estimate at x (one path).
    template <class Rng> V irradiance(V x, V n, Rng& rng) const {
        std::uniform_real_distribution<double> U(0.0, 1.0);
        V sum(0.0), weight(1.0);
        for (int depth = 0; depth < 1000; ++depth) {
            sum += weight * direct(x, n, rng);
            // Cosine-weighted direction about n.
            const V t = std::abs(n.x) > 0.5 ? glm::normalize(glm::cross(n, V(0, 1, 0)))
                                            : glm::normalize(glm::cross(n, V(1, 0, 0)));
            const V b = glm::cross(n, t);
            const double u1 = U(rng), u2 = U(rng);
            const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
            const V d = glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b +
                                       std::sqrt(std::max(0.0, 1 - u1)) * n);
            V y;
            const int s = trace(x, d, y);
            if (s < 0) break;
            const V R = scene.surfaces[static_cast<std::size_t>(s)].reflectivity;
            const double p = std::max({R.x, R.y, R.z});
            if (U(rng) >= p) break;
            weight *= R / p;
            x = y;
            n = normal[static_cast<std::size_t>(s)];
        }
        return sum;
    }
};

} // namespace

int main(int argc, char** argv) {
    long paths = 200000;
    int batches = 8;
    std::string only, outPath, keepLit; // --black-except NAME: other surfaces' R = 0
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--paths" && a + 1 < argc)
            paths = std::stol(argv[++a]);
        else if (arg == "--batches" && a + 1 < argc)
            batches = std::stoi(argv[++a]);
        else if (arg == "--only" && a + 1 < argc)
            only = argv[++a];
        else if (arg == "--black-except" && a + 1 < argc)
            keepLit = argv[++a];
        else if (arg == "--out" && a + 1 < argc)
            outPath = argv[++a];
        else {
            std::cerr << "usage: radiosity_mc [--paths N] [--batches K] [--only NAME] [--out F]\n";
            return 2;
        }
    }
    rad::Scene scene = rad::cornellBox();
    if (!keepLit.empty())
        for (rad::Surface& f : scene.surfaces)
            if (f.name.find(keepLit) == std::string::npos) f.reflectivity = V(0.0);
    const Tracer tr(scene);
    std::ostringstream js;
    js << "{\"renderer\": \"radiosity_mc\", \"paths\": " << paths << ", \"batches\": " << batches
       << ", \"surfaces\": [";
    bool first = true;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const auto& f = scene.surfaces[s];
        if (!only.empty() && f.name.find(only) == std::string::npos) continue;
        std::vector<V> means;
        long accepted = 0, drawn = 0;
        for (int k = 0; k < batches; ++k) {
            std::mt19937_64 rng(1000003ull * (s + 1) + 7919ull * static_cast<unsigned>(k));
            V acc(0.0);
            long n = 0;
            while (n < paths / batches) {
                const V x = tr.samplePoint(static_cast<int>(s), rng);
                ++drawn;
                if (!tr.exposed(x, static_cast<int>(s))) continue;
                ++n;
                acc += f.emission + f.reflectivity * tr.irradiance(x, tr.normal[s], rng);
            }
            accepted += n;
            means.push_back(acc / static_cast<double>(n));
        }
        V mean(0.0), se(0.0);
        for (const V& m : means)
            mean += m;
        mean /= static_cast<double>(batches);
        for (const V& m : means)
            se += (m - mean) * (m - mean);
        se = glm::sqrt(se / static_cast<double>(batches - 1) / static_cast<double>(batches));
        std::printf("MC %-26s B = %.5f %.5f %.5f  se %.3f%% %.3f%% %.3f%%  exposed %.4f\n",
                    f.name.c_str(), mean.x, mean.y, mean.z, 100 * se.x / mean.x,
                    100 * se.y / mean.y, 100 * se.z / std::max(mean.z, 1e-12),
                    static_cast<double>(accepted) / static_cast<double>(drawn));
        std::fflush(stdout);
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "%s\n {\"name\": \"%s\", \"B\": [%.9g, %.9g, %.9g], \"stderr\": [%.9g, %.9g, "
                      "%.9g], \"exposed_fraction\": %.6f}",
                      first ? "" : ",", f.name.c_str(), mean.x, mean.y, mean.z, se.x, se.y, se.z,
                      static_cast<double>(accepted) / static_cast<double>(drawn));
        js << buf;
        first = false;
    }
    js << "\n]}\n";
    if (!outPath.empty()) std::ofstream(outPath) << js.str();
    return 0;
}
