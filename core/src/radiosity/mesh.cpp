#include "core/radiosity/mesh.h"

#include "core/radiosity/patch_bvh.h"

#include <algorithm>
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
    int maxLevel = 0;
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
        maxLevel = std::max(maxLevel, d.level);
        mesh.patches.push_back(std::move(p));
    }
    // Outlines: walk each edge at the finest spacing any patch of the mesh can have and
    // insert the vertices found there (T-vertices of finer neighbours).
    for (Patch& p : mesh.patches) {
        p.outline.clear();
        const int steps = 1 << (maxLevel - p.level);
        for (int k = 0; k < p.cornerCount; ++k) {
            p.outline.push_back(p.corners[static_cast<std::size_t>(k)]);
            if (steps == 1) continue;
            const glm::dvec2 a = p.lattice[static_cast<std::size_t>(k)];
            const glm::dvec2 b = p.lattice[static_cast<std::size_t>((k + 1) % p.cornerCount)];
            for (int m = 1; m < steps; ++m) {
                const glm::dvec2 l = a + (b - a) * (static_cast<double>(m) / steps);
                if (l.x != std::floor(l.x) || l.y != std::floor(l.y)) continue; // off lattice
                auto it = ids.find(std::make_tuple(p.surface, l.x, l.y));
                if (it != ids.end()) p.outline.push_back(it->second);
            }
        }
        p.centreVertex = -1;
        if (p.outline.size() > static_cast<std::size_t>(p.cornerCount)) {
            glm::dvec2 l(0.0);
            for (int k = 0; k < p.cornerCount; ++k) l += p.lattice[static_cast<std::size_t>(k)] / double(p.cornerCount);
            p.centreVertex = static_cast<int>(mesh.vertices.size());
            mesh.vertices.push_back(p.centre);
            mesh.vertexSurface.push_back(p.surface);
            mesh.vertexLattice.push_back(l);
        }
    }
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

// A point of a surface is covered when the first surface along its normal is met from behind:
// it lies inside a body (the floor under a block, which has no bottom face). nearestPatch
// gives −1 for a back side and for nothing at all; `visible` tells them apart.
bool covered(const PatchBvh& bvh, const glm::dvec3& p, const glm::dvec3& n) {
    const glm::dvec3 o = p + 1e-7 * (1.0 + glm::length(p)) * n;
    if (bvh.nearestPatch(o, n, 0.0, 1e4) >= 0) return false;
    return !bvh.visible(o, o + 1e4 * n);
}

glm::dvec3 pointOn(const std::vector<glm::dvec3>& c, double u, double v) {
    if (c.size() == 3) {
        const double su = std::sqrt(u);
        return c[0] + su * (1 - v) * (c[1] - c[0]) + su * v * (c[2] - c[0]);
    }
    return (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
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
            if (hits == 0) continue;
            centre[i] = sum / static_cast<double>(hits);
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
        if (fit[i].first == 1.0) continue;
        Patch& p = mesh.patches[i];
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
    if (!(config.shooterEdge >= 0.0) || !std::isfinite(config.shooterEdge))
        throw std::invalid_argument("radiosity meshing: shooterEdge must be >= 0");
    const bool grouped = config.shooterEdge > config.maxEdge;
    std::vector<PatchDesc> descs;
    double total = 0.0;
    int groupBase = 0;
    for (std::size_t si = 0; si < scene.surfaces.size(); ++si) {
        const auto& c = scene.surfaces[si].vertices;
        const int surface = static_cast<int>(si);
        auto cells = [&](double len, double edge) { return std::max(1.0, std::ceil(len / edge - 1e-9)); };
        // The fine grid depends on maxEdge only (so meshes with and without groups, or with
        // different group sizes, have the same patches); a shooting group is a block of `per`
        // fine cells along each direction, `per` = how many fine cells fit in shooterEdge.
        auto counts = [&](double len, int& fine, int& coarse, int& per) {
            if (fine < 1) fine = static_cast<int>(cells(len, config.maxEdge));
            per = grouped ? std::max(1, static_cast<int>(std::floor(config.shooterEdge / (len / fine) + 1e-9))) : 1;
            coarse = (fine + per - 1) / per;
        };
        int fu = 0, cu = 1, mu = 1, fv = 0, cv = 1, mv = 1;
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
            for (int j = 0; j < g.y; ++j)
                for (int i = 0; i < g.x; ++i)
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
