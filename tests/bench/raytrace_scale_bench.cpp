// Ray tracer at scale (issue 6): speed against error, in one run of this program.
// SPD rules: 512×512 with eye rays through the pixel corners (513² rays), maximum
// depth 5, setup (scene + BVH build) and tracing timed apart. For one sphere, two
// spheres, balls 2–4, jacks 2–4 and a 9,248-triangle OBJ mesh: BVH build time, frame
// time with 1 thread and with all threads (median of several runs), ray counts, rays
// per second, primary-ray traversal throughput; the brute-force crossover; the binned
// SAH build rate; the image error of every speed option against the full-depth,
// no-cut-off double reference. Writes docs/bench/raytrace.md and raytrace.png (or
// into --out-dir DIR). With -DWORKBENCH_EMBREE=ON the same eye and shadow rays go
// through Embree 3 too.
//
// Usage: raytrace_scale_bench [--out-dir DIR] [--quick] [--runs N] [--embree-only] [--build-only]
//                             [--frames-only [--scene NAME]]
// --frames-only prints the frames' times to stdout (no report; NAME: scenes whose name
// contains it, or several such parts separated by commas), for measuring the shading and
// the thread scaling while working on them.
#include "bench_scenes.h"
#include "core/image.h"
#include "core/raytrace/bvh.h"
#include "core/raytrace/obj_file.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/spd.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"
#ifdef WB_EMBREE
#include "embree_compare.h"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

using namespace wb::rt;

namespace {

using Clock = std::chrono::steady_clock;

// CPU time of the calling thread: what one-thread figures use. On this shared 2-core
// machine (load averages of 5-20 while other engineers build) wall time of a
// single-threaded loop measures the queue more than the code.
double threadCpu() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// CPU time of every thread of the process.
double processCpu() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double seconds(Clock::time_point a) {
    return std::chrono::duration<double>(Clock::now() - a).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Options {
    std::string outDir = WB_SOURCE_DIR "/docs/bench";
    std::string workDir = WB_BINARY_DIR "/bench-out";
    int runs = 5;          // frames per measurement; the median is reported
    int size = 512;        // image size (SPD: 512)
    bool traversal = true; // measure the traversal-only rate too (--frames-only skips it)
};

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

std::string withCommas(long long v) {
    std::string s = std::to_string(v), out;
    int n = 0;
    for (auto it = s.rbegin(); it != s.rend(); ++it) {
        if (n && n % 3 == 0) out.insert(out.begin(), ',');
        out.insert(out.begin(), *it);
        ++n;
    }
    return out;
}

// A 9,248-triangle bumpy sphere (68×68 grid, two triangles a cell, with vertex
// normals), written as OBJ so the bench loads it through tinyobjloader. Two runs
// of one build share the directory: each writes its own file and renames it into
// place, so neither ever reads the other's half-written mesh (one run aborted so).
std::string writeMesh(const std::string& dir) {
    const std::string path = dir + "/bumpy_sphere.obj";
    const std::string tmp = path + "." + std::to_string(::getpid()) + ".tmp";
    std::ofstream out(tmp);
    const int n = 68;
    const double pi = 3.14159265358979323846;
    auto pos = [&](int i, int j) {
        const double u = 2 * pi * i / n, v = pi * (j + 0.5) / (n + 0.0);
        const double r = 1 + 0.08 * std::sin(5 * u) * std::sin(4 * v);
        return glm::dvec3(r * std::cos(u) * std::sin(v), r * std::cos(v),
                          r * std::sin(u) * std::sin(v));
    };
    out << "# bumpy sphere, " << 2 * n * (n - 1) << " triangles\n";
    out.precision(9);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 p = pos(i, j);
            out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        }
    auto id = [&](int i, int j) { return (j * n + (i % n)) + 1; };
    int tris = 0;
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i < n; ++i) {
            out << "f " << id(i, j) << ' ' << id(i + 1, j) << ' ' << id(i + 1, j + 1) << '\n';
            out << "f " << id(i, j) << ' ' << id(i + 1, j + 1) << ' ' << id(i, j + 1) << '\n';
            tris += 2;
        }
    // Cap the two poles' rings with fans so the mesh is closed: n triangles each.
    out << "v 0 1 0\nv 0 -1 0\n";
    const int top = n * n + 1, bottom = n * n + 2;
    for (int i = 0; i < n; ++i) {
        out << "f " << top << ' ' << id(i + 1, 0) << ' ' << id(i, 0) << '\n';
        out << "f " << bottom << ' ' << id(i, n - 1) << ' ' << id(i + 1, n - 1) << '\n';
        tris += 2;
    }
    (void)tris;
    out.close();
    if (!out || std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::fprintf(stderr, "raytrace_scale_bench: cannot write %s\n", path.c_str());
        std::exit(1);
    }
    return path;
}

struct FrameResult {
    double setupS = 0, buildS = 0, frame1 = 0, frameN = 0;
    double frame1Single = 0; // one thread, eye rays one by one (ParallelRenderOptions::packets off)
    double cpuN = 0;         // CPU time of all threads of the process during the all-threads frame
    ParallelRenderStats stats;
    double traversal1 = 0; // M primary rays/s, closest hit only, 1 thread
    std::size_t prims = 0;
    int depth = 0, nodes = 0;
    bool bvh = false;
};

double traversalRate(const Scene& scene, const LookAtCamera& cam, int size, int runs) {
    // Closest hit of the 513² eye rays, no shading, one thread.
    std::vector<double> t;
    long long hits = 0;
    for (int r = 0; r < runs; ++r) {
        const double t0 = threadCpu();
        hits = 0;
        for (int y = 0; y <= size; ++y)
            for (int x = 0; x <= size; ++x) {
                Hit h;
                hits += scene.intersect(cam.rayAt(x, y, size, size), 0.0, 1e300, h);
            }
        t.push_back(threadCpu() - t0);
    }
    if (hits < 0) std::puts(""); // keep the loop observable
    return double(size + 1) * double(size + 1) / median(t) / 1e6;
}

FrameResult measure(const BenchScene& bs, const Options& o, bool quickRuns) {
    FrameResult r;
    const auto t0 = Clock::now();
    SceneFile sf = bs.make();
    auto bvh = makeAggregate(*sf.scene);
    sf.scene->setAggregate(bvh.get());
    r.setupS = seconds(t0);
    r.buildS = bvh ? bvh->stats().buildSeconds : 0.0;
    r.bvh = bool(bvh);
    r.prims = sf.scene->primitives.size();
    if (bvh) {
        r.depth = bvh->stats().maxDepth;
        r.nodes = bvh->stats().nodes;
    }
    const LookAtCamera cam = sf.camera();
    PhongModel model;
    ParallelRenderOptions opt;
    opt.cornerRays = true;
    // SPD "maximum depth 5" counts the eye ray as level 1: four reflections, our
    // maxDepth 4 (which reproduces the SPD README's ray counts, see docs/raytrace-scale.md).
    opt.trace.maxDepth = 4;
    // One-thread and all-thread frames alternated, so a disturbance of the shared machine
    // falls on both alike; frames under 0.1 s get three times the repeats (a 3 ms hiccup
    // is a fifth of a 16 ms frame: the mesh's speed-up read 1.69 in one run, 1.94-2.03 in
    // five others of the same code).
    int runs = quickRuns ? 3 : o.runs;
    std::vector<double> t1, tN, cpu, t1Single;
    auto frame = [&](int threads, bool packets = true) {
        opt.threads = threads;
        opt.packets = packets;
        ParallelRenderStats st;
        // One thread: the arena of 1 runs the tiles on this thread, so its CPU time.
        const double c0 = threadCpu(), p0 = processCpu();
        renderParallel(*sf.scene, cam, model, o.size, o.size, opt, &st);
        if (threads == 1) {
            (packets ? t1 : t1Single).push_back(threadCpu() - c0);
        } else {
            tN.push_back(st.seconds);
            cpu.push_back(processCpu() - p0);
        }
        r.stats = st;
    };
    for (int i = 0; i < runs; ++i) {
        frame(1);
        if (i == 0 && !quickRuns && t1[0] < 0.1) runs *= 3;
        frame(hardwareThreads());
        frame(1, false); // the single-ray eye path, forced (issue 21)
    }
    r.frame1 = median(t1);
    r.frame1Single = median(t1Single);
    r.frameN = median(tN);
    r.cpuN = median(cpu);
    if (o.traversal) r.traversal1 = traversalRate(*sf.scene, cam, o.size, quickRuns ? 1 : 3);
    return r;
}

// Speed-against-error rows on one scene.
struct ErrorRow {
    std::string option;
    double frameS = 0;
    int maxDiff = 0;
    double meanDiff = 0;
    int series = 0; // 0 reference, 1 depth, 2 weight cut-off, 3 binary tree, 4 brute force
    long long reflection = 0, shadow = 0; // ray counts of the frame
};

// The speed-against-error plot with gnuplot (pngcairo): the rows as CSV next to the
// report, a script, and gnuplot run on it. Frame time (x) against mean error (y); one
// series per option kind, the depth and cut-off series joined from the reference.
bool plotWithGnuplot(const std::vector<ErrorRow>& rows, const std::string& dir,
                     const std::string& what) {
    {
        std::ofstream csv(dir + "/raytrace_error.csv");
        csv << "option,series,frame_ms,mean_diff,max_diff\n";
        for (const ErrorRow& r : rows)
            csv << '"' << r.option << "\"," << r.series << ',' << fmt("%.2f", r.frameS * 1e3) << ','
                << fmt("%.4f", r.meanDiff) << ',' << r.maxDiff << '\n';
    }
    std::ofstream gp(dir + "/raytrace.gp");
    gp << "# Generated by raytrace_scale_bench: gnuplot raytrace.gp (in this directory)\n"
          "set terminal pngcairo size 800,500 font 'DejaVu Sans,10'\n"
          "set output 'raytrace.png'\n"
          "set datafile separator ','\n"
          "set title 'Ray tracer speed against error ("
       << what
       << ", all threads)'\n"
          "set xlabel 'frame time, ms'\nset ylabel 'mean |difference|, 8-bit levels'\n"
          "set key top right\nset grid\nset yrange [-0.5:*]\n"
          "plot 'raytrace_error.csv' every ::1 using ($2==0||$2==1 ? $3 : 1/0):($2==0||$2==1 ? $4 "
          ": "
          "1/0) with linespoints lc rgb 'red' pt 7 title 'depth limit 5..0', \\\n"
          "     '' every ::1 using ($2==0||$2==2 ? $3 : 1/0):($2==0||$2==2 ? $4 : 1/0) with "
          "linespoints lc rgb 'blue' pt 5 title 'weight cut-off', \\\n"
          "     '' every ::1 using ($2==3 ? $3 : 1/0):($2==3 ? $4 : 1/0) with points lc rgb "
          "'dark-green' pt 9 ps 1.5 title 'binary double-box tree', \\\n"
          "     '' every ::1 using ($2==0 ? $3 : 1/0):($2==0 ? $4 : 1/0) with points lc rgb "
          "'black' pt 7 ps 1.5 title 'reference (default wide tree)'\n";
    gp.close();
    const std::string cmd = "cd '" + dir + "' && gnuplot raytrace.gp";
    return std::system(cmd.c_str()) == 0;
}

// The machine's load: the bench shares its cores with whatever else runs.
std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a.empty() ? "unknown" : a + " " + b + " " + c;
}

} // namespace

namespace {

// Issue 21 item 4: what this machine gives two threads at the minute of a 2-thread build.
// On the shared 2-core machine the wall-clock speed-up of a build moves with the other
// processes (0.1 to 1.99 in a day); a loop with no serial part, run beside each build the
// same way (1 thread: CPU time; N threads: wall time in an N-thread arena, as the build),
// shows what any code could have had then. Two loops: one of arithmetic alone (no memory
// traffic), and one that streams memory as a partition does (the build is memory-bound).
struct Ceiling {
    double compute = 0, memory = 0; // 1-thread CPU / N-thread wall of each loop
};

// 64 blocks of 4 independent multiply-add chains each, in registers.
double computeBlock(std::size_t iterations, std::size_t block) {
    double a = 1.0 + 1e-9 * double(block), b = a + 0.25, c = a + 0.5, d = a + 0.75;
    for (std::size_t i = 0; i < iterations; ++i) {
        a = a * 0.999999 + 1e-7;
        b = b * 0.999999 + 1e-7;
        c = c * 0.999999 + 1e-7;
        d = d * 0.999999 + 1e-7;
    }
    return a + b + c + d;
}

// A partition-like pass over an array of n 32-byte records (the build's references): each
// block of 4096 read once and written to the two ends of its place in the other array by
// a branchless choice on one of its floats, as the build's scatter does.
struct Rec {
    float lo[3];
    std::uint32_t index;
    float hi[3];
    float zero;
};
constexpr std::size_t kCeilingBlock = 4096;
void partitionBlock(const Rec* in, Rec* out, std::size_t n) {
    Rec *l = out, *r = out + n;
    for (std::size_t i = 0; i < n; ++i) {
        const bool left = in[i].lo[0] < 0.5f;
        Rec* dst = left ? l : r - 1;
        *dst = in[i];
        l += left;
        r -= !left;
    }
}

struct CeilingLoops {
    std::vector<Rec> a, b;
    std::size_t computeIterations = 1, passes = 1;
    double sink = 0;
    explicit CeilingLoops(std::size_t n) : a(std::max<std::size_t>(n, 1)), b(a.size()) {
        std::mt19937 g(11);
        std::uniform_real_distribution<float> u(0, 1);
        for (std::size_t i = 0; i < a.size(); ++i)
            a[i] = Rec{{u(g), u(g), u(g)}, std::uint32_t(i), {u(g), u(g), u(g)}, 0};
        b = a;
    }
    static constexpr std::size_t kComputeBlocks = 64;
    void compute(int threads) {
        if (threads == 1) {
            for (std::size_t k = 0; k < kComputeBlocks; ++k)
                sink += computeBlock(computeIterations, k);
            return;
        }
        std::vector<double> part(kComputeBlocks);
        tbb::task_arena(threads).execute([&] {
            tbb::parallel_for(std::size_t(0), kComputeBlocks,
                              [&](std::size_t k) { part[k] = computeBlock(computeIterations, k); });
        });
        for (const double v : part)
            sink += v;
    }
    void memory(int threads) {
        const std::size_t n = a.size(), blocks = (n + kCeilingBlock - 1) / kCeilingBlock;
        auto pass = [&](std::size_t k) {
            const std::size_t at = k * kCeilingBlock, len = std::min(kCeilingBlock, n - at);
            partitionBlock(a.data() + at, b.data() + at, len);
        };
        // One arena for all passes: made per pass, its start-up alone (not memory) held the
        // small rows' 2-thread loop below 1.
        auto passes1 = [&] {
            for (std::size_t p = 0; p < passes; ++p) {
                if (threads == 1) {
                    for (std::size_t k = 0; k < blocks; ++k)
                        pass(k);
                } else {
                    tbb::parallel_for(std::size_t(0), blocks, pass);
                }
                a.swap(b);
            }
        };
        if (threads == 1)
            passes1();
        else
            tbb::task_arena(threads).execute(passes1);
        sink += double(a[n / 2].lo[0]);
    }
    // Sizes both loops to about half the 1-thread build's CPU time `target`.
    void calibrate(double target) {
        computeIterations = 1 << 12;
        double c0 = threadCpu();
        compute(1);
        const double tc = std::max(threadCpu() - c0, 1e-6);
        computeIterations =
            std::max<std::size_t>(1, std::size_t(double(computeIterations) * 0.5 * target / tc));
        passes = 1;
        memory(1); // the pages touched
        c0 = threadCpu();
        memory(1);
        const double tm = std::max(threadCpu() - c0, 1e-6);
        passes = std::size_t(std::clamp(0.5 * target / tm, 1.0, 64.0) + 0.5);
    }
    // Each loop once with one thread (CPU time) and once with `threads` (wall time).
    template <class F> double speedUp(F&& loop, int threads) {
        const double c0 = threadCpu();
        loop(1);
        const double one = threadCpu() - c0;
        const auto w0 = Clock::now();
        loop(threads);
        return one / std::max(seconds(w0), 1e-9);
    }
    double computeSpeedUp(int threads) {
        return speedUp([this](int t) { compute(t); }, threads);
    }
    double memorySpeedUp(int threads) {
        return speedUp([this](int t) { memory(t); }, threads);
    }
};

} // namespace

// The binned SAH build rate (BVH construction alone, as Bvh reports it).
static std::string buildRateSection(bool quick) {
    std::ostringstream md;
    const int threads = hardwareThreads();
    md << "\n## Binned SAH build rate\n\nWhole BVH construction as Bvh reports it (float boxes, "
          "binned SAH binary tree, then the collapse into the default wide tree (8-wide with AVX2, "
          "else 4) with its leaf arrays, its subtrees collapsed as parallel tasks; the width-2 "
          "column builds the binary tree of double boxes "
          "alone, so the difference is the collapse). 1 thread: BvhOptions::buildThreads 1, "
          "CPU time; "
       << threads
       << " threads: the parallel build (nodes over 16,384 primitives binned and partitioned "
          "in blocks by TBB tasks, subtrees over 2048 primitives split into TBB tasks), "
          "wall time. "
          "Median of 5 builds each, alternated. Ceilings (issue 21): right after a row's "
          "builds (run between them, they moved the builds' own times), two loops with no "
          "serial part run the same way (1 thread: CPU time; "
       << threads
       << " threads: wall time in a task arena of that many threads, as the build): 64 blocks "
          "of multiply-add chains in registers (compute), and partition-like passes over an "
          "array of 32-byte records as large as the build's references (memory: each block "
          "of 4096 read once and written to both ends of its place in a second array); each "
          "about half a 1-thread build long. A ceiling is that loop's speed-up, median of 5: "
          "what this machine gave two threads at that minute. Speed-up over a ceiling: the "
          "build's speed-up over that ceiling. SAH cost: BvhStats::sahCost of the binary tree "
          "as built (root area 1; the same tree for any thread count; since issue 21 the wide "
          "build stops at the subtrees the collapse makes one leaf, so binary nodes and SAH "
          "cost are of that shorter tree: the wide tree is the same, see --build-embree).\n\n"
          "| input | primitives | build ms, 1 thread | M primitives/s, 1 thread | binary tree "
          "alone "
          "(width 2) ms, 1 thread "
          "| build ms, "
       << threads
       << " threads | M primitives/s | speed-up | speed-up from CPU time (threads × 1-thread "
          "CPU / CPU of all threads) | ceiling: compute loop | ceiling: memory loop | speed-up "
          "over the compute ceiling | speed-up over the memory ceiling | binary nodes | wide "
          "nodes | depth | SAH cost |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    auto row = [&](const std::string& name, const std::vector<std::unique_ptr<Primitive>>& prims) {
        std::vector<double> t1, tn, tc, tp, cc, cm;
        BvhStats st;
        for (int r = 0; r < 5; ++r) {
            BvhOptions one;
            one.buildThreads = 1;
            const double c0 = threadCpu();
            Bvh b1(prims, one);
            t1.push_back(threadCpu() - c0);
            BvhOptions two = one;
            two.width = 2;
            const double c1 = threadCpu();
            Bvh b2(prims, two);
            tc.push_back(threadCpu() - c1);
            BvhOptions all;
            all.buildThreads = threads;
            const double p0 = processCpu();
            Bvh bn(prims, all);
            tp.push_back(processCpu() - p0);
            tn.push_back(bn.stats().buildSeconds);
            st = bn.stats();
        }
        // The ceilings right after the builds, not between them: their arrays and arenas
        // beside each build changed what the build met (glibc's mappings, a woken worker) and
        // moved its own times (balls 6's 1-thread build 150 -> 300-420 ms on a quiet machine).
        CeilingLoops loops(prims.size());
        loops.calibrate(median(t1));
        for (int r = 0; r < 5; ++r) {
            const bool computeFirst = r % 2 == 0;
            for (int k = 0; k < 2; ++k) {
                if ((k == 0) == computeFirst)
                    cc.push_back(loops.computeSpeedUp(threads));
                else
                    cm.push_back(loops.memorySpeedUp(threads));
            }
        }
        if (loops.sink == 12345.678) std::puts(""); // keep the loops observable
        const double m1 = median(t1), mn = median(tn), n = double(st.primitives);
        md << "| " << name << " | " << withCommas(long(st.primitives)) << " | "
           << fmt("%.1f", m1 * 1e3) << " | " << fmt("%.2f", n / m1 / 1e6) << " | "
           << fmt("%.1f", median(tc) * 1e3) << " | " << fmt("%.1f", mn * 1e3) << " | "
           << fmt("%.2f", n / mn / 1e6) << " | " << fmt("%.2f", m1 / mn) << " | "
           << fmt("%.2f", threads * m1 / median(tp)) << " | " << fmt("%.2f", median(cc)) << " | "
           << fmt("%.2f", median(cm)) << " | " << fmt("%.3f", m1 / mn / median(cc)) << " | "
           << fmt("%.3f", m1 / mn / median(cm)) << " | " << st.nodes << " | " << st.wideNodes
           << " | " << st.maxDepth << " | " << fmt("%.4f", st.sahCost) << " |\n";
    };
    for (int sf : {5, 6}) {
        if (quick && sf == 6) continue;
        SceneFile s = toScene(spdBalls(sf));
        row("balls " + std::to_string(sf), s.scene->primitives);
    }
    {
        SceneFile s = toScene(spdJacks(5));
        row("jacks 5", s.scene->primitives);
    }
    {
        Scene s;
        std::mt19937_64 g(7);
        std::uniform_real_distribution<double> u(-100, 100), d(-1, 1);
        const int n = quick ? 100000 : 1000000;
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 c(u(g), u(g), u(g));
            s.add(Triangle(c, c + glm::dvec3(d(g), d(g), d(g)), c + glm::dvec3(d(g), d(g), d(g))),
                  0);
        }
        row("random triangles", s.primitives);
    }
    return md.str();
}

int main(int argc, char** argv) {
    Options o;
    bool quick = false, embreeOnly = false, framesOnly = false;
    std::string sceneFilter;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--out-dir") && i + 1 < argc)
            o.outDir = argv[++i];
        else if (!std::strcmp(argv[i], "--quick")) {
            quick = true;
            o.runs = 1;
            o.size = 128;
        } else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
            o.runs = std::max(1, std::atoi(argv[++i])); // frames (and Embree passes) per median
        } else if (!std::strcmp(argv[i], "--build-only")) {
            std::fputs(buildRateSection(quick).c_str(), stdout); // while tuning the build
            return 0;
        } else if (!std::strcmp(argv[i], "--build-embree")) {
#ifdef WB_EMBREE
            // The builds alone against Embree's (issue 21 item 4), then the build table.
            if (std::system(("mkdir -p '" + o.workDir + "'").c_str()) != 0) return 1;
            std::printf("load %s\n", loadAverage().c_str());
            std::fputs(embreeBuildSection(std::max(o.runs, 9), writeMesh(o.workDir)).c_str(),
                       stdout);
            std::fflush(stdout);
            std::fputs(buildRateSection(quick).c_str(), stdout);
            std::printf("load %s\n", loadAverage().c_str());
            return 0;
#else
            std::fputs("--build-embree needs -DWORKBENCH_EMBREE=ON\n", stderr);
            return 2;
#endif
        } else if (!std::strcmp(argv[i], "--frames-only")) {
            framesOnly = true;
        } else if (!std::strcmp(argv[i], "--scene") && i + 1 < argc) {
            sceneFilter = argv[++i];
        } else if (!std::strcmp(argv[i], "--embree-only")) {
            embreeOnly = true; // the Embree comparison to stdout (while tuning), no report
        } else {
            std::fprintf(stderr,
                         "usage: %s [--out-dir DIR] [--quick] [--runs N] [--embree-only] "
                         "[--build-only] [--build-embree] "
                         "[--frames-only [--scene NAME]]\n",
                         argv[0]);
            return 2;
        }
    }
#ifdef WB_EMBREE
    if (embreeOnly) {
        if (std::system(("mkdir -p '" + o.workDir + "'").c_str()) != 0) return 1;
        std::printf("load %s\n", loadAverage().c_str());
        std::fputs(embreeSection(o.size, quick ? 1 : o.runs, writeMesh(o.workDir)).c_str(), stdout);
        std::printf("load %s\n", loadAverage().c_str());
        return 0;
    }
#else
    (void)embreeOnly;
#endif
    if (framesOnly) {
        if (std::system(("mkdir -p '" + o.workDir + "'").c_str()) != 0) return 1;
        std::printf("load %s\n%-14s %8s %9s %9s %6s %9s %6s %9s %6s\n", loadAverage().c_str(),
                    "scene", "setup ms", "1 thr ms", "N thr ms", "wall x", "CPU N ms", "CPU x",
                    "1 single", "pk/sg");
        o.traversal = false;
        for (const auto& bs : benchScenes(writeMesh(o.workDir))) {
            bool wanted = sceneFilter.empty();
            for (std::size_t a = 0; a <= sceneFilter.size() && !wanted;) {
                const std::size_t b = std::min(sceneFilter.find(',', a), sceneFilter.size());
                wanted = bs.name.find(sceneFilter.substr(a, b - a)) != std::string::npos;
                a = b + 1;
            }
            if (!wanted) continue;
            const FrameResult r = measure(bs, o, quick);
            std::printf("%-14s %8.1f %9.1f %9.1f %6.2f %9.1f %6.2f %9.1f %6.3f\n", bs.name.c_str(),
                        r.setupS * 1e3, r.frame1 * 1e3, r.frameN * 1e3, r.frame1 / r.frameN,
                        r.cpuN * 1e3, hardwareThreads() * r.frame1 / r.cpuN, r.frame1Single * 1e3,
                        r.frame1 / r.frame1Single);
            std::fflush(stdout);
        }
        std::printf("load %s\n", loadAverage().c_str());
        return 0;
    }
    std::string cmd = "mkdir -p '" + o.workDir + "' '" + o.outDir + "'";
    if (std::system(cmd.c_str()) != 0) return 1;
    std::ostringstream md;
    const std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    md << "# Ray tracer at scale: bench report\n\n"
       << "Generated by `build/bin/raytrace_scale_bench` (tests/bench/raytrace_scale_bench.cpp) on "
       << date << ", " << hardwareThreads() << " hardware threads, Release build. One run of the "
       << "program; every time is the median of " << o.runs << " frames (" << 3 * o.runs
       << " in the frames table for frames under 0.1 s, the one-thread, all-thread and one-thread "
          "single-eye-ray frames "
          "alternated; "
       << o.size << "×" << o.size << ", " << (o.size + 1)
       << "² eye rays through the pixel corners, SPD depth 5 = the eye ray and 4 reflections "
          "(TraceSettings::maxDepth 4), phong model). One-thread figures (frames, traversal, "
          "builds, the Embree comparison) are CPU time of the working thread; figures with all "
          "threads are wall time, and only they feel the other processes on this shared "
          "machine. 'Speed-up from CPU time' = threads × (1-thread CPU time) / (CPU time of all "
          "threads in the all-threads frame): the speed-up the frame would have on otherwise "
          "idle cores if its threads never waited (TBB's idle spinning counts against it). "
          "Load average at the start (1, 5, 15 min): "
       << loadAverage()
       << ".\n\nRegenerate the whole report, with the Embree tables and the goals of issue 21 at "
          "the end, with one command: `scripts/bench/raytrace_report.sh` (configures build-bench "
          "with -DWORKBENCH_EMBREE=ON, builds, runs this program between two `uptime`s; 4.5 "
          "minutes of bench on the 2-core machine at load 8-13, plus the build).\n\n";

    const std::string meshPath = writeMesh(o.workDir);
    const std::vector<BenchScene> scenes = benchScenes(meshPath);
    double balls4Packets = 0; // the balls 4 frame, packets / single rays (issue 21's goal)
    md << "## Frames\n\n"
       << "| scene | primitives | setup ms | of it BVH build ms | BVH nodes/depth | frame ms, 1 "
          "thread "
          "| frame ms, "
       << hardwareThreads()
       << " threads (wall) | speed-up (wall) | CPU ms of all threads | speed-up from CPU "
          "time | eye rays | shadow rays | "
          "reflection+refraction rays | M rays/s, 1 thread | M rays/s, all | M eye rays/s "
          "traversal only, 1 thread | frame ms, 1 thread, eye rays one by one | packets / one "
          "by one |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& bs : scenes) {
        std::fprintf(stderr, "frames: %s\n", bs.name.c_str());
        const FrameResult r = measure(bs, o, quick);
        const ParallelRenderStats& s = r.stats;
        const double rays = double(s.primaryRays + s.secondaryRays + s.shadowRays);
        md << "| " << bs.name << " | " << withCommas(long(r.prims)) << " | "
           << fmt("%.1f", r.setupS * 1e3) << " | " << fmt("%.2f", r.buildS * 1e3) << " | "
           << (r.bvh ? std::to_string(r.nodes) + "/" + std::to_string(r.depth) : "plain loop")
           << " | " << fmt("%.1f", r.frame1 * 1e3) << " | " << fmt("%.1f", r.frameN * 1e3) << " | "
           << fmt("%.2f", r.frame1 / r.frameN) << " | " << fmt("%.1f", r.cpuN * 1e3) << " | "
           << fmt("%.2f", hardwareThreads() * r.frame1 / r.cpuN) << " | "
           << withCommas(s.primaryRays) << " | " << withCommas(s.shadowRays) << " | "
           << withCommas(s.secondaryRays) << " | " << fmt("%.2f", rays / r.frame1 / 1e6) << " | "
           << fmt("%.2f", rays / r.frameN / 1e6) << " | " << fmt("%.2f", r.traversal1) << " | "
           << fmt("%.1f", r.frame1Single * 1e3) << " | " << fmt("%.3f", r.frame1 / r.frame1Single)
           << " |\n";
        if (bs.name == "balls 4") balls4Packets = r.frame1 / r.frame1Single;
        std::fprintf(stderr, "  build %.2f ms, frame %.1f / %.1f ms\n", r.buildS * 1e3,
                     r.frame1 * 1e3, r.frameN * 1e3);
    }

    // Crossover: random non-overlapping-ish spheres, n = 1..32, primary rays + shading.
    md << "\n## Plain loop against BVH: the crossover\n\n"
       << "n random spheres (radius 0.3 in a 6³ box, one light), 160×160 centre rays, depth 5, one "
          "thread, the fastest of "
       << (quick ? 3 : 9)
       << " frames (the minimum: these frames take milliseconds, and any other process on the "
          "machine shows up as noise in a median).\n\n"
       << "| n | plain loop ms | BVH ms | BVH/plain |\n|---|---|---|---|\n";
    int crossover = -1;
    for (int n : {1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 24, 32}) {
        SceneFile sf;
        sf.scene = std::make_unique<Scene>();
        std::mt19937_64 g{std::uint64_t(n)};
        std::uniform_real_distribution<double> u(-3, 3);
        for (int i = 0; i < n; ++i)
            sf.scene->add(Sphere({u(g), u(g), u(g)}, 0.3), 0);
        sf.scene->lights.push_back(Light::point({5, 5, 10}));
        const LookAtCamera cam({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 40);
        PhongModel model;
        ParallelRenderOptions opt;
        opt.threads = 1;
        double times[2];
        Bvh bvh(sf.scene->primitives);
        for (int k = 0; k < 2; ++k) {
            sf.scene->setAggregate(k ? &bvh : nullptr);
            std::vector<double> t;
            for (int r = 0; r < (quick ? 3 : 9); ++r) {
                ParallelRenderStats st;
                const double c0 = threadCpu(); // one thread: its CPU time
                renderParallel(*sf.scene, cam, model, 160, 160, opt, &st);
                t.push_back(threadCpu() - c0);
            }
            times[k] = *std::min_element(t.begin(), t.end()); // least disturbed by other load
        }
        if (crossover < 0 && times[1] < times[0]) crossover = n;
        md << "| " << n << " | " << fmt("%.2f", times[0] * 1e3) << " | "
           << fmt("%.2f", times[1] * 1e3) << " | " << fmt("%.2f", times[1] / times[0]) << " |\n";
    }
    md << "\nFirst n where the BVH is faster: **" << crossover
       << "** (the code's `kBvhCrossover` is " << kBvhCrossover << ").\n";

    md << buildRateSection(quick);

    // Speed against error on balls 4 (balls 3 for the plain loop, which is slow).
    std::fprintf(stderr, "speed against error\n");
    std::vector<ErrorRow> rows;
    {
        SceneFile sf = toScene(spdBalls(quick ? 2 : 4));
        const LookAtCamera cam = sf.camera();
        PhongModel model;
        long long lastRefl = 0, lastShadow = 0;
        auto run = [&](const TraceSettings& ts, const Aggregate* agg, wb::Image& img) {
            sf.scene->setAggregate(agg);
            ParallelRenderOptions opt;
            opt.cornerRays = true;
            opt.trace = ts;
            std::vector<double> t;
            for (int r = 0; r < (quick ? 1 : 3); ++r) {
                ParallelRenderStats st;
                img = renderParallel(*sf.scene, cam, model, o.size, o.size, opt, &st);
                t.push_back(st.seconds);
                lastRefl = st.secondaryRays;
                lastShadow = st.shadowRays;
            }
            return median(t);
        };
        BvhOptions binaryOpt;
        binaryOpt.width = 2;
        Bvh bvhD(sf.scene->primitives), bvhF(sf.scene->primitives, binaryOpt);
        TraceSettings ref;
        ref.maxDepth = 5;
        ref.minWeight = 0.0;
        wb::Image refImg, img;
        rows.push_back({"reference", run(ref, &bvhD, refImg), 0, 0.0, 0, lastRefl, lastShadow});
        wb::writePng(o.workDir + "/balls_reference.png", refImg);
        auto add = [&](const std::string& name, const TraceSettings& ts, const Aggregate* a,
                       int series) {
            const double t = run(ts, a, img);
            const wb::ImageDiff d = wb::compareImages(refImg, img);
            rows.push_back({name, t, d.maxDiff, d.meanDiff, series, lastRefl, lastShadow});
        };
        add("binary double-box tree (width 2)", ref, &bvhF, 3);
        for (int depth : {4, 3, 2, 1, 0}) {
            TraceSettings ts = ref;
            ts.maxDepth = depth;
            add("depth " + std::to_string(depth), ts, &bvhD, 1);
        }
        for (double w : {0.01, 0.05, 0.1, 0.2, 0.3}) {
            TraceSettings ts = ref;
            ts.minWeight = w;
            add("weight cut-off " + fmt("%g", w), ts, &bvhD, 2);
        }
    }
    ErrorRow bruteRow;
    {
        // The plain loop must give exactly the BVH's image: balls 3 (822 primitives).
        SceneFile sf = toScene(spdBalls(quick ? 2 : 3));
        const LookAtCamera cam = sf.camera();
        PhongModel model;
        ParallelRenderOptions opt;
        opt.cornerRays = true;
        opt.trace.minWeight = 0.0;
        Bvh bvh(sf.scene->primitives);
        sf.scene->setAggregate(&bvh);
        ParallelRenderStats a, b;
        const wb::Image withBvh = renderParallel(*sf.scene, cam, model, o.size, o.size, opt, &a);
        sf.scene->setAggregate(nullptr);
        const wb::Image plain = renderParallel(*sf.scene, cam, model, o.size, o.size, opt, &b);
        const wb::ImageDiff d = wb::compareImages(withBvh, plain);
        bruteRow = {"plain loop (balls 3; BVH frame " + fmt("%.0f", a.seconds * 1e3) + " ms)",
                    b.seconds,
                    d.maxDiff,
                    d.meanDiff,
                    4,
                    b.secondaryRays,
                    b.shadowRays};
    }
    md << "\n## Speed against error (balls " << (quick ? 2 : 4) << ", all threads)\n\n"
       << "Reference: depth 5, no weight cut-off (every reflected ray traced), the default wide "
          "float tree with exact primitive tests. "
          "Error = |difference| of 8-bit channels against the reference image.\n\n"
       << "| option | frame ms | max diff | mean diff | reflection rays | shadow rays |\n"
       << "|---|---|---|---|---|---|\n";
    rows.push_back(bruteRow);
    for (const auto& r : rows)
        md << "| " << r.option << " | " << fmt("%.1f", r.frameS * 1e3) << " | " << r.maxDiff
           << " | " << fmt("%.4f", r.meanDiff) << " | " << withCommas(r.reflection) << " | "
           << withCommas(r.shadow) << " |\n";
    rows.pop_back(); // the plot shows balls 4 only
    const bool plotted = plotWithGnuplot(rows, o.outDir,
                                         std::string(quick ? "balls 2" : "balls 4") + ", " +
                                             std::to_string(o.size) + "x" + std::to_string(o.size));
    md << "\n![frame time against mean error: red depth limits 5..0, blue weight cut-offs, green "
          "the binary double-box tree, black the reference](raytrace.png)\n\n"
          "Plot (gnuplot, from raytrace_error.csv and raytrace.gp next to this report"
       << (plotted ? "" : "; gnuplot FAILED in this run, the png is stale")
       << "): x = frame time in ms, y = mean error in 8-bit levels. The reference, the "
          "cut-off 0.01 and the binary tree give the same image (error 0).\n";
#ifdef WB_EMBREE
    std::vector<EmbreeGoalRow> goals;
    md << embreeSection(o.size, quick ? 1 : o.runs, meshPath, &goals);
    // Issue 21's goals, from the tables above (this run).
    {
        auto row = [&](const std::string& name) -> const EmbreeGoalRow* {
            for (const EmbreeGoalRow& g : goals)
                if (g.scene.rfind(name, 0) == 0) return &g;
            return nullptr;
        };
        const char* names[3] = {"balls 4", "jacks 4", "mesh"};
        auto line = [&](const char* goal, double EmbreeGoalRow::*field, double target) {
            std::string measured, met = "yes";
            for (const char* n : names) {
                const EmbreeGoalRow* g = row(n);
                if (!g) continue;
                measured +=
                    (measured.empty() ? "" : ", ") + std::string(n) + " " + fmt("%.2f", g->*field);
                if (g->*field < target) met = "**no**";
            }
            md << "| " << goal << " | " << measured << " | " << met << " |\n";
        };
        md << "\n## Goals of issue 21 (this run)\n\n| goal | measured | met? |\n|---|---|---|\n";
        line("single eye rays ours/Embree >= 1.0", &EmbreeGoalRow::eye, 1.0);
        line("single shadow rays ours/Embree >= 1.0", &EmbreeGoalRow::shadow, 1.0);
        line("eye packets ours/Embree packets >= 1.0", &EmbreeGoalRow::packetsVsPackets, 1.0);
        line("our eye packets / Embree single rays >= 1.5", &EmbreeGoalRow::packetsVsSingle, 1.5);
        if (balls4Packets > 0)
            md << "| balls 4 SPD frame, packets / single rays <= 0.67 (one thread) | "
               << fmt("%.3f", balls4Packets) << " | " << (balls4Packets <= 0.67 ? "yes" : "**no**")
               << " |\n";
    }
#endif
    (void)balls4Packets; // read only with Embree
    md << "\nLoad average at the end (1, 5, 15 min): " << loadAverage() << ".\n";
    const std::string mdPath = o.outDir + "/raytrace.md";
    std::ofstream(mdPath) << md.str();
    std::fputs(md.str().c_str(), stdout);
    std::fprintf(stderr, "wrote %s and raytrace.png\n", mdPath.c_str());
    return 0;
}
