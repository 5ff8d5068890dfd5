// Lab 08's OpenGL hemicube (OSMesa, llvmpipe) against core's CPU hemicube: time per hemicube
// and error against the exact point-to-polygon form factor, for resolutions 16² ... 1024².
// Writes its section of docs/bench/radiosity.md between the markers
//   <!-- gl-hemicube:begin --> ... <!-- gl-hemicube:end -->
// (appended when missing; the rest of the file is core's bench report). Not a test: run
//   bin/radiosity_gl_bench [--write docs/bench/radiosity.md] [--quick]
//
// Error: a hemicube estimates the form factor from the patch CENTRE (a differential area) to
// each patch j, so its reference is pointToPolygon(centre_i, n_i, P_j), exact for unoccluded
// pairs. Two configurations of core's closed-form tests: parallel unit plates 1 apart and
// perpendicular unit plates sharing an edge (near pairs: the hard case), each meshed into
// 4×4 patches; every (i on one plate, j on the other) pair counts.
// Time: per hemicube (5 faces drawn, read back, accumulated) on a room with a box meshed into
// ~2,800 patches, median over patches; the CPU hemicube (castItemBuffer on all cores + the
// same accumulate) on the same patches in the same run, for the ratio.
#include "gl_hemicube.h"

#include "core/radiosity/closed_forms.h"
#include "core/radiosity/hemicube.h"
#include "core/radiosity/mesh.h"
#include "core/radiosity/patch_bvh.h"

#include "common/headless_context.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using glm::dvec3;
namespace rad = wb::rad;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of the calling thread, ms: the one-thread timings (issue 21 compares one CPU thread
// against the GL path; on a shared machine wall time counts the other engineers' work too).
double threadMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

// CPU time of the whole process, ms: the GL hemicube's cost over llvmpipe's threads.
double processMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

rad::Surface quad(dvec3 o, dvec3 a, dvec3 b, const std::string& name, double e = 0.0) {
    rad::Surface s;
    s.vertices = {o, o + a, o + a + b, o + b};
    s.reflectivity = dvec3(0.5);
    s.emission = dvec3(e);
    s.name = name;
    return s;
}

// Two unit plates facing each other 1 apart (z = 0 up, z = 1 down).
rad::Scene parallelPlates() {
    rad::Scene sc;
    sc.surfaces = {quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "bottom", 1.0),
                   quad({0, 0, 1}, {0, 1, 0}, {1, 0, 0}, "top")};
    return sc;
}

// Two unit plates sharing the edge x = 0, z = 0 at a right angle (floor facing +z, wall +x).
rad::Scene perpendicularPlates() {
    rad::Scene sc;
    sc.surfaces = {quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "floor", 1.0),
                   quad({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, "wall")};
    return sc;
}

// A room 1 × 0.94 × 1.07 (normals inward) with a floating box (normals outward).
rad::Scene roomWithBox() {
    const dvec3 X(1, 0, 0), Y(0, 0.9373, 0), Z(0, 0, 1.0719);
    rad::Scene sc;
    sc.closed = true;
    sc.surfaces = {quad({0, 0, 0}, Z, X, "floor"), quad(Y, X, Z, "ceiling", 1.0),
                   quad({0, 0, 0}, Y, Z, "wall"),  quad(X, Z, Y, "wall"),
                   quad({0, 0, 0}, X, Y, "wall"),  quad(Z, Y, X, "wall")};
    const dvec3 lo(0.3071, 0.2563, 0.3389), hi(0.6237, 0.5117, 0.7043), d = hi - lo;
    const dvec3 dx(d.x, 0, 0), dy(0, d.y, 0), dz(0, 0, d.z);
    sc.surfaces.push_back(quad(lo, dx, dz, "box"));
    sc.surfaces.push_back(quad({lo.x, hi.y, lo.z}, dz, dx, "box"));
    sc.surfaces.push_back(quad(lo, dz, dy, "box"));
    sc.surfaces.push_back(quad({hi.x, lo.y, lo.z}, dy, dz, "box"));
    sc.surfaces.push_back(quad(lo, dy, dx, "box"));
    sc.surfaces.push_back(quad({lo.x, lo.y, hi.z}, dx, dy, "box"));
    return sc;
}

void upload(wb::GlHemicube& gl, const rad::PatchMesh& mesh) {
    std::vector<glm::vec3> verts;
    std::vector<uint32_t> items;
    wb::patchFans(mesh, verts, items);
    std::string err;
    if (!gl.setGeometry(verts, items, err)) {
        std::fprintf(stderr, "%s\n", err.c_str());
        std::exit(1);
    }
}

double sceneRadius(const rad::PatchMesh& mesh) {
    dvec3 lo(1e300), hi(-1e300);
    for (const dvec3& v : mesh.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    return 0.5 * glm::length(hi - lo);
}

bool glRow(wb::GlHemicube& gl, const rad::PatchMesh& mesh, const rad::DeltaFormFactors& table,
           int i, double nearDist, rad::ItemBuffer& items, std::vector<float>& row) {
    std::string err;
    if (!gl.render(rad::hemicubeFrame(mesh, i), table.resolution, nearDist, items, err)) {
        std::fprintf(stderr, "%s\n", err.c_str());
        return false;
    }
    rad::accumulate(items, table, int(mesh.patches.size()), i, row);
    return true;
}

struct ErrorStats {
    double maxErr = 0, sumErr = 0;
    long long pairs = 0;
};

// Max and mean |F_gl − F_exact| over the pairs (i on surface 0, j on surface 1) and back.
ErrorStats closedFormError(wb::GlHemicube& gl, const rad::PatchMesh& mesh,
                           const rad::DeltaFormFactors& table) {
    upload(gl, mesh);
    ErrorStats e;
    rad::ItemBuffer items;
    std::vector<float> row;
    const double nearDist = wb::GlHemicube::kNearFraction * sceneRadius(mesh);
    for (int i = 0; i < int(mesh.patches.size()); ++i) {
        if (!glRow(gl, mesh, table, i, nearDist, items, row)) std::exit(1);
        const rad::Patch& pi = mesh.patches[size_t(i)];
        for (int j = 0; j < int(mesh.patches.size()); ++j) {
            if (mesh.patches[size_t(j)].surface == pi.surface) continue;
            const double exact = rad::pointToPolygon(pi.centre, pi.normal, mesh.cornersOf(j));
            const double err = std::abs(double(row[size_t(j)]) - exact);
            e.maxErr = std::max(e.maxErr, err);
            e.sumErr += err;
            ++e.pairs;
        }
    }
    return e;
}

// castItemBuffer as it was before issue 21 (one BVH ray per pixel, rows on all cores): the
// CPU hemicube's single-ray path, timed beside the packet one in the same run.
void castOneByOne(const rad::PatchBvh& bvh, const rad::HemicubeFrame& frame, int res,
                  rad::ItemBuffer& out) {
    if (out.resolution != res) out.resize(res);
    const int half = res / 2;
    tbb::parallel_for(0, res + 4 * half, [&](int r) {
        rad::HemicubeFace f = rad::HemicubeFace::Top;
        int row = r;
        if (r >= res) {
            f = static_cast<rad::HemicubeFace>(1 + (r - res) / half);
            row = (r - res) % half;
        }
        auto& face = out.faces[static_cast<std::size_t>(f)];
        for (int col = 0; col < res; ++col)
            face[std::size_t(row) * std::size_t(res) + std::size_t(col)] = bvh.nearestPatch(
                frame.origin, glm::normalize(rad::pixelDirection(frame, res, f, col, row)), 0.0,
                std::numeric_limits<double>::infinity());
    });
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

std::string replaceSection(const std::string& doc, const std::string& section) {
    const std::string begin = "<!-- gl-hemicube:begin -->", end = "<!-- gl-hemicube:end -->";
    const size_t a = doc.find(begin), b = doc.find(end);
    if (a == std::string::npos || b == std::string::npos || b < a)
        return doc + (doc.empty() || doc.back() == '\n' ? "" : "\n") + "\n" + begin + "\n" +
               section + end + "\n";
    return doc.substr(0, a + begin.size()) + "\n" + section + doc.substr(b);
}

} // namespace

int main(int argc, char** argv) {
    std::string writePath;
    bool quick = false;
    int onlyRes = 0; // --res N: that resolution alone, 9 patches (issue 21: the 128² goal)
    int cpuOnly = 0; // --cpu-only K: K passes of the one-thread CPU hemicube alone (for a profiler)
    for (int a = 1; a < argc; ++a) {
        if (!std::strcmp(argv[a], "--write") && a + 1 < argc) writePath = argv[++a];
        else if (!std::strcmp(argv[a], "--quick")) quick = true;
        else if (!std::strcmp(argv[a], "--res") && a + 1 < argc)
            onlyRes = std::atoi(argv[++a]);
        else if (!std::strcmp(argv[a], "--cpu-only") && a + 1 < argc)
            cpuOnly = std::atoi(argv[++a]);
        else {
            std::fprintf(stderr,
                         "usage: %s [--write docs/bench/radiosity.md] [--quick] [--res N] [--cpu-only K]\n",
                         argv[0]);
            return 2;
        }
    }
    if (cpuOnly > 0) {
        const rad::PatchMesh room = rad::meshScene(roomWithBox(), {0.05});
        const rad::PatchBvh bvh(room);
        const int res = onlyRes > 0 ? onlyRes : 128, n = int(room.patches.size());
        rad::ItemBuffer items;
        const double c0 = threadMs();
        for (int pass = 0; pass < cpuOnly; ++pass)
            for (int k = 0; k < 9; ++k)
                rad::castItemBuffer(bvh, rad::hemicubeFrame(room, int((long long)(k) * n / 9 + n / 18)),
                                    res, items, false);
        std::printf("one-thread CPU hemicube %d²: %.3f ms a patch (CPU time, %d passes of 9)\n", res,
                    (threadMs() - c0) / (9.0 * cpuOnly), cpuOnly);
        return 0;
    }
    const wb::HeadlessContext context(64, 64); // the hemicube draws into its own framebuffer
    if (!context.ok()) {
        std::fprintf(stderr, "radiosity_gl_bench: %s\n", context.error().c_str());
        return 1;
    }
    const rad::PatchMesh parallel = rad::meshScene(parallelPlates(), {0.25});
    const rad::PatchMesh perpendicular = rad::meshScene(perpendicularPlates(), {0.25});
    const rad::PatchMesh room = rad::meshScene(roomWithBox(), {0.05});
    const rad::PatchBvh roomBvh(room);
    const double roomNear = wb::GlHemicube::kNearFraction * sceneRadius(room);
    wb::GlHemicube gl;

    std::vector<int> resolutions = {16, 32, 64, 128, 256, 512, 1024};
    if (quick) resolutions = {16, 64};
    if (onlyRes > 0) resolutions = {onlyRes};
    const int timedPatches = quick ? 3 : 9;
    std::ostringstream md;
    char line[512];
    md << "## GL hemicube (lab 08): time against error\n\n"
       << "`bin/radiosity_gl_bench --write docs/bench/radiosity.md` (tests/bench/radiosity_gl_bench.cpp). "
       << "The hemicube of labs/08-radiosity/gl_hemicube.cpp drawn by OSMesa (Mesa llvmpipe, "
       << std::thread::hardware_concurrency() << " cores, shared and noisy machine) into core's "
       << "item buffer, against core's CPU hemicube (each face rasterised by the edge planes through the eye, the watertight test only where triangles compete (issue 21), TBB over the faces on all cores; 'one thread': the same on the calling thread, its CPU time; 'packets': the BVH walk, 8 neighbouring pixels of a row as one packet, as before; 'one ray per pixel': one BVH ray each; all rows required equal) in "
       << "the same run. Error: |F − F_exact| with F_exact the point-to-polygon form factor from "
       << "the patch centre (what a hemicube estimates), over every pair of patches on two unit "
       << "plates meshed 4×4: parallel 1 apart, and perpendicular with a common edge (near "
       << "pairs). Time: per hemicube (5 faces drawn, read back, accumulated) on a room with a "
       << "box, " << room.patches.size() << " patches, median of " << timedPatches
       << " patches. |GL − CPU|: largest difference of a row entry between the two hemicubes on "
       << "those rows (edge pixels decided differently, see tests/render/radiosity_gl_hemicube_test.cpp).\n\n"
       << "| hemicube | GL ms | CPU ms | GL/CPU | CPU ms, one thread (CPU time) | GL/CPU one thread "
          "| GL CPU time, all threads, ms | parallel max err | mean | perpendicular max err "
          "| mean | max \\|GL − CPU\\| | CPU packets ms | packets, one thread | CPU ms, one ray per pixel |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::printf("%6s %9s %9s %7s %12s %12s %12s %12s %12s %9s %9s %9s %9s %7s %9s %7s\n", "res", "GL ms",
                "CPU ms", "GL/CPU", "par max", "par mean", "perp max", "perp mean", "|GL-CPU|",
                "CPU 1by1", "packets", "CPU 1thr", "pack 1thr", "GL/1thr", "GL cpu", "GLc/1t");
    for (int res : resolutions) {
        const rad::DeltaFormFactors table = rad::deltaFormFactors(res);
        const ErrorStats par = closedFormError(gl, parallel, table);
        const ErrorStats perp = closedFormError(gl, perpendicular, table);
        upload(gl, room);
        rad::ItemBuffer items, cpuItems;
        std::vector<float> rowGl, rowCpu;
        std::vector<double> glTimes, glCpuTimes, cpuTimes, singleTimes, packetTimes, cpu1Times,
            packet1Times;
        rad::ItemBuffer singleItems;
        std::vector<float> rowSingle;
        double maxDiff = 0;
        const int n = int(room.patches.size());
        glRow(gl, room, table, 0, roomNear, items, rowGl); // warm-up: target allocation
        rad::ItemBuffer packetItems;
        std::vector<float> rowPacket;
        // --res N: the patches three times, every method alternated patch by patch (medians
        // of 27); the one-by-one rays (slow) on the first pass only.
        const int passes = onlyRes > 0 ? 3 : 1;
        for (int pass = 0; pass < passes; ++pass)
        for (int k = 0; k < timedPatches; ++k) {
            const int i = int((long long)(k) * n / timedPatches + n / (2 * timedPatches));
            const rad::HemicubeFrame frame = rad::hemicubeFrame(room, i);
            const double g0 = processMs();
            auto t0 = std::chrono::steady_clock::now();
            if (!glRow(gl, room, table, i, roomNear, items, rowGl)) return 1;
            glTimes.push_back(secondsSince(t0) * 1e3);
            glCpuTimes.push_back(processMs() - g0);
            t0 = std::chrono::steady_clock::now();
            rad::castItemBuffer(roomBvh, frame, res, cpuItems, true);
            rad::accumulate(cpuItems, table, n, i, rowCpu);
            cpuTimes.push_back(secondsSince(t0) * 1e3);
            t0 = std::chrono::steady_clock::now();
            rad::castItemBuffer(roomBvh, frame, res, packetItems, true, rad::HemicubeCast::Packets);
            rad::accumulate(packetItems, table, n, i, rowPacket);
            packetTimes.push_back(secondsSince(t0) * 1e3);
            double c0 = threadMs();
            rad::castItemBuffer(roomBvh, frame, res, cpuItems, false);
            rad::accumulate(cpuItems, table, n, i, rowCpu);
            cpu1Times.push_back(threadMs() - c0);
            c0 = threadMs();
            rad::castItemBuffer(roomBvh, frame, res, packetItems, false, rad::HemicubeCast::Packets);
            rad::accumulate(packetItems, table, n, i, rowPacket);
            packet1Times.push_back(threadMs() - c0);
            if (rowPacket != rowCpu) {
                std::fprintf(stderr, "raster and packets differ at patch %d\n", i);
                return 1;
            }
            if (pass > 0) continue;
            t0 = std::chrono::steady_clock::now();
            castOneByOne(roomBvh, frame, res, singleItems);
            rad::accumulate(singleItems, table, n, i, rowSingle);
            singleTimes.push_back(secondsSince(t0) * 1e3);
            if (rowSingle != rowCpu) {
                std::fprintf(stderr, "raster and one ray per pixel differ at patch %d\n", i);
                return 1;
            }
            for (int j = 0; j < n; ++j)
                maxDiff = std::max(maxDiff, std::abs(double(rowGl[size_t(j)]) - double(rowCpu[size_t(j)])));
        }
        const double g = median(glTimes), c = median(cpuTimes), c1 = median(singleTimes);
        const double pk = median(packetTimes), t1 = median(cpu1Times), p1 = median(packet1Times);
        const double gc = median(glCpuTimes);
        std::printf("%6d %9.2f %9.2f %7.2f %12.3e %12.3e %12.3e %12.3e %12.3e %9.2f %9.2f %9.2f %9.2f %7.2f %9.2f %7.2f\n",
                    res, g, c, g / c, par.maxErr, par.sumErr / double(par.pairs), perp.maxErr,
                    perp.sumErr / double(perp.pairs), maxDiff, c1, pk, t1, p1, g / t1, gc, gc / t1);
        std::fflush(stdout);
        std::snprintf(line, sizeof line,
                      "| %d² | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2e | %.2e | %.2e | %.2e | %.1e | %.2f | %.2f | %.2f |\n",
                      res, g, c, g / c, t1, g / t1, gc, par.maxErr, par.sumErr / double(par.pairs),
                      perp.maxErr, perp.sumErr / double(perp.pairs), maxDiff, pk, p1, c1);
        md << line;
    }
    double load[3] = {0, 0, 0};
    if (FILE* f = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
        std::fclose(f);
    }
    std::snprintf(line, sizeof line,
                  "\nLoad average at the end of the run: %.1f %.1f %.1f (1, 5, 15 min) on %u cores: "
                  "single timings are noisy, compare rows of one run. ",
                  load[0], load[1], load[2], std::thread::hardware_concurrency());
    md << line
       << "Reading: the GL hemicube costs a roughly fixed few ms per hemicube up to 256² (five "
          "viewports, each drawing every patch twice - front faces in item colours, back faces "
          "black - plus the read-back and the accumulation), and its cost grows with the pixels "
          "only beyond. The CPU hemicube (issue 21, since branch rthemi) rasterises: per "
          "hemicube every triangle's edge planes through the eye, per face a whole-face test, a "
          "box and per-row spans, per pixel three edge functions; the watertight test runs only "
          "where two triangles compete or a pixel lies within the margin of an edge (~5% of "
          "the pixels at 128²). So it has a fixed part per triangle (~5,500 here) and a part per "
          "pixel, and it gives exactly the ids of one BVH ray per pixel (the bench requires the "
          "rows equal). The packet walk it replaced grew with the pixels from the start. Both "
          "hemicubes sample the same pixel centres: the error columns are the GL rows', and the "
          "CPU rows agree to the last column. The "
          "error falls as 1/res² for the parallel plates (a smooth integrand: pixel aliasing "
          "and the midpoint rule) and only as ~1/res for the perpendicular plates, whose near "
          "pairs put a patch edge across the hemicube at grazing angles.\n\n";
    if (!writePath.empty()) {
        std::string doc;
        {
            std::ifstream in(writePath);
            std::stringstream ss;
            ss << in.rdbuf();
            doc = ss.str();
        }
        std::ofstream out(writePath);
        out << replaceSection(doc, md.str());
        if (!out) {
            std::fprintf(stderr, "radiosity_gl_bench: cannot write %s\n", writePath.c_str());
            return 1;
        }
        std::printf("wrote the GL hemicube section of %s\n", writePath.c_str());
    } else {
        std::fputs(md.str().c_str(), stdout);
    }
    return 0;
}
