#include "embree_compare.h"

#include "bench_scenes.h"

#include "core/raytrace/bvh.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/obj_file.h"
#include "core/raytrace/spd.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

using namespace wb::rt;

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

template <class F> double timeMedian(int runs, F&& f) {
    std::vector<double> t;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = Clock::now();
        f();
        t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }
    return median(t);
}

// Medians of `runs` passes of each function, the functions taking turns in every round
// (so a burst of other load on the shared machine hits all of them alike).
// Times are CPU time of this thread (single-ray calls run here), not wall time: the
// shared machine's load would otherwise dominate.
double threadCpu() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::vector<double> timeAlternated(int runs, const std::vector<std::function<void()>>& fs) {
    std::vector<std::vector<double>> t(fs.size());
    for (int i = 0; i < runs; ++i)
        for (std::size_t k = 0; k < fs.size(); ++k) {
            const double t0 = threadCpu();
            fs[k]();
            t[k].push_back(threadCpu() - t0);
        }
    std::vector<double> m;
    for (auto& v : t)
        m.push_back(median(v));
    return m;
}

struct Cones {
    std::vector<const Cone*> cones;
};

void coneBounds(const RTCBoundsFunctionArguments* args) {
    const auto* c = static_cast<const Cones*>(args->geometryUserPtr);
    const Aabb b = c->cones[args->primID]->bounds();
    RTCBounds* o = args->bounds_o;
    o->lower_x = std::nextafter(float(b.lo.x), -1e30f);
    o->lower_y = std::nextafter(float(b.lo.y), -1e30f);
    o->lower_z = std::nextafter(float(b.lo.z), -1e30f);
    o->upper_x = std::nextafter(float(b.hi.x), 1e30f);
    o->upper_y = std::nextafter(float(b.hi.y), 1e30f);
    o->upper_z = std::nextafter(float(b.hi.z), 1e30f);
}

Ray toRay(float ox, float oy, float oz, float dx, float dy, float dz) {
    Ray r;
    r.origin = {ox, oy, oz};
    r.direction = glm::normalize(glm::dvec3(dx, dy, dz));
    return r;
}

void coneIntersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* c = static_cast<const Cones*>(args->geometryUserPtr);
    RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(args->rayhit); // N == 1 (rtcIntersect1)
    Hit h;
    const Ray r = toRay(rh->ray.org_x, rh->ray.org_y, rh->ray.org_z, rh->ray.dir_x, rh->ray.dir_y,
                        rh->ray.dir_z);
    if (!c->cones[args->primID]->intersect(r, rh->ray.tnear, rh->ray.tfar, h)) return;
    rh->ray.tfar = float(h.t);
    rh->hit.Ng_x = float(h.outwardNormal.x);
    rh->hit.Ng_y = float(h.outwardNormal.y);
    rh->hit.Ng_z = float(h.outwardNormal.z);
    rh->hit.u = rh->hit.v = 0;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
}

void coneOccluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* c = static_cast<const Cones*>(args->geometryUserPtr);
    RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
    Hit h;
    const Ray r = toRay(ray->org_x, ray->org_y, ray->org_z, ray->dir_x, ray->dir_y, ray->dir_z);
    if (c->cones[args->primID]->intersect(r, ray->tnear, ray->tfar, h))
        ray->tfar = -std::numeric_limits<float>::infinity();
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    Cones cones;
    double buildS = 0;
    explicit EmbreeScene(const Scene& s) {
        const auto t0 = Clock::now();
        device = rtcNewDevice("threads=1");
        scene = rtcNewScene(device);
        std::vector<const Sphere*> spheres;
        std::vector<const Triangle*> tris;
        for (const auto& p : s.primitives) {
            if (auto* sp = dynamic_cast<const Sphere*>(p.get()))
                spheres.push_back(sp);
            else if (auto* t = dynamic_cast<const Triangle*>(p.get()))
                tris.push_back(t);
            else if (auto* c = dynamic_cast<const Cone*>(p.get()))
                cones.cones.push_back(c);
        }
        if (!spheres.empty()) {
            RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                        4 * sizeof(float), spheres.size()));
            for (std::size_t i = 0; i < spheres.size(); ++i) {
                v[4 * i] = float(spheres[i]->centre.x);
                v[4 * i + 1] = float(spheres[i]->centre.y);
                v[4 * i + 2] = float(spheres[i]->centre.z);
                v[4 * i + 3] = float(spheres[i]->radius);
            }
            rtcCommitGeometry(g);
            rtcAttachGeometry(scene, g);
            rtcReleaseGeometry(g);
        }
        if (!tris.empty()) {
            RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        3 * sizeof(float), 3 * tris.size()));
            auto* ix = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris.size()));
            for (std::size_t i = 0; i < tris.size(); ++i) {
                const glm::dvec3 p[3] = {tris[i]->v0, tris[i]->v1, tris[i]->v2};
                for (int k = 0; k < 3; ++k) {
                    v[9 * i + 3 * size_t(k)] = float(p[k].x);
                    v[9 * i + 3 * size_t(k) + 1] = float(p[k].y);
                    v[9 * i + 3 * size_t(k) + 2] = float(p[k].z);
                    ix[3 * i + size_t(k)] = unsigned(3 * i + size_t(k));
                }
            }
            rtcCommitGeometry(g);
            rtcAttachGeometry(scene, g);
            rtcReleaseGeometry(g);
        }
        if (!cones.cones.empty()) {
            RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
            rtcSetGeometryUserPrimitiveCount(g, unsigned(cones.cones.size()));
            rtcSetGeometryUserData(g, &cones);
            rtcSetGeometryBoundsFunction(g, coneBounds, nullptr);
            rtcSetGeometryIntersectFunction(g, coneIntersect);
            rtcSetGeometryOccludedFunction(g, coneOccluded);
            rtcCommitGeometry(g);
            rtcAttachGeometry(scene, g);
            rtcReleaseGeometry(g);
        }
        rtcCommitScene(scene);
        buildS = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

struct PathSpec {
    const char* name;
    int width;
    BvhSimd simd;
};

// The wide BVH's SIMD paths this CPU can run.
const std::vector<PathSpec>& pathSpecs() {
    static const std::vector<PathSpec> specs = [] {
        std::vector<PathSpec> v{{"SSE2 4-wide", 4, BvhSimd::Sse2}};
        if (__builtin_cpu_supports("avx2")) {
            v.push_back({"AVX2 4-wide", 4, BvhSimd::Avx2});
            v.push_back({"AVX2 8-wide", 8, BvhSimd::Avx2});
        }
        return v;
    }();
    return specs;
}

struct Segment {
    Ray ray;
    double tMin, tMax;
    const Primitive* skip; // the flat primitive the ray leaves (issue 21), else null
};

} // namespace

std::string embreeSection(int size, int runs, const std::string& meshPath) {
    std::ostringstream md;
    md << "\n## Against Embree 3 (one thread, the same rays)\n\n"
       << "Eye rays: the " << (size + 1)
       << "² corner rays, nearest hit. Shadow rays: from each eye "
          "hit (offset off the surface as the tracer does) to every light on the lit side, any "
          "hit. "
          "Embree: spheres as RTC_GEOMETRY_TYPE_SPHERE_POINT, triangles native, cones/cylinders as "
          "user geometry calling our exact double intersection; Embree traverses in float. Ours: "
          "the wide float BVH with exact double primitive tests (Bvh::intersect / "
          "Bvh::occluded); 'binary' is the binary double-box tree of before (BvhOptions::width 2) "
          "on the same rays. CPU time of the one thread; median of "
       << runs << " passes, ours and Embree's alternated.\n\n"
       << "| scene | BVH build ms ours / Embree | eye M rays/s ours | binary | Embree | "
          "ours/Embree | "
          "shadow M "
          "rays/s ours | binary | Embree | ours/Embree | eye hits ours / Embree | occluded ours / "
          "Embree |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const std::vector<BenchScene> items = benchScenes(meshPath);
    std::ostringstream pathRows; // the SIMD paths' table
    std::string defaultPath;
    // WB_EMBREE_SCENES="balls 4,mesh": only the scenes whose names contain one of the
    // comma-separated parts (while tuning or profiling).
    const char* only = std::getenv("WB_EMBREE_SCENES");
    auto selected = [&](const std::string& name) {
        if (!only || !*only) return true;
        std::stringstream parts(only);
        std::string part;
        while (std::getline(parts, part, ','))
            if (!part.empty() && name.find(part) != std::string::npos) return true;
        return false;
    };
    for (const BenchScene& it : items) {
        if (!selected(it.name)) continue;
        std::fprintf(stderr, "embree: %s\n", it.name.c_str());
        SceneFile sf = it.make();
        Bvh bvh(sf.scene->primitives); // the default path
        defaultPath = std::string(bvh.stats().avx2 ? "AVX2 " : "SSE2 ") +
                      std::to_string(bvh.stats().width) + "-wide";
        // Every SIMD path this CPU has, forced: SSE2 4-wide, AVX2 4- and 8-wide.
        std::vector<std::unique_ptr<Bvh>> paths;
        for (const PathSpec& ps : pathSpecs()) {
            BvhOptions po;
            po.width = ps.width;
            po.simd = ps.simd;
            paths.push_back(std::make_unique<Bvh>(sf.scene->primitives, po));
        }
        BvhOptions binOpt;
        binOpt.width = 2;
        Bvh bin(sf.scene->primitives, binOpt);
        EmbreeScene es(*sf.scene);
        const LookAtCamera cam = sf.camera();
        std::vector<Ray> eye;
        for (int y = 0; y <= size; ++y)
            for (int x = 0; x <= size; ++x)
                eye.push_back(cam.rayAt(x, y, size, size));
        std::vector<Segment> shadow;
        long long ourHits = 0;
        for (const Ray& r : eye) {
            Hit h;
            if (!bvh.intersect(r, 0, std::numeric_limits<double>::infinity(), h)) continue;
            ++ourHits;
            for (const Light& l : sf.scene->lights) {
                const glm::dvec3 v = l.position - h.point;
                const double d = glm::length(v);
                const glm::dvec3 dir = v / d;
                if (glm::dot(dir, h.normal) <= 0) continue;
                Segment s;
                s.ray.origin = offsetRayOrigin(h.point, h.normal);
                s.ray.direction = dir;
                s.tMin = 0;
                s.tMax = d;
                s.skip = h.primitive->planar() ? h.primitive : nullptr;
                shadow.push_back(s);
            }
        }
        long long sink = 0;
        auto eyePass = [&](const Bvh& b) {
            return [&] {
                for (const Ray& r : eye) {
                    Hit h;
                    sink += b.intersect(r, 0, std::numeric_limits<double>::infinity(), h);
                }
            };
        };
        long long ourOcc = 0, binOcc = 0;
        auto shadowPass = [&](const Bvh& b, long long& occ) {
            return [&] {
                occ = 0;
                for (const Segment& s : shadow)
                    occ += b.occluded(s.ray, s.tMin, s.tMax, s.skip);
            };
        };
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        long long emHits = 0;
        auto emEyePass = [&] {
            emHits = 0;
            for (const Ray& r : eye) {
                RTCRayHit rh;
                rh.ray.org_x = float(r.origin.x);
                rh.ray.org_y = float(r.origin.y);
                rh.ray.org_z = float(r.origin.z);
                rh.ray.dir_x = float(r.direction.x);
                rh.ray.dir_y = float(r.direction.y);
                rh.ray.dir_z = float(r.direction.z);
                rh.ray.tnear = 0;
                rh.ray.tfar = std::numeric_limits<float>::infinity();
                rh.ray.mask = ~0u;
                rh.ray.flags = 0;
                rh.ray.time = 0;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(es.scene, &ctx, &rh);
                emHits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        };
        long long emOcc = 0;
        auto emShadowPass = [&] {
            emOcc = 0;
            for (const Segment& s : shadow) {
                RTCRay r;
                r.org_x = float(s.ray.origin.x);
                r.org_y = float(s.ray.origin.y);
                r.org_z = float(s.ray.origin.z);
                r.dir_x = float(s.ray.direction.x);
                r.dir_y = float(s.ray.direction.y);
                r.dir_z = float(s.ray.direction.z);
                // Embree traverses in float: the double offset of the origin is lost when it is
                // rounded to float, so the shadow ray starts a relative 1e-4 away instead
                // (what Embree's own tutorials do) or it would hit its own surface.
                const double scale = 1 + glm::length(s.ray.origin);
                r.tnear = float(std::max(s.tMin, 1e-4 * scale));
                r.tfar = float(s.tMax);
                r.mask = ~0u;
                r.flags = 0;
                r.time = 0;
                rtcOccluded1(es.scene, &ctx, &r);
                emOcc += r.tfar < 0;
            }
        };
        // Ours (default), binary, Embree, then the forced paths: alternated pass by pass.
        std::vector<std::function<void()>> eyeFs{eyePass(bvh), eyePass(bin), emEyePass};
        std::vector<long long> pathOcc(paths.size(), 0);
        std::vector<std::function<void()>> shadowFs{shadowPass(bvh, ourOcc),
                                                    shadowPass(bin, binOcc), emShadowPass};
        for (std::size_t k = 0; k < paths.size(); ++k) {
            eyeFs.push_back(eyePass(*paths[k]));
            shadowFs.push_back(shadowPass(*paths[k], pathOcc[k]));
        }
        const std::vector<double> tEye = timeAlternated(runs, eyeFs);
        const std::vector<double> tShadow = timeAlternated(runs, shadowFs);
        for (long long occ : pathOcc)
            if (occ != ourOcc)
                std::fprintf(stderr, "%s: the SIMD paths disagree on occlusion\n", it.name.c_str());
        if (binOcc != ourOcc)
            std::fprintf(stderr, "%s: binary and wide BVH disagree on occlusion\n",
                         it.name.c_str());
        const double ourEye = tEye[0], binEye = tEye[1], emEye = tEye[2];
        const double ourShadow = tShadow[0], binShadow = tShadow[1], emShadow = tShadow[2];
        if (sink < 0) std::puts("");
        const double ne = double(eye.size()), ns = double(shadow.size());
        char buf[512];
        std::snprintf(
            buf, sizeof buf,
            "| %s | %.2f / %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %lld / "
            "%lld | %lld / %lld |\n",
            it.name.c_str(), bvh.stats().buildSeconds * 1e3, es.buildS * 1e3, ne / ourEye / 1e6,
            ne / binEye / 1e6, ne / emEye / 1e6, emEye / ourEye, ns / ourShadow / 1e6,
            ns / binShadow / 1e6, ns / emShadow / 1e6, emShadow / ourShadow, ourHits, emHits,
            ourOcc, emOcc);
        md << buf;
        pathRows << "| " << it.name;
        for (std::size_t k = 0; k < paths.size(); ++k) {
            std::snprintf(buf, sizeof buf, " | %.2f / %.2f", emEye / tEye[3 + k],
                          emShadow / tShadow[3 + k]);
            pathRows << buf;
        }
        pathRows << " |\n";
    }
    md << "\nThe SIMD paths, each forced (BvhOptions::width and simd), in the same alternated "
          "passes: ours/Embree for eye / shadow rays. The default above is "
       << defaultPath << ".\n\n| scene";
    for (const PathSpec& ps : pathSpecs())
        md << " | " << ps.name;
    md << " |\n|---";
    for (std::size_t k = 0; k < pathSpecs().size(); ++k)
        md << "|---";
    md << "|\n" << pathRows.str();
    return md.str();
}
