#include "raster_mesh.h"

#include "core/raytrace/box.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/polyhedron.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace wb {

using glm::dvec3;

void sceneBounds(const rt::Scene& scene, dvec3& centre, double& radius) {
    rt::Aabb all;
    for (const auto& p : scene.primitives) {
        const rt::Aabb b = p->bounds();
        if (b.empty() || !b.bounded()) continue;
        all.extend(b.lo);
        all.extend(b.hi);
    }
    if (all.empty()) {
        centre = dvec3(0.0);
        radius = 1.0;
        return;
    }
    centre = (all.lo + all.hi) * 0.5;
    radius = std::max(glm::length(all.hi - all.lo) * 0.5, 1e-9);
}

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kCoarsestSegments = 4; // around a circle once the budget forces coarsening

struct Builder {
    std::map<int, MeshBatch> batches;
    long long triangles = 0;
    bool countOnly = false;               // count the triangles a primitive makes, store nothing
    std::map<int, long long> perMaterial; // count mode: triangles per material

    // Adds a triangle wound counter-clockwise as seen from the side its normals point to
    // (GL decides front/back faces by winding; two-sided lighting flips by that).
    void tri(int mat, dvec3 a, dvec3 b, dvec3 c, dvec3 na, dvec3 nb, dvec3 nc) {
        if (countOnly) {
            ++triangles;
            ++perMaterial[mat];
            return;
        }
        const dvec3 face = glm::cross(b - a, c - a);
        if (!(glm::dot(face, face) > 0)) return; // degenerate
        if (glm::dot(face, na + nb + nc) < 0) {
            std::swap(b, c);
            std::swap(nb, nc);
        }
        MeshBatch& m = batches[mat];
        m.material = mat;
        for (const dvec3* v : {&a, &b, &c})
            for (int i = 0; i < 3; ++i)
                m.pos.push_back(float((*v)[i]));
        for (const dvec3* n : {&na, &nb, &nc}) {
            const dvec3 u = glm::length(*n) > 0 ? glm::normalize(*n) : dvec3(0, 0, 1);
            for (int i = 0; i < 3; ++i)
                m.normal.push_back(float(u[i]));
        }
        ++triangles;
    }
    void flatTri(int mat, const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& n) {
        tri(mat, a, b, c, n, n, n);
    }
    // A parallelogram o + s·e1 + t·e2 split into nu × nv cells, constant normal n.
    void grid(int mat, const dvec3& o, const dvec3& e1, const dvec3& e2, const dvec3& n, int nu,
              int nv) {
        if (countOnly) {
            triangles += 2LL * nu * nv;
            perMaterial[mat] += 2LL * nu * nv;
            return;
        }
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                const double s0 = double(i) / nu, s1 = double(i + 1) / nu;
                const double t0 = double(j) / nv, t1 = double(j + 1) / nv;
                const dvec3 p00 = o + s0 * e1 + t0 * e2, p10 = o + s1 * e1 + t0 * e2;
                const dvec3 p01 = o + s0 * e1 + t1 * e2, p11 = o + s1 * e1 + t1 * e2;
                flatTri(mat, p00, p10, p11, n);
                flatTri(mat, p00, p11, p01, n);
            }
    }
    // A parametric surface f(u, v) with normal g(u, v) on [u0,u1] × [v0,v1], nu × nv cells.
    template <class F, class G>
    void surface(int mat, F f, G g, double u0, double u1, double v0, double v1, int nu, int nv) {
        if (countOnly) {
            triangles += 2LL * nu * nv;
            perMaterial[mat] += 2LL * nu * nv;
            return;
        }
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                const double ua = u0 + (u1 - u0) * i / nu, ub = u0 + (u1 - u0) * (i + 1) / nu;
                const double va = v0 + (v1 - v0) * j / nv, vb = v0 + (v1 - v0) * (j + 1) / nv;
                tri(mat, f(ua, va), f(ub, va), f(ub, vb), g(ua, va), g(ub, va), g(ub, vb));
                tri(mat, f(ua, va), f(ub, vb), f(ua, vb), g(ua, va), g(ub, vb), g(ua, vb));
            }
    }
};

// Orthonormal e1, e2 perpendicular to unit a.
void frame(const dvec3& a, dvec3& e1, dvec3& e2) {
    const dvec3 h = std::fabs(a.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    e1 = glm::normalize(glm::cross(a, h));
    e2 = glm::cross(a, e1);
}

// Clips a convex polygon to n·x <= d (Sutherland–Hodgman, one plane).
std::vector<dvec3> clip(const std::vector<dvec3>& poly, const dvec3& n, double d) {
    std::vector<dvec3> out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const dvec3& a = poly[i];
        const dvec3& b = poly[(i + 1) % poly.size()];
        const double da = glm::dot(n, a) - d, db = glm::dot(n, b) - d;
        if (da <= 0) out.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

} // namespace

std::vector<MeshBatch> tessellate(const rt::Scene& scene, const ViewCamera& cam,
                                  const TessellationOptions& opt, TessellationStats* stats) {
    int skipped = 0;
    dvec3 sceneCentre;
    double sceneRadius;
    sceneBounds(scene, sceneCentre, sceneRadius);
    const double extent = opt.planeExtent > 0 ? opt.planeExtent : 40.0 * sceneRadius;
    const double pixelAngle = cam.screen.pixelSize / cam.dist; // radians per pixel near the axis
    // Pixels covered by a length at the nearest distance any orbit brings the bounding
    // sphere (c, r) to the eye (the mesh is kept while the view turns).
    auto pixels = [&](double length, const dvec3& c, double r) {
        const double d = std::max(cam.dist - glm::length(c - cam.target) - r, 0.05 * cam.dist);
        return length / d / pixelAngle;
    };
    // `level` < 1 coarsens everything when the scene would need more than the budget:
    // triangles grow as segments², so segments scale by sqrt(level).
    double level = 1.0;
    auto segments = [&](double radiusPixels) {
        const double n =
            kPi * std::sqrt(std::max(radiusPixels, 0.0) / opt.maxErrorPixels) * std::sqrt(level);
        // The floor coarsens with the level too (smoothly: a jump from 8 to 4 segments
        // would halve a scene of small spheres at the first step below 1).
        const int lo =
            std::min(opt.minSegments, std::max(kCoarsestSegments,
                                               int(std::ceil(opt.minSegments * std::sqrt(level)))));
        return std::clamp(int(std::ceil(n)), lo, opt.maxSegments);
    };
    auto cells = [&](double lengthPixels) {
        return std::clamp(int(std::ceil(lengthPixels / opt.gridPixels * std::sqrt(level))), 1, 64);
    };

    // One primitive into `b` (or counted, in count mode).
    auto emitOne = [&](const rt::Primitive* p, Builder& b) {
        const int mat = p->material;
        if (auto* s = dynamic_cast<const rt::Sphere*>(p)) {
            if (!(s->radius > 0)) return;
            const int n = segments(pixels(s->radius, s->centre, s->radius));
            if (b.countOnly) {
                // What the build keeps: each pole ring's n triangles with two vertices at
                // the pole are degenerate and dropped (counting them overstated a scene
                // of small spheres by 25% and coarsened balls 4 under the budget).
                const long long kept = 2LL * n * std::max(n / 2, 4) - 2LL * n;
                b.triangles += kept;
                b.perMaterial[mat] += kept;
                return;
            }
            const dvec3 c = s->centre;
            const double r = s->radius;
            auto normal = [](double u, double v) {
                return dvec3(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
            };
            auto at = [&](double u, double v) { return c + r * normal(u, v); };
            // As Builder::surface, without the triangle of each pole cell that has two
            // corners at the pole (cos(±π/2) is 6e-17, not 0, so they were not always
            // recognised as degenerate): exactly the count above.
            const int nv = std::max(n / 2, 4);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < nv; ++j) {
                    const double ua = 2 * kPi * i / n, ub = 2 * kPi * (i + 1) / n;
                    const double va = -kPi / 2 + kPi * j / nv, vb = -kPi / 2 + kPi * (j + 1) / nv;
                    if (j != 0)
                        b.tri(mat, at(ua, va), at(ub, va), at(ub, vb), normal(ua, va),
                              normal(ub, va), normal(ub, vb));
                    if (j != nv - 1)
                        b.tri(mat, at(ua, va), at(ub, vb), at(ua, vb), normal(ua, va),
                              normal(ub, vb), normal(ua, vb));
                }
        } else if (auto* rc = dynamic_cast<const rt::Rectangle*>(p)) {
            const dvec3 c = rc->loc + 0.5 * (rc->e1 + rc->e2);
            const double r = 0.5 * glm::length(rc->e1 + rc->e2);
            b.grid(mat, rc->loc, rc->e1, rc->e2, rc->normal,
                   cells(pixels(glm::length(rc->e1), c, r)),
                   cells(pixels(glm::length(rc->e2), c, r)));
        } else if (auto* t = dynamic_cast<const rt::Triangle*>(p)) {
            // Large triangles (an NFF floor) are split n ways along each edge, so Gouraud
            // lighting samples the point lights as densely as on rectangles.
            auto* st = dynamic_cast<const rt::SmoothTriangle*>(p);
            const dvec3 g = glm::cross(t->v1 - t->v0, t->v2 - t->v0);
            const dvec3 n0 = st ? st->n0 : g, n1 = st ? st->n1 : g, n2 = st ? st->n2 : g;
            const dvec3 c = (t->v0 + t->v1 + t->v2) / 3.0;
            const double edge = std::max({glm::length(t->v1 - t->v0), glm::length(t->v2 - t->v0),
                                          glm::length(t->v2 - t->v1)});
            const int n = cells(pixels(edge, c, edge));
            if (b.countOnly) { // n² triangles (n(n+1)/2 up, n(n−1)/2 down), some degenerate
                b.triangles += (long long)n * n;
                b.perMaterial[mat] += (long long)n * n;
                return;
            }
            auto at = [&](int i, int j) {
                const double a = double(i) / n, bb = double(j) / n;
                return std::pair<dvec3, dvec3>{t->v0 + a * (t->v1 - t->v0) + bb * (t->v2 - t->v0),
                                               (1 - a - bb) * n0 + a * n1 + bb * n2};
            };
            for (int i = 0; i < n; ++i)
                for (int j = 0; i + j < n; ++j) {
                    const auto [p00, q00] = at(i, j);
                    const auto [p10, q10] = at(i + 1, j);
                    const auto [p01, q01] = at(i, j + 1);
                    b.tri(mat, p00, p10, p01, q00, q10, q01);
                    if (i + j + 2 <= n) {
                        const auto [p11, q11] = at(i + 1, j + 1);
                        b.tri(mat, p10, p11, p01, q10, q11, q01);
                    }
                }
        } else if (auto* bx = dynamic_cast<const rt::Box*>(p)) {
            const dvec3 e[3] = {bx->e1, bx->e2, bx->e3};
            const double r = 0.5 * glm::length(e[0] + e[1] + e[2]);
            for (int k = 0; k < 3; ++k) {
                const dvec3& a = e[(k + 1) % 3];
                const dvec3& c2 = e[(k + 2) % 3];
                dvec3 n = glm::normalize(glm::cross(a, c2));
                if (glm::dot(n, e[k]) > 0) n = -n; // the face at loc points away from e[k]
                const int na = cells(pixels(glm::length(a), bx->centre, r));
                const int nc = cells(pixels(glm::length(c2), bx->centre, r));
                b.grid(mat, bx->loc, a, c2, n, na, nc);
                b.grid(mat, bx->loc + e[k], a, c2, -n, na, nc);
            }
        } else if (auto* cn = dynamic_cast<const rt::Cone*>(p)) {
            const dvec3 axis = cn->c1 - cn->c0;
            const double h = glm::length(axis);
            if (!(h > 0)) return;
            const dvec3 a = axis / h;
            dvec3 ex, ey;
            frame(a, ex, ey);
            const double rmax = std::max(cn->r0, cn->r1);
            const dvec3 mid = 0.5 * (cn->c0 + cn->c1);
            const int n = segments(pixels(rmax, mid, std::max(rmax, h / 2)));
            const double k = (cn->r1 - cn->r0) / h;
            auto side = [&](double u, double z) {
                return cn->c0 + z * a + (cn->r0 + k * z) * (std::cos(u) * ex + std::sin(u) * ey);
            };
            auto sideNormal = [&](double u, double) {
                return std::cos(u) * ex + std::sin(u) * ey - k * a;
            };
            b.surface(mat, side, sideNormal, 0, 2 * kPi, 0, h, n,
                      cells(pixels(h, mid, std::max(rmax, h / 2))));
            for (int cap = 0; cap < 2; ++cap) {
                const double r = cap ? cn->r1 : cn->r0;
                if (!(r > 0)) return;
                const dvec3 c = cap ? cn->c1 : cn->c0;
                const dvec3 nrm = cap ? a : -a;
                for (int i = 0; i < n; ++i) {
                    const double u0 = 2 * kPi * i / n, u1 = 2 * kPi * (i + 1) / n;
                    b.flatTri(mat, c, c + r * (std::cos(u0) * ex + std::sin(u0) * ey),
                              c + r * (std::cos(u1) * ex + std::sin(u1) * ey), nrm);
                }
            }
        } else if (auto* q = dynamic_cast<const rt::Quadric*>(p)) {
            const dvec3 c = q->centre, ax = q->axes;
            // Cuts beyond the scene are clamped to it: an uncut paraboloid is infinite.
            const double zl = std::max(q->zLow, c.z - extent),
                         zh = std::min(q->zHigh, c.z + extent);
            if (!(zl < zh)) return;
            const double rpx = pixels(std::max({ax.x, ax.y}), c, glm::length(ax));
            const int n = segments(rpx);
            const int nz = std::max(n / 2, 4);
            if (q->kind == rt::Quadric::Kind::Ellipsoid) {
                const double s0 = std::asin(std::clamp((zl - c.z) / ax.z, -1.0, 1.0));
                const double s1 = std::asin(std::clamp((zh - c.z) / ax.z, -1.0, 1.0));
                if (!(s0 < s1)) return;
                auto f = [&](double u, double v) {
                    return c + dvec3(ax.x * std::cos(v) * std::cos(u),
                                     ax.y * std::cos(v) * std::sin(u), ax.z * std::sin(v));
                };
                auto g = [&](double u, double v) {
                    const dvec3 d = f(u, v) - c;
                    return dvec3(d.x / (ax.x * ax.x), d.y / (ax.y * ax.y), d.z / (ax.z * ax.z));
                };
                b.surface(mat, f, g, 0, 2 * kPi, s0, s1, n, nz);
            } else if (q->kind == rt::Quadric::Kind::Paraboloid) {
                // (x/A)² + (y/B)² = (z − z0)/C: s = sqrt((z − z0)/C) is the ring's scale.
                auto sOf = [&](double z) { return std::sqrt(std::max((z - c.z) / ax.z, 0.0)); };
                const double s0 = ax.z > 0 ? sOf(zl) : sOf(zh), s1 = ax.z > 0 ? sOf(zh) : sOf(zl);
                if (!(s0 < s1)) return;
                auto f = [&](double u, double k) {
                    return c + dvec3(ax.x * k * std::cos(u), ax.y * k * std::sin(u), ax.z * k * k);
                };
                auto g = [&](double u, double k) {
                    const dvec3 d = f(u, k) - c;
                    return dvec3(2 * d.x / (ax.x * ax.x), 2 * d.y / (ax.y * ax.y), -1 / ax.z);
                };
                b.surface(mat, f, g, 0, 2 * kPi, s0, s1, n, nz);
            } else {
                // One sheet: x = A cosh w cos u, y = B cosh w sin u, z = z0 + C sinh w.
                const double w0 = std::asinh((zl - c.z) / ax.z), w1 = std::asinh((zh - c.z) / ax.z);
                auto f = [&](double u, double w) {
                    return c + dvec3(ax.x * std::cosh(w) * std::cos(u),
                                     ax.y * std::cosh(w) * std::sin(u), ax.z * std::sinh(w));
                };
                auto g = [&](double u, double w) {
                    const dvec3 d = f(u, w) - c;
                    return dvec3(d.x / (ax.x * ax.x), d.y / (ax.y * ax.y), -d.z / (ax.z * ax.z));
                };
                b.surface(mat, f, g, 0, 2 * kPi, w0, w1, n, nz);
            }
        } else if (auto* pl = dynamic_cast<const rt::Plane*>(p)) {
            const dvec3 n = pl->normal;
            const dvec3 c = sceneCentre - (glm::dot(n, sceneCentre) - pl->d) * n;
            dvec3 e1, e2;
            frame(n, e1, e2);
            const int k = cells(pixels(2 * extent, c, extent));
            b.grid(mat, c - extent * (e1 + e2), 2 * extent * e1, 2 * extent * e2, n, k, k);
        } else if (auto* ph = dynamic_cast<const rt::ConvexPolyhedron*>(p)) {
            // Each face: a large square in its plane clipped by every other half-space.
            for (size_t i = 0; i < ph->faces.size(); ++i) {
                const dvec3 n = ph->faces[i].normal;
                const dvec3 c = sceneCentre - (glm::dot(n, sceneCentre) - ph->faces[i].d) * n;
                dvec3 e1, e2;
                frame(n, e1, e2);
                std::vector<dvec3> poly = {c - extent * (e1 + e2), c + extent * (e1 - e2),
                                           c + extent * (e1 + e2), c - extent * (e1 - e2)};
                for (size_t j = 0; j < ph->faces.size() && poly.size() >= 3; ++j)
                    if (j != i) poly = clip(poly, ph->faces[j].normal, ph->faces[j].d);
                for (size_t j = 1; j + 1 < poly.size(); ++j)
                    b.flatTri(mat, poly[0], poly[j], poly[j + 1], n);
            }
        } else {
            ++skipped; // counted once, in the build pass below
        }
    };

    // 1. Count at full level; 2. coarsen until the whole scene fits the budget or the
    //    coarsest level is reached; 3. walk the primitives in order until the budget is
    //    spent: the rest becomes one bounding-box stand-in (12 triangles); 4. reserve the
    //    arrays exactly (no doubling growth: memory stays at the budget) and build.
    const long long budget = std::max<long long>(opt.maxTriangles, 1000);
    Builder counter;
    counter.countOnly = true;
    auto countAll = [&] {
        counter.triangles = 0;
        for (const auto& up : scene.primitives)
            emitOne(up.get(), counter);
        return counter.triangles;
    };
    long long need = countAll();
    if (need > budget) {
        // The largest level that fits, by bisection on a log scale (counting is O(objects)):
        // 12 steps between 1e-6 and 1 pin it to within a factor 1.004.
        double lo = 1e-6, hi = 1.0;
        for (int step = 0; step < 12; ++step) {
            level = std::sqrt(lo * hi);
            if (countAll() <= budget)
                lo = level;
            else
                hi = level;
        }
        level = lo;
        need = countAll();
    }
    counter.perMaterial.clear();
    counter.triangles = 0;
    size_t cut = scene.primitives.size(); // primitives [cut, end) go into the stand-in
    Builder one;                          // one primitive's count
    one.countOnly = true;
    for (size_t i = 0; i < scene.primitives.size(); ++i) {
        one.triangles = 0;
        one.perMaterial.clear();
        emitOne(scene.primitives[i].get(), one);
        if (counter.triangles + one.triangles > budget - 12) {
            cut = i;
            break;
        }
        counter.triangles += one.triangles;
        for (const auto& [mat, n] : one.perMaterial)
            counter.perMaterial[mat] += n;
    }
    long long standIns = 0;
    rt::Aabb rest;
    int restMaterial = -1;
    for (size_t i = cut; i < scene.primitives.size(); ++i) {
        const rt::Primitive* p = scene.primitives[i].get();
        ++standIns;
        const rt::Aabb box = p->bounds();
        if (box.empty() || !box.bounded()) continue;
        rest.extend(box.lo);
        rest.extend(box.hi);
        if (restMaterial < 0) restMaterial = p->material;
    }
    Builder b;
    for (const auto& [mat, n] : counter.perMaterial) {
        MeshBatch& m = b.batches[mat];
        m.material = mat;
        m.pos.reserve(size_t(n + (mat == restMaterial ? 12 : 0)) * 9);
        m.normal.reserve(size_t(n + (mat == restMaterial ? 12 : 0)) * 9);
    }
    skipped = 0;
    for (size_t i = 0; i < cut; ++i)
        emitOne(scene.primitives[i].get(), b);
    if (!rest.empty()) {
        const dvec3 lo = rest.lo, e = rest.hi - rest.lo;
        const dvec3 ex(e.x, 0, 0), ey(0, e.y, 0), ez(0, 0, e.z);
        b.grid(restMaterial, lo, ey, ez, {-1, 0, 0}, 1, 1);
        b.grid(restMaterial, lo + ex, ey, ez, {1, 0, 0}, 1, 1);
        b.grid(restMaterial, lo, ex, ez, {0, -1, 0}, 1, 1);
        b.grid(restMaterial, lo + ey, ex, ez, {0, 1, 0}, 1, 1);
        b.grid(restMaterial, lo, ex, ey, {0, 0, -1}, 1, 1);
        b.grid(restMaterial, lo + ez, ex, ey, {0, 0, 1}, 1, 1);
    }
    std::vector<MeshBatch> out;
    for (auto& [mat, batch] : b.batches)
        if (!batch.pos.empty()) out.push_back(std::move(batch));
    if (stats) {
        stats->triangles = b.triangles;
        stats->skipped = skipped;
        stats->level = level;
        stats->standIns = standIns;
        stats->budget = budget;
    }
    return out;
}

} // namespace wb
