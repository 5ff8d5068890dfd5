#include "core/radiosity/mesh.h"

#include "core/radiosity/patch_bvh.h"

#include "cdt2.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace wb::rad {

namespace {

// A patch before its vertices are shared: its surface, level and lattice corners.
struct PatchDesc {
    int surface;
    int level;
    int count; // 3 or 4
    std::array<glm::dvec2, 4> lat;
    int group = -1; // shooting group, −1 without grouping
};

// Grid cells of a quad surface are at most this many times longer than wide (along the
// surface's two edge directions); with the scenes' near-rectangular quads, patchAspect stays
// below kMaxAspect (mesh.h).
constexpr double kMaxGridAspect = 1.5;

// Hard cap so a tiny maxEdge gives a clear error, not an out-of-memory (~1 KB per patch with F
// rows on demand; 4 million patches is far beyond what the solvers can use anyway).
constexpr double kMaxPatches = 4.0e6;

glm::dvec3 latticePoint(const Surface& s, const glm::ivec2& grid, const glm::dvec2& l) {
    const auto& c = s.vertices;
    if (c.size() == 3) {
        const double a = l.x / (grid.x * kLatticeScale), b = l.y / (grid.x * kLatticeScale);
        return c[0] + a * (c[1] - c[0]) + b * (c[2] - c[0]);
    }
    const double u = l.x / (grid.x * kLatticeScale), v = l.y / (grid.y * kLatticeScale);
    return (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
}

// The plane of a surface as 2D coordinates (the constrained triangulation works in them).
struct PlaneFrame {
    glm::dvec3 o, e1, e2;
    explicit PlaneFrame(const std::vector<glm::dvec3>& c) : o(c[0]) {
        e1 = glm::normalize(c[1] - c[0]);
        e2 = glm::cross(polygonNormal(c), e1);
    }
    glm::dvec2 to2(const glm::dvec3& p) const { return {glm::dot(p - o, e1), glm::dot(p - o, e2)}; }
    glm::dvec3 to3(const glm::dvec2& q) const { return o + q.x * e1 + q.y * e2; }
};

// Lattice coordinates of a point of a quad surface: latticePoint inverted (Newton on the
// bilinear map; the scenes' quads are near-rectangles, 3-4 steps).
glm::dvec2 latticeOf(const Surface& s, const glm::ivec2& grid, const glm::dvec3& p) {
    const auto& c = s.vertices;
    const PlaneFrame f(c);
    const glm::dvec2 q = f.to2(p), c0 = f.to2(c[0]), c1 = f.to2(c[1]), c2 = f.to2(c[2]), c3 = f.to2(c[3]);
    double u = 0.5, v = 0.5;
    for (int it = 0; it < 50; ++it) {
        const glm::dvec2 r = (1 - u) * (1 - v) * c0 + u * (1 - v) * c1 + u * v * c2 + (1 - u) * v * c3 - q;
        const glm::dvec2 du = (1 - v) * (c1 - c0) + v * (c2 - c3), dv = (1 - u) * (c3 - c0) + u * (c2 - c1);
        const double det = du.x * dv.y - du.y * dv.x;
        const double su = (r.x * dv.y - r.y * dv.x) / det, sv = (du.x * r.y - du.y * r.x) / det;
        u -= su;
        v -= sv;
        if (std::abs(su) + std::abs(sv) < 1e-16) break;
    }
    return {u * grid.x * kLatticeScale, v * grid.y * kLatticeScale};
}

// The lattice points along edge k of a surface meshed `grid` (its grid vertices there, in order).
std::vector<glm::dvec2> edgeLattice(std::size_t corners, const glm::ivec2& g, int k) {
    const double S = kLatticeScale;
    std::vector<glm::dvec2> out;
    if (corners == 3) {
        for (int i = 0; i <= g.x; ++i)
            out.push_back(k == 0 ? glm::dvec2(i * S, 0) : k == 1 ? glm::dvec2((g.x - i) * S, i * S) : glm::dvec2(0, (g.x - i) * S));
        return out;
    }
    const int n = k % 2 == 0 ? g.x : g.y;
    for (int i = 0; i <= n; ++i)
        out.push_back(k == 0   ? glm::dvec2(i * S, 0)
                      : k == 1 ? glm::dvec2(g.x * S, i * S)
                      : k == 2 ? glm::dvec2((g.x - i) * S, g.y * S)
                               : glm::dvec2(0, (g.y - i) * S));
    return out;
}

// Where bodies stand on a quad surface (the blocks on the Cornell floor, table panels and the
// lamp's pole on a room's floor): the edges of other surfaces lying in its plane, inside it and
// not along its border. Each comes with its grid points (the other surface's vertices there),
// so the surface's patches meet the body's patches vertex to vertex.
std::vector<std::vector<glm::dvec3>> contactEdges(const Scene& scene, const std::vector<glm::ivec2>& grids,
                                                  std::size_t si) {
    const auto& c = scene.surfaces[si].vertices;
    const glm::dvec3 n = polygonNormal(c);
    double ext = 0.0;
    for (const auto& v : c) ext = std::max(ext, glm::length(v - c[0]));
    const double tol = 1e-9 * (1.0 + ext);
    auto offLine = [&](const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b) {
        return glm::length(glm::cross(b - a, q - a)) / glm::length(b - a);
    };
    std::vector<std::vector<glm::dvec3>> out;
    for (std::size_t sj = 0; sj < scene.surfaces.size(); ++sj) {
        const auto& d = scene.surfaces[sj].vertices;
        if (sj == si || std::abs(std::abs(glm::dot(polygonNormal(d), n)) - 1.0) < 1e-9) continue;
        for (std::size_t k = 0; k < d.size(); ++k) {
            const glm::dvec3 a = d[k], b = d[(k + 1) % d.size()];
            if (std::abs(glm::dot(a - c[0], n)) > tol || std::abs(glm::dot(b - c[0], n)) > tol) continue;
            bool in = true, border = false;
            for (std::size_t m = 0; m < c.size(); ++m) {
                const glm::dvec3 p = c[m], q = c[(m + 1) % c.size()];
                for (const glm::dvec3& x : {a, b})
                    in = in && glm::dot(glm::cross(q - p, x - p), n) >= -tol * glm::length(q - p);
                border = border || (offLine(a, p, q) < tol && offLine(b, p, q) < tol);
            }
            if (!in || border) continue;
            std::vector<glm::dvec3> pts;
            for (const glm::dvec2& l : edgeLattice(d.size(), grids[sj], static_cast<int>(k)))
                pts.push_back(latticePoint(scene.surfaces[sj], grids[sj], l));
            out.push_back(std::move(pts));
        }
    }
    return out;
}

// The grid cells of a quad surface near its contact edges (those the edges cross, and one cell
// around them) are meshed as one region by a constrained Delaunay triangulation: its border
// (grid edges), the contact edges and their points are kept, every triangle has angles of at
// least 20.7° and edges of at most maxEdge (cdt2.h). The footprints' insides are triangulated
// too and dropped later (buildFitted: a patch wholly inside a body). Fills `ring` (cells not to
// be meshed as quads) and returns the triangles' lattice corners.
std::vector<std::vector<glm::dvec2>> contactTriangles(const Scene& scene, const std::vector<glm::ivec2>& grids,
                                                        std::size_t si, double maxEdge, std::vector<char>& ring) {
    const Surface& surf = scene.surfaces[si];
    const glm::ivec2 g = grids[si];
    ring.assign(static_cast<std::size_t>(g.x) * static_cast<std::size_t>(g.y), 0);
    if (surf.vertices.size() != 4) return {};
    const auto contacts = contactEdges(scene, grids, si);
    if (contacts.empty()) return {};
    const double S = kLatticeScale;
    std::vector<char> hit(ring.size(), 0);
    auto cellOf = [&](const glm::dvec3& p) {
        const glm::dvec2 l = latticeOf(surf, g, p) / S;
        const int i = std::clamp(static_cast<int>(std::floor(l.x)), 0, g.x - 1);
        const int j = std::clamp(static_cast<int>(std::floor(l.y)), 0, g.y - 1);
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(g.x) + static_cast<std::size_t>(i);
    };
    for (const auto& pts : contacts)
        for (std::size_t k = 0; k + 1 < pts.size(); ++k)
            for (int m = 0; m <= 16; ++m) hit[cellOf(pts[k] + (m / 16.0) * (pts[k + 1] - pts[k]))] = 1;
    for (int j = 0; j < g.y; ++j)
        for (int i = 0; i < g.x; ++i)
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int a = i + di, b = j + dj;
                    if (a >= 0 && b >= 0 && a < g.x && b < g.y && hit[static_cast<std::size_t>(b * g.x + a)])
                        ring[static_cast<std::size_t>(j * g.x + i)] = 1;
                }
    const PlaneFrame frame(surf.vertices);
    std::vector<glm::dvec2> pts2, lat;
    std::vector<char> onGrid;
    std::map<std::pair<int, int>, int> gridId;
    auto gridPoint = [&](int i, int j) {
        auto it = gridId.find({i, j});
        if (it != gridId.end()) return it->second;
        const glm::dvec2 l(i * S, j * S);
        pts2.push_back(frame.to2(latticePoint(surf, g, l)));
        lat.push_back(l);
        onGrid.push_back(1);
        gridId.emplace(std::make_pair(i, j), static_cast<int>(pts2.size() - 1));
        return static_cast<int>(pts2.size() - 1);
    };
    std::vector<std::array<int, 2>> segs;
    auto inRing = [&](int i, int j) { return i >= 0 && j >= 0 && i < g.x && j < g.y && ring[static_cast<std::size_t>(j * g.x + i)]; };
    for (int j = 0; j < g.y; ++j)
        for (int i = 0; i < g.x; ++i) {
            if (!inRing(i, j)) continue;
            if (!inRing(i, j - 1)) segs.push_back({gridPoint(i, j), gridPoint(i + 1, j)});
            if (!inRing(i + 1, j)) segs.push_back({gridPoint(i + 1, j), gridPoint(i + 1, j + 1)});
            if (!inRing(i, j + 1)) segs.push_back({gridPoint(i + 1, j + 1), gridPoint(i, j + 1)});
            if (!inRing(i - 1, j)) segs.push_back({gridPoint(i, j + 1), gridPoint(i, j)});
        }
    // Contact points, merged where two edges share a corner (computed from two surfaces' own
    // corners: equal to rounding).
    double ext = 0.0;
    for (const auto& v : surf.vertices) ext = std::max(ext, glm::length(v - surf.vertices[0]));
    const double tol = 1e-9 * (1.0 + ext);
    const std::size_t firstContact = pts2.size();
    auto contactPoint = [&](const glm::dvec3& p) {
        const glm::dvec2 q = frame.to2(p);
        for (std::size_t k = firstContact; k < pts2.size(); ++k)
            if (glm::length(pts2[k] - q) < tol) return static_cast<int>(k);
        pts2.push_back(q);
        lat.push_back(latticeOf(surf, g, p));
        onGrid.push_back(0);
        return static_cast<int>(pts2.size() - 1);
    };
    for (const auto& pts : contacts)
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
            const int a = contactPoint(pts[k]), b = contactPoint(pts[k + 1]);
            if (a != b) segs.push_back({a, b});
        }
    const detail::Cdt2 cdt = detail::meshRegion(pts2, segs, maxEdge);
    for (std::size_t k = pts2.size(); k < cdt.points.size(); ++k) {
        glm::dvec2 l = latticeOf(surf, g, frame.to3(cdt.points[k]));
        // A point the mesher put on a grid edge of the region's border is that edge's midpoint
        // (or a midpoint's midpoint): on the lattice, where the quad beside it finds it as its
        // T-vertex (build). Rounding off Newton's last bits puts it there exactly.
        const glm::dvec2 r(std::round(l.x), std::round(l.y));
        if (std::abs(l.x - r.x) < 1e-4 && std::abs(l.y - r.y) < 1e-4) l = r;
        lat.push_back(l);
    }
    // Pairs of triangles across an unconstrained edge become one quad where the quad is convex
    // and well shaped (L²/A <= kMergeAspect, each angle <= 150°): fewer patches (about as many
    // as the grid cells they replace), within the quads' bound (mesh.h). Best pairs first.
    const auto& P = cdt.points;
    const auto& T = cdt.triangles;
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edgeOf; // edge -> (triangle, opposite corner)
    for (std::size_t t = 0; t < T.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = T[t][static_cast<std::size_t>((k + 1) % 3)], b = T[t][static_cast<std::size_t>((k + 2) % 3)];
            edgeOf[{std::min(a, b), std::max(a, b)}].emplace_back(static_cast<int>(t), k);
        }
    struct Pair {
        double aspect;
        int t, u;
        std::array<int, 4> quad;
    };
    auto quadAspect = [&](const std::array<int, 4>& q) {
        double area = 0.0, longest = 0.0, worstCos = 1.0;
        for (int k = 0; k < 4; ++k) {
            const glm::dvec2 a = P[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])];
            const glm::dvec2 b = P[static_cast<std::size_t>(q[static_cast<std::size_t>((k + 1) % 4)])];
            const glm::dvec2 c = P[static_cast<std::size_t>(q[static_cast<std::size_t>((k + 3) % 4)])];
            area += 0.5 * (a.x * b.y - a.y * b.x);
            longest = std::max(longest, glm::length(b - a));
            const glm::dvec2 u = glm::normalize(b - a), v = glm::normalize(c - a);
            if (u.x * v.y - u.y * v.x <= 0.0) return 1e300; // reflex or flat corner: not convex
            worstCos = std::min(worstCos, glm::dot(u, v));
        }
        if (worstCos < std::cos(glm::radians(150.0))) return 1e300;
        return longest * longest / area;
    };
    constexpr double kMergeAspect = 2.0;
    std::vector<Pair> pairs;
    for (const auto& [e, ts] : edgeOf) {
        if (ts.size() != 2) continue;
        const auto [t, k] = ts[0];
        const auto [u, m] = ts[1];
        if (cdt.constrained[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)]) continue;
        const auto& A = T[static_cast<std::size_t>(t)];
        const std::array<int, 4> q{A[static_cast<std::size_t>(k)], A[static_cast<std::size_t>((k + 1) % 3)],
                                   T[static_cast<std::size_t>(u)][static_cast<std::size_t>(m)], A[static_cast<std::size_t>((k + 2) % 3)]};
        const double a = quadAspect(q);
        if (a <= kMergeAspect) pairs.push_back({a, t, u, q});
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
        return x.aspect < y.aspect || (x.aspect == y.aspect && std::tie(x.t, x.u) < std::tie(y.t, y.u));
    });
    std::vector<char> used(T.size(), 0);
    std::vector<std::vector<glm::dvec2>> out;
    for (const Pair& p : pairs) {
        if (used[static_cast<std::size_t>(p.t)] || used[static_cast<std::size_t>(p.u)]) continue;
        used[static_cast<std::size_t>(p.t)] = used[static_cast<std::size_t>(p.u)] = 1;
        out.push_back({lat[static_cast<std::size_t>(p.quad[0])], lat[static_cast<std::size_t>(p.quad[1])],
                       lat[static_cast<std::size_t>(p.quad[2])], lat[static_cast<std::size_t>(p.quad[3])]});
    }
    for (std::size_t t = 0; t < T.size(); ++t)
        if (!used[t])
            out.push_back({lat[static_cast<std::size_t>(T[t][0])], lat[static_cast<std::size_t>(T[t][1])], lat[static_cast<std::size_t>(T[t][2])]});
    return out;
}

// A patch with T-vertices on its outline is drawn as a fan from a vertex at its centre
// (displayTriangles): that vertex, at the patch's centroid, on its surface, at the mean of its
// lattice corners. Given by build() (T-vertices of finer neighbours) and by stitch() (seam
// vertices of another surface).
void addCentreVertex(PatchMesh& mesh, Patch& p) {
    glm::dvec2 l(0.0);
    for (int k = 0; k < p.cornerCount; ++k) l += p.lattice[static_cast<std::size_t>(k)] / double(p.cornerCount);
    p.centreVertex = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(p.centre);
    mesh.vertexSurface.push_back(p.surface);
    mesh.vertexLattice.push_back(l);
}

// Stitching where surfaces meet (issue 19 item 10): along an edge of one surface that lies on
// another (a block's bottom edge on the floor, a wall's bottom edge on the floor's border, the
// block's faces at its corners, the ceiling's pieces around the light), each side's vertices
// are put on the other side's patch edges there, and vertices within a few µm of each other
// get one position. Display triangles then meet vertex to vertex across surfaces: no
// T-junction, so the rasteriser leaves no pixel open between them (a crack showing the
// background or a body's inside). Vertices stay per surface (smoothing never mixes surfaces).
void stitch(PatchMesh& mesh, bool coplanarOnly) {
    mesh.seamVertices.clear();
    const std::size_t nv0 = mesh.vertices.size();
    std::vector<int> parent(nv0);
    for (std::size_t v = 0; v < nv0; ++v) parent[v] = static_cast<int>(v);
    std::function<int(int)> find = [&](int v) {
        while (parent[static_cast<std::size_t>(v)] != v) v = parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
        return v;
    };
    auto unite = [&](int a, int b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b); // the lower id's position
    };
    std::vector<std::vector<int>> bySurface(mesh.surfaces.size());
    for (std::size_t v = 0; v < nv0; ++v) bySurface[static_cast<std::size_t>(mesh.vertexSurface[v])].push_back(static_cast<int>(v));
    std::vector<std::vector<int>> patchesOf(mesh.surfaces.size());
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) patchesOf[static_cast<std::size_t>(mesh.patches[i].surface)].push_back(static_cast<int>(i));
    std::map<std::tuple<int, int, int, int>, int> inserted; // (surface, a, b, class of x) -> vertex
    std::vector<char> grown(mesh.patches.size(), 0);
    auto moved = [&](const Patch& p) {
        for (int k = 0; k < p.cornerCount; ++k)
            if (find(p.corners[static_cast<std::size_t>(k)]) != p.corners[static_cast<std::size_t>(k)]) return true;
        return false;
    };
    for (std::size_t st = 0; st < mesh.surfaces.size(); ++st) {
        const auto& c = mesh.surfaces[st].vertices;
        for (std::size_t k = 0; k < c.size(); ++k) {
            const glm::dvec3 a = c[k], b = c[(k + 1) % c.size()];
            const double len = glm::length(b - a);
            const glm::dvec3 dir = (b - a) / len;
            // A few µm: rounding of two surfaces' own corners (1e-16) and a refined patch's
            // corner on a trapezoid (the bilinear map's lattice midpoint lies ~1e-6 m off the
            // straight edge) stitch; the Cornell red wall, 20 µm off the back wall's plane
            // (scenes.cpp), does not.
            const double tol = 1e-5 * (1.0 + len);
            auto onLine = [&](const glm::dvec3& x, double& t) {
                t = glm::dot(x - a, dir);
                return glm::length(x - a - t * dir) < tol;
            };
            auto onEdge = [&](const glm::dvec3& x, double& t) { return onLine(x, t) && t > -tol && t < len + tol; };
            for (std::size_t ss = 0; ss < mesh.surfaces.size(); ++ss) {
                if (ss == st) continue;
                const auto& d = mesh.surfaces[ss].vertices;
                const glm::dvec3 n = polygonNormal(d);
                if (coplanarOnly && glm::dot(n, polygonNormal(c)) < 1.0 - 1e-9) continue;
                if (std::abs(glm::dot(a - d[0], n)) > tol || std::abs(glm::dot(b - d[0], n)) > tol) continue;
                const glm::dvec3 mid = 0.5 * (a + b);
                bool in = true;
                for (std::size_t m = 0; m < d.size(); ++m)
                    in = in && glm::dot(glm::cross(d[(m + 1) % d.size()] - d[m], mid - d[m]), n) >= -tol * glm::length(d[(m + 1) % d.size()] - d[m]);
                if (!in) continue;
                // The seam: this edge of surface st lies on surface ss. Each side's vertices on
                // it go onto the other side's outline segments along it.
                for (int side = 0; side < 2; ++side) {
                    const std::size_t into = side == 0 ? st : ss, from = side == 0 ? ss : st;
                    std::vector<std::pair<double, int>> xs;
                    double t = 0.0;
                    for (int v : bySurface[from])
                        if (onEdge(mesh.vertices[static_cast<std::size_t>(v)], t)) xs.emplace_back(t, v);
                    if (xs.empty()) continue;
                    std::sort(xs.begin(), xs.end());
                    for (int pi : patchesOf[into]) {
                        Patch& p = mesh.patches[static_cast<std::size_t>(pi)];
                        int along = 0; // a patch edge along the seam has both its corners on its line
                        for (int k2 = 0; k2 < p.cornerCount; ++k2)
                            along += onLine(mesh.vertices[static_cast<std::size_t>(p.corners[static_cast<std::size_t>(k2)])], t) ? 1 : 0;
                        if (along < 2) continue;
                        for (const auto& [tx, x] : xs) {
                            const glm::dvec3 px = mesh.vertices[static_cast<std::size_t>(x)];
                            for (std::size_t o = 0; o < p.outline.size(); ++o) {
                                const int va = p.outline[o], vb = p.outline[(o + 1) % p.outline.size()];
                                double ta = 0.0, tb = 0.0;
                                if (!onLine(mesh.vertices[static_cast<std::size_t>(va)], ta) ||
                                    !onLine(mesh.vertices[static_cast<std::size_t>(vb)], tb))
                                    continue;
                                const double lo = std::min(ta, tb), hi = std::max(ta, tb);
                                if (tx < lo - tol || tx > hi + tol) continue;
                                if (std::abs(tx - ta) < tol) { unite(va, x); break; }
                                if (std::abs(tx - tb) < tol) { unite(vb, x); break; }
                                // Strictly inside the segment: a new vertex of this surface there,
                                // shared by the patches on both sides of the segment.
                                const int e0 = std::min(va, vb), e1 = std::max(va, vb);
                                const auto key = std::make_tuple(static_cast<int>(into), e0, e1, find(x));
                                auto it = inserted.find(key);
                                int nv;
                                if (it != inserted.end()) {
                                    nv = it->second;
                                } else {
                                    nv = static_cast<int>(mesh.vertices.size());
                                    const double f = (tx - ta) / (tb - ta);
                                    const glm::dvec2 la = mesh.vertexLattice[static_cast<std::size_t>(va)],
                                                     lb = mesh.vertexLattice[static_cast<std::size_t>(vb)];
                                    glm::dvec2 l = la + f * (lb - la);
                                    if (la.x == lb.x) l.x = la.x; // stays on a lattice line (border tests)
                                    if (la.y == lb.y) l.y = la.y;
                                    mesh.vertices.push_back(px);
                                    mesh.vertexSurface.push_back(static_cast<int>(into));
                                    mesh.vertexLattice.push_back(l);
                                    parent.push_back(nv);
                                    unite(nv, x);
                                    inserted.emplace(key, nv);
                                    mesh.seamVertices.push_back({nv, va, vb, f});
                                }
                                p.outline.insert(p.outline.begin() + static_cast<std::ptrdiff_t>(o + 1), nv);
                                grown[static_cast<std::size_t>(pi)] = 1;
                                break;
                            }
                        }
                    }
                }
            }
        }
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        mesh.vertices[v] = mesh.vertices[static_cast<std::size_t>(find(static_cast<int>(v)))];
    // Corners moved by up to the tolerance: area and centroid again from the corners (the form
    // factors take a patch whose area falls short of its polygon's for one partly inside a body).
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        Patch& p = mesh.patches[i];
        if (!grown[i] && !moved(p)) continue;
        const auto poly = mesh.cornersOf(static_cast<int>(i));
        p.area = polygonArea(poly);
        polygonCentroid(poly, p.centre);
    }
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        Patch& p = mesh.patches[i];
        if (grown[i] && p.centreVertex < 0) addCentreVertex(mesh, p);
    }
}

// Builds the mesh from patch descriptions: shares vertices per surface (lattice keys),
// computes geometry and outlines with their T-vertices.
void build(PatchMesh& mesh, const std::vector<PatchDesc>& descs) {
    mesh.vertices.clear();
    mesh.vertexSurface.clear();
    mesh.vertexLattice.clear();
    mesh.patches.clear();
    mesh.patches.reserve(descs.size());
    std::map<std::tuple<int, double, double>, int> ids;
    auto vertexId = [&](int surface, const glm::dvec2& l) {
        const auto key = std::make_tuple(surface, l.x, l.y);
        auto it = ids.find(key);
        if (it != ids.end()) return it->second;
        const int id = static_cast<int>(mesh.vertices.size());
        const auto& surf = mesh.surfaces[static_cast<std::size_t>(surface)];
        mesh.vertices.push_back(latticePoint(surf, mesh.grid[static_cast<std::size_t>(surface)], l));
        mesh.vertexSurface.push_back(surface);
        mesh.vertexLattice.push_back(l);
        ids.emplace(key, id);
        return id;
    };
    for (const PatchDesc& d : descs) {
        Patch p;
        p.surface = d.surface;
        p.level = d.level;
        p.cornerCount = d.count;
        p.lattice = d.lat;
        const Surface& s = mesh.surfaces[static_cast<std::size_t>(d.surface)];
        std::vector<glm::dvec3> poly;
        for (int k = 0; k < d.count; ++k) {
            p.corners[static_cast<std::size_t>(k)] = vertexId(d.surface, d.lat[static_cast<std::size_t>(k)]);
            poly.push_back(mesh.vertices[static_cast<std::size_t>(p.corners[static_cast<std::size_t>(k)])]);
        }
        p.area = polygonArea(poly);
        p.normal = polygonNormal(s.vertices); // the surface's: identical for all its patches
        // Centroid: triangles (0,k,k+1) weighted by their areas.
        glm::dvec3 c(0.0);
        double wsum = 0.0;
        for (int k = 1; k + 1 < d.count; ++k) {
            const double a = 0.5 * glm::length(glm::cross(poly[static_cast<std::size_t>(k)] - poly[0],
                                                          poly[static_cast<std::size_t>(k + 1)] - poly[0]));
            c += a * (poly[0] + poly[static_cast<std::size_t>(k)] + poly[static_cast<std::size_t>(k + 1)]) / 3.0;
            wsum += a;
        }
        p.centre = wsum > 0.0 ? c / wsum : poly[0];
        p.reflectivity = s.reflectivity;
        p.emission = s.emission;
        p.group = d.group;
        mesh.patches.push_back(std::move(p));
    }
    // Outlines: the vertices a finer neighbour put on an edge are its midpoints, the midpoints'
    // midpoints and so on (a split cuts at 0.5·(a + b) on the lattice, exact in double: the same
    // number from either side of the edge), so they are found by halving the edge recursively
    // (the mesher of contactTriangles splits a region's border edge the same way). 12 levels:
    // the lattice's resolution.
    std::function<void(Patch&, int, const glm::dvec2&, const glm::dvec2&, int)> between =
        [&](Patch& p, int surface, const glm::dvec2& a, const glm::dvec2& b, int depth) {
            if (depth <= 0) return;
            const glm::dvec2 m = 0.5 * (a + b);
            auto it = ids.find(std::make_tuple(surface, m.x, m.y));
            if (it == ids.end()) return;
            between(p, surface, a, m, depth - 1);
            p.outline.push_back(it->second);
            between(p, surface, m, b, depth - 1);
        };
    // An edge along a lattice line (every grid edge) takes every vertex on it: the mesher of
    // contactTriangles may split a region's border edge at a point that is not a midpoint.
    std::map<std::tuple<int, int, double>, std::vector<std::pair<double, int>>> onLine; // (surface, axis, value)
    for (const auto& [key, id] : ids) {
        const auto& [surface, lx, ly] = key;
        onLine[{surface, 0, lx}].emplace_back(ly, id);
        onLine[{surface, 1, ly}].emplace_back(lx, id);
    }
    for (auto& [key, list] : onLine) std::sort(list.begin(), list.end());
    for (Patch& p : mesh.patches) {
        p.outline.clear();
        for (int k = 0; k < p.cornerCount; ++k) {
            p.outline.push_back(p.corners[static_cast<std::size_t>(k)]);
            const glm::dvec2 a = p.lattice[static_cast<std::size_t>(k)];
            const glm::dvec2 b = p.lattice[static_cast<std::size_t>((k + 1) % p.cornerCount)];
            if (a.x == b.x || a.y == b.y) {
                const int axis = a.x == b.x ? 0 : 1;
                const double lo = axis == 0 ? a.y : a.x, hi = axis == 0 ? b.y : b.x;
                const auto it = onLine.find({p.surface, axis, axis == 0 ? a.x : a.y});
                if (it == onLine.end()) continue;
                const auto& list = it->second;
                std::vector<int> found;
                for (const auto& [t, id] : list)
                    if (t > std::min(lo, hi) && t < std::max(lo, hi)) found.push_back(id);
                if (lo > hi) std::reverse(found.begin(), found.end());
                p.outline.insert(p.outline.end(), found.begin(), found.end());
                continue;
            }
            between(p, p.surface, a, b, 12);
        }
        p.centreVertex = -1;
        if (p.outline.size() > static_cast<std::size_t>(p.cornerCount)) addCentreVertex(mesh, p);
    }
    // The grid mesh stitches pieces of one plane (a ceiling around its lamps): their shared
    // edges are cut differently on each side, and the T-junctions left 1 px cracks.
    stitch(mesh, !mesh.conforming);
    // Shooting groups: numbered densely (a triangle's grid leaves some coarse cells empty),
    // then members, area, centroid; the frame comes from the surface.
    std::map<int, int> dense;
    for (const Patch& p : mesh.patches)
        if (p.group >= 0) dense.emplace(p.group, 0);
    int groups = 0;
    for (auto& [id, to] : dense) to = groups++;
    for (Patch& p : mesh.patches)
        if (p.group >= 0) p.group = dense[p.group];
    mesh.groups.assign(static_cast<std::size_t>(groups), ShooterGroup{});
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        if (p.group < 0) continue;
        ShooterGroup& g = mesh.groups[static_cast<std::size_t>(p.group)];
        g.members.push_back(static_cast<int>(i));
        g.area += p.area;
        g.centre += p.area * p.centre;
        g.surface = p.surface;
        g.normal = p.normal;
    }
    for (ShooterGroup& g : mesh.groups) {
        if (g.area > 0.0) g.centre /= g.area;
        const auto& c = mesh.surfaces[static_cast<std::size_t>(g.surface)].vertices;
        const glm::dvec3 e = c[1] - c[0];
        g.u = glm::normalize(e - glm::dot(e, g.normal) * g.normal);
    }
}

// Whether the first surface along d from o is met from behind (true) or from the front or
// not at all (false). nearestPatch gives −1 for a back side and for nothing at all; `visible`
// tells them apart.
bool metFromBehind(const PatchBvh& bvh, const glm::dvec3& o, const glm::dvec3& d) {
    if (bvh.nearestPatch(o, d, 0.0, 1e4) >= 0) return false;
    return !bvh.visible(o, o + 1e4 * d);
}

// A point of a surface is covered when it lies inside a body (the floor under a block, which
// has no bottom face): the first surface along its normal is met from behind, and so it is
// along grazing directions. The grazing rays tell a body standing on the surface (they meet
// its sides from inside) from one hanging just off it: a panel hanging 2 cm under a ceiling
// with no top face (the classroom's lamps until the fifth session), tested along the normal
// only, had the ceiling above it dropped, which showed the background through the gap (the
// crack census: 852 px). 88° from the normal leaves a 2 cm gap within 2/tan(2°) = 57 cm of a
// panel's edge; 60° covers bodies the grazing rays would pass under. Eight azimuths.
// A body whose top is another body's face turned towards it (a table's side panel, closed by
// the table top's underside, which faces down into it) is met from the front along the
// normal: there every ray at 88° meeting a back face marks it covered (a floor patch of the
// classroom whose centre fell inside a panel, 2 cm thick, was drawn black in flat mode).
bool covered(const PatchBvh& bvh, const glm::dvec3& p, const glm::dvec3& n) {
    const glm::dvec3 o = p + 1e-7 * (1.0 + glm::length(p)) * n;
    const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t1 = glm::normalize(glm::cross(n, a)), t2 = glm::cross(n, t1);
    constexpr double kPi = 3.14159265358979323846;
    auto ring = [&](double elevation) {
        const double polar = elevation * kPi / 180.0;
        for (int k = 0; k < 8; ++k) {
            const double phi = k * kPi / 4.0;
            const glm::dvec3 d = std::cos(polar) * n +
                                 std::sin(polar) * (std::cos(phi) * t1 + std::sin(phi) * t2);
            if (!metFromBehind(bvh, o, d)) return false;
        }
        return true;
    };
    if (!metFromBehind(bvh, o, n)) return ring(88.0);
    return ring(60.0) && ring(88.0);
}

glm::dvec3 pointOn(const std::vector<glm::dvec3>& c, double u, double v) {
    if (c.size() == 3) {
        const double su = std::sqrt(u);
        return c[0] + su * (1 - v) * (c[1] - c[0]) + su * v * (c[2] - c[0]);
    }
    return (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
}

// The exposed part of a patch whose 8×8 exposure samples all lie inside a body, found from
// its corners: where a body's footprint edge cuts a corner (or a strip) off the patch narrower
// than the samples' 1/16 inset, that sliver showed the background through a 1 px hole beside
// the Cornell box's short block (the crack census) when the patch was dropped. A convex
// footprint that covers every corner of a convex patch covers the whole patch, so a sliver
// has an exposed corner. The exposed polygon is the exposed corners plus, on each edge between
// an exposed and a covered corner, the point where the cover begins (bisection to 2^-40 of the
// edge): exact for one straight footprint edge crossing the patch. Returns false when every
// corner is covered (the patch is dropped, as before); else its exposed area and centroid.
// "Covered" here is "under a body's top" (the normal ray met from behind), as mesh_test's
// edge checks ask: these points lie within a hair of a footprint's border, where covered()'s
// grazing rays can leave past the body's side at its foot (the conforming mesh's triangles
// inside a footprint, their corners on its border, read as exposed by it).
bool exposedSliver(const PatchBvh& bvh, const std::vector<glm::dvec3>& c, const glm::dvec3& n, double& area,
                   glm::dvec3& centroid) {
    glm::dvec3 mid(0.0);
    for (const glm::dvec3& q : c) mid += q / static_cast<double>(c.size());
    // A point of the patch just inside from x, 1e-3 of the way to the middle (~20 µm on the
    // lab's patches): a corner on a footprint's border is decided by the side the patch lies on.
    auto inset = [&](const glm::dvec3& x) { return x + 1e-3 * (mid - x); };
    auto under = [&](const glm::dvec3& x) { return metFromBehind(bvh, x + 1e-7 * (1.0 + glm::length(x)) * n, n); };
    std::vector<char> open(c.size());
    bool any = false;
    for (std::size_t k = 0; k < c.size(); ++k) any |= (open[k] = !under(inset(c[k]))) != 0;
    if (!any) return false;
    std::vector<glm::dvec3> poly;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const std::size_t k1 = (k + 1) % c.size();
        if (open[k]) poly.push_back(inset(c[k]));
        if (open[k] == open[k1]) continue;
        double lo = 0.0, hi = 1.0; // lo: on open[k]'s side, hi: on open[k1]'s side
        for (int it = 0; it < 40; ++it) {
            const double t = 0.5 * (lo + hi);
            (!under(inset(c[k] + t * (c[k1] - c[k]))) == (open[k] != 0) ? lo : hi) = t;
        }
        poly.push_back(inset(c[k] + (open[k] ? lo : hi) * (c[k1] - c[k])));
    }
    area = poly.size() >= 3 ? polygonArea(poly) : 0.0;
    if (!(area > 0.0)) return false;
    if (!polygonCentroid(poly, centroid)) return false;
    // The centroid of a non-convex exposed part may lie under the body: an exposed corner then.
    if (under(centroid))
        for (std::size_t k = 0; k < c.size(); ++k)
            if (open[k]) {
                centroid = inset(c[k]);
                break;
            }
    return true;
}

// Builds the mesh, then fits it to where bodies stand on surfaces (issue 19 item 10: black
// blotches on the floor at the base of the Cornell box's blocks). A patch wholly inside a body
// is dropped: nobody sees it, and its hemicube saw only the body's inside (B = 0). A patch
// partly inside keeps its polygon for drawing (the covered part is hidden by the body) but its
// area becomes the exposed area and its centre the centroid of the exposed part, so its
// hemicube (cast from the centre) and its power are those of what is seen: before, a patch
// whose centre lay under the block was drawn black where it showed. Exposure is sampled on an
// 8×8 grid of the patch (a patch is first tested at its centre and four points near its
// corners; most are wholly exposed). `parents` (refinement) is filtered like `descs`.
void buildFitted(PatchMesh& mesh, std::vector<PatchDesc>& descs, std::vector<int>* parents) {
    build(mesh, descs);
    const std::size_t n = mesh.patches.size();
    std::vector<double> fraction(n, 1.0);
    std::vector<glm::dvec3> centre(n);
    for (std::size_t i = 0; i < n; ++i) centre[i] = mesh.patches[i].centre;
    {
        const PatchBvh bvh(mesh);
        for (std::size_t i = 0; i < n; ++i) {
            const Patch& p = mesh.patches[i];
            const auto c = mesh.cornersOf(static_cast<int>(i));
            bool any = false;
            for (const glm::dvec2 uv : {glm::dvec2(0.5, 0.5), glm::dvec2(0.02, 0.02), glm::dvec2(0.98, 0.02),
                                        glm::dvec2(0.98, 0.98), glm::dvec2(0.02, 0.98)})
                any |= covered(bvh, pointOn(c, uv.x, uv.y), p.normal);
            if (!any) continue;
            constexpr int g = 8;
            int hits = 0;
            glm::dvec3 sum(0.0);
            std::vector<glm::dvec3> open;
            for (int a = 0; a < g; ++a)
                for (int b = 0; b < g; ++b) {
                    const glm::dvec3 q = pointOn(c, (a + 0.5) / g, (b + 0.5) / g);
                    if (covered(bvh, q, p.normal)) continue;
                    ++hits;
                    sum += q;
                    open.push_back(q);
                }
            fraction[i] = static_cast<double>(hits) / (g * g);
            if (hits == 0) {
                double exposed = 0.0;
                if (exposedSliver(bvh, c, p.normal, exposed, centre[i])) fraction[i] = exposed / p.area;
                continue;
            }
            centre[i] = sum / static_cast<double>(hits);
            // Every sample open but the centre itself inside a body (a floor patch whose centre
            // falls inside a table's 2 cm side panel, between the samples): the centre moves
            // to the nearest sample, the area stays whole. Else a wholly open patch keeps its
            // centroid.
            if (hits == g * g) centre[i] = p.centre;
            if (covered(bvh, centre[i], p.normal)) { // a non-convex exposed part: its nearest sample
                glm::dvec3 best = open.front();
                for (const glm::dvec3& q : open)
                    if (glm::length(q - centre[i]) < glm::length(best - centre[i])) best = q;
                centre[i] = best;
            }
        }
    }
    std::vector<std::pair<double, glm::dvec3>> fit; // per kept patch
    std::vector<PatchDesc> kept;
    std::vector<int> keptParents;
    for (std::size_t i = 0; i < n; ++i) {
        if (fraction[i] == 0.0) continue;
        kept.push_back(descs[i]);
        if (parents) keptParents.push_back((*parents)[i]);
        fit.emplace_back(fraction[i], centre[i]);
    }
    if (kept.size() != n) {
        descs = std::move(kept);
        if (parents) *parents = std::move(keptParents);
        build(mesh, descs);
    }
    bool any = false;
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        Patch& p = mesh.patches[i];
        if (fit[i].first == 1.0 && fit[i].second == p.centre) continue;
        p.area *= fit[i].first;
        p.centre = fit[i].second;
        any = true;
    }
    if (!any || mesh.groups.empty()) return;
    // Shooting groups: area and centroid of what is exposed; a group's hemicube eye (its
    // centroid) under a body would shoot the group's power into the body's inside, so such a
    // centroid moves to the nearest member's (exposed) centre.
    const PatchBvh bvh(mesh);
    for (ShooterGroup& g : mesh.groups) {
        g.area = 0.0;
        g.centre = glm::dvec3(0.0);
        for (int m : g.members) {
            const Patch& p = mesh.patches[static_cast<std::size_t>(m)];
            g.area += p.area;
            g.centre += p.area * p.centre;
        }
        if (g.area > 0.0) g.centre /= g.area;
        if (g.members.empty() || !covered(bvh, g.centre, g.normal)) continue;
        glm::dvec3 best = mesh.patches[static_cast<std::size_t>(g.members.front())].centre;
        for (int m : g.members) {
            const glm::dvec3& c = mesh.patches[static_cast<std::size_t>(m)].centre;
            if (glm::length(c - g.centre) < glm::length(best - g.centre)) best = c;
        }
        g.centre = best;
    }
}

} // namespace

std::vector<glm::dvec3> PatchMesh::cornersOf(int patch) const {
    const Patch& p = patches.at(static_cast<std::size_t>(patch));
    std::vector<glm::dvec3> out;
    for (int k = 0; k < p.cornerCount; ++k)
        out.push_back(vertices[static_cast<std::size_t>(p.corners[static_cast<std::size_t>(k)])]);
    return out;
}

double PatchMesh::totalArea() const {
    double a = 0.0;
    for (const Patch& p : patches) a += p.area;
    return a;
}

double patchAspect(const PatchMesh& mesh, int patch) {
    const Patch& p = mesh.patches.at(static_cast<std::size_t>(patch));
    const auto c = mesh.cornersOf(patch);
    double longest = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) longest = std::max(longest, glm::length(c[(k + 1) % c.size()] - c[k]));
    const double area = polygonArea(c); // the polygon's shape, not its exposed area
    if (!(area > 0.0)) return std::numeric_limits<double>::infinity();
    return longest * longest / ((p.cornerCount == 3 ? 2.0 : 1.0) * area);
}

PatchMesh meshScene(const Scene& scene, const MeshConfig& config) {
    if (!(config.maxEdge > 0.0) || !std::isfinite(config.maxEdge))
        throw std::invalid_argument("radiosity meshing: maxEdge " + std::to_string(config.maxEdge) +
                                    " must be a positive length");
    validate(scene);
    PatchMesh mesh;
    mesh.surfaces = scene.surfaces;
    mesh.closed = scene.closed;
    mesh.conforming = config.conforming;
    if (!(config.shooterEdge >= 0.0) || !std::isfinite(config.shooterEdge))
        throw std::invalid_argument("radiosity meshing: shooterEdge must be >= 0");
    const bool grouped = config.shooterEdge > config.maxEdge;
    std::vector<PatchDesc> descs;
    double total = 0.0;
    int groupBase = 0;
    struct Layout {
        int fu = 0, cu = 1, mu = 1, fv = 0, cv = 1, mv = 1; // fine cells, groups, cells per group
    };
    auto layoutOf = [&](std::size_t si) {
        const auto& c = scene.surfaces[si].vertices;
        Layout L;
        int &fu = L.fu, &cu = L.cu, &mu = L.mu, &fv = L.fv, &cv = L.cv, &mv = L.mv;
        auto cells = [&](double len, double edge) { return std::max(1.0, std::ceil(len / edge - 1e-9)); };
        // The fine grid depends on maxEdge only (so meshes with and without groups, or with
        // different group sizes, have the same patches); a shooting group is a block of `per`
        // fine cells along each direction, `per` = how many fine cells fit in shooterEdge.
        auto counts = [&](double len, int& fine, int& coarse, int& per) {
            if (fine < 1) fine = static_cast<int>(cells(len, config.maxEdge));
            per = grouped ? std::max(1, static_cast<int>(std::floor(config.shooterEdge / (len / fine) + 1e-9))) : 1;
            coarse = (fine + per - 1) / per;
        };
        if (c.size() == 3) {
            const double longest = std::max({glm::length(c[1] - c[0]), glm::length(c[2] - c[1]),
                                             glm::length(c[0] - c[2])});
            counts(longest, fu, cu, mu);
            fv = fu;
            cv = cu;
            mv = mu;
        } else {
            const double U = std::max(glm::length(c[1] - c[0]), glm::length(c[2] - c[3]));
            const double V = std::max(glm::length(c[3] - c[0]), glm::length(c[2] - c[1]));
            // Bounded aspect: a long thin surface (a table top's 3 cm edge strip, a lamp
            // shade's rim) is cut across its length too, so no cell is more than
            // kMaxGridAspect times longer than wide (a 1.2 m × 3 cm strip at maxEdge 0.4 m
            // was 3 cells of aspect 13).
            fu = static_cast<int>(cells(U, config.maxEdge));
            fv = static_cast<int>(cells(V, config.maxEdge));
            fu = std::max(fu, static_cast<int>(std::ceil(U * fv / (kMaxGridAspect * V) - 1e-9)));
            fv = std::max(fv, static_cast<int>(std::ceil(V * fu / (kMaxGridAspect * U) - 1e-9)));
            counts(U, fu, cu, mu);
            counts(V, fv, cv, mv);
        }
        return L;
    };
    std::vector<glm::ivec2> grids;
    for (std::size_t si = 0; si < scene.surfaces.size(); ++si) {
        const Layout L = layoutOf(si);
        grids.emplace_back(L.fu, L.fv);
    }
    for (std::size_t si = 0; si < scene.surfaces.size(); ++si) {
        const auto& c = scene.surfaces[si].vertices;
        const int surface = static_cast<int>(si);
        const Layout L = layoutOf(si);
        const int fu = L.fu, fv = L.fv, cu = L.cu, cv = L.cv, mu = L.mu, mv = L.mv;
        const double nu = fu, nv = fv;
        total += nu * nv;
        if (total > kMaxPatches) break;
        mesh.grid.emplace_back(fu, fv);
        const glm::ivec2 g = mesh.grid.back();
        const double S = kLatticeScale;
        auto groupOf = [&](int i, int j) { return grouped ? groupBase + (j / mv) * cu + i / mu : -1; };
        if (c.size() == 3) {
            for (int j = 0; j < g.x; ++j)
                for (int i = 0; i + j < g.x; ++i) {
                    descs.push_back({surface, 0, 3,
                                     {glm::dvec2(i * S, j * S), glm::dvec2((i + 1) * S, j * S),
                                      glm::dvec2(i * S, (j + 1) * S), glm::dvec2(0.0)},
                                     groupOf(i, j)});
                    if (i + j + 1 < g.x)
                        descs.push_back({surface, 0, 3,
                                         {glm::dvec2((i + 1) * S, j * S),
                                          glm::dvec2((i + 1) * S, (j + 1) * S),
                                          glm::dvec2(i * S, (j + 1) * S), glm::dvec2(0.0)},
                                         groupOf(i, j)});
                }
        } else {
            std::vector<char> ring;
            for (const auto& t : !config.conforming ? std::vector<std::vector<glm::dvec2>>{} : contactTriangles(scene, grids, si, config.maxEdge, ring)) {
                glm::dvec2 m(0.0);
                std::array<glm::dvec2, 4> lat{};
                for (std::size_t k = 0; k < t.size(); ++k) {
                    m += t[k] / (static_cast<double>(t.size()) * S);
                    lat[k] = t[k];
                }
                const int i = std::clamp(static_cast<int>(std::floor(m.x)), 0, g.x - 1);
                const int j = std::clamp(static_cast<int>(std::floor(m.y)), 0, g.y - 1);
                descs.push_back({surface, 0, static_cast<int>(t.size()), lat, groupOf(i, j)});
            }
            for (int j = 0; j < g.y; ++j)
                for (int i = 0; i < g.x; ++i)
                    if (ring.empty() || !ring[static_cast<std::size_t>(j * g.x + i)])
                    descs.push_back({surface, 0, 4,
                                     {glm::dvec2(i * S, j * S), glm::dvec2((i + 1) * S, j * S),
                                      glm::dvec2((i + 1) * S, (j + 1) * S),
                                      glm::dvec2(i * S, (j + 1) * S)},
                                     groupOf(i, j)});
        }
        if (grouped) groupBase += cu * cv;
    }
    if (total > kMaxPatches)
        throw std::invalid_argument("radiosity meshing: maxEdge " + std::to_string(config.maxEdge) +
                                    " m gives more than 4 million patches; use a larger patch size");
    buildFitted(mesh, descs, nullptr);
    return mesh;
}

int refineAdaptive(PatchMesh& mesh, const std::vector<glm::dvec3>& B, const RefineConfig& config,
                   std::vector<int>* parentOf) {
    const std::size_t n = mesh.patches.size();
    if (B.size() != n)
        throw std::invalid_argument("radiosity refine: " + std::to_string(B.size()) +
                                    " radiosities for " + std::to_string(n) + " patches");
    if (config.maxLevel > 12)
        throw std::invalid_argument("radiosity refine: maxLevel above 12 leaves the lattice");
    // 1. Brightness per patch (max channel) and the largest over the patches that do not emit:
    //    the threshold is about reflected light (an emitter ~17× brighter than the walls, as
    //    in the Cornell box, would otherwise make it split nothing). All patches if all emit.
    std::vector<double> lum(n);
    double top = 0.0, topAll = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        lum[i] = std::max({B[i].x, B[i].y, B[i].z});
        if (!std::isfinite(lum[i])) throw std::invalid_argument("radiosity refine: non-finite B");
        topAll = std::max(topAll, lum[i]);
        const glm::dvec3& e = mesh.patches[i].emission;
        if (e.x == 0.0 && e.y == 0.0 && e.z == 0.0) top = std::max(top, lum[i]);
    }
    if (top == 0.0) top = topAll;
    // 2. Neighbours through shared outline vertices (edge or corner contact, same surface).
    std::vector<std::vector<int>> byVertex(mesh.vertices.size());
    for (std::size_t i = 0; i < n; ++i)
        for (int v : mesh.patches[i].outline) byVertex[static_cast<std::size_t>(v)].push_back(static_cast<int>(i));
    std::vector<char> split(n, 0);
    std::size_t count = n;
    for (std::size_t i = 0; i < n && count + 3 <= config.maxPatches; ++i) {
        const Patch& p = mesh.patches[i];
        if (p.level >= config.maxLevel) continue;
        double shortest = 1e300;
        const auto cs = mesh.cornersOf(static_cast<int>(i));
        for (std::size_t k = 0; k < cs.size(); ++k)
            shortest = std::min(shortest, glm::length(cs[(k + 1) % cs.size()] - cs[k]));
        if (shortest < 2.0 * config.minEdge) continue; // children would be below minEdge
        double jump = 0.0;
        for (int v : p.outline)
            for (int q : byVertex[static_cast<std::size_t>(v)])
                jump = std::max(jump, std::abs(lum[static_cast<std::size_t>(q)] - lum[i]));
        if (jump > config.threshold * top) {
            split[i] = 1;
            count += static_cast<std::size_t>(3);
        }
    }
    // 3. New descriptions: unsplit patches as they are, split ones into 4 at edge midpoints.
    std::vector<PatchDesc> descs;
    std::vector<int> parents;
    int splits = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Patch& p = mesh.patches[i];
        const auto& L = p.lattice;
        if (!split[i]) {
            descs.push_back({p.surface, p.level, p.cornerCount, L, p.group});
            parents.push_back(static_cast<int>(i));
            continue;
        }
        ++splits;
        const int lv = p.level + 1;
        if (p.cornerCount == 3) {
            const glm::dvec2 ab = 0.5 * (L[0] + L[1]), bc = 0.5 * (L[1] + L[2]), ca = 0.5 * (L[2] + L[0]);
            const glm::dvec2 z(0.0);
            descs.push_back({p.surface, lv, 3, {L[0], ab, ca, z}, p.group});
            descs.push_back({p.surface, lv, 3, {ab, L[1], bc, z}, p.group});
            descs.push_back({p.surface, lv, 3, {ca, bc, L[2], z}, p.group});
            descs.push_back({p.surface, lv, 3, {ab, bc, ca, z}, p.group});
        } else {
            const glm::dvec2 m01 = 0.5 * (L[0] + L[1]), m12 = 0.5 * (L[1] + L[2]),
                             m23 = 0.5 * (L[2] + L[3]), m30 = 0.5 * (L[3] + L[0]),
                             mc = 0.25 * (L[0] + L[1] + L[2] + L[3]);
            descs.push_back({p.surface, lv, 4, {L[0], m01, mc, m30}, p.group});
            descs.push_back({p.surface, lv, 4, {m01, L[1], m12, mc}, p.group});
            descs.push_back({p.surface, lv, 4, {mc, m12, L[2], m23}, p.group});
            descs.push_back({p.surface, lv, 4, {m30, mc, m23, L[3]}, p.group});
        }
        for (int c = 0; c < 4; ++c) parents.push_back(static_cast<int>(i));
    }
    if (splits == 0) {
        if (parentOf) {
            parentOf->resize(n);
            for (std::size_t i = 0; i < n; ++i) (*parentOf)[i] = static_cast<int>(i);
        }
        return 0;
    }
    buildFitted(mesh, descs, &parents);
    if (parentOf) *parentOf = std::move(parents);
    return splits;
}

std::vector<std::array<int, 3>> displayTriangles(const PatchMesh& mesh, std::vector<int>* patchOf) {
    std::vector<std::array<int, 3>> tris;
    if (patchOf) patchOf->clear();
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        const auto& o = p.outline;
        if (p.centreVertex >= 0) {
            // T-vertices: fan from the centre through every outline vertex.
            for (std::size_t k = 0; k < o.size(); ++k) {
                tris.push_back({p.centreVertex, o[k], o[(k + 1) % o.size()]});
                if (patchOf) patchOf->push_back(static_cast<int>(i));
            }
            continue;
        }
        for (std::size_t k = 1; k + 1 < o.size(); ++k) { // plain polygon: fan from corner 0
            tris.push_back({o[0], o[k], o[k + 1]});
            if (patchOf) patchOf->push_back(static_cast<int>(i));
        }
    }
    return tris;
}

} // namespace wb::rad
