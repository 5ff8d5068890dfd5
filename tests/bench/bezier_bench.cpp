// Speed against error for lab 6 (DESIGN.md): the radial error of the two-curve
// circle and the two-patch sphere against the true circle and sphere, the better
// approximations (more arcs, fitted handles, a fitted net), and for grid sizes
// 4..256 the error of what is drawn against the time per mesh, both Mesa's
// evaluator (glEvalMesh under OSMesa, as the lab draws) and core's CPU tessellation.
// Writes docs/bench/bezier.md and docs/bench/bezier.png (or into --out-dir DIR).
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

// A log-log plot drawn pixel by pixel (no plotting dependency): x = log2 n, y = log10 value.
struct Plot {
    wb::Image img;
    int x0, y0, w, h;          // plot area in pixels
    double lx0, lx1, ly0, ly1; // log axis ranges
    Plot(int width, int height, double xmin, double xmax, double ymin, double ymax)
        : img(width, height), x0(48), y0(10), w(width - 58), h(height - 50), lx0(std::log2(xmin)),
          lx1(std::log2(xmax)), ly0(std::log10(ymin)), ly1(std::log10(ymax)) {
        std::fill(img.data.begin(), img.data.end(), uint8_t(255));
        for (double d = std::ceil(ly0); d <= ly1; d += 1.0)
            hline(d, {220, 220, 220}, false);             // decades
        for (double e = lx0; e <= lx1 + 1e-9; e += 1.0) { // powers of two
            const int px = x0 + int(std::lround((e - lx0) / (lx1 - lx0) * (w - 1)));
            for (int py = y0; py < y0 + h; ++py)
                set(px, py, {220, 220, 220});
        }
        for (int px = x0; px < x0 + w; ++px)
            set(px, y0 + h - 1, {0, 0, 0});
        for (int py = y0; py < y0 + h; ++py)
            set(x0, py, {0, 0, 0});
    }
    void set(int x, int y, std::array<uint8_t, 3> c) {
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
        std::memcpy(img.at(x, y), c.data(), 3);
    }
    int px(double n) const {
        return x0 + int(std::lround((std::log2(n) - lx0) / (lx1 - lx0) * (w - 1)));
    }
    int py(double v) const {
        const double t = (std::log10(std::max(v, 1e-30)) - ly0) / (ly1 - ly0);
        return y0 + h - 1 - int(std::lround(std::clamp(t, 0.0, 1.0) * (h - 1)));
    }
    void hline(double logv, std::array<uint8_t, 3> c, bool dashed) {
        const int y = py(std::pow(10.0, logv));
        for (int x = x0; x < x0 + w; ++x)
            if (!dashed || (x / 6) % 2 == 0) set(x, y, c);
    }
    void line(int ax, int ay, int bx, int by, std::array<uint8_t, 3> c) {
        const int steps = std::max(std::abs(bx - ax), std::abs(by - ay)) + 1;
        for (int i = 0; i <= steps; ++i)
            for (int t = -1; t <= 1; ++t) { // 2-3 px thick
                const int x = ax + (bx - ax) * i / steps, y = ay + (by - ay) * i / steps;
                set(x, y + t, c);
            }
    }
    // Tick labels in a 3×5 pixel font (digits, e, -, n), drawn at twice the size.
    void text(int x, int y, const std::string& str) {
        static const char* const glyphs = "0111101101101111"
                                          "1010110010010111"
                                          "2111001111100111"
                                          "3111001111001111"
                                          "4101101111001001"
                                          "5111100111001111"
                                          "6111100111101111"
                                          "7111001001001001"
                                          "8111101111101111"
                                          "9111101111001111"
                                          "e000110111100011"
                                          "-000000111000000"
                                          "n000110101101101";
        for (char ch : str) {
            for (const char* g = glyphs; *g; g += 16)
                if (*g == ch)
                    for (int r = 0; r < 5; ++r)
                        for (int c = 0; c < 3; ++c)
                            if (g[1 + r * 3 + c] == '1')
                                for (int d = 0; d < 4; ++d)
                                    set(x + 2 * c + d % 2, y + 2 * r + d / 2, {0, 0, 0});
            x += 8;
        }
    }
    void labels() {
        for (double e = lx0; e <= lx1 + 1e-9; e += 1.0) {
            const std::string t = std::to_string(int(std::lround(std::exp2(e))));
            text(px(std::exp2(e)) - int(t.size()) * 4, y0 + h + 6, t);
        }
        text(x0 + w - 8, y0 + h + 20, "n");
        for (double d = std::ceil(ly0); d <= ly1; d += 1.0) {
            const std::string t = d == 0.0 ? "1" : "1e" + std::to_string(int(d));
            text(x0 - 4 - 8 * int(t.size()), py(std::pow(10.0, d)) - 5, t);
        }
    }
    void series(const std::vector<Row>& rows, double Row::*field, std::array<uint8_t, 3> c) {
        for (size_t i = 0; i + 1 < rows.size(); ++i)
            line(px(rows[i].n), py(rows[i].*field), px(rows[i + 1].n), py(rows[i + 1].*field), c);
        for (const Row& r : rows)
            for (int dx = -3; dx <= 3; ++dx)
                for (int dy = -3; dy <= 3; ++dy)
                    set(px(r.n) + dx, py(r.*field) + dy, c);
    }
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
    md += "![error (log) against grid n (log): red course circle, orange 8 fitted arcs, blue "
          "course sphere, "
          "cyan fitted sphere; dashed: the exact shapes' errors](bezier.png)\n\n";
    md += "Plot: x = grid n from 4 to 256 (log₂, one grid line per doubling), y = error from 1e-7 "
          "to 1 "
          "(log₁₀, one grid line per decade). Red: course circle; orange: 8 fitted arcs; blue: "
          "course "
          "sphere; cyan: fitted sphere; dashed lines: the exact Bezier shapes' errors in the same "
          "colours.\n";

    Plot plot(640, 400, 4, 256, 1e-7, 1.0);
    plot.hline(std::log10(circles[0].e.maxError), {220, 40, 40}, true);
    plot.hline(std::log10(circles[5].e.maxError), {240, 150, 0}, true);
    plot.hline(std::log10(courseErr.relative()), {40, 80, 220}, true);
    plot.hline(std::log10(fittedErr.relative()), {0, 190, 210}, true);
    plot.series(rows, &Row::circleErr, {220, 40, 40});
    plot.series(rows, &Row::circle8Err, {240, 150, 0});
    plot.series(rows, &Row::sphereErr, {40, 80, 220});
    plot.series(rows, &Row::sphereFitErr, {0, 190, 210});
    plot.labels();

    const std::string mdPath = o.outDir + "/bezier.md", pngPath = o.outDir + "/bezier.png";
    std::FILE* f = std::fopen(mdPath.c_str(), "w");
    if (!f || std::fputs(md.c_str(), f) < 0 || std::fclose(f) != 0) {
        std::fprintf(stderr, "%s: %s: cannot write\n", argv[0], mdPath.c_str());
        return 1;
    }
    if (!wb::writePng(pngPath, plot.img, &err)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], err.c_str());
        return 1;
    }
    std::fputs(md.c_str(), stdout);
    std::fprintf(stderr, "wrote %s and %s\n", mdPath.c_str(), pngPath.c_str());
    return 0;
}
