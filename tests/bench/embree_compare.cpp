#include "embree_compare.h"

#include "bench_scenes.h"

#include "core/raytrace/bvh.h"
#include "core/raytrace/bvh_slots.h"
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
#include <cstring>
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

// CPU time of every thread of the process (the 2-thread builds' CPU-time speed-up).
double processCpu() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
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

// N rays (1 for rtcIntersect1, 8 for rtcIntersect8), the lanes of `valid`.
void coneIntersect(const RTCIntersectFunctionNArguments* args) {
    const auto* c = static_cast<const Cones*>(args->geometryUserPtr);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    const unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i]) continue;
        Hit h;
        const Ray r = toRay(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i),
                            RTCRayN_org_z(ray, N, i), RTCRayN_dir_x(ray, N, i),
                            RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
        if (!c->cones[args->primID]->intersect(r, RTCRayN_tnear(ray, N, i),
                                               RTCRayN_tfar(ray, N, i), h))
            continue;
        RTCRayN_tfar(ray, N, i) = float(h.t);
        RTCHitN_Ng_x(hit, N, i) = float(h.outwardNormal.x);
        RTCHitN_Ng_y(hit, N, i) = float(h.outwardNormal.y);
        RTCHitN_Ng_z(hit, N, i) = float(h.outwardNormal.z);
        RTCHitN_u(hit, N, i) = RTCHitN_v(hit, N, i) = 0;
        RTCHitN_primID(hit, N, i) = args->primID;
        RTCHitN_geomID(hit, N, i) = args->geomID;
        RTCHitN_instID(hit, N, i, 0) = args->context->instID[0];
    }
}

void coneOccluded(const RTCOccludedFunctionNArguments* args) {
    const auto* c = static_cast<const Cones*>(args->geometryUserPtr);
    const unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i]) continue;
        Hit h;
        const Ray r = toRay(RTCRayN_org_x(args->ray, N, i), RTCRayN_org_y(args->ray, N, i),
                            RTCRayN_org_z(args->ray, N, i), RTCRayN_dir_x(args->ray, N, i),
                            RTCRayN_dir_y(args->ray, N, i), RTCRayN_dir_z(args->ray, N, i));
        if (c->cones[args->primID]->intersect(r, RTCRayN_tnear(args->ray, N, i),
                                              RTCRayN_tfar(args->ray, N, i), h))
            RTCRayN_tfar(args->ray, N, i) = -std::numeric_limits<float>::infinity();
    }
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    Cones cones;
    double buildS = 0;    // wall time
    double buildCpuS = 0; // CPU time of this thread (the whole build with threads=1)
    // The build is timed from the new scene on (the device, created first, is not part of
    // it). `config`: rtcNewDevice's, e.g. "threads=1".
    explicit EmbreeScene(const Scene& s, const char* config = "threads=1") {
        device = rtcNewDevice(config);
        const auto t0 = Clock::now();
        const double c0 = threadCpu();
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
        buildCpuS = threadCpu() - c0;
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
    BvhNodes nodes = BvhNodes::Float;
};

// The wide BVH's SIMD paths this CPU can run.
const std::vector<PathSpec>& pathSpecs() {
    static const std::vector<PathSpec> specs = [] {
        std::vector<PathSpec> v{{"SSE2 4-wide", 4, BvhSimd::Sse2}};
        if (__builtin_cpu_supports("avx2")) {
            v.push_back({"AVX2 4-wide", 4, BvhSimd::Avx2});
            v.push_back({"AVX2 8-wide", 8, BvhSimd::Avx2});
            v.push_back({"AVX2 8-wide quantised", 8, BvhSimd::Avx2, BvhNodes::Quantised});
        }
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) {
            v.push_back({"AVX-512 8-wide", 8, BvhSimd::Avx512});
            v.push_back({"AVX-512 8-wide quantised", 8, BvhSimd::Avx512, BvhNodes::Quantised});
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

std::string embreeSection(int size, int runs, const std::string& meshPath,
                          std::vector<EmbreeGoalRow>* goals) {
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
          "on the same rays. Builds: ours (BvhOptions::buildThreads 1 and 2) and Embree's "
          "(device threads=1 and 2, the device made before the clock starts) alternated, median of "
       << runs << " each. CPU time of the one thread; median of "
       << runs << " passes, ours and Embree's alternated.\n\n"
       << "| scene | BVH build ms ours / Embree: 1 thread (CPU) · 2 threads (wall) | eye M rays/s ours | binary | Embree | "
          "ours/Embree | "
          "shadow M "
          "rays/s ours | binary | Embree | ours/Embree | eye hits ours / Embree | occluded ours / "
          "Embree |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const std::vector<BenchScene> items = benchScenes(meshPath);
    std::ostringstream pathRows;   // the SIMD paths' table
    std::ostringstream packetRows; // the packets' table
    char buf0[640];
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
        defaultPath = std::string(bvh.stats().avx512 ? "AVX-512 " : bvh.stats().avx2 ? "AVX2 " : "SSE2 ") +
                      std::to_string(bvh.stats().width) + "-wide";
        // Every SIMD path this CPU has, forced: SSE2 4-wide, AVX2 4- and 8-wide.
        std::vector<std::unique_ptr<Bvh>> paths;
        for (const PathSpec& ps : pathSpecs()) {
            BvhOptions po;
            po.width = ps.width;
            po.simd = ps.simd;
            po.nodes = ps.nodes;
            paths.push_back(std::make_unique<Bvh>(sf.scene->primitives, po));
        }
        BvhOptions binOpt;
        binOpt.width = 2;
        Bvh bin(sf.scene->primitives, binOpt);
        EmbreeScene es(*sf.scene);
        // Builds: ours and Embree's alternated, medians of `runs`; one thread (CPU time of
        // this thread: BvhOptions::buildThreads 1, Embree threads=1) and two (wall time:
        // buildThreads 2, Embree threads=2).
        double ourB1 = 0, emB1 = 0, ourB2 = 0, emB2 = 0;
        {
            std::vector<double> o1, e1, o2, e2;
            for (int k = 0; k < runs; ++k) {
                BvhOptions b1;
                b1.buildThreads = 1;
                const double c0 = threadCpu();
                { Bvh t(sf.scene->primitives, b1); }
                o1.push_back(threadCpu() - c0);
                { EmbreeScene e(*sf.scene, "threads=1"); e1.push_back(e.buildCpuS); }
                BvhOptions b2;
                b2.buildThreads = 2;
                { Bvh t(sf.scene->primitives, b2); o2.push_back(t.stats().buildSeconds); }
                { EmbreeScene e(*sf.scene, "threads=2"); e2.push_back(e.buildS); }
            }
            ourB1 = median(o1);
            emB1 = median(e1);
            ourB2 = median(o2);
            emB2 = median(e2);
        }
        const LookAtCamera cam = sf.camera();
        std::vector<Ray> eye;
        for (int y = 0; y <= size; ++y)
            for (int x = 0; x <= size; ++x)
                eye.push_back(cam.rayAt(x, y, size, size));
        // Eye packets: 8 neighbouring corner rays of a row (the last of a row fewer).
        struct Span {
            std::size_t first;
            int n;
        };
        std::vector<Span> eyePackets;
        for (int y = 0; y <= size; ++y)
            for (int x = 0; x <= size; x += 8)
                eyePackets.push_back(
                    {std::size_t(y) * std::size_t(size + 1) + std::size_t(x), std::min(8, size + 1 - x)});
        // Shadow rays: per eye packet and light, the feelers of its rays that hit something
        // lit from that side, side by side (a shadow packet).
        std::vector<Segment> shadow;
        std::vector<Span> shadowPackets;
        long long ourHits = 0;
        for (const Span& sp : eyePackets) {
            Hit hs[8];
            bool hit[8];
            for (int j = 0; j < sp.n; ++j) {
                hit[j] = bvh.intersect(eye[sp.first + std::size_t(j)], 0,
                                       std::numeric_limits<double>::infinity(), hs[j]);
                ourHits += hit[j];
            }
            for (const Light& l : sf.scene->lights) {
                const std::size_t first = shadow.size();
                for (int j = 0; j < sp.n; ++j) {
                    if (!hit[j]) continue;
                    const Hit& h = hs[j];
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
                if (shadow.size() > first) shadowPackets.push_back({first, int(shadow.size() - first)});
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
        // Packets: ours (Bvh::intersectPacket / occludedPacket on the default path) and
        // Embree's rtcIntersect8 / rtcOccluded8 with the coherent-rays flag.
        long long ourPkHits = 0, ourPkOcc = 0, emPkHits = 0, emPkOcc = 0;
        auto ourEyePackets = [&] {
            ourPkHits = 0;
            double tMin[8], tMax[8];
            for (int j = 0; j < 8; ++j) {
                tMin[j] = 0;
                tMax[j] = std::numeric_limits<double>::infinity();
            }
            for (const Span& sp : eyePackets) {
                Hit h[8];
                ourPkHits += __builtin_popcount(
                    bvh.intersectPacket(&eye[sp.first], tMin, tMax, h, (1u << sp.n) - 1));
            }
        };
        auto ourShadowPackets = [&] {
            ourPkOcc = 0;
            Ray rays[8];
            double tMin[8], tMax[8];
            const Primitive* skip[8];
            for (const Span& sp : shadowPackets) {
                for (int j = 0; j < sp.n; ++j) {
                    const Segment& s = shadow[sp.first + std::size_t(j)];
                    rays[j] = s.ray;
                    tMin[j] = s.tMin;
                    tMax[j] = s.tMax;
                    skip[j] = s.skip;
                }
                ourPkOcc += __builtin_popcount(
                    bvh.occludedPacket(rays, tMin, tMax, skip, (1u << sp.n) - 1));
            }
        };
        RTCIntersectContext ctx8;
        rtcInitIntersectContext(&ctx8);
        ctx8.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        auto emEyePackets = [&] {
            emPkHits = 0;
            for (const Span& sp : eyePackets) {
                alignas(32) int valid[8];
                alignas(32) RTCRayHit8 rh;
                for (int j = 0; j < 8; ++j) {
                    valid[j] = j < sp.n ? -1 : 0;
                    const Ray& r = eye[sp.first + std::size_t(std::min(j, sp.n - 1))];
                    rh.ray.org_x[j] = float(r.origin.x);
                    rh.ray.org_y[j] = float(r.origin.y);
                    rh.ray.org_z[j] = float(r.origin.z);
                    rh.ray.dir_x[j] = float(r.direction.x);
                    rh.ray.dir_y[j] = float(r.direction.y);
                    rh.ray.dir_z[j] = float(r.direction.z);
                    rh.ray.tnear[j] = 0;
                    rh.ray.tfar[j] = std::numeric_limits<float>::infinity();
                    rh.ray.mask[j] = ~0u;
                    rh.ray.flags[j] = 0;
                    rh.ray.time[j] = 0;
                    rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
                    rh.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
                }
                rtcIntersect8(valid, es.scene, &ctx8, &rh);
                for (int j = 0; j < sp.n; ++j)
                    emPkHits += rh.hit.geomID[j] != RTC_INVALID_GEOMETRY_ID;
            }
        };
        auto emShadowPackets = [&] {
            emPkOcc = 0;
            for (const Span& sp : shadowPackets) {
                alignas(32) int valid[8];
                alignas(32) RTCRay8 r;
                for (int j = 0; j < 8; ++j) {
                    valid[j] = j < sp.n ? -1 : 0;
                    const Segment& s = shadow[sp.first + std::size_t(std::min(j, sp.n - 1))];
                    r.org_x[j] = float(s.ray.origin.x);
                    r.org_y[j] = float(s.ray.origin.y);
                    r.org_z[j] = float(s.ray.origin.z);
                    r.dir_x[j] = float(s.ray.direction.x);
                    r.dir_y[j] = float(s.ray.direction.y);
                    r.dir_z[j] = float(s.ray.direction.z);
                    const double scale = 1 + glm::length(s.ray.origin); // as the single pass
                    r.tnear[j] = float(std::max(s.tMin, 1e-4 * scale));
                    r.tfar[j] = float(s.tMax);
                    r.mask[j] = ~0u;
                    r.flags[j] = 0;
                    r.time[j] = 0;
                }
                rtcOccluded8(valid, es.scene, &ctx8, &r);
                for (int j = 0; j < sp.n; ++j)
                    emPkOcc += r.tfar[j] < 0;
            }
        };
        // Ours (default), binary, Embree, then the forced paths, then the packets:
        // alternated pass by pass.
        std::vector<std::function<void()>> eyeFs{eyePass(bvh), eyePass(bin), emEyePass};
        std::vector<long long> pathOcc(paths.size(), 0);
        std::vector<std::function<void()>> shadowFs{shadowPass(bvh, ourOcc),
                                                    shadowPass(bin, binOcc), emShadowPass};
        for (std::size_t k = 0; k < paths.size(); ++k) {
            eyeFs.push_back(eyePass(*paths[k]));
            shadowFs.push_back(shadowPass(*paths[k], pathOcc[k]));
        }
        const std::size_t kPk = eyeFs.size(); // the packet passes' index
        eyeFs.push_back(ourEyePackets);
        eyeFs.push_back(emEyePackets);
        shadowFs.push_back(ourShadowPackets);
        shadowFs.push_back(emShadowPackets);
        const std::vector<double> tEye = timeAlternated(runs, eyeFs);
        const std::vector<double> tShadow = timeAlternated(runs, shadowFs);
        if (ourPkHits != ourHits || ourPkOcc != ourOcc)
            std::fprintf(stderr, "%s: packets and single rays disagree\n", it.name.c_str());
        std::snprintf(buf0, sizeof buf0,
                      "| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | "
                      "%.2f | %.2f | %lld / %lld | %lld / %lld |\n",
                      it.name.c_str(), double(eye.size()) / tEye[0] / 1e6,
                      double(eye.size()) / tEye[kPk] / 1e6, double(eye.size()) / tEye[2] / 1e6,
                      double(eye.size()) / tEye[kPk + 1] / 1e6, tEye[kPk + 1] / tEye[kPk],
                      tEye[2] / tEye[kPk], double(shadow.size()) / tShadow[0] / 1e6,
                      double(shadow.size()) / tShadow[kPk] / 1e6,
                      double(shadow.size()) / tShadow[2] / 1e6,
                      double(shadow.size()) / tShadow[kPk + 1] / 1e6,
                      tShadow[kPk + 1] / tShadow[kPk], tShadow[2] / tShadow[kPk], ourPkHits,
                      emPkHits, ourPkOcc, emPkOcc);
        packetRows << buf0;
        if (goals)
            goals->push_back({it.name, tEye[2] / tEye[0], tShadow[2] / tShadow[0],
                              tEye[kPk + 1] / tEye[kPk], tEye[2] / tEye[kPk]});
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
            "| %s | %.2f / %.2f · %.2f / %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | "
            "%lld / %lld | %lld / %lld |\n",
            it.name.c_str(), ourB1 * 1e3, emB1 * 1e3, ourB2 * 1e3, emB2 * 1e3, ne / ourEye / 1e6,
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
        // Node bytes of the 8-wide float and quantised trees, and the default's layout.
        std::size_t floatBytes = 0, quantBytes = 0;
        for (std::size_t k = 0; k < paths.size(); ++k)
            if (paths[k]->stats().width == 8)
                (paths[k]->stats().quantised ? quantBytes : floatBytes) =
                    paths[k]->stats().nodeBytes;
        std::snprintf(buf, sizeof buf, " | %.1f / %.1f | %s |\n", double(floatBytes) / 1024,
                      double(quantBytes) / 1024, bvh.stats().quantised ? "quantised" : "float");
        pathRows << buf;
    }
    md << "\nThe SIMD paths, each forced (BvhOptions::width and simd), in the same alternated "
          "passes: ours/Embree for eye / shadow rays. The default above is "
       << defaultPath
       << " with the node layout of the last column. 'quantised': "
          "BvhNodes::Quantised, child boxes as 8-bit offsets in the node's box (128-byte nodes "
          "against 256).\n\n| scene";
    for (const PathSpec& ps : pathSpecs())
        md << " | " << ps.name;
    md << " | 8-wide node KB float / quantised | default nodes (BvhNodes::Auto) |\n|---";
    for (std::size_t k = 0; k < pathSpecs().size() + 2; ++k)
        md << "|---";
    md << "|\n" << pathRows.str();
    md << "\nPackets (issue 21), in the same alternated passes: eye rays 8 neighbouring corner "
          "rays of a row; shadow rays per 8 eye rays and light, the lit ones. Ours: "
          "Bvh::intersectPacket / occludedPacket on the default path (a shared walk with "
          "an interval test of the node for the packet, then each ray's own float test; "
          "leaves entered by 3+ rays test each sphere or triangle against all of them in "
          "the lanes; the exact double primitive code); single: Bvh::intersect / occluded "
          "ray by ray. "
          "Embree: rtcIntersect8 / rtcOccluded8 with RTC_INTERSECT_CONTEXT_FLAG_COHERENT, "
          "and rtcIntersect1 / rtcOccluded1. M rays/s, CPU time of the one thread.\n\n"
       << "| scene | eye ours single | ours packets | Embree single | Embree packets | ours/Embree "
          "packets | ours packets / Embree single | shadow ours single | ours packets | Embree "
          "single | Embree packets | ours/Embree packets | ours packets / Embree single | eye "
          "hits ours / Embree packets | occluded ours / Embree packets |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
       << packetRows.str();
    return md.str();
}

std::string embreeBuildSection(int runs, const std::string& meshPath) {
    // The builds alone (issue 21 item 4), every scene of the Embree table: ours and
    // Embree's alternated in every round, medians of `runs`. One thread: CPU time of this
    // thread from the call to the finished tree (ours: the Bvh constructor, its
    // destructor not counted; Embree: rtcNewScene .. rtcCommitScene, as above). Two
    // threads: wall time of the same, so the machine's other load counts.
    std::ostringstream md;
    md << "\n## Builds against Embree 3 (ours / Embree, alternated, median of " << runs
       << "). Tree: the wide tree ours builds against the one the full binary build collapses "
          "to (BvhOptions::fullBinary, the build before issue 21): wide nodes, the same slots "
          "(DFS of boxes and leaf ranges), SAH cost of the full binary tree, and the eye-ray "
          "walk (257² corner rays, Bvh::intersect, CPU time, median of the passes alternated).\n\n"
          "| scene | primitives | 1 thread CPU ms ours | Embree | ours/Embree | 2 threads wall "
          "ms ours | Embree | ours/Embree | ours 1→2 threads (1 thread CPU / 2 threads wall) | "
          "ours 1→2 threads from CPU time (2 × 1 thread CPU / CPU of both threads) | "
          "1 thread CPU ms, full binary build | wide nodes | same wide tree | SAH cost | eye walk "
          "ms "
          "ours | full binary build's tree |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const char* only = std::getenv("WB_EMBREE_SCENES");
    for (const BenchScene& it : benchScenes(meshPath)) {
        if (only && *only) {
            bool hit = false;
            std::stringstream parts(only);
            std::string part;
            while (std::getline(parts, part, ','))
                hit = hit || (!part.empty() && it.name.find(part) != std::string::npos);
            if (!hit) continue;
        }
        SceneFile sf = it.make();
        std::vector<double> o1, e1, o2, o2cpu, e2, f1;
        BvhStats st;
        for (int k = 0; k < runs; ++k) {
            BvhOptions b1;
            b1.buildThreads = 1;
            {
                const double c0 = threadCpu();
                Bvh t(sf.scene->primitives, b1);
                o1.push_back(threadCpu() - c0);
                st = t.stats();
            }
            {
                EmbreeScene e(*sf.scene, "threads=1");
                e1.push_back(e.buildCpuS);
            }
            BvhOptions b2;
            b2.buildThreads = 2;
            {
                const auto t0 = Clock::now();
                const double p0 = processCpu();
                Bvh t(sf.scene->primitives, b2);
                o2.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
                o2cpu.push_back(processCpu() - p0);
            }
            {
                EmbreeScene e(*sf.scene, "threads=2");
                e2.push_back(e.buildS);
            }
            BvhOptions bf;
            bf.buildThreads = 1;
            bf.fullBinary = true;
            {
                const double c0 = threadCpu();
                Bvh t(sf.scene->primitives, bf);
                f1.push_back(threadCpu() - c0);
            }
        }
        // The trees: ours and the full binary build's, slot for slot, and their walks.
        BvhOptions fo;
        fo.fullBinary = true;
        const Bvh ours(sf.scene->primitives), full(sf.scene->primitives, fo);
        const bool same = wideSlots(ours) == wideSlots(full);
        const LookAtCamera cam = sf.camera();
        std::vector<Ray> eye;
        for (int y = 0; y <= 256; ++y)
            for (int x = 0; x <= 256; ++x)
                eye.push_back(cam.rayAt(x, y, 256, 256));
        std::vector<double> wo, wf;
        long hitsO = 0, hitsF = 0;
        for (int k = 0; k < runs; ++k)
            for (const Bvh* b : {&ours, &full}) {
                long h = 0;
                const double c0 = threadCpu();
                for (const Ray& r : eye) {
                    Hit hit;
                    h += b->intersect(r, 1e-9, std::numeric_limits<double>::infinity(), hit);
                }
                (b == &ours ? wo : wf).push_back(threadCpu() - c0);
                (b == &ours ? hitsO : hitsF) = h;
            }
        const double a = median(o1), b = median(e1), c = median(o2), d = median(e2);
        char line[768];
        std::snprintf(
            line, sizeof line,
            "| %s | %zu | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %d / %d | "
            "%s | %.4f | %.2f | %.2f |\n",
            it.name.c_str(), st.primitives + st.unbounded, a * 1e3, b * 1e3, b > 0 ? a / b : 0.0,
            c * 1e3, d * 1e3, d > 0 ? c / d : 0.0, c > 0 ? a / c : 0.0,
            median(o2cpu) > 0 ? 2 * a / median(o2cpu) : 0.0, median(f1) * 1e3,
            ours.stats().wideNodes, full.stats().wideNodes, same && hitsO == hitsF ? "yes" : "NO",
            full.stats().sahCost, median(wo) * 1e3, median(wf) * 1e3);
        md << line;
        std::fputs(line, stderr);
    }
    return md.str();
}
