#include "core/raytrace/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace wb::rt {

namespace {

using P2 = glm::dvec2;

// Twice the signed area of (a, b, c): > 0 counter-clockwise.
double orient(const P2& a, const P2& b, const P2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// p inside or on the boundary of the triangle (a, b, c) of orientation sign s.
bool inTriangle(const P2& p, const P2& a, const P2& b, const P2& c, double s) {
    return s * orient(a, b, p) >= 0 && s * orient(b, c, p) >= 0 && s * orient(c, a, p) >= 0;
}

std::vector<std::array<int, 3>> fan(int n) {
    std::vector<std::array<int, 3>> out;
    for (int i = 1; i + 1 < n; ++i)
        out.push_back({0, i, i + 1});
    return out;
}

bool triangulateWithin(const std::vector<glm::dvec3>& v, long long& budget,
                       std::vector<std::array<int, 3>>& out, bool fanWhenOver);

} // namespace

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<glm::dvec3>& v) {
    long long budget = 200'000'000; // past this many vertex visits (~1 s) the rest is fanned
    std::vector<std::array<int, 3>> out;
    triangulateWithin(v, budget, out, true);
    return out;
}

bool triangulatePolygon(const std::vector<glm::dvec3>& v, long long& budget,
                        std::vector<std::array<int, 3>>& out) {
    return triangulateWithin(v, budget, out, false);
}

namespace {

bool triangulateWithin(const std::vector<glm::dvec3>& v, long long& budget,
                       std::vector<std::array<int, 3>>& out, bool fanWhenOver) {
    out.clear();
    const int n = int(v.size());
    if (n < 3) return true;
    // 1. Project onto the coordinate plane most parallel to the polygon (the largest
    //    component of Newell's normal), keeping the winding.
    glm::dvec3 normal(0.0);
    for (int i = 0; i < n; ++i) {
        const glm::dvec3& a = v[size_t(i)];
        const glm::dvec3& b = v[size_t((i + 1) % n)];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                             (a.x - b.x) * (a.y + b.y));
    }
    const glm::dvec3 an = glm::abs(normal);
    const int axis = an.x > an.y ? (an.x > an.z ? 0 : 2) : (an.y > an.z ? 1 : 2);
    if (!(an[axis] > 0) || !std::isfinite(an[axis])) { // degenerate: no area
        out = fan(n);
        return true;
    }
    const int ax = (axis + 1) % 3, ay = (axis + 2) % 3;
    std::vector<P2> p(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
        p[size_t(i)] = {v[size_t(i)][ax], v[size_t(i)][ay]};
    const double s = normal[axis] > 0 ? 1.0 : -1.0; // orientation of the polygon in 2D

    // 2. Convex (no corner turning the other way): the fan from vertex 0.
    bool convex = true;
    for (int i = 0; i < n && convex; ++i)
        convex = s * orient(p[size_t((i + n - 1) % n)], p[size_t(i)], p[size_t((i + 1) % n)]) >= 0;
    if (convex) {
        out = fan(n);
        return true;
    }

    // 3. Ear clipping on a doubly linked ring. A corner b (a before, c after) is an ear
    //    when it turns the polygon's way and no reflex vertex lies in or on (a, b, c)
    //    (a vertex at the same point as a, b or c does not count: polygons may touch
    //    themselves there). Only reflex vertices can block an ear.
    std::vector<int> prev(static_cast<size_t>(n)), next(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        prev[size_t(i)] = (i + n - 1) % n;
        next[size_t(i)] = (i + 1) % n;
    }
    const auto turn = [&](int i) {
        return s * orient(p[size_t(prev[size_t(i)])], p[size_t(i)], p[size_t(next[size_t(i)])]);
    };
    std::vector<char> reflex(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
        reflex[size_t(i)] = turn(i) < 0;
    // Hostile input (a 10^5-gon with half its corners reflex) must not take minutes:
    // past the budget's vertex visits the rest is fanned, or the polygon refused.
    const long long kWork = budget;
    long long work = 0;
    const auto isEar = [&](int b) {
        if (!(turn(b) > 0)) return false;
        const int a = prev[size_t(b)], c = next[size_t(b)];
        for (int q = next[size_t(c)]; q != a; q = next[size_t(q)]) {
            ++work;
            if (!reflex[size_t(q)]) continue;
            const P2& pq = p[size_t(q)];
            if (pq == p[size_t(a)] || pq == p[size_t(b)] || pq == p[size_t(c)]) continue;
            if (inTriangle(pq, p[size_t(a)], p[size_t(b)], p[size_t(c)], s)) return false;
        }
        return true;
    };

    out.reserve(size_t(n - 2));
    int left = n, cur = 0, sinceEar = 0;
    while (left > 3) {
        if (++work > kWork) break; // over the budget, ears or not: fan the rest or refuse
        const int a = prev[size_t(cur)], c = next[size_t(cur)];
        if (turn(cur) == 0 &&
            glm::dot(p[size_t(a)] - p[size_t(cur)], p[size_t(c)] - p[size_t(cur)]) <= 0) {
            // A straight corner (b between a and c): dropping it loses no area.
        } else if (isEar(cur)) {
            out.push_back({a, cur, c});
        } else {
            cur = c;
            if (++sinceEar > left || work > kWork) break; // no ear left: self-intersecting
            continue;
        }
        next[size_t(a)] = c;
        prev[size_t(c)] = a;
        --left;
        reflex[size_t(a)] = turn(a) < 0; // a and c lost a neighbour: re-classify them
        reflex[size_t(c)] = turn(c) < 0;
        cur = a;
        sinceEar = 0;
    }
    budget -= std::min(work, budget);
    if (work > kWork && !fanWhenOver) {
        out.clear();
        return false;
    }
    // The last triangle, or (no ear found) a fan over what is left.
    const int start = cur;
    for (int b = next[size_t(start)]; next[size_t(b)] != start; b = next[size_t(b)])
        out.push_back({start, b, next[size_t(b)]});
    return true;
}

} // namespace

} // namespace wb::rt
