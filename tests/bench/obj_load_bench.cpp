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
    std::size_t bytes = 0, vertices = 0, triangles = 0;
};

// A bumpy sphere of `cols` × `rows` quads, two triangles each. Every row of quads has
// its own vertices (a seam per row, as exporters write meshes with UV islands), so
// there are about as many v/vt/vn records as triangles; %.17g prints every double with
// 17 significant digits. 280 × 140 gives 78,400 triangles and about 18 MB.
MeshFile writeMesh(const std::string& path, int cols, int rows) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    const double pi = 3.14159265358979323846;
    MeshFile mf;
    mf.path = path;
    char buf[256];
    auto put = [&](const char* f, double a, double b, double c) {
        const int n = std::snprintf(buf, sizeof buf, f, a, b, c);
        out.write(buf, n);
        mf.bytes += std::size_t(n);
    };
    auto text = [&](const std::string& s) {
        out << s;
        mf.bytes += s.size();
    };
    text("# obj_load_bench: bumpy sphere, " + std::to_string(2 * cols * rows) + " triangles\n");
    for (int j = 0; j < rows; ++j)
        for (int jj = j; jj <= j + 1; ++jj)
            for (int i = 0; i <= cols; ++i) {
                const double u = 2 * pi * i / cols, v = pi * (jj + 0.25) / (rows + 0.5);
                const double r = 1 + 0.08 * std::sin(5 * u) * std::sin(4 * v);
                const double x = r * std::cos(u) * std::sin(v), y = r * std::cos(v),
                             z = r * std::sin(u) * std::sin(v);
                const double l = std::sqrt(x * x + y * y + z * z);
                put("v %.17g %.17g %.17g\n", x, y, z);
                put("vt %.17g %.17g\n", double(i) / cols, double(jj) / rows, 0);
                put("vn %.17g %.17g %.17g\n", x / l, y / l, z / l);
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

struct Times {
    std::vector<double> read, tinyMem, tinyFile, load, scan, parse, build, loadRead, bvh;
};

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
    const MeshFile mf = writeMesh(workDir + "/obj_load_bench.obj", cols, rows);
    if (once) {
        const SceneFile sf = loadObjFile(mf.path);
        std::printf("%zu primitives\n", sf.scene->primitives.size());
        return 0;
    }

    Times t;
    std::size_t tinyTriangles = 0, prims = 0;
    for (int r = 0; r < runs; ++r) {
        // 1. The file into memory, as loadObjFile reads it.
        double c0 = threadCpu();
        std::string raw, why;
        if (!wb::readRegularFile(mf.path, kObjMaxBytes, raw, why)) {
            std::fprintf(stderr, "%s\n", why.c_str());
            return 1;
        }
        t.read.push_back(threadCpu() - c0);
        // 2. tinyobjloader alone on those bytes (what loadObjFile calls), and reading the
        //    file itself through its ifstream (the library used directly).
        {
            tinyobj::attrib_t at;
            std::vector<tinyobj::shape_t> shapes;
            std::vector<tinyobj::material_t> mats;
            std::string w, e;
            MemoryBuf buf(raw.data(), raw.size());
            std::istream in(&buf);
            c0 = threadCpu();
            tinyobj::LoadObj(&at, &shapes, &mats, &w, &e, &in, nullptr, false, false);
            t.tinyMem.push_back(threadCpu() - c0);
            tinyTriangles = 0;
            for (const auto& s : shapes)
                tinyTriangles += s.mesh.num_face_vertices.size();
        }
        {
            tinyobj::attrib_t at;
            std::vector<tinyobj::shape_t> shapes;
            std::vector<tinyobj::material_t> mats;
            std::string w, e;
            c0 = threadCpu();
            tinyobj::LoadObj(&at, &shapes, &mats, &w, &e, mf.path.c_str(), nullptr, false, false);
            t.tinyFile.push_back(threadCpu() - c0);
        }
        raw.clear();
        raw.shrink_to_fit();
        // 3. The whole loadObjFile, with its own split of the same call.
        ObjLoadReport rep;
        c0 = threadCpu();
        SceneFile sf = loadObjFile(mf.path, &rep);
        t.load.push_back(threadCpu() - c0);
        t.loadRead.push_back(rep.times.read);
        t.scan.push_back(rep.times.scan);
        t.parse.push_back(rep.times.parse);
        t.build.push_back(rep.times.build);
        prims = sf.scene->primitives.size();
        // 4. The BVH of the result, one thread, for scale.
        BvhOptions one;
        one.buildThreads = 1;
        c0 = threadCpu();
        const Bvh bvh(sf.scene->primitives, one);
        t.bvh.push_back(threadCpu() - c0);
    }
    const std::string load1 = loadAverage();

    const double load = median(t.load), tiny = median(t.tinyMem);
    std::ostringstream md;
    const std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    char mb[32];
    std::snprintf(mb, sizeof mb, "%.1f", double(mf.bytes) / 1e6);
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
          "thread; the machine is a shared 2-core box, so CPU time and not wall time). Load "
          "average (1, 5, 15 min) at the start "
       << load0 << ", at the end " << load1 << ".\n\n"
       << "| step | ms | share of loadObjFile |\n|---|---:|---:|\n";
    auto row = [&](const char* what, double s) {
        char share[32];
        std::snprintf(share, sizeof share, "%.0f%%", 100 * s / load);
        md << "| " << what << " | " << ms(s) << " | " << share << " |\n";
    };
    row("1. read the file (`readRegularFile`)", median(t.loadRead));
    row("2. pre-pass (`scanObj`: numbers, indices, lines)", median(t.scan));
    row("3. tinyobjloader `LoadObj` on the text in memory", median(t.parse));
    row("4. build: triangles, materials, view, light", median(t.build));
    row("**loadObjFile, whole**", load);
    md << "\nThe same bytes through the library alone, and the BVH of the result:\n\n"
       << "| measured separately | ms | against loadObjFile |\n|---|---:|---:|\n";
    auto ref = [&](const char* what, double s) {
        char ratio[32];
        std::snprintf(ratio, sizeof ratio, "%.2f×", load / s);
        md << "| " << what << " | " << ms(s) << " | loadObjFile is " << ratio << " |\n";
    };
    ref("readRegularFile alone", median(t.read));
    ref("tinyobjloader `LoadObj` from memory (the library's speed)", tiny);
    ref("tinyobjloader `LoadObj(path)` (reads the file itself)", median(t.tinyFile));
    ref("BVH build of the result (one thread)", median(t.bvh));
    md << "\n" << prims << " primitives loaded (tinyobjloader: " << tinyTriangles << " faces).\n";
    const std::string out = outDir + "/obj_load.md";
    std::ofstream(out) << md.str();
    std::fputs(md.str().c_str(), stdout);
    std::printf("\nwritten %s\n", out.c_str());
    return 0;
}
