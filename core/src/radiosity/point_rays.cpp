#include "core/radiosity/point_rays.h"

#include "core/radiosity/closed_forms.h"
#include "core/raytrace/ray.h"

#include <glm/gtc/constants.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace wb::rad {

namespace {

// 16 points spread evenly over patch `id` (each stands for 1/16 of its area): a 4×4 grid of the
// bilinear quad, or a triangle's 16 sub-triangles (each edge cut in 4) at their centroids. The
// receivers next to a group's plane average F over them (the kernel is steep and convex across
// them). Before, triangles took their centre's value only: the floor's triangles at a block's
// foot (issue 19 item 10's conforming mesh) came out ~5-20% short of the block face's light.
std::vector<glm::dvec3> receiverPoints(const PatchMesh& mesh, int id) {
    const Patch& p = mesh.patches[static_cast<std::size_t>(id)];
    std::vector<glm::dvec3> c;
    for (int q = 0; q < p.cornerCount; ++q)
        c.push_back(mesh.vertices[static_cast<std::size_t>(p.corners[static_cast<std::size_t>(q)])]);
    std::vector<glm::dvec3> out;
    if (p.cornerCount == 4) {
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                const double u = (a + 0.5) / 4, v = (b + 0.5) / 4;
                out.push_back((1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3]);
            }
        return out;
    }
    // Sub-triangle (a, b) of the 4-cut: up ones' centroids at barycentric ((a, b) + 1/3) / 4,
    // down ones' at ((a, b) + 2/3) / 4.
    for (int a = 0; a < 4; ++a)
        for (int b = 0; a + b < 4; ++b) {
            const double u = (a + 1.0 / 3) / 4, v = (b + 1.0 / 3) / 4;
            out.push_back((1 - u - v) * c[0] + u * c[1] + v * c[2]);
            if (a + b < 3) {
                const double u2 = (a + 2.0 / 3) / 4, v2 = (b + 2.0 / 3) / 4;
                out.push_back((1 - u2 - v2) * c[0] + u2 * c[1] + v2 * c[2]);
            }
        }
    return out;
}

// The exposed part of patch `id` as convex pieces. A patch straddling a body's outline (the floor
// at a block's foot) keeps its whole polygon in the mesh and gets its exposed AREA from an 8×8
// sample grid (mesh.h); here the same grid's exposed cells, merged into strips along each grid
// row, stand for its exposed SHAPE: a receiver next to the block (its face) must not get F
// from the floor under it, nor lose the part in front of it to a uniform scale. A patch whose
// area is its polygon's is one piece.
std::vector<std::vector<glm::dvec3>> exposedPieces(const PatchMesh& mesh, const PatchBvh& bvh,
                                                   int id) {
    const Patch& p = mesh.patches[static_cast<std::size_t>(id)];
    auto c = mesh.cornersOf(id);
    const double full = polygonArea(c);
    if (p.area >= (1.0 - 1e-9) * full || c.size() != 4) return {c};
    auto at = [&](double u, double v) {
        return (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
    };
    // The meshing's test (mesh.cpp, covered()): the first surface along the normal met from
    // behind means inside a body.
    auto covered = [&](const glm::dvec3& q) {
        const glm::dvec3 o = q + 1e-7 * (1.0 + glm::length(q)) * p.normal;
        if (bvh.nearestPatch(o, p.normal, 0.0, 1e4) >= 0) return false;
        return !bvh.visible(o, o + 1e4 * p.normal);
    };
    constexpr int g = 8; // mesh.cpp's exposure grid
    std::vector<std::vector<glm::dvec3>> out;
    for (int b = 0; b < g; ++b) {
        int a = 0;
        while (a < g) {
            if (covered(at((a + 0.5) / g, (b + 0.5) / g))) {
                ++a;
                continue;
            }
            int e = a + 1;
            while (e < g && !covered(at((e + 0.5) / g, (b + 0.5) / g)))
                ++e;
            const double u0 = double(a) / g, u1 = double(e) / g, v0 = double(b) / g,
                         v1 = double(b + 1) / g;
            out.push_back({at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)});
            a = e;
        }
    }
    return out;
}

// One edge's term of Lambert's contour integral, exactly as pointToPolygon sums it for a
// polygon wholly in front of the point (closed_forms.cpp): a, b the edge's ends minus the
// point. term(b, a) = −term(a, b) bit for bit (the cross product's components and the dot
// products negate exactly), so two members sharing an edge can share its atan2.
double contourTerm(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& normal) {
    const glm::dvec3 c = glm::cross(a, b);
    const double cl = glm::length(c);
    if (!(cl > 0.0)) return 0.0; // pointToPolygon skips it: adding +0 leaves |sum| as it is
    return edgeAngle(cl, glm::dot(a, b)) * glm::dot(normal, c) / cl;
}

// A group's members as a grid of quads share their inner edges: a 6×6 group has 84 distinct
// edges for 144 member edges. The near field evaluates F(x → member) for every member from
// the same point x, so each distinct edge's term is computed once per point (the atan2 was
// ~20% of a default run: docs/bench/radiosity.md, "Lab 08 defaults").
struct SharedContours {
    std::vector<glm::dvec3> vertex;       // the members' corners, each once
    std::vector<std::array<int, 2>> edge; // vertex pairs, each undirected edge once
    // Per member: its corners and its edges in polygon order (edge id × 2 + 1 if traversed
    // from edge[1] to edge[0]); empty when the member is not its whole polygon (ragged:
    // pieces from exposedPieces), whose F is pointToPolygon's over its pieces.
    std::vector<std::vector<int>> corner, edgeOf;
};

SharedContours sharedContours(const PatchMesh& mesh, const ShooterGroup& sg,
                              const std::vector<std::vector<std::vector<glm::dvec3>>>& pieces) {
    SharedContours sc;
    std::map<int, int> vertexOf;               // mesh vertex id -> sc.vertex
    std::map<std::pair<int, int>, int> edgeOf; // (low, high) sc.vertex ids -> sc.edge
    sc.corner.resize(sg.members.size());
    sc.edgeOf.resize(sg.members.size());
    for (std::size_t m = 0; m < sg.members.size(); ++m) {
        const Patch& p = mesh.patches[static_cast<std::size_t>(sg.members[m])];
        const auto c = mesh.cornersOf(sg.members[m]);
        if (pieces[m].size() != 1 || pieces[m][0] != c) continue; // ragged: its own pieces
        for (int k = 0; k < p.cornerCount; ++k) {
            const int id = p.corners[static_cast<std::size_t>(k)];
            auto it = vertexOf.find(id);
            if (it == vertexOf.end()) {
                it = vertexOf.emplace(id, static_cast<int>(sc.vertex.size())).first;
                sc.vertex.push_back(mesh.vertices[static_cast<std::size_t>(id)]);
            }
            sc.corner[m].push_back(it->second);
        }
        const std::size_t q = sc.corner[m].size();
        for (std::size_t k = 0; k < q; ++k) {
            const int a = sc.corner[m][k], b = sc.corner[m][(k + 1) % q];
            const std::pair<int, int> key(std::min(a, b), std::max(a, b));
            auto it = edgeOf.find(key);
            if (it == edgeOf.end()) {
                it = edgeOf.emplace(key, static_cast<int>(sc.edge.size())).first;
                sc.edge.push_back({a, b});
            }
            const bool reversed = sc.edge[static_cast<std::size_t>(it->second)][0] != a;
            sc.edgeOf[m].push_back(it->second * 2 + (reversed ? 1 : 0));
        }
    }
    return sc;
}

} // namespace

std::vector<glm::dvec3> groupHull(const PatchMesh& mesh, int g) {
    const ShooterGroup& sg = mesh.groups.at(static_cast<std::size_t>(g));
    const glm::dvec3 u = sg.u, v = glm::cross(sg.normal, sg.u);
    struct P2 {
        double x, y;
        glm::dvec3 p;
    };
    std::vector<P2> pts;
    for (int m : sg.members) {
        const Patch& p = mesh.patches[static_cast<std::size_t>(m)];
        for (int c = 0; c < p.cornerCount; ++c) {
            const glm::dvec3 q =
                mesh.vertices[static_cast<std::size_t>(p.corners[static_cast<std::size_t>(c)])];
            // Snapped to a grid of 1e-9 of the group's size: corners on one edge of the group
            // get exactly the same coordinate (dot products differ in the last bits, and the
            // hull's collinearity test then dropped a true corner: the ceiling's group lost
            // one, its F came out 1.29).
            const double quantum = 1e-9 * std::sqrt(sg.area);
            auto snap = [&](double x) { return std::round(x / quantum) * quantum; };
            pts.push_back({snap(glm::dot(q - sg.centre, u)), snap(glm::dot(q - sg.centre, v)), q});
        }
    }
    std::sort(pts.begin(), pts.end(),
              [](const P2& a, const P2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    // Andrew's monotone chain, counter-clockwise about the normal (u, v, n right-handed);
    // collinear points dropped with a tolerance relative to the group's size.
    const double eps = 1e-12 * (1.0 + sg.area);
    auto cross = [](const P2& o, const P2& a, const P2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<P2> h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= eps)
            --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= eps)
            --k;
        h[k++] = pts[i - 1];
    }
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i + 1 < k; ++i)
        out.push_back(h[i].p);
    return out;
}

void groupGatherRow(const PatchMesh& mesh, const PatchBvh& bvh, int g, int k,
                    std::vector<float>& out, const GroupNearField* near, bool exactPieces) {
    if (k < 1 || k > 4096)
        throw std::invalid_argument("group ray row: k = " + std::to_string(k) + " outside 1..4096");
    const ShooterGroup& sg = mesh.groups.at(static_cast<std::size_t>(g));
    const std::size_t n = mesh.patches.size();
    const std::size_t members = sg.members.size();
    out.assign(n, 0.0f);
    if (members == 0) return;
    const std::vector<glm::dvec3> hull = groupHull(mesh, g);
    std::vector<glm::dvec3> target(members);
    for (std::size_t m = 0; m < members; ++m) {
        const Patch& p = mesh.patches[static_cast<std::size_t>(sg.members[m])];
        target[m] = rt::offsetRayOrigin(p.centre, p.normal);
    }
    auto seen = std::make_unique<std::atomic<bool>[]>(members);
    for (std::size_t m = 0; m < members; ++m)
        seen[m] = false;
    const std::size_t kk = std::min<std::size_t>(static_cast<std::size_t>(k), members);
    std::vector<double> cumArea(members); // members' areas summed in list order
    for (std::size_t m = 0; m < members; ++m)
        cumArea[m] = (m ? cumArea[m - 1] : 0.0) + mesh.patches[static_cast<std::size_t>(sg.members[m])].area;
    // A group whose members do not fill its hull: a floor group straddling a block's outline
    // (its members' exposed areas leave out the floor under the block) or a ragged one at a
    // surface's edge. Its hull would emit from the covered floor too: such groups shot 2-4%
    // more power than they had, every wall and the ceiling came out ~+1% against Cycles
    // (docs/bench/radiosity.md, "Why ours was off"). There F is summed over the members'
    // exposed parts (meshing keeps a straddling patch's whole polygon and gives it its exposed
    // area; the covered part lies under the block, behind the faces
    // that see it: exposedPieces).
    double hullArea = polygonArea(hull), membersArea = 0.0;
    std::vector<std::vector<std::vector<glm::dvec3>>> memberPieces;
    for (std::size_t m = 0; m < members; ++m)
        membersArea += mesh.patches[static_cast<std::size_t>(sg.members[m])].area;
    const bool ragged = exactPieces && membersArea < (1.0 - 1e-6) * hullArea;
    // Without pieces the hull stands for the group: its F scaled to the members' share of it.
    const double hullScale = !exactPieces && membersArea < hullArea ? membersArea / hullArea : 1.0;
    if (ragged)
        for (std::size_t m = 0; m < members; ++m)
            memberPieces.push_back(exposedPieces(mesh, bvh, sg.members[m]));
    // Near-field receivers: marked, their F not computed (the solver ignores their entries).
    // nearIndex[j]: j's place in near->receivers (−1: not near), to read the visibility its
    // near field has already cast from j to every member (GroupNearField::visible).
    std::vector<int> nearIndex;
    const bool nearVisible = near && near->members == members &&
                             near->visible.size() == near->receivers.size() * members;
    if (near) {
        nearIndex.assign(n, -1);
        for (std::size_t r = 0; r < near->receivers.size(); ++r)
            nearIndex[static_cast<std::size_t>(near->receivers[r])] = static_cast<int>(r);
    }
    // Whether pointToPolygon(x, nrm, ·) could be > 0: some vertex of G (hull, or the members'
    // pieces) strictly in front of x's tangent plane, the test its clipping makes first.
    auto inFront = [&](const glm::dvec3& x, const glm::dvec3& nrm) {
        auto any = [&](const std::vector<glm::dvec3>& poly) {
            for (const glm::dvec3& v : poly)
                if (glm::dot(v - x, nrm) > 0.0) return true;
            return false;
        };
        if (!ragged) return any(hull);
        for (const auto& pieces : memberPieces)
            for (const auto& piece : pieces)
                if (any(piece)) return true;
        return false;
    };
    auto formFactorAt = [&](const glm::dvec3& x, const glm::dvec3& nrm) {
        if (!ragged) return pointToPolygon(x, nrm, hull);
        double f = 0.0;
        for (const auto& pieces : memberPieces)
            for (const auto& piece : pieces)
                f += pointToPolygon(x, nrm, piece);
        return f;
    };
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t j) {
        const Patch& p = mesh.patches[j];
        // Receivers behind G's plane or in it get nothing (the ceiling's pieces around the
        // light share a plane: the contour integral from a point in the polygon's plane is not
        // 0 numerically, it gave row sums of 1.29). Whether G is in front of the receiver is
        // left to pointToPolygon, which clips G to the receiver's front half-space: testing
        // G's centroid instead dropped the floor in front of a block's face whenever the
        // floor group's centroid lay under the block (the face came out 92% dark).
        const double tiny = 1e-9 * std::sqrt(sg.area);
        if (p.group == g || glm::dot(sg.normal, p.centre - sg.centre) <= tiny) return;
        const bool nearJ = near && nearIndex[j] >= 0;
        double f = nearJ ? (inFront(p.centre, p.normal) ? 1.0 : 0.0)
                         : formFactorAt(p.centre, p.normal);
        // Receivers within two of their own sizes of G's plane (the walls meeting G along an
        // edge): the kernel is steep and convex across them and their centre's value runs low
        // (row sums of a closed cube 0.965-0.979): average a 4×4 grid of points instead.
        const double size = std::sqrt(p.area);
        if (glm::dot(sg.normal, p.centre - sg.centre) < 2.0 * size) {
            double acc = 0.0;
            for (const glm::dvec3& x : receiverPoints(mesh, static_cast<int>(j)))
                acc += nearJ ? (inFront(x, p.normal) ? 1.0 : 0.0) : formFactorAt(x, p.normal);
            f = acc / 16.0;
        }
        if (f <= 0.0) return;
        const glm::dvec3 from = rt::offsetRayOrigin(p.centre, p.normal);
        // V weighted by each sample's point-to-point kernel cos·cos/r²: the samples that carry
        // the form factor count most, and samples behind the receiver's plane (a floor group
        // running under a block, seen from the block's face) count not at all. Unweighted,
        // they counted as blocked and the block faces came out 20-50% dark.
        double seenW = 0.0, allW = 0.0;
        for (std::size_t s = 0; s < kk; ++s) {
            // Stratified over the member list (grid order: spread over the group), rotated by
            // a per-receiver offset over the whole list so that every member is looked at by
            // some receivers (A_live counts only members seen).
            // Stratified by AREA over the member list (list order: spread over the group), the
            // strata shifted by a per-receiver fraction so that every member is looked at by
            // some receivers (A_live counts only members seen). By index (before), a group of
            // cells and small triangles (the floor at a block's foot, conforming mesh) was
            // sampled where its many small members are: the triangles next to the block took
            // most samples, the floor seen from the ceiling came out too occluded (ceiling in
            // front of the light -1.28% against Cycles; -0.82% by area, the grid -0.73%).
            const double shift = static_cast<double>((j * 7919u) % members) / static_cast<double>(members);
            const double at = (static_cast<double>(s) + shift) / static_cast<double>(kk) * cumArea.back();
            const std::size_t m = std::min<std::size_t>(
                static_cast<std::size_t>(std::upper_bound(cumArea.begin(), cumArea.end(), at) - cumArea.begin()),
                members - 1);
            const glm::dvec3 d = target[m] - from;
            const double r2 = glm::dot(d, d);
            const double w = std::max(0.0, glm::dot(p.normal, d)) *
                             std::max(0.0, -glm::dot(sg.normal, d)) / (r2 * r2 + 1e-300);
            if (w <= 0.0) continue;
            allW += w;
            // A near receiver's ray from `from` to target[m] was cast by its near field (the
            // same two points, so the same answer): read it instead of casting it again.
            const bool vis =
                nearJ && nearVisible
                    ? near->visible[static_cast<std::size_t>(nearIndex[j]) * members + m] != 0
                    : bvh.visible(from, target[m]);
            if (vis) {
                seenW += w;
                seen[m] = true;
            }
        }
        if (nearJ) return; // its rays counted for A_live; the solver shoots it member by member
        const double V = allW > 0.0 ? seenW / allW : 1.0;
        out[j] = static_cast<float>(p.area * f * V * hullScale); // / A_live below
    });
    double live = 0.0;
    for (std::size_t m = 0; m < members; ++m)
        if (seen[m]) live += mesh.patches[static_cast<std::size_t>(sg.members[m])].area;
    if (live <= 0.0) {
        std::fill(out.begin(), out.end(), 0.0f);
        return;
    }
    for (float& x : out)
        x = static_cast<float>(x / live);
}

GroupNearField groupNearField(const PatchMesh& mesh, const PatchBvh& bvh, int g, double radius,
                              bool offsets, bool shareEdges) {
    const ShooterGroup& sg = mesh.groups.at(static_cast<std::size_t>(g));
    const std::size_t members = sg.members.size();
    GroupNearField nf;
    if (members == 0 || !(radius > 0.0)) return nf;
    std::vector<std::vector<std::vector<glm::dvec3>>> pieces(members);
    std::vector<glm::dvec3> target(members);
    for (std::size_t m = 0; m < members; ++m) {
        const int id = sg.members[m];
        const Patch& p = mesh.patches[static_cast<std::size_t>(id)];
        pieces[m] = exposedPieces(mesh, bvh, id);
        target[m] = rt::offsetRayOrigin(p.centre, p.normal);
    }
    const SharedContours shared = shareEdges ? sharedContours(mesh, sg, pieces) : SharedContours{};
    const double tiny = 1e-9 * std::sqrt(sg.area);
    nf.everyReceiver = true;
    for (std::size_t j = 0; j < mesh.patches.size(); ++j) {
        const Patch& p = mesh.patches[j];
        if (p.group == g || glm::dot(sg.normal, p.centre - sg.centre) <= tiny) continue;
        if (glm::length(p.centre - sg.centre) > radius) {
            nf.everyReceiver = false;
            continue;
        }
        nf.receivers.push_back(static_cast<int>(j));
    }
    nf.w.assign(nf.receivers.size() * members, 0.0f);
    nf.members = members;
    nf.visible.assign(nf.receivers.size() * members, 0);
    tbb::parallel_for(std::size_t(0), nf.receivers.size(), [&](std::size_t r) {
        const int j = nf.receivers[r];
        const Patch& p = mesh.patches[static_cast<std::size_t>(j)];
        // Receivers within two of their sizes of the group's plane (meeting it along an edge):
        // a 4×4 grid of points, as groupGatherRow does (the kernel is steep across them).
        const double size = std::sqrt(p.area);
        std::vector<glm::dvec3> pts;
        if (glm::dot(sg.normal, p.centre - sg.centre) < 2.0 * size) {
            pts = receiverPoints(mesh, j);
        } else {
            pts.push_back(p.centre);
        }
        const glm::dvec3 from = rt::offsetRayOrigin(p.centre, p.normal);
        // F(x → member) summed over the points x, member by member in the order of the
        // points (the same sums as pointToPolygon per member: bit-identical, tested).
        std::vector<double> fm(members, 0.0);
        const std::size_t nv = shared.vertex.size(), ne = shared.edge.size();
        std::vector<glm::dvec3> a(nv);
        std::vector<char> front(nv);
        std::vector<double> term(ne);
        std::vector<char> known(ne);
        for (const glm::dvec3& x : pts) {
            for (std::size_t v = 0; v < nv; ++v) {
                a[v] = shared.vertex[v] - x;
                front[v] = glm::dot(a[v], p.normal) > 0.0 ? 1 : 0;
            }
            std::fill(known.begin(), known.end(), 0);
            for (std::size_t m = 0; m < members; ++m) {
                bool whole = shareEdges && !shared.corner[m].empty();
                if (whole)
                    for (int v : shared.corner[m])
                        whole = whole && front[static_cast<std::size_t>(v)];
                if (!whole) { // clipped by x's tangent plane, or ragged: on its own
                    for (const auto& piece : pieces[m])
                        fm[m] += pointToPolygon(x, p.normal, piece);
                    continue;
                }
                double sum = 0.0;
                for (int code : shared.edgeOf[m]) {
                    const auto e = static_cast<std::size_t>(code / 2);
                    if (!known[e]) {
                        term[e] =
                            contourTerm(a[static_cast<std::size_t>(shared.edge[e][0])],
                                        a[static_cast<std::size_t>(shared.edge[e][1])], p.normal);
                        known[e] = 1;
                    }
                    sum += code % 2 ? -term[e] : term[e];
                }
                const double f = std::abs(sum) / (2.0 * glm::pi<double>());
                fm[m] += std::isfinite(f) ? std::min(f, 1.0) : 0.0;
            }
        }
        for (std::size_t m = 0; m < members; ++m) {
            const double f = fm[m] / static_cast<double>(pts.size());
            // The ray is cast where w needs it (f > 0) or where the group's row samples it
            // (groupGatherRow: both cosines at the centres > 0); the row reads it from here.
            const glm::dvec3 d = target[m] - from;
            const bool sampled = glm::dot(p.normal, d) > 0.0 && -glm::dot(sg.normal, d) > 0.0;
            if (f <= 0.0 && !sampled) continue;
            const bool vis = bvh.visible(from, target[m]);
            nf.visible[r * members + m] = vis ? 1 : 0;
            if (f <= 0.0 || !vis) continue;
            nf.w[r * members + m] = static_cast<float>(f);
        }
    });
    if (offsets && !nf.everyReceiver) {
        const std::size_t n = mesh.patches.size();
        nf.du.assign(n, 0.0f);
        nf.dv.assign(n, 0.0f);
        std::vector<char> nearJ(n, 0);
        for (int j : nf.receivers)
            nearJ[static_cast<std::size_t>(j)] = 1;
        const glm::dvec3 v = glm::cross(sg.normal, sg.u);
        std::vector<glm::dvec3> centre(members);
        std::vector<double> area(members);
        for (std::size_t m = 0; m < members; ++m) {
            const Patch& q = mesh.patches[static_cast<std::size_t>(sg.members[m])];
            centre[m] = q.centre;
            area[m] = q.area;
        }
        tbb::parallel_for(std::size_t(0), n, [&](std::size_t j) {
            const Patch& p = mesh.patches[j];
            if (nearJ[j] || p.group == g || glm::dot(sg.normal, p.centre - sg.centre) <= tiny)
                return;
            double w = 0.0;
            glm::dvec3 at(0.0);
            for (std::size_t m = 0; m < members; ++m) {
                const glm::dvec3 d = p.centre - centre[m];
                const double r2 = glm::dot(d, d);
                const double k = area[m] * std::max(0.0, glm::dot(sg.normal, d)) *
                                 std::max(0.0, -glm::dot(p.normal, d)) / (r2 * r2);
                w += k;
                at += k * (centre[m] - sg.centre);
            }
            if (!(w > 0.0)) return;
            at /= w;
            nf.du[j] = static_cast<float>(glm::dot(at, sg.u));
            nf.dv[j] = static_cast<float>(glm::dot(at, v));
        });
    }
    return nf;
}

} // namespace wb::rad
