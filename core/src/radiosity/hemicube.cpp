#include "core/radiosity/hemicube.h"

#include "core/radiosity/closed_forms.h"
#include "core/raytrace/ray.h"
#include "core/raytrace/triangle.h"

#include <glm/gtc/constants.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

namespace wb::rad {

namespace {

void checkResolution(int res) {
    if (res < 2 || res > 8192 || res % 2 != 0)
        throw std::invalid_argument("hemicube: resolution " + std::to_string(res) +
                                    " must be even and in 2..8192");
}

// Point on face f at continuous face coordinates (s horizontal in −1..1, w vertical: t in
// −1..1 on the top face, z in 0..1 on the sides), in frame axes (not normalised).
glm::dvec3 facePoint(const HemicubeFrame& fr, HemicubeFace f, double s, double w) {
    switch (f) {
    case HemicubeFace::Top:
        return s * fr.u + w * fr.v + fr.n;
    case HemicubeFace::PosU:
        return fr.u - s * fr.v + w * fr.n;
    case HemicubeFace::NegU:
        return -fr.u + s * fr.v + w * fr.n;
    case HemicubeFace::PosV:
        return fr.v + s * fr.u + w * fr.n;
    case HemicubeFace::NegV:
        return -fr.v - s * fr.u + w * fr.n;
    }
    return fr.n;
}

// Vertical face coordinate of a pixel row's lower edge (row + 0 ) or centre (row + ½).
double vertical(int res, HemicubeFace f, double row) {
    const double px = 2.0 / res;
    return f == HemicubeFace::Top ? -1.0 + row * px : row * px;
}

} // namespace

HemicubeFrame hemicubeFrame(const PatchMesh& mesh, int patch) {
    const Patch& p = mesh.patches.at(static_cast<std::size_t>(patch));
    HemicubeFrame fr;
    fr.n = p.normal;
    fr.origin = rt::offsetRayOrigin(p.centre, p.normal);
    const glm::dvec3 e = mesh.vertices[static_cast<std::size_t>(p.corners[1])] -
                         mesh.vertices[static_cast<std::size_t>(p.corners[0])];
    glm::dvec3 u = e - glm::dot(e, fr.n) * fr.n; // exactly in the plane
    fr.u = glm::normalize(u);
    fr.v = glm::cross(fr.n, fr.u);
    return fr;
}

int faceWidth(int resolution, HemicubeFace) { return resolution; }
int faceHeight(int resolution, HemicubeFace f) {
    return f == HemicubeFace::Top ? resolution : resolution / 2;
}

glm::dvec3 pixelDirection(const HemicubeFrame& frame, int resolution, HemicubeFace f, int col,
                          int row) {
    const double s = -1.0 + (col + 0.5) * 2.0 / resolution;
    return facePoint(frame, f, s, vertical(resolution, f, row + 0.5));
}

void ItemBuffer::resize(int res) {
    checkResolution(res);
    resolution = res;
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto hf = static_cast<HemicubeFace>(f);
        faces[static_cast<std::size_t>(f)].assign(
            static_cast<std::size_t>(faceWidth(res, hf)) * static_cast<std::size_t>(faceHeight(res, hf)),
            -1);
    }
}

DeltaFormFactors deltaFormFactors(int resolution, bool exactPixels) {
    checkResolution(resolution);
    DeltaFormFactors t;
    t.resolution = resolution;
    const HemicubeFrame canonical; // u = x, v = y, n = z, origin 0
    const double px = 2.0 / resolution;
    const double dA = px * px;
    const double invPi = 1.0 / glm::pi<double>();
    double sum = 0.0;
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto hf = static_cast<HemicubeFace>(f);
        const int w = faceWidth(resolution, hf), h = faceHeight(resolution, hf);
        auto& face = t.faces[static_cast<std::size_t>(f)];
        face.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        for (int row = 0; row < h; ++row)
            for (int col = 0; col < w; ++col) {
                double weight;
                if (exactPixels) {
                    const double s0 = -1.0 + col * px, s1 = s0 + px;
                    const double v0 = vertical(resolution, hf, row), v1 = v0 + px;
                    const std::vector<glm::dvec3> sq = {
                        facePoint(canonical, hf, s0, v0), facePoint(canonical, hf, s1, v0),
                        facePoint(canonical, hf, s1, v1), facePoint(canonical, hf, s0, v1)};
                    weight = pointToPolygon(glm::dvec3(0.0), glm::dvec3(0, 0, 1), sq);
                } else {
                    const glm::dvec3 p = pixelDirection(canonical, resolution, hf, col, row);
                    const double d2 = glm::dot(p, p); // x² + y² + 1 (top) or s² + z² + 1
                    // Top face: cos φ_i = cos φ_j = 1/d -> ΔA/(π d⁴); sides: cos φ_i = z/d,
                    // cos φ_j = 1/d -> z ΔA/(π d⁴) (§1.15.2).
                    const double cosWeight = hf == HemicubeFace::Top ? 1.0 : p.z;
                    weight = cosWeight * dA * invPi / (d2 * d2);
                }
                face[static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                     static_cast<std::size_t>(col)] = weight;
                sum += weight;
            }
    }
    t.sum = sum;
    return t;
}

namespace {
// ---- The rasteriser (issue 21): every pixel's ray leaves frame.origin ----
//
// A triangle with vertices a, b, c (relative to the origin) can be hit by direction d only
// if d lies in the cone a, b, c span, i.e. the three triple products d·(b×c), d·(c×a),
// d·(a×b) ("edge planes through the origin") do not have mixed signs. The watertight test
// (core/raytrace/triangle.cpp) decides exactly this: its shear has determinant 1, so its 2D
// edge function of vertices c, b is (d/d_kz)·(c×b) — the same triple products times one
// common factor 1/|d_kz| >= 1 (and one sign). It computes them from the same rounded
// differences a = fl(v − o) with an error of at most ~17u·|b|₁|c|₁ in these units (u = 2^-53:
// the shear's three roundings and |sx|, |sy| <= 1 make each sheared coordinate off by
// <= 3.1u·|·|₁, then two products and a difference). Our evaluation, for the unnormalised
// pixel direction p = l + s·h + w·v (|p|₁ <= 3) as A + B·col + C·row, and the rounding of
// d = normalize(p) against p/|p|, add a few more u·|b|₁|c|₁·|p|₁. So a pixel is rejected
// only when an edge function is below −kEdgeMargin·4·|b|₁|c|₁ (2^-40 = 8192u: a factor ~100
// over the sum), and it is "certainly inside" — the watertight test gives u, v, w one strict
// sign — only when all three are above that margin. No margin grows with the distance from
// the scene's origin: only the vertices' distances from the eye enter.
//
// Depth: when the watertight test hits, t = (u·za + v·zb + w·zc)/(u + v + w) with u, v, w of
// one sign, where z_i = fl(sz·(v_i − o)[kz]) are the vertices' sheared depths; a weighted mean
// computed with <= 9 roundings, so t lies in [min z·(1 − 9u), max z·(1 + 9u)] when the z_i
// are positive. With kDepthMargin = 2^-40 these bound the test's own t without calling it.
//
// A pixel keeps one triangle "pending" without its exact test while every other candidate
// is certainly farther (its lower bound above the pending one's upper bound, which exists only
// when the pending one is certainly hit) or certainly nearer than it; otherwise both take the
// exact test, and from then on the pixel is an exact z-buffer: the watertight test asked for
// t <= the nearest so far, ties to the triangle later in the scene — the walk's own rule
// (bvh_wide_impl.h, intersect()). A back side seen (rare) falls back to nearestPatch, whose
// patchOf looks around the hit with the walk. So every id is nearestPatch's for that pixel.
constexpr double kEdgeMargin = 0x1p-40;
constexpr double kDepthMargin = 0x1p-40;
// Vertices nearer than this to the eye (but not at it) or farther: the whole item buffer
// takes the packet walk (subnormal and overflowing products are outside the bounds above).
constexpr double kMinDistance = 0x1p-200, kMaxDistance = 0x1p200;

struct RasterTri {
    double p[3][3];        // vertex − origin, rounded as the watertight test rounds it
    double ef[3][3];       // the edge planes through the origin b×c, c×a, a×b, in frame axes
    double margin[3];      // kEdgeMargin·4·|b|₁|c|₁ and its rotations
    double sigma = 1.0;    // sign of det(a, b, c): the cone in front of the eye
    bool bothCones = false; // det ~ 0: the plane passes by the eye, keep the cone behind too
    bool certainOk = true;  // may be decided without its exact test
    std::int32_t prim = 0;  // index in PatchBvh::triangles()
    std::int32_t patch = 0;
};

enum : std::uint8_t { kEmpty = 0, kPending = 1, kResolved = 2 };
struct PixelState {
    double lo, hi;     // pending: bounds of its t (hi = inf unless certainly hit); resolved: hi = nearest t
    std::int32_t tri;  // pending or nearest triangle (index in the RasterTri list), −1 none
    std::uint8_t state;
};

struct FaceScratch {
    std::vector<glm::dvec3> dirs;
    std::vector<double> sz;
    std::vector<std::uint8_t> kz;
    std::vector<PixelState> st;
};

// Frame coordinates (x = ·u, y = ·v, z = ·n) to the face's (h, v, l) with p = l + s·h + w·v
// (facePoint's columns).
inline void toFace(HemicubeFace f, const double* x, double& h, double& v, double& l) {
    switch (f) {
    case HemicubeFace::Top: h = x[0], v = x[1], l = x[2]; return;
    case HemicubeFace::PosU: h = -x[1], v = x[2], l = x[0]; return;
    case HemicubeFace::NegU: h = x[1], v = x[2], l = -x[0]; return;
    case HemicubeFace::PosV: h = x[0], v = x[2], l = x[1]; return;
    default: h = -x[0], v = x[2], l = -x[1]; return; // NegV
    }
}

// Bounding box of the pixel centres (col, row) in [0, w−1] × [0, h−1] where all three
// g_k = a_k + b_k·col + c_k·row >= 0 (the rectangle clipped by three half-planes), widened by
// a pixel and each half-plane by 2^-30 of its size against the clip's own rounding. False
// when empty. Only bounds the loop: every pixel in it is tested on its own.
bool clipBox(const double* a, const double* b, const double* c, int w, int h, int& x0, int& x1,
             int& y0, int& y1) {
    double px[2][16], py[2][16];
    const double W = w - 1, H = h - 1;
    px[0][0] = 0, py[0][0] = 0, px[0][1] = W, py[0][1] = 0;
    px[0][2] = W, py[0][2] = H, px[0][3] = 0, py[0][3] = H;
    int n = 4, cur = 0;
    for (int k = 0; k < 3 && n > 0; ++k) {
        const double slack = 0x1p-30 * (std::abs(a[k]) + std::abs(b[k]) * W + std::abs(c[k]) * H);
        const double ak = a[k] + slack;
        const int nxt = 1 - cur;
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const int j = i + 1 == n ? 0 : i + 1;
            const double xi = px[cur][i], yi = py[cur][i], xj = px[cur][j], yj = py[cur][j];
            const double gi = ak + b[k] * xi + c[k] * yi, gj = ak + b[k] * xj + c[k] * yj;
            if (gi >= 0) px[nxt][m] = xi, py[nxt][m++] = yi;
            if ((gi >= 0) != (gj >= 0)) {
                const double s = gi / (gi - gj);
                px[nxt][m] = xi + s * (xj - xi), py[nxt][m++] = yi + s * (yj - yi);
            }
        }
        n = m;
        cur = nxt;
    }
    if (n == 0) return false;
    double lx = px[cur][0], hx = lx, ly = py[cur][0], hy = ly;
    for (int i = 1; i < n; ++i) {
        lx = std::min(lx, px[cur][i]), hx = std::max(hx, px[cur][i]);
        ly = std::min(ly, py[cur][i]), hy = std::max(hy, py[cur][i]);
    }
    x0 = std::max(0, int(std::floor(lx)) - 1), x1 = std::min(w - 1, int(std::ceil(hx)) + 1);
    y0 = std::max(0, int(std::floor(ly)) - 1), y1 = std::min(h - 1, int(std::ceil(hy)) + 1);
    return x0 <= x1 && y0 <= y1;
}

// clipBox for the common case, without clipping: when the three lines g_k = 0 meet pairwise
// at well-defined corners (not within 2^-20 of parallel) and each corner lies inside the third
// half-plane by more than its rounding, the region is exactly the triangle of those corners
// (a triangle on the inner side of each of its edge lines is their intersection). Returns 1
// with the box (corners' bounds widened by a pixel), 0 when that triangle misses the face,
// −1 when undecided (a vertex behind the eye: the region is unbounded; near-parallel lines).
int cornerBox(const double* a, const double* b, const double* c, int w, int h, int& x0, int& x1,
              int& y0, int& y1) {
    double lx = 0, hx = 0, ly = 0, hy = 0;
    for (int i = 0; i < 3; ++i) {
        const int j = i == 2 ? 0 : i + 1, k = j == 2 ? 0 : j + 1;
        const double det = b[i] * c[j] - b[j] * c[i];
        const double gi = std::abs(b[i]) + std::abs(c[i]), gj = std::abs(b[j]) + std::abs(c[j]);
        if (!(std::abs(det) > 0x1p-20 * gi * gj)) return -1;
        const double x = (c[i] * a[j] - c[j] * a[i]) / det;
        const double y = (b[j] * a[i] - b[i] * a[j]) / det;
        const double gk = a[k] + b[k] * x + c[k] * y;
        const double tol = 0x1p-30 * (std::abs(a[k]) + std::abs(b[k] * x) + std::abs(c[k] * y));
        if (!(gk > tol)) return -1;
        if (i == 0) lx = hx = x, ly = hy = y;
        else lx = std::min(lx, x), hx = std::max(hx, x), ly = std::min(ly, y), hy = std::max(hy, y);
    }
    if (!(std::isfinite(lx) && std::isfinite(hx) && std::isfinite(ly) && std::isfinite(hy)))
        return -1;
    // Clamped in double: a corner may lie ~1e20 pixels out (a vertex near the face's plane).
    const double fx0 = std::max(0.0, std::floor(lx) - 1), fx1 = std::min(w - 1.0, std::ceil(hx) + 1);
    const double fy0 = std::max(0.0, std::floor(ly) - 1), fy1 = std::min(h - 1.0, std::ceil(hy) + 1);
    if (!(fx0 <= fx1 && fy0 <= fy1)) return 0;
    x0 = int(fx0), x1 = int(fx1), y0 = int(fy0), y1 = int(fy1);
    return 1;
}

// The triangles of the hemicube's half-space, in scene order; false when a vertex is out of
// the range the margins are proved for.
bool setUpTriangles(const PatchBvh& bvh, const HemicubeFrame& fr, std::vector<RasterTri>& out) {
    out.clear();
    const auto& prims = bvh.triangles();
    const double o[3] = {fr.origin.x, fr.origin.y, fr.origin.z};
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const auto& tri = static_cast<const rt::Triangle&>(*prims[i]);
        RasterTri t;
        const glm::dvec3* v[3] = {&tri.v0, &tri.v1, &tri.v2};
        double n1[3];
        for (int k = 0; k < 3; ++k) {
            t.p[k][0] = v[k]->x - o[0], t.p[k][1] = v[k]->y - o[1], t.p[k][2] = v[k]->z - o[2];
            n1[k] = std::abs(t.p[k][0]) + std::abs(t.p[k][1]) + std::abs(t.p[k][2]);
            if (n1[k] > kMaxDistance || (n1[k] > 0 && n1[k] < kMinDistance)) return false;
        }
        const glm::dvec3 a(t.p[0][0], t.p[0][1], t.p[0][2]), b(t.p[1][0], t.p[1][1], t.p[1][2]),
            c(t.p[2][0], t.p[2][1], t.p[2][2]);
        const glm::dvec3 edge[3] = {glm::cross(b, c), glm::cross(c, a), glm::cross(a, b)};
        for (int k = 0; k < 3; ++k) {
            t.ef[k][0] = glm::dot(edge[k], fr.u);
            t.ef[k][1] = glm::dot(edge[k], fr.v);
            t.ef[k][2] = glm::dot(edge[k], fr.n);
        }
        t.margin[0] = kEdgeMargin * 4 * n1[1] * n1[2];
        t.margin[1] = kEdgeMargin * 4 * n1[2] * n1[0];
        t.margin[2] = kEdgeMargin * 4 * n1[0] * n1[1];
        const double det = glm::dot(a, edge[0]);
        t.sigma = det < 0 ? -1.0 : 1.0;
        // Behind the eye the test's t is the plane's (negative) t up to the barycentric
        // weights' errors, <= ~400u·|a|₁|b|₁|c|₁ / |det| of it: keep the cone behind only
        // where det is within 2^-36 of that scale (the plane passes by the eye).
        t.bothCones = std::abs(det) <= 0x1p-36 * n1[0] * n1[1] * n1[2];
        t.certainOk = !t.bothCones && n1[0] > 0 && n1[1] > 0 && n1[2] > 0;
        t.prim = static_cast<std::int32_t>(i);
        t.patch = tri.material;
        out.push_back(t);
    }
    return true;
}

void rasterFace(const PatchBvh& bvh, const HemicubeFrame& fr, int res, HemicubeFace f,
                const std::vector<RasterTri>& tris, std::vector<std::int32_t>& out) {
    static thread_local FaceScratch scratch;
    const int w = faceWidth(res, f), h = faceHeight(res, f);
    const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    scratch.dirs.resize(count);
    scratch.sz.resize(count);
    scratch.kz.resize(count);
    scratch.st.resize(count);
    glm::dvec3* dirs = scratch.dirs.data();
    double* sz = scratch.sz.data();
    std::uint8_t* kz = scratch.kz.data();
    PixelState* st = scratch.st.data();
    const double inf = std::numeric_limits<double>::infinity();
    for (int row = 0; row < h; ++row)
        for (int col = 0; col < w; ++col) {
            const std::size_t k = static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                                  static_cast<std::size_t>(col);
            dirs[k] = glm::normalize(pixelDirection(fr, res, f, col, row));
            // triangleShear's kz and sz (the same expressions, so the same bits).
            const double d[3] = {dirs[k].x, dirs[k].y, dirs[k].z};
            const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
            const int z = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
            sz[k] = 1.0 / d[z];
            kz[k] = static_cast<std::uint8_t>(z);
            st[k] = {0.0, inf, -1, kEmpty};
        }
    const auto& prims = bvh.triangles();
    rt::Ray ray;
    ray.origin = fr.origin;
    // The watertight test for pixel k, offered as the walk offers (nearest; ties to the
    // triangle later in the scene).
    auto offerExact = [&](std::size_t k, std::int32_t ti) {
        PixelState& s = st[k];
        ray.direction = dirs[k];
        rt::Hit hit;
        const double before = s.hi;
        if (!prims[static_cast<std::size_t>(tris[static_cast<std::size_t>(ti)].prim)]->intersect(
                ray, 0.0, before, hit))
            return;
        if (s.tri >= 0 && hit.t == before && ti < s.tri) return;
        s.tri = ti;
        s.hi = hit.t;
    };
    const double ds = 2.0 / res, s0 = -1.0 + 0.5 * ds, w0 = vertical(res, f, 0.5);
    for (std::size_t ti = 0; ti < tris.size(); ++ti) {
        const RasterTri& t = tris[ti];
        double A[3], B[3], C[3], m[3];
        bool front = true, back = t.bothCones;
        for (int e = 0; e < 3; ++e) {
            double nh, nv, nl;
            toFace(f, t.ef[e], nh, nv, nl);
            A[e] = t.sigma * (nl + s0 * nh + w0 * nv);
            B[e] = t.sigma * (ds * nh);
            C[e] = t.sigma * (ds * nv);
            m[e] = t.margin[e];
            // The whole face at once (an affine function's extremes are at the corners; 2^-30
            // of its size covers the per-pixel evaluation's different rounding): no pixel
            // passes this edge, so none passes the triangle.
            const double bw = B[e] * (w - 1), ch = C[e] * (h - 1);
            const double slack = 0x1p-30 * (std::abs(A[e]) + std::abs(bw) + std::abs(ch));
            front = front && A[e] + std::max(0.0, bw) + std::max(0.0, ch) >= -m[e] - slack;
            back = back && A[e] + std::min(0.0, bw) + std::min(0.0, ch) <= m[e] + slack;
        }
        if (!front && !back) continue;
        int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
        const double Af[3] = {A[0] + m[0], A[1] + m[1], A[2] + m[2]};
        bool any = false;
        if (front) {
            const int quick = back ? -1 : cornerBox(Af, B, C, w, h, x0, x1, y0, y1);
            any = quick < 0 ? clipBox(Af, B, C, w, h, x0, x1, y0, y1) : quick == 1;
        }
        if (back) {
            const double Ab[3] = {m[0] - A[0], m[1] - A[1], m[2] - A[2]};
            const double Bb[3] = {-B[0], -B[1], -B[2]}, Cb[3] = {-C[0], -C[1], -C[2]};
            int bx0, bx1, by0, by1;
            if (clipBox(Ab, Bb, Cb, w, h, bx0, bx1, by0, by1)) {
                if (any) {
                    x0 = std::min(x0, bx0), x1 = std::max(x1, bx1);
                    y0 = std::min(y0, by0), y1 = std::max(y1, by1);
                } else {
                    x0 = bx0, x1 = bx1, y0 = by0, y1 = by1;
                }
                any = true;
            }
        }
        if (!any) continue;
        const auto tri = static_cast<std::int32_t>(ti);
        for (int row = y0; row <= y1; ++row) {
            const double r0 = A[0] + C[0] * row, r1 = A[1] + C[1] * row, r2 = A[2] + C[2] * row;
            int c0 = x0, c1 = x1;
            if (!back) {
                // The row's span in front: where each edge function's line crosses −m, widened
                // by 2^-20 of a pixel and by 2^-40 of the terms' size over |B| (the quotient's
                // rounding), so no pixel the test below would take is left out.
                double lo = x0, hi = x1;
                const double r[3] = {r0, r1, r2};
                for (int e = 0; e < 3; ++e) {
                    const double num = -m[e] - r[e];
                    if (B[e] == 0.0) {
                        if (num > 0.0) lo = hi + 1; // the whole row is beyond this edge
                        continue;
                    }
                    const double x = num / B[e];
                    const double pad = 0x1p-20 + 0x1p-40 * (std::abs(A[e]) + std::abs(C[e] * row) +
                                                            m[e] + std::abs(num)) /
                                                               std::abs(B[e]);
                    if (B[e] > 0) lo = std::max(lo, x - pad);
                    else hi = std::min(hi, x + pad);
                }
                if (!(lo <= hi)) continue;
                c0 = std::max(x0, int(std::ceil(lo)));
                c1 = std::min(x1, int(std::floor(hi)));
            }
            for (int col = c0; col <= c1; ++col) {
                const double e0 = r0 + B[0] * col, e1 = r1 + B[1] * col, e2 = r2 + B[2] * col;
                const bool inFront = e0 >= -m[0] && e1 >= -m[1] && e2 >= -m[2];
                if (!inFront && !(back && e0 <= m[0] && e1 <= m[1] && e2 <= m[2])) continue;
                const std::size_t k = static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                                      static_cast<std::size_t>(col);
                const int z = kz[k];
                const double za = sz[k] * t.p[0][z], zb = sz[k] * t.p[1][z],
                             zc = sz[k] * t.p[2][z];
                const double zmin = std::min({za, zb, zc});
                const double lo = zmin > 0 ? zmin * (1.0 - kDepthMargin) : 0.0;
                const bool certain = t.certainOk && zmin > 0 && e0 > m[0] && e1 > m[1] && e2 > m[2];
                const double hi = certain ? std::max({za, zb, zc}) * (1.0 + kDepthMargin) : inf;
                PixelState& s = st[k];
                if (s.state == kEmpty) {
                    s = {lo, hi, tri, kPending};
                    continue;
                }
                if (s.state == kPending) {
                    if (lo > s.hi) continue;    // certainly behind the pending one's hit
                    if (hi < s.lo) {            // certainly hit, and in front of the pending one
                        s = {lo, hi, tri, kPending};
                        continue;
                    }
                    const std::int32_t p = s.tri;
                    s = {0.0, inf, -1, kResolved};
                    offerExact(k, p);
                }
                if (lo > s.hi) continue; // certainly behind the nearest hit so far
                offerExact(k, tri);
            }
        }
    }
    const auto& patches = bvh.mesh().patches;
    for (std::size_t k = 0; k < count; ++k) {
        PixelState& s = st[k];
        if (s.state == kPending && !(s.hi < inf)) {
            const std::int32_t p = s.tri;
            s = {0.0, inf, -1, kResolved};
            offerExact(k, p);
        }
        std::int32_t id = -1;
        if (s.tri >= 0) {
            id = tris[static_cast<std::size_t>(s.tri)].patch;
            // patchOf: a back side seen is resolved by the walk around the hit (rare).
            if (!(glm::dot(patches[static_cast<std::size_t>(id)].normal, dirs[k]) < 0.0))
                id = bvh.nearestPatch(fr.origin, dirs[k], 0.0, inf);
        }
        out[k] = id;
    }
}

void castPackets(const PatchBvh& bvh, const HemicubeFrame& frame, int resolution,
                 ItemBuffer& out, bool parallel) {
    const int half = resolution / 2;
    const int rows = resolution + 4 * half; // top rows, then each side's rows
    auto doRow = [&](int r) {
        HemicubeFace f = HemicubeFace::Top;
        int row = r;
        if (r >= resolution) {
            f = static_cast<HemicubeFace>(1 + (r - resolution) / half);
            row = (r - resolution) % half;
        }
        auto& face = out.faces[static_cast<std::size_t>(f)];
        // Neighbouring pixels of the row as one packet (issue 21): one walk of the BVH
        // for up to 8 coherent rays from the same origin, the same patch ids as one by one.
        for (int col = 0; col < resolution; col += rt::kMaxPacket) {
            const int n = std::min(rt::kMaxPacket, resolution - col);
            glm::dvec3 d[rt::kMaxPacket];
            int ids[rt::kMaxPacket];
            for (int j = 0; j < n; ++j)
                d[j] = glm::normalize(pixelDirection(frame, resolution, f, col + j, row));
            bvh.nearestPatches(frame.origin, d, n, ids);
            for (int j = 0; j < n; ++j)
                face[static_cast<std::size_t>(row) * static_cast<std::size_t>(resolution) +
                     static_cast<std::size_t>(col + j)] = ids[j];
        }
    };
    if (parallel)
        tbb::parallel_for(0, rows, doRow);
    else
        for (int r = 0; r < rows; ++r) doRow(r);
}

} // namespace

void castItemBuffer(const PatchBvh& bvh, const HemicubeFrame& frame, int resolution,
                    ItemBuffer& out, bool parallel, HemicubeCast method) {
    if (out.resolution != resolution) out.resize(resolution);
    if (method == HemicubeCast::Raster) {
        // The triangle list (~0.8 MB on lab 08's scenes) is taken from a pool, not allocated
        // per hemicube (fresh pages cost ~10%); not thread_local: a thread waiting in the
        // faces' parallel_for may run another hemicube of an outer parallel loop.
        static std::mutex poolMutex;
        static std::vector<std::vector<RasterTri>> pool;
        std::vector<RasterTri> tris;
        {
            const std::lock_guard<std::mutex> lock(poolMutex);
            if (!pool.empty()) {
                tris = std::move(pool.back());
                pool.pop_back();
            }
        }
        struct GiveBack {
            std::vector<RasterTri>& t;
            ~GiveBack() {
                const std::lock_guard<std::mutex> lock(poolMutex);
                pool.push_back(std::move(t));
            }
        } giveBack{tris};
        if (setUpTriangles(bvh, frame, tris)) {
            auto face = [&](int f) {
                const auto hf = static_cast<HemicubeFace>(f);
                rasterFace(bvh, frame, resolution, hf, tris, out.faces[static_cast<std::size_t>(f)]);
            };
            if (parallel)
                tbb::parallel_for(0, kHemicubeFaces, face);
            else
                for (int f = 0; f < kHemicubeFaces; ++f) face(f);
            return;
        }
    }
    castPackets(bvh, frame, resolution, out, parallel);
}

void accumulate(const ItemBuffer& items, const DeltaFormFactors& table, int patchCount, int self,
                std::vector<float>& out) {
    if (items.resolution != table.resolution)
        throw std::invalid_argument("hemicube accumulate: item buffer resolution " +
                                    std::to_string(items.resolution) + " but delta table " +
                                    std::to_string(table.resolution));
    // Sum in double: at 1024² a float sum of ~3 million terms would lose ~1e-4.
    std::vector<double> acc(static_cast<std::size_t>(std::max(patchCount, 0)), 0.0);
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto& ids = items.faces[static_cast<std::size_t>(f)];
        const auto& w = table.faces[static_cast<std::size_t>(f)];
        if (ids.size() != w.size())
            throw std::invalid_argument("hemicube accumulate: face " + std::to_string(f) +
                                        " has " + std::to_string(ids.size()) +
                                        " items for " + std::to_string(w.size()) + " weights");
        for (std::size_t k = 0; k < ids.size(); ++k) {
            const std::int32_t id = ids[k];
            if (id >= 0 && id < patchCount) acc[static_cast<std::size_t>(id)] += w[k];
        }
    }
    if (self >= 0 && self < patchCount) acc[static_cast<std::size_t>(self)] = 0.0;
    out.resize(acc.size());
    for (std::size_t j = 0; j < acc.size(); ++j) out[j] = static_cast<float>(acc[j]);
}

void hemicubeRow(const PatchMesh& mesh, const PatchBvh& bvh, const DeltaFormFactors& table,
                 int i, std::vector<float>& out, bool parallel) {
    ItemBuffer items;
    castItemBuffer(bvh, hemicubeFrame(mesh, i), table.resolution, items, parallel);
    accumulate(items, table, static_cast<int>(mesh.patches.size()), i, out);
}

} // namespace wb::rad
