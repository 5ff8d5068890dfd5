// OBJ load (issue 13 item 5): where the time of loadObjFile goes, against
// tinyobjloader's own parse of the same bytes, with the BVH build of the result for
// scale. Generates an 18 MB-class OBJ (78,400 triangles, v/vt/vn at 17 significant
// digits; not kept in the repository), then, in one run, repeats and takes medians of
// the calling thread's CPU time (the machine is shared: wall time would measure the
// queue). Writes docs/bench/obj_load.md (or into --out-dir DIR).
//
// Usage: obj_load_bench [--out-dir DIR] [--runs N] [--quick] [--once]
//   --once: one loadObjFile and nothing else (for valgrind --tool=callgrind).
#include "core/file_read.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/obj_file.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <istream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

using namespace wb::rt;

namespace {

double threadCpu() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a.empty() ? "unknown" : a + " " + b + " " + c;
}

std::string ms(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", 1e3 * s);
    return buf;
}

// tinyobjloader reads from a stream: the text already in memory, without a copy (as
// loadObjFile does).
struct MemoryBuf : std::streambuf {
    MemoryBuf(const char* b, std::size_t n) {
        char* p = const_cast<char*>(b); // read only
        setg(p, p, p + n);
    }
};

struct MeshFile {
    std::string path;
    int digits = 17;
    std::size_t bytes = 0, vertices = 0, triangles = 0;
};

// A bumpy sphere of `cols` × `rows` quads, two triangles each. Every row of quads has
// its own vertices (a seam per row, as exporters write meshes with UV islands), so
// there are about as many v/vt/vn records as triangles; every number is printed with
// `digits` significant digits (%.*g). 280 × 140 at 17 digits: 78,400 triangles, 18 MB.
MeshFile writeMesh(const std::string& path, int cols, int rows, int digits) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    const double pi = 3.14159265358979323846;
    MeshFile mf;
    mf.path = path;
    mf.digits = digits;
    char buf[256];
    auto put = [&](const char* cmd, int count, double a, double b, double c) {
        int n = std::snprintf(buf, sizeof buf, "%s %.*g %.*g", cmd, digits, a, digits, b);
        if (count == 3)
            n += std::snprintf(buf + n, sizeof buf - std::size_t(n), " %.*g", digits, c);
        buf[n++] = '\n';
        out.write(buf, n);
        mf.bytes += std::size_t(n);
    };
    const std::string head =
        "# obj_load_bench: bumpy sphere, " + std::to_string(2 * cols * rows) + " triangles\n";
    out << head;
    mf.bytes += head.size();
    for (int j = 0; j < rows; ++j)
        for (int jj = j; jj <= j + 1; ++jj)
            for (int i = 0; i <= cols; ++i) {
                const double u = 2 * pi * i / cols, v = pi * (jj + 0.25) / (rows + 0.5);
                const double r = 1 + 0.08 * std::sin(5 * u) * std::sin(4 * v);
                const double x = r * std::cos(u) * std::sin(v), y = r * std::cos(v),
                             z = r * std::sin(u) * std::sin(v);
                const double l = std::sqrt(x * x + y * y + z * z);
                put("v", 3, x, y, z);
                put("vt", 2, double(i) / cols, double(jj) / rows, 0);
                put("vn", 3, x / l, y / l, z / l);
                ++mf.vertices;
            }
    for (int j = 0; j < rows; ++j) {
        const int base = j * 2 * (cols + 1) + 1; // first vertex of the row's lower edge
        for (int i = 0; i < cols; ++i) {
            const int a = base + i, b = a + 1, c = a + cols + 1, d = c + 1;
            const int tri[2][3] = {{a, b, d}, {a, d, c}};
            for (const auto& t : tri) {
                const int n = std::snprintf(buf, sizeof buf, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", t[0],
                                            t[0], t[0], t[1], t[1], t[1], t[2], t[2], t[2]);
                out.write(buf, n);
                mf.bytes += std::size_t(n);
                ++mf.triangles;
            }
        }
    }
    return mf;
}

// Medians over the repeats, in seconds (thread CPU unless said).
struct Result {
    double read = 0, tinyMem = 0, tinyFile = 0, load = 0, loadWall = 0;
    ObjLoadTimes split; // loadObjFile's own split
    double bvh = 0;
    std::size_t prims = 0, tinyFaces = 0;
};

// One repeat is: the file read, tinyobjloader on those bytes, tinyobjloader reading the
// file itself, loadObjFile, and the BVH of its result; the steps alternate, so a change
// of load on the machine touches all of them alike.
bool measure(const MeshFile& mf, int runs, Result& res) {
    std::vector<double> read, tinyMem, tinyFile, load, loadWall, scan, parse, build, lread, bvh;
    for (int r = 0; r < runs; ++r) {
        // 1. The file into memory, as loadObjFile reads it.
        double c0 = threadCpu();
        std::string raw, why;
        if (!wb::readRegularFile(mf.path, kObjMaxBytes, raw, why)) {
            std::fprintf(stderr, "%s\n", why.c_str());
            return false;
        }
        read.push_back(threadCpu() - c0);
        // 2. tinyobjloader alone on those bytes (the call loadObjFile makes), and reading
        //    the file itself through its ifstream (the library used directly).
        {
            tinyobj::attrib_t at;
            std::vector<tinyobj::shape_t> shapes;
            std::vector<tinyobj::material_t> mats;
            std::string w, e;
            MemoryBuf buf(raw.data(), raw.size());
            std::istream in(&buf);
            c0 = threadCpu();
            tinyobj::LoadObj(&at, &shapes, &mats, &w, &e, &in, nullptr, false, false);
            tinyMem.push_back(threadCpu() - c0);
            res.tinyFaces = 0;
            for (const auto& s : shapes)
                res.tinyFaces += s.mesh.num_face_vertices.size();
        }
        {
            tinyobj::attrib_t at;
            std::vector<tinyobj::shape_t> shapes;
            std::vector<tinyobj::material_t> mats;
            std::string w, e;
            c0 = threadCpu();
            tinyobj::LoadObj(&at, &shapes, &mats, &w, &e, mf.path.c_str(), nullptr, false, false);
            tinyFile.push_back(threadCpu() - c0);
        }
        raw.clear();
        raw.shrink_to_fit();
        // 3. The whole loadObjFile, with its own split of the same call.
        ObjLoadReport rep;
        const auto w0 = std::chrono::steady_clock::now();
        c0 = threadCpu();
        SceneFile sf = loadObjFile(mf.path, &rep);
        load.push_back(threadCpu() - c0);
        loadWall.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
        lread.push_back(rep.times.read);
        scan.push_back(rep.times.scan);
        parse.push_back(rep.times.parse);
        build.push_back(rep.times.build);
        res.prims = sf.scene->primitives.size();
        // 4. The BVH of the result, one thread, for scale.
        BvhOptions one;
        one.buildThreads = 1;
        c0 = threadCpu();
        const Bvh b(sf.scene->primitives, one);
        bvh.push_back(threadCpu() - c0);
    }
    res.read = median(read);
    res.tinyMem = median(tinyMem);
    res.tinyFile = median(tinyFile);
    res.load = median(load);
    res.loadWall = median(loadWall);
    res.split.read = median(lread);
    res.split.scan = median(scan);
    res.split.parse = median(parse);
    res.split.build = median(build);
    res.bvh = median(bvh);
    return true;
}

std::string ratio(double a, double b) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f×", a / b);
    return buf;
}

} // namespace

int main(int argc, char** argv) {
    std::string outDir = WB_SOURCE_DIR "/docs/bench";
    const std::string workDir = WB_BINARY_DIR "/bench-out";
    int runs = 7, cols = 280, rows = 140;
    bool once = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--out-dir") && i + 1 < argc) {
            outDir = argv[++i];
        } else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (!std::strcmp(argv[i], "--quick")) {
            runs = 1;
            cols = 40;
            rows = 20;
        } else if (!std::strcmp(argv[i], "--once")) {
            once = true;
        } else {
            std::fprintf(stderr, "usage: %s [--out-dir DIR] [--runs N] [--quick] [--once]\n",
                         argv[0]);
            return 2;
        }
    }
    if (std::system(("mkdir -p '" + workDir + "' '" + outDir + "'").c_str()) != 0) return 1;
    const std::string load0 = loadAverage();
    const MeshFile mf = writeMesh(workDir + "/obj_load_bench.obj", cols, rows, 17);
    if (once) {
        const SceneFile sf = loadObjFile(mf.path);
        std::printf("%zu primitives\n", sf.scene->primitives.size());
        return 0;
    }
    // The same mesh at 9 digits (enough for a float, what many exporters write): how much
    // of tinyobjloader's time the long numbers cost.
    const MeshFile mf9 = writeMesh(workDir + "/obj_load_bench9.obj", cols, rows, 9);
    Result r, r9;
    if (!measure(mf, runs, r) || !measure(mf9, runs, r9)) return 1;
    const std::string load1 = loadAverage();

    std::ostringstream md;
    const std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    char mb[32], mb9[32];
    std::snprintf(mb, sizeof mb, "%.1f", double(mf.bytes) / 1e6);
    std::snprintf(mb9, sizeof mb9, "%.1f", double(mf9.bytes) / 1e6);
    md << "# OBJ load: where the time goes\n\n"
       << "Written by `obj_load_bench` (tests/bench/obj_load_bench.cpp), " << date
       << ". Issue 13 item 5: loading a large OBJ against tinyobjloader's own parse.\n\n"
       << "The file is generated by the bench (not kept in the repository): a bumpy sphere of "
       << mf.triangles << " triangles whose rows of quads have their own vertices, so "
       << mf.vertices
       << " `v`, `vt` and `vn` records, every number printed with 17 significant "
          "digits (`%.17g`), faces `f v/vt/vn`: "
       << mb << " MB. Every figure is the median of " << runs
       << " repeats of the calling thread's CPU time in one run of this program (one "
          "thread; the machine is a shared 2-core box, so CPU time, not wall time, except "
          "where said). Load average (1, 5, 15 min) at the start "
       << load0 << ", at the end " << load1 << ".\n\n"
       << "| step of loadObjFile | ms | share |\n|---|---:|---:|\n";
    auto row = [&](const char* what, double s) {
        char share[32];
        std::snprintf(share, sizeof share, "%.0f%%", 100 * s / r.load);
        md << "| " << what << " | " << ms(s) << " | " << share << " |\n";
    };
    row("1. read the file (`readRegularFile`)", r.split.read);
    row("2. pre-pass (`scanObj`: numbers, indices, lines)", r.split.scan);
    row("3. tinyobjloader `LoadObj` on the text in memory", r.split.parse);
    row("4. build: triangles, materials, view, light", r.split.build);
    row("**loadObjFile, whole**", r.load);
    md << "\nThe same bytes through the library alone, and the BVH of the result:\n\n"
       << "| measured on its own | ms | loadObjFile ÷ this |\n|---|---:|---:|\n"
       << "| tinyobjloader `LoadObj` from memory (the library's speed) | " << ms(r.tinyMem)
       << " | **" << ratio(r.load, r.tinyMem) << "** |\n"
       << "| tinyobjloader `LoadObj(path)` (reads the file itself) | " << ms(r.tinyFile) << " | "
       << ratio(r.load, r.tinyFile) << " |\n"
       << "| readRegularFile | " << ms(r.read) << " | |\n"
       << "| BVH build of the result (binned SAH + 4-wide collapse, one thread) | " << ms(r.bvh)
       << " | " << ratio(r.load, r.bvh) << " |\n"
       << "| loadObjFile, wall time | " << ms(r.loadWall) << " | |\n"
       << "\n"
       << r.prims << " primitives loaded (tinyobjloader: " << r.tinyFaces << " faces).\n\n"
       << "The same mesh printed with 9 significant digits (enough for a float; " << mb9
       << " MB), same method:\n\n"
       << "| 9 digits | ms |\n|---|---:|\n"
       << "| pre-pass | " << ms(r9.split.scan) << " |\n"
       << "| tinyobjloader `LoadObj` from memory | " << ms(r9.tinyMem) << " |\n"
       << "| loadObjFile, whole | " << ms(r9.load) << " (" << ratio(r9.load, r9.tinyMem)
       << " tinyobjloader's) |\n";
    const std::string out = outDir + "/obj_load.md";
    std::ofstream(out) << md.str();
    std::fputs(md.str().c_str(), stdout);
    std::printf("\nwritten %s\n", out.c_str());
    return 0;
}
