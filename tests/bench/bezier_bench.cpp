// Speed against error for lab 6 (DESIGN.md): the radial error of the two-curve
// circle and the two-patch sphere against the true circle and sphere, the better
// approximations (more arcs, fitted handles, a fitted net), and for grid sizes
// 4..256 the error of what is drawn against the time per mesh, both Mesa's
// evaluator (glEvalMesh under OSMesa, as the lab draws) and core's CPU tessellation.
// Writes docs/bench/bezier.md (the report, with its tables) and docs/bench/bezier.csv (the
// grid sweep's numbers), or into --out-dir DIR; scripts/plot/bezier.gp draws bezier.png
// from the CSV with gnuplot (docs/bench/README.md: `cmake --build B --target plot_bezier`).
//
// Usage: bezier_bench [--out-dir DIR] [--quick]
#include "common/gl.h"
#include "common/shell.h"
#include "core/bezier.h"
#include "core/bezier_shapes.h"
#include "core/image.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
    std::string outDir = WB_SOURCE_DIR "/docs/bench";
    int samples = 9;       // timing samples per measurement; the median is reported
    double sampleMs = 4.0; // each sample repeats the work until it lasts at least this long
};

// Median time of one call of `work`, in milliseconds: `samples` samples, each
// repeating the work enough times to last sampleMs (so that tiny meshes are not
// lost in clock and glFinish overhead).
double medianMs(const Options& o, const std::function<void()>& work) {
    int reps = 1;
    for (;;) { // calibrate
        const auto t0 = Clock::now();
        for (int i = 0; i < reps; ++i)
            work();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        if (ms >= o.sampleMs || reps >= 1 << 20) break;
        reps *= 2;
    }
    std::vector<double> t;
    for (int s = 0; s < o.samples; ++s) {
        const auto t0 = Clock::now();
        for (int i = 0; i < reps; ++i)
            work();
        t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / reps);
    }
    std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
    return t[t.size() / 2];
}

std::vector<float> floats(const std::vector<glm::dvec3>& p) {
    std::vector<float> f;
    for (const auto& q : p)
        f.insert(f.end(), {float(q.x), float(q.y), float(q.z)});
    return f;
}

struct Row {
    int n = 0;
    double circleErr = 0, circle8Err = 0, sphereErr = 0, sphereFitErr = 0; // drawn shape vs true
    double circleGl = 0, sphereGl = 0, sphereGlLine = 0;                   // ms per mesh, Mesa
    double circleCpu = 0, sphereCpu = 0;                                   // ms per mesh, core
};

// Runs the GL measurements inside the OSMesa context the shell creates.
class TimingLab : public wb::Lab {
  public:
    TimingLab(const Options& o, std::vector<Row>& rows) : o_(o), rows_(rows) {}
    std::string title() const override { return "bezier bench"; }
    std::vector<wb::KeyHelp> keys() const override { return {}; }
    bool key(int) override { return false; }
    void draw(const wb::View&) override {
        renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-6, 6, -6, 6, -20, 20); // the lab's framing of the sphere
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glRotated(-60, 1, 0, 0);
        glEnable(GL_DEPTH_TEST);
        const auto arcs = wb::circleArcs(2, wb::circleHandle(2));
        const auto sphere = wb::sphereFromNet(wb::labHemisphereNet());
        std::vector<std::vector<float>> arcData, patchData;
        for (const auto& a : arcs)
            arcData.push_back(floats(a));
        for (const auto& p : sphere)
            patchData.push_back(floats(p.points));
        for (Row& r : rows_) {
            const int n = r.n;
            glDisable(GL_LIGHTING);
            glEnable(GL_MAP1_VERTEX_3);
            r.circleGl = medianMs(o_, [&] {
                for (size_t a = 0; a < arcs.size(); ++a) {
                    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, GLint(arcs[a].size()), arcData[a].data());
                    glMapGrid1f(n, 0, 1);
                    glEvalMesh1(GL_LINE, 0, n);
                }
                glFinish();
            });
            glDisable(GL_MAP1_VERTEX_3);
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glEnable(GL_AUTO_NORMAL);
            glEnable(GL_NORMALIZE);
            glEnable(GL_MAP2_VERTEX_3);
            for (GLenum mode : {GL_FILL, GL_LINE}) {
                const double ms = medianMs(o_, [&] {
                    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                    for (size_t p = 0; p < sphere.size(); ++p) {
                        glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, patchData[p].data());
                        glMapGrid2f(n, 0, 1, n, 0, 1);
                        glEvalMesh2(mode, 0, n, 0, n);
                    }
                    glFinish();
                });
                (mode == GL_FILL ? r.sphereGl : r.sphereGlLine) = ms;
            }
            glDisable(GL_MAP2_VERTEX_3);
        }
    }
    std::string renderer;

  private:
    const Options& o_;
    std::vector<Row>& rows_;
};

} // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--out-dir" && i + 1 < argc) {
            o.outDir = argv[++i];
        } else if (a == "--quick") {
            o.samples = 3;
            o.sampleMs = 1.0;
        } else {
            std::fprintf(stderr, "%s: unknown argument '%s'\nusage: %s [--out-dir DIR] [--quick]\n",
                         argv[0], a.c_str(), argv[0]);
            return 2;
        }
    }
    const unsigned cores = std::thread::hardware_concurrency();

    // The approximations and the error of the exact Bezier shapes.
    struct Approx {
        std::string name;
        double k;
        wb::RadialError e;
    };
    std::vector<Approx> circles;
    for (int n : {2, 4, 8}) {
        const double k = wb::circleHandle(n), kf = wb::fitCircleHandle(n);
        circles.push_back({std::to_string(n) + " arcs, k = 4/3·tan(π/" + std::to_string(2 * n) +
                               ")" + (n == 2 ? " (course)" : ""),
                           k, wb::curvesRadialError(wb::circleArcs(n, k), 1.0, 1 << 14)});
        circles.push_back({std::to_string(n) + " arcs, fitted (minimax) k", kf,
                           wb::curvesRadialError(wb::circleArcs(n, kf), 1.0, 1 << 14)});
    }
    const auto t0 = Clock::now();
    const wb::BezierPatch fitted = wb::fitHemisphereNet();
    const double fitSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const auto course = wb::sphereFromNet(wb::labHemisphereNet());
    const auto fittedSphere = wb::sphereFromNet(fitted);
    const wb::RadialError courseErr = wb::patchesRadialError(course, 0.0, 1024);
    const wb::RadialError fittedErr = wb::patchesRadialError(fittedSphere, 0.0, 1024);

    // The grid sweep: error of the drawn polyline / triangles, CPU and GL time.
    std::vector<Row> rows;
    const auto arcs2 = wb::circleArcs(2, wb::circleHandle(2));
    const auto arcs8 = wb::circleArcs(8, wb::fitCircleHandle(8));
    for (int n = 4; n <= 256; n *= 2) {
        Row r;
        r.n = n;
        r.circleErr = wb::polylineRadialError(arcs2, 1.0, n).maxError;
        r.circle8Err = wb::polylineRadialError(arcs8, 1.0, n).maxError;
        r.sphereErr = wb::meshRadialError(course, courseErr.radius, n).maxError / courseErr.radius;
        r.sphereFitErr =
            wb::meshRadialError(fittedSphere, fittedErr.radius, n).maxError / fittedErr.radius;
        std::vector<glm::dvec3> pts(size_t(n) + 1), nrm;
        r.circleCpu = medianMs(o, [&] {
            for (const auto& a : arcs2)
                for (int i = 0; i <= n; ++i)
                    pts[size_t(i)] = wb::evalDeCasteljau(a, double(i) / n);
        });
        r.sphereCpu = medianMs(o, [&] {
            for (const auto& p : course)
                wb::tessellatePatch(p, n, pts, nrm);
        });
        rows.push_back(r);
        std::fprintf(stderr, "grid %d done\n", n);
    }
    TimingLab lab(o, rows);
    wb::Image frame;
    std::string err;
    if (!wb::renderHeadless(lab, 512, 512, {}, frame, err)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], err.c_str());
        return 1;
    }

    // The report.
    std::string md;
    char buf[2048];
    auto add = [&](const char* fmt, auto... a) {
        std::snprintf(buf, sizeof buf, fmt, a...);
        md += buf;
    };
    md += "# Bezier tessellation: speed against error (lab 6)\n\n";
    md += "Written by `bin/bezier_bench` (tests/bench/bezier_bench.cpp); do not edit by hand.\n";
    add("Machine: %u cores (the bench runs on one thread); GL: %s (OSMesa), 512×512 viewport.\n",
        cores, lab.renderer.c_str());
    // The machine is shared: say how busy it was when this run started.
    std::string load = "unknown";
    if (std::FILE* la = std::fopen("/proc/loadavg", "r")) {
        char l[64] = {0};
        if (std::fgets(l, sizeof l, la)) load = std::string(l, std::strcspn(l, " ")); // 1-min
        std::fclose(la);
    }
    add("Load average (1 min) when the run started: %s on %u cores.\n", load.c_str(), cores);
    add("Times are medians of %d samples, each repeating the work for at least %.0f ms; they are "
        "noisy on a "
        "shared machine, compare within a column and use the ratios.\n\n",
        o.samples, o.sampleMs);

    md += "## The exact Bezier shapes against the true circle and sphere\n\n";
    md += "Radial error = max |‖q‖ − R| over the shape, sampled at 16385 parameters per arc and "
          "1025² per patch.\n\n";
    md +=
        "| circle (R = 1) | handle k | min r | max r | max radial error |\n|---|---|---|---|---|\n";
    for (const auto& c : circles)
        add("| %s | %.9f | %.7f | %.7f | %.3e |\n", c.name.c_str(), c.k, c.e.minRadius,
            c.e.maxRadius, c.e.maxError);
    md +=
        "\nThe course's half circles bulge out by 1.8 %; the k = 4/3·tan(θ/4) handles put each "
        "arc's "
        "midpoint on the circle, so the error is all outward, and the fitted (minimax) k splits it "
        "evenly in and out, about 30 % smaller. The error falls like θ⁶: ×64 per halving of the "
        "arc.\n\n";
    md += "| sphere (two patches) | R (minimax) | min r | max r | max \\|r − R\\| / R "
          "|\n|---|---|---|---|---|\n";
    add("| course net (lab 6) | %.5f | %.5f | %.5f | %.3e |\n", courseErr.radius,
        courseErr.minRadius, courseErr.maxRadius, courseErr.relative());
    add("| fitted net | %.5f | %.5f | %.5f | %.3e |\n\n", fittedErr.radius, fittedErr.minRadius,
        fittedErr.maxRadius, fittedErr.relative());
    md += "The course's net does not name a radius: the true sphere is taken as the one about the "
          "origin that "
          "minimises the maximum error, R = (min + max)/2. The fitted net keeps the corners at "
          "(±2, ±2, 0) "
          "and moves the edge handles to (±a, ±b, 0) and the inner points to (±p, ±q, h) "
          "(Nelder–Mead on the "
          "maximum relative error, ";
    add("%.1f s): a = %.5f, b = %.5f, p = %.5f, q = %.5f, h = %.5f (course: 3, 1, 2, 3, 5). ",
        fitSeconds, fitted.at(1, 0).x, -fitted.at(1, 0).y, fitted.at(1, 1).x, -fitted.at(1, 1).y,
        fitted.at(1, 1).z);
    md += "A polynomial patch cannot be exactly spherical; a four-sided patch over a hemisphere "
          "also has "
          "tangent boundary curves at its corners (du ∥ dv), where GL_AUTO_NORMAL has no normal "
          "(see docs/lab06-bezier.md).\n\n";

    md += "## Grid resolution: error of what is drawn against time per mesh\n\n";
    md += "n = glMapGrid segments per curve / per patch side. Error of the drawn line strip or "
          "triangles "
          "(exact distances: a segment's or triangle's nearest point to the centre, its farthest "
          "vertex) against the true shape; the sphere's relative to R. GL = Mesa's "
          "glEvalMesh1(GL_LINE) "
          "for the two curves / glEvalMesh2 for the two patches with GL_AUTO_NORMAL and lighting, "
          "with "
          "glFinish, rasterisation included; CPU = core's evaluation of the same grid in double "
          "(points, and for the patches normals). n is per curve: the 8 arcs draw 4× the segments "
          "of the "
          "course's 2 at the same n.\n\n";
    md += "| n | circle, course: max \\|r−1\\| | circle, 8 fitted arcs | sphere, course: rel. | "
          "sphere, "
          "fitted: rel. | circle GL ms | circle CPU ms | sphere GL fill ms | sphere GL line ms | "
          "sphere "
          "CPU ms | CPU/GL (sphere) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows)
        add("| %d | %.3e | %.3e | %.3e | %.3e | %.4f | %.4f | %.3f | %.3f | %.3f | %.2f |\n", r.n,
            r.circleErr, r.circle8Err, r.sphereErr, r.sphereFitErr, r.circleGl, r.circleCpu,
            r.sphereGl, r.sphereGlLine, r.sphereCpu, r.sphereCpu / r.sphereGl);
    // Where refining the grid stops paying: the chord error falls below the shape's own error.
    auto enough = [&](double Row::*f, double shapeErr) {
        for (const Row& r : rows)
            if (r.*f <= 1.1 * shapeErr) return std::to_string(r.n);
        return std::string("beyond ") + std::to_string(rows.back().n);
    };
    add("\nThe drawn error stops falling once the chords are finer than the Bezier shape's own "
        "error: grid %s for the course's circle (1.8 %%), %s for the 8 fitted arcs, %s for the "
        "course's sphere, %s for the fitted sphere (first n within 10 %% of the exact shape's "
        "error). Beyond that a finer grid costs time (roughly ∝ n for curves, n² for patches) and "
        "buys nothing; better control points do.\n\n",
        enough(&Row::circleErr, circles[0].e.maxError).c_str(),
        enough(&Row::circle8Err, circles[5].e.maxError).c_str(),
        enough(&Row::sphereErr, courseErr.relative()).c_str(),
        enough(&Row::sphereFitErr, fittedErr.relative()).c_str());
    md += "![Two log-log panels against the grid n: the drawn shapes' error (course circle, 8 "
          "fitted arcs, course sphere, fitted sphere, each with its exact Bezier shape's error "
          "dashed) and the time per mesh (GL fill and line, CPU)](bezier.png)\n\n";
    md += "The plot is drawn by gnuplot (scripts/plot/bezier.gp) from bezier.csv, the numbers of "
          "the table above; see docs/bench/README.md.\n";

    // The grid sweep as CSV for the plot: one row per n; the exact shapes' errors repeat in
    // every row so the script draws them as lines without a second file.
    std::string csv = "n,circle_course_err,circle_8fit_err,sphere_course_rel,sphere_fit_rel,"
                      "circle_course_exact,circle_8fit_exact,sphere_course_exact,sphere_fit_exact,"
                      "circle_gl_ms,circle_cpu_ms,sphere_gl_fill_ms,sphere_gl_line_ms,"
                      "sphere_cpu_ms\n";
    for (const Row& r : rows) {
        std::snprintf(buf, sizeof buf,
                      "%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6g,%.6g,%.6g,%.6g,%.6g\n", r.n,
                      r.circleErr, r.circle8Err, r.sphereErr, r.sphereFitErr, circles[0].e.maxError,
                      circles[5].e.maxError, courseErr.relative(), fittedErr.relative(), r.circleGl,
                      r.circleCpu, r.sphereGl, r.sphereGlLine, r.sphereCpu);
        csv += buf;
    }

    const std::string mdPath = o.outDir + "/bezier.md", csvPath = o.outDir + "/bezier.csv";
    for (const auto& [path, text] : {std::pair{mdPath, &md}, std::pair{csvPath, &csv}}) {
        std::FILE* f = std::fopen(path.c_str(), "w");
        if (!f || std::fputs(text->c_str(), f) < 0 || std::fclose(f) != 0) {
            std::fprintf(stderr, "%s: %s: cannot write\n", argv[0], path.c_str());
            return 1;
        }
    }
    std::fputs(md.c_str(), stdout);
    std::fprintf(stderr, "wrote %s and %s; plot: scripts/plot/plot.sh bezier %s\n", mdPath.c_str(),
                 csvPath.c_str(), o.outDir.c_str());
    return 0;
}
