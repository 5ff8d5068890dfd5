#include "core/radiosity/flatland.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace wb::rad {

namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// Angle of direction d from q measured from the normal n towards the tangent t, in
// (−π/2, π/2) for directions in front.
double angleOf(const glm::dvec2& d, const glm::dvec2& t, const glm::dvec2& n) {
    return std::atan2(glm::dot(d, t), glm::dot(d, n));
}

// The angular interval a segment covers seen from q, clipped to the front half-plane;
// empty (lo >= hi) when wholly behind.
std::pair<double, double> interval(const glm::dvec2& q, const glm::dvec2& t, const glm::dvec2& n,
                                   glm::dvec2 a, glm::dvec2 b) {
    const double da = glm::dot(a - q, n), db = glm::dot(b - q, n);
    if (da <= 0 && db <= 0) return {0.0, 0.0};
    const double halfPi = 0.5 * glm::pi<double>();
    double fa, fb;
    if (da > 0 && db > 0) {
        fa = angleOf(a - q, t, n);
        fb = angleOf(b - q, t, n);
    } else {
        // One end behind q's line: the segment reaches the horizon on the side its
        // behind-end lies towards (the direction from q to the crossing point).
        const glm::dvec2 front = da > 0 ? a : b, back = da > 0 ? b : a;
        const double dfront = std::max(da, db), dback = std::min(da, db);
        const glm::dvec2 cut = front + (back - front) * (dfront / (dfront - dback));
        fa = angleOf(front - q, t, n);
        fb = glm::dot(cut - q, t) >= 0 ? halfPi : -halfPi;
    }
    if (fa > fb) std::swap(fa, fb);
    return {fa, fb};
}

} // namespace

double crossedStrings(const Segment2& pi, const Segment2& pj) {
    return crossedStringsOccluded(pi, pj, {});
}

double crossedStringsOccluded(const Segment2& pi, const Segment2& pj,
                              const std::vector<Segment2>& occluders) {
    if (occluders.size() > 1)
        throw std::invalid_argument("crossedStringsOccluded: at most one occluder");
    const double L = glm::length(pi.b - pi.a);
    if (!(L > 0.0) || !(glm::length(pj.b - pj.a) > 0.0)) return 0.0;
    // Frame of P_i: t along it, n its emitting (left) normal; (t, n) is right-handed.
    const glm::dvec2 t = (pi.b - pi.a) / L, n(-t.y, t.x);
    const glm::dvec2 A = pi.a, B = pi.b;
    // C, D: the ends of P_j with the smaller and larger t coordinate (uncrossed: A–C, B–D).
    glm::dvec2 C = pj.a, D = pj.b;
    if (glm::dot(C - A, t) > glm::dot(D - A, t)) std::swap(C, D);
    if (occluders.empty()) {
        const double crossed = glm::length(D - A) + glm::length(C - B);
        const double uncrossed = glm::length(C - A) + glm::length(D - B);
        return std::max(0.0, (crossed - uncrossed) / (2.0 * L));
    }
    // One occluder E1E2: the light passes through two channels, left and right of it. In each
    // the strings are taut around the occluder; Hottel's rule holds per channel and the form
    // factor is the sum (the course's γ1 + γ2 of figure 15.50).
    const glm::dvec2 E1 = occluders[0].a, E2 = occluders[0].b;
    auto toFrame = [&](const glm::dvec2& p) { return glm::dvec2(glm::dot(p - A, t), glm::dot(p - A, n)); };
    const glm::dvec2 e1 = toFrame(E1), e2 = toFrame(E2);
    // Taut string from x (on P_i) to y (on P_j) keeping the whole occluder on one side
    // (side −1: on its right, the channel left of the occluder; +1: on its left): the shortest
    // of the chains x→y, x→e→y, x→e→e'→y whose every leg has both ends of the occluder on
    // that side (it wraps the occluder's convex hull, a segment).
    auto taut = [&](const glm::dvec2& x, const glm::dvec2& y, double side) {
        const glm::dvec2 X = toFrame(x), Y = toFrame(y);
        auto legOk = [&](const glm::dvec2& p, const glm::dvec2& q) {
            const glm::dvec2 d = q - p;
            return cross2(d, e1 - p) * side >= -1e-15 && cross2(d, e2 - p) * side >= -1e-15;
        };
        const std::vector<std::vector<glm::dvec2>> chains = {
            {X, Y}, {X, e1, Y}, {X, e2, Y}, {X, e1, e2, Y}, {X, e2, e1, Y}};
        double best = std::numeric_limits<double>::infinity();
        for (const auto& ch : chains) {
            double len = 0.0;
            bool ok = true;
            for (std::size_t k = 0; k + 1 < ch.size() && ok; ++k) {
                ok = legOk(ch[k], ch[k + 1]);
                len += glm::length(ch[k + 1] - ch[k]);
            }
            if (ok) best = std::min(best, len);
        }
        return best;
    };
    double f = 0.0;
    for (double side : {-1.0, 1.0}) {
        const double crossed = taut(A, D, side) + taut(B, C, side);
        const double uncrossed = taut(A, C, side) + taut(B, D, side);
        if (std::isfinite(crossed) && std::isfinite(uncrossed))
            f += std::max(0.0, (crossed - uncrossed) / (2.0 * L));
    }
    return f;
}

double course2D(const Segment2& pi, const Segment2& pj, const std::vector<Segment2>& occluders,
                int samples, bool lambertian) {
    if (samples < 1) throw std::invalid_argument("course2D: samples must be >= 1");
    const double L = glm::length(pi.b - pi.a);
    if (!(L > 0.0)) return 0.0;
    const glm::dvec2 t = (pi.b - pi.a) / L;
    const glm::dvec2 n(-t.y, t.x); // left normal: the emitting side
    // 5-point Gauss–Legendre on each of `samples` equal subintervals of P_i.
    static const double x5[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                 0.5384693101056831, 0.9061798459386640};
    static const double w5[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                 0.4786286704993665, 0.2369268850561891};
    double total = 0.0;
    for (int s = 0; s < samples; ++s)
        for (int g = 0; g < 5; ++g) {
            const double u = (s + 0.5 * (1.0 + x5[g])) / samples;
            const glm::dvec2 q = pi.a + u * (pi.b - pi.a);
            // Visible part of P_j's interval: remove the occluders' intervals (occluders are
            // assumed to lie between P_i and P_j, as in the course's figure 15.50).
            std::vector<std::pair<double, double>> vis = {interval(q, t, n, pj.a, pj.b)};
            for (const Segment2& o : occluders) {
                const auto oc = interval(q, t, n, o.a, o.b);
                if (oc.first >= oc.second) continue;
                std::vector<std::pair<double, double>> next;
                for (const auto& v : vis) {
                    if (v.first >= v.second) continue;
                    if (oc.second <= v.first || oc.first >= v.second) {
                        next.push_back(v);
                        continue;
                    }
                    if (oc.first > v.first) next.push_back({v.first, oc.first});
                    if (oc.second < v.second) next.push_back({oc.second, v.second});
                }
                vis = std::move(next);
            }
            double f = 0.0; // γ1 + γ2 + … over π, or the cosine-weighted fraction
            for (const auto& v : vis) {
                if (v.first >= v.second) continue;
                f += lambertian ? 0.5 * (std::sin(v.second) - std::sin(v.first))
                                : (v.second - v.first) / glm::pi<double>();
            }
            total += w5[g] * 0.5 / samples * f;
        }
    return total;
}

} // namespace wb::rad
