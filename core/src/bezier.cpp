#include "core/bezier.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wb {
namespace {

void checkCurve(const BezierCurve& p, const char* what) {
    if (p.empty())
        throw std::invalid_argument(std::string(what) +
                                    ": a Bezier curve needs at least one control point");
}

void checkParam(double u, const char* what) {
    if (!std::isfinite(u))
        throw std::invalid_argument(std::string(what) + ": the parameter is not a finite number");
}

// Interpolates a row of the net along u and returns the v-curve through those points,
// or, with derivU, the u-derivative of each row (the v-curve of ∂q/∂u).
BezierCurve collapseU(const BezierPatch& patch, double u, bool derivU) {
    BezierCurve column(size_t(patch.orderV));
    BezierCurve row(size_t(patch.orderU));
    for (int j = 0; j < patch.orderV; ++j) {
        for (int i = 0; i < patch.orderU; ++i)
            row[size_t(i)] = patch.at(i, j);
        column[size_t(j)] = derivU ? evalDerivative(row, u, 1) : evalDeCasteljau(row, u);
    }
    return column;
}

struct Partials {
    glm::dvec3 point, du, dv, duv;
};

Partials partials(const BezierPatch& patch, double u, double v) {
    const BezierCurve c = collapseU(patch, u, false);
    const BezierCurve cu = collapseU(patch, u, true);
    return {evalDeCasteljau(c, v), evalDeCasteljau(cu, v), evalDerivative(c, v, 1),
            evalDerivative(cu, v, 1)};
}

// du × dv is a usable direction when neither factor vanishes against the patch size
// and they are not parallel. 1e-9 is far above double rounding (1e-16 relative) and far
// below any angle a real net makes; at a pole both tests fail by many orders of magnitude.
bool usable(const glm::dvec3& du, const glm::dvec3& dv, double scale) {
    const double a = glm::length(du), b = glm::length(dv);
    if (a <= 1e-12 * scale || b <= 1e-12 * scale) return false;
    return glm::length(glm::cross(du, dv)) > 1e-9 * a * b;
}

} // namespace

double binomial(int n, int i) {
    if (i < 0 || i > n) return 0.0;
    if (i > n - i) i = n - i;
    double c = 1.0;
    for (int t = 1; t <= i; ++t)
        c = c * double(n - i + t) / double(t); // each step is an exact integer
    return c;
}

double bernstein(int k, int i, double u) {
    if (i < 0 || i > k) return 0.0;
    // C(k, i) overflows a double past k ≈ 1020 (and inf · 0 would be NaN): beyond a safe
    // degree, evaluate in logarithms, where the huge and tiny factors cancel.
    if (k <= 500) return binomial(k, i) * std::pow(u, i) * std::pow(1.0 - u, k - i);
    if (u == 0.0 || u == 1.0) return (u == 0.0 ? i == 0 : i == k) ? 1.0 : 0.0;
    const double logB = std::lgamma(k + 1.0) - std::lgamma(i + 1.0) - std::lgamma(k - i + 1.0) +
                        i * std::log(std::abs(u)) + (k - i) * std::log(std::abs(1.0 - u));
    const double sign = ((u < 0.0 && i % 2) != 0) != ((u > 1.0 && (k - i) % 2) != 0) ? -1.0 : 1.0;
    return sign * std::exp(logB);
}

glm::dvec3 evalBernstein(const BezierCurve& p, double u) {
    checkCurve(p, "evalBernstein");
    checkParam(u, "evalBernstein");
    const int k = int(p.size()) - 1;
    glm::dvec3 q(0.0);
    for (int i = 0; i <= k; ++i)
        q += bernstein(k, i, u) * p[size_t(i)];
    return q;
}

glm::dvec3 evalDeCasteljau(const BezierCurve& p, double u) {
    checkCurve(p, "evalDeCasteljau");
    checkParam(u, "evalDeCasteljau");
    BezierCurve w = p;
    for (size_t r = 1; r < p.size(); ++r)
        for (size_t i = 0; i + r < p.size(); ++i)
            w[i] = (1.0 - u) * w[i] + u * w[i + 1];
    return w[0];
}

std::pair<BezierCurve, BezierCurve> subdivide(const BezierCurve& p, double u0) {
    checkCurve(p, "subdivide");
    checkParam(u0, "subdivide");
    const size_t n = p.size();
    BezierCurve left(n), right(n), w = p;
    left[0] = w[0];
    right[n - 1] = w[n - 1];
    for (size_t r = 1; r < n; ++r) {
        for (size_t i = 0; i + r < n; ++i)
            w[i] = (1.0 - u0) * w[i] + u0 * w[i + 1];
        left[r] = w[0];                  // p_0^r
        right[n - 1 - r] = w[n - 1 - r]; // p_{k-r}^r
    }
    return {left, right};
}

BezierCurve elevateDegree(const BezierCurve& p) {
    checkCurve(p, "elevateDegree");
    const size_t k = p.size() - 1;
    BezierCurve e(k + 2);
    e[0] = p[0];
    e[k + 1] = p[k];
    const double k1 = double(k + 1);
    for (size_t i = 1; i <= k; ++i)
        e[i] = (double(i) / k1) * p[i - 1] + (double(k + 1 - i) / k1) * p[i];
    return e;
}

BezierCurve derivativeCurve(const BezierCurve& p) {
    checkCurve(p, "derivativeCurve");
    if (p.size() == 1) return {glm::dvec3(0.0)};
    const double k = double(p.size() - 1);
    BezierCurve d(p.size() - 1);
    for (size_t i = 0; i + 1 < p.size(); ++i)
        d[i] = k * (p[i + 1] - p[i]);
    return d;
}

glm::dvec3 evalDerivative(const BezierCurve& p, double u, int order) {
    checkCurve(p, "evalDerivative");
    checkParam(u, "evalDerivative");
    if (order < 0) throw std::invalid_argument("evalDerivative: negative derivative order");
    BezierCurve d = p;
    for (int r = 0; r < order; ++r) {
        if (d.size() == 1) return glm::dvec3(0.0);
        d = derivativeCurve(d);
    }
    return evalDeCasteljau(d, u);
}

void checkPatch(const BezierPatch& patch) {
    if (patch.orderU < 1 || patch.orderV < 1)
        throw std::invalid_argument("Bezier patch: orders must be >= 1, got " +
                                    std::to_string(patch.orderU) + "x" +
                                    std::to_string(patch.orderV));
    if (patch.points.size() != size_t(patch.orderU) * size_t(patch.orderV))
        throw std::invalid_argument("Bezier patch: " + std::to_string(patch.orderU) + "x" +
                                    std::to_string(patch.orderV) + " net needs " +
                                    std::to_string(patch.orderU * patch.orderV) + " points, got " +
                                    std::to_string(patch.points.size()));
}

PatchSample evalPatch(const BezierPatch& patch, double u, double v) {
    checkPatch(patch);
    checkParam(u, "evalPatch");
    checkParam(v, "evalPatch");
    const Partials d = partials(patch, u, v);
    PatchSample s;
    s.point = d.point;
    s.du = d.du;
    s.dv = d.dv;

    double scale = 0.0; // size of the net, the yardstick for "vanishing"
    for (const auto& q : patch.points)
        scale = std::max(scale, glm::length(q - patch.points[0]));
    if (scale == 0.0) {
        s.normal = {0.0, 0.0, 1.0};
        s.normalKind = 2;
        return s;
    }
    if (usable(d.du, d.dv, scale)) {
        s.normal = glm::normalize(glm::cross(d.du, d.dv));
        return s;
    }
    s.normalKind = 1;
    // First-order limits: where a row of the net collapses to a point (a pole), du
    // vanishes along it and du(u, v+δ) ≈ δ·duv, so the normal tends to δ·(duv × dv),
    // δ pointing into the patch; likewise for a collapsed column.
    const double sv = v < 0.5 ? 1.0 : -1.0;
    const double su = u < 0.5 ? 1.0 : -1.0;
    const bool duVanishes = glm::length(d.du) <= 1e-12 * scale;
    const bool dvVanishes = glm::length(d.dv) <= 1e-12 * scale;
    if (duVanishes && !dvVanishes && usable(sv * d.duv, d.dv, scale)) {
        s.normal = glm::normalize(glm::cross(sv * d.duv, d.dv));
        return s;
    }
    if (dvVanishes && !duVanishes && usable(d.du, su * d.duv, scale)) {
        s.normal = glm::normalize(glm::cross(d.du, su * d.duv));
        return s;
    }
    // Anything worse (a corner where both edges collapse, or where the two boundary
    // curves are tangent so du ∥ dv, as at the corners of the lab's hemisphere net):
    // the normal of the nearest good point on the diagonal towards the patch centre.
    for (double h : {1e-7, 1e-5, 1e-3, 1e-1, 0.5}) {
        const double du0 = (u == 0.5 ? 1.0 : 0.5 - u), dv0 = (v == 0.5 ? 1.0 : 0.5 - v);
        const Partials q = partials(patch, u + h * du0, v + h * dv0);
        if (usable(q.du, q.dv, scale)) {
            s.normal = glm::normalize(glm::cross(q.du, q.dv));
            return s;
        }
    }
    s.normal = {0.0, 0.0, 1.0};
    s.normalKind = 2;
    return s;
}

} // namespace wb
