#include "core/bezier_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wb {
namespace {

constexpr double kPi = 3.14159265358979323846;

void extend(RadialError& e, double r) {
    e.minRadius = std::min(e.minRadius, r);
    e.maxRadius = std::max(e.maxRadius, r);
}

RadialError start() {
    RadialError e;
    e.minRadius = 1e300;
    e.maxRadius = 0.0;
    return e;
}

// Fixes the compared radius (the minimax one when radius <= 0) and the error.
RadialError finish(RadialError e, double radius) {
    e.radius = radius > 0.0 ? radius : 0.5 * (e.minRadius + e.maxRadius);
    e.maxError = std::max(e.maxRadius - e.radius, e.radius - e.minRadius);
    return e;
}

void checkN(int n, const char* what) {
    if (n < 1 || n > 1 << 14)
        throw std::invalid_argument(std::string(what) + ": grid size " + std::to_string(n) +
                                    " is outside 1..16384");
}

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5),
// by the Voronoi region of p; exact for degenerate (sliver) triangles too.
glm::dvec3 closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double denom = va + vb + vc;
    if (denom <= 0) return a; // all three points coincide
    return a + ab * (vb / denom) + ac * (vc / denom);
}

// Points of the (n+1)×(n+1) grid, [j·(n+1) + i], without derivatives: each u column's
// v-curve is built once and reused for all v, so this is far cheaper than evalPatch per
// point (it dominates the net fit and the error measures).
void gridPoints(const BezierPatch& patch, int n, std::vector<glm::dvec3>& points) {
    checkPatch(patch);
    const size_t w = size_t(n) + 1;
    points.assign(w * w, glm::dvec3(0.0));
    BezierCurve row(size_t(patch.orderU)), column(size_t(patch.orderV)), work;
    for (size_t i = 0; i < w; ++i) {
        const double u = double(i) / n;
        for (int j = 0; j < patch.orderV; ++j) {
            for (int k = 0; k < patch.orderU; ++k)
                row[size_t(k)] = patch.at(k, j);
            column[size_t(j)] = evalDeCasteljau(row, u);
        }
        for (size_t j = 0; j < w; ++j) {
            const double v = double(j) / n;
            work = column;
            for (size_t r = 1; r < work.size(); ++r)
                for (size_t k = 0; k + r < work.size(); ++k)
                    work[k] = (1.0 - v) * work[k] + v * work[k + 1];
            points[j * w + i] = work[0];
        }
    }
}

// The course's net as (a, b, p, q, h); see fitHemisphereNet.
BezierPatch hemisphere(const std::array<double, 5>& x) {
    const double a = x[0], b = x[1], p = x[2], q = x[3], h = x[4];
    BezierPatch net;
    net.orderU = net.orderV = 4;
    net.points = {{2, -2, 0},  {a, -b, 0},  {a, b, 0},  {2, 2, 0},  //
                  {b, -a, 0},  {p, -q, h},  {p, q, h},  {b, a, 0},  //
                  {-b, -a, 0}, {-p, -q, h}, {-p, q, h}, {-b, a, 0}, //
                  {-2, -2, 0}, {-a, -b, 0}, {-a, b, 0}, {-2, 2, 0}};
    return net;
}

double hemisphereObjective(const std::array<double, 5>& x) {
    // 48×48 samples: enough to rank nets, the final net is re-measured densely.
    return patchesRadialError({hemisphere(x)}, 0.0, 48).relative();
}

} // namespace

double circleHandle(int nArcs) {
    if (nArcs < 2)
        throw std::invalid_argument("circleHandle: need at least 2 arcs, got " +
                                    std::to_string(nArcs));
    return 4.0 / 3.0 * std::tan(2.0 * kPi / double(nArcs) / 4.0);
}

std::vector<BezierCurve> circleArcs(int nArcs, double k, double radius, double startAngle) {
    if (nArcs < 2)
        throw std::invalid_argument("circleArcs: need at least 2 arcs, got " +
                                    std::to_string(nArcs));
    if (!(radius > 0.0) || !(k > 0.0) || !std::isfinite(radius) || !std::isfinite(k))
        throw std::invalid_argument("circleArcs: radius and handle must be positive and finite");
    std::vector<BezierCurve> arcs;
    const double theta = 2.0 * kPi / double(nArcs);
    for (int m = 0; m < nArcs; ++m) {
        const double a0 = startAngle + theta * double(m), a1 = a0 + theta;
        const glm::dvec3 p0(radius * std::cos(a0), radius * std::sin(a0), 0.0);
        const glm::dvec3 p3(radius * std::cos(a1), radius * std::sin(a1), 0.0);
        const glm::dvec3 t0(-std::sin(a0), std::cos(a0), 0.0), t1(-std::sin(a1), std::cos(a1), 0.0);
        arcs.push_back({p0, p0 + k * radius * t0, p3 - k * radius * t1, p3});
    }
    return arcs;
}

double fitCircleHandle(int nArcs) {
    const double k0 = circleHandle(nArcs);
    auto err = [&](double k) {
        return curvesRadialError({circleArcs(nArcs, k)[0]}, 1.0, 2048).maxError;
    };
    // The error is max(bulge, dip): the bulge grows and the dip shrinks with k, so it is
    // unimodal in k; golden-section search on ±20 % around the midpoint-exact handle.
    double lo = 0.8 * k0, hi = 1.2 * k0;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = err(x1), f2 = err(x2);
    for (int it = 0; it < 80 && hi - lo > 1e-13; ++it) {
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - g * (hi - lo), f1 = err(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + g * (hi - lo), f2 = err(x2);
        }
    }
    return 0.5 * (lo + hi);
}

RadialError curvesRadialError(const std::vector<BezierCurve>& curves, double radius, int samples) {
    checkN(samples, "curvesRadialError");
    RadialError e = start();
    for (const auto& c : curves)
        for (int i = 0; i <= samples; ++i)
            extend(e, glm::length(evalDeCasteljau(c, double(i) / samples)));
    return finish(e, radius);
}

RadialError polylineRadialError(const std::vector<BezierCurve>& curves, double radius, int n) {
    checkN(n, "polylineRadialError");
    RadialError e = start();
    for (const auto& c : curves) {
        glm::dvec3 prev = evalDeCasteljau(c, 0.0);
        extend(e, glm::length(prev));
        for (int i = 1; i <= n; ++i) {
            const glm::dvec3 next = evalDeCasteljau(c, double(i) / n);
            const glm::dvec3 d = next - prev;
            const double dd = glm::dot(d, d);
            const double t = dd > 0.0 ? std::clamp(-glm::dot(prev, d) / dd, 0.0, 1.0) : 0.0;
            extend(e, glm::length(prev + t * d));
            extend(e, glm::length(next));
            prev = next;
        }
    }
    return finish(e, radius);
}

BezierPatch labHemisphereNet() {
    return hemisphere({3, 1, 2, 3, 5});
}

std::vector<BezierPatch> sphereFromNet(const BezierPatch& upper) {
    checkPatch(upper);
    BezierPatch lower = upper;
    for (int j = 0; j < upper.orderV; ++j)
        for (int i = 0; i < upper.orderU; ++i) {
            const glm::dvec3 q = upper.at(i, upper.orderV - 1 - j);
            lower.at(i, j) = {q.x, q.y, -q.z};
        }
    return {upper, lower};
}

BezierPatch fitHemisphereNet() {
    // Nelder–Mead on the five free coordinates, from the course's net.
    using P = std::array<double, 5>;
    std::array<P, 6> s;
    std::array<double, 6> f;
    s[0] = {3, 1, 2, 3, 5};
    for (size_t i = 1; i < 6; ++i) {
        s[i] = s[0];
        s[i][i - 1] += 0.5;
    }
    for (size_t i = 0; i < 6; ++i)
        f[i] = hemisphereObjective(s[i]);
    for (int it = 0; it < 400; ++it) {
        std::array<size_t, 6> o{0, 1, 2, 3, 4, 5};
        std::sort(o.begin(), o.end(), [&](size_t x, size_t y) { return f[x] < f[y]; });
        const size_t best = o[0], worst = o[5], second = o[4];
        if (f[worst] - f[best] < 1e-10) break;
        P c{};
        for (size_t i = 0; i < 6; ++i)
            if (i != worst)
                for (size_t d = 0; d < 5; ++d)
                    c[d] += s[i][d] / 5.0;
        auto along = [&](double t) {
            P x;
            for (size_t d = 0; d < 5; ++d)
                x[d] = c[d] + t * (s[worst][d] - c[d]);
            return x;
        };
        const P r = along(-1.0);
        const double fr = hemisphereObjective(r);
        if (fr < f[best]) {
            const P e = along(-2.0);
            const double fe = hemisphereObjective(e);
            if (fe < fr)
                s[worst] = e, f[worst] = fe;
            else
                s[worst] = r, f[worst] = fr;
        } else if (fr < f[second]) {
            s[worst] = r, f[worst] = fr;
        } else {
            const P k = along(fr < f[worst] ? -0.5 : 0.5);
            const double fk = hemisphereObjective(k);
            if (fk < std::min(fr, f[worst])) {
                s[worst] = k, f[worst] = fk;
            } else { // shrink towards the best
                for (size_t i = 0; i < 6; ++i)
                    if (i != best) {
                        for (size_t d = 0; d < 5; ++d)
                            s[i][d] = s[best][d] + 0.5 * (s[i][d] - s[best][d]);
                        f[i] = hemisphereObjective(s[i]);
                    }
            }
        }
    }
    size_t best = 0;
    for (size_t i = 1; i < 6; ++i)
        if (f[i] < f[best]) best = i;
    return hemisphere(s[best]);
}

RadialError patchesRadialError(const std::vector<BezierPatch>& patches, double radius,
                               int samples) {
    checkN(samples, "patchesRadialError");
    RadialError e = start();
    std::vector<glm::dvec3> pts;
    for (const auto& p : patches) {
        gridPoints(p, samples, pts);
        for (const auto& q : pts)
            extend(e, glm::length(q));
    }
    return finish(e, radius);
}

RadialError meshRadialError(const std::vector<BezierPatch>& patches, double radius, int n) {
    checkN(n, "meshRadialError");
    RadialError e = start();
    std::vector<glm::dvec3> pts;
    const glm::dvec3 o(0.0);
    for (const auto& p : patches) {
        gridPoints(p, n, pts);
        const size_t w = size_t(n) + 1;
        for (const auto& q : pts)
            extend(e, glm::length(q));
        for (size_t j = 0; j < size_t(n); ++j)
            for (size_t i = 0; i < size_t(n); ++i) {
                const glm::dvec3 &a = pts[j * w + i], &b = pts[j * w + i + 1],
                                 &c = pts[(j + 1) * w + i + 1], &d = pts[(j + 1) * w + i];
                extend(e, glm::length(closestOnTriangle(o, a, b, c)));
                extend(e, glm::length(closestOnTriangle(o, a, c, d)));
            }
    }
    return finish(e, radius);
}

void tessellatePatch(const BezierPatch& patch, int n, std::vector<glm::dvec3>& points,
                     std::vector<glm::dvec3>& normals) {
    checkPatch(patch);
    checkN(n, "tessellatePatch");
    const size_t w = size_t(n) + 1;
    points.assign(w * w, glm::dvec3(0.0));
    normals.assign(w * w, glm::dvec3(0.0));
    for (size_t j = 0; j < w; ++j)
        for (size_t i = 0; i < w; ++i) {
            const PatchSample s = evalPatch(patch, double(i) / n, double(j) / n);
            points[j * w + i] = s.point;
            normals[j * w + i] = s.normal;
        }
}

} // namespace wb
