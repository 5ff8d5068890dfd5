// Lab 08's OpenGL hemicube (labs/08-radiosity/gl_hemicube.*) against core's CPU hemicube
// (rad::castItemBuffer: one double-precision ray per pixel centre through the patch BVH), on
// a closed room with a floating box that shadows part of the floor and walls (occlusion).
//
// The two item buffers sample the same pixel centres, so they can differ only where the two
// rasterizers decide a pixel centre differently: GL snaps window coordinates to llvmpipe's
// sub-pixel grid (1/256 px) and breaks ties on an edge by its top-left rule; the CPU tests the
// exact double ray. Such pixels lie on a projected patch edge. The tolerance is therefore
// stated in pixels, not in an arbitrary epsilon:
//  (1) every pixel where GL and CPU disagree is a BOUNDARY pixel: its square is crossed by a
//      patch edge, detected independently by CPU rays through the pixel's four corners
//      (some corner sees another patch than the centre);
//  (2) for every patch j, |F_gl,ij − F_cpu,ij| ≤ the delta-form-factor mass of the boundary
//      pixels in which either buffer sees j (a consequence of (1), checked on the rows
//      core's accumulate() makes, which is what the solver uses);
//  (3) on a scene with no exact ties, GL's id at a disagreeing pixel is what a CPU ray
//      within 1/64 px of the centre sees (llvmpipe snaps vertices to 1/256 px), and the
//      disagreeing pixels weigh under 2% of the boundary pixels (measured: 0.5% at 16²,
//      0.05% at 64², none at 256², largest shift 1/256 px; a mirrored face, a wrong near
//      plane or depth order needs shifts of whole pixels and fails (1) first).
// On an axis-aligned scene meshed on a dyadic grid, edges pass exactly through pixel
// centres and both answers are legitimate ties: (1) and (2) hold, the share is reported.
#include "gl_hemicube.h"

#include "common/headless_context.h"
#include "core/radiosity/hemicube.h"
#include "core/radiosity/mesh.h"
#include "core/radiosity/patch_bvh.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using glm::dvec3;

namespace {

struct Context : wb::HeadlessContext {
    Context(int w, int h) : HeadlessContext(w, h) { REQUIRE(ok()); }
};

// A quad o, o+a, o+a+b, o+b: its front (normal a × b) is the side it emits and receives on.
wb::rad::Surface quad(dvec3 o, dvec3 a, dvec3 b, const std::string& name, double e = 0.0) {
    wb::rad::Surface s;
    s.vertices = {o, o + a, o + a + b, o + b};
    s.reflectivity = dvec3(0.5);
    s.emission = dvec3(e);
    s.name = name;
    return s;
}

// A room (normals inward, the ceiling emits) with a box floating in it (normals outward).
// `aligned`: a unit room and a box on simple decimals, meshed on a 0.25 grid: patch edges
// project exactly through many pixel centres (exact ties, as in the Cornell box's grids).
// Otherwise sizes with no common measure with the pixel grid: ties have probability 0.
wb::rad::Scene roomWithBox(bool aligned) {
    const dvec3 size = aligned ? dvec3(1.0) : dvec3(1.0, 0.9373, 1.0719);
    const dvec3 X(size.x, 0, 0), Y(0, size.y, 0), Z(0, 0, size.z);
    wb::rad::Scene sc;
    sc.name = "room with a floating box";
    sc.closed = true;
    sc.surfaces = {quad({0, 0, 0}, Z, X, "floor"),       quad(Y, X, Z, "ceiling", 1.0),
                   quad({0, 0, 0}, Y, Z, "wall x=0"),    quad(X, Z, Y, "wall x=1"),
                   quad({0, 0, 0}, X, Y, "wall z=0"),    quad(Z, Y, X, "wall z=1")};
    const dvec3 lo = aligned ? dvec3(0.3, 0.25, 0.35) : dvec3(0.3071, 0.2563, 0.3389);
    const dvec3 hi = aligned ? dvec3(0.62, 0.5, 0.7) : dvec3(0.6237, 0.5117, 0.7043);
    const dvec3 d = hi - lo;
    const dvec3 dx(d.x, 0, 0), dy(0, d.y, 0), dz(0, 0, d.z);
    sc.surfaces.push_back(quad(lo, dx, dz, "box bottom"));
    sc.surfaces.push_back(quad({lo.x, hi.y, lo.z}, dz, dx, "box top"));
    sc.surfaces.push_back(quad(lo, dz, dy, "box x-"));
    sc.surfaces.push_back(quad({hi.x, lo.y, lo.z}, dy, dz, "box x+"));
    sc.surfaces.push_back(quad(lo, dy, dx, "box z-"));
    sc.surfaces.push_back(quad({lo.x, lo.y, hi.z}, dx, dy, "box z+"));
    return sc;
}

// Direction through continuous face coordinates (s, w) of face f: core's layout table.
dvec3 faceDirection(const wb::rad::HemicubeFrame& fr, wb::rad::HemicubeFace f, double s, double w) {
    using F = wb::rad::HemicubeFace;
    switch (f) {
    case F::Top: return s * fr.u + w * fr.v + fr.n;
    case F::PosU: return fr.u - s * fr.v + w * fr.n;
    case F::NegU: return -fr.u + s * fr.v + w * fr.n;
    case F::PosV: return fr.v + s * fr.u + w * fr.n;
    default: return -fr.v - s * fr.u + w * fr.n;
    }
}

struct Comparison {
    long long pixels = 0, boundary = 0, mismatched = 0, mismatchedInterior = 0;
    double boundaryMass = 0, mismatchedMass = 0;
    double worstRowExcess = -1; // max over j of |ΔF_j| − (boundary mass touching j); must be <= 0
    double rowSumGl = 0, rowSumCpu = 0;
    double worstShift = 0; // pixels: GL's id is what a CPU ray this far from the centre sees
};

Comparison compare(wb::GlHemicube& gl, const wb::rad::PatchMesh& mesh,
                   const wb::rad::PatchBvh& bvh, int patch, int res) {
    using namespace wb::rad;
    const HemicubeFrame frame = hemicubeFrame(mesh, patch);
    ItemBuffer cpu, glItems;
    castItemBuffer(bvh, frame, res, cpu, false);
    std::string err;
    INFO(err);
    REQUIRE(gl.render(frame, res, wb::GlHemicube::kNearFraction * 0.87, glItems, err)); // room radius √3/2
    const DeltaFormFactors table = deltaFormFactors(res);
    const int n = int(mesh.patches.size());
    std::vector<double> touch(size_t(n), 0.0); // boundary mass of pixels where j is seen
    Comparison c;
    const double inf = std::numeric_limits<double>::infinity();
    const double px = 2.0 / res;
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto face = HemicubeFace(f);
        const int w = faceWidth(res, face), h = faceHeight(res, face);
        for (int row = 0; row < h; ++row)
            for (int col = 0; col < w; ++col) {
                const size_t k = size_t(row) * size_t(w) + size_t(col);
                const int32_t a = cpu.faces[size_t(f)][k], b = glItems.faces[size_t(f)][k];
                const double weight = table.faces[size_t(f)][k];
                // Corners of the pixel square through independent CPU rays.
                const double s0 = -1.0 + col * px;
                const double w0 = face == HemicubeFace::Top ? -1.0 + row * px : row * px;
                bool edge = false;
                for (int corner = 0; corner < 4 && !edge; ++corner) {
                    const dvec3 d = glm::normalize(faceDirection(
                        frame, face, s0 + (corner & 1) * px, w0 + (corner >> 1) * px));
                    edge = bvh.nearestPatch(frame.origin, d, 0.0, inf) != a;
                }
                ++c.pixels;
                if (edge) {
                    ++c.boundary;
                    c.boundaryMass += weight;
                    if (a >= 0) touch[size_t(a)] += weight;
                    if (b >= 0 && b != a) touch[size_t(b)] += weight;
                }
                if (a != b) {
                    ++c.mismatched;
                    c.mismatchedMass += weight;
                    if (!edge) ++c.mismatchedInterior;
                    // (3) The smallest shift of the sample point (in pixels, 8 directions)
                    // at which the CPU ray sees what GL saw.
                    const double sc = s0 + 0.5 * px, wc = w0 + 0.5 * px;
                    double found = 1.0;
                    for (double shift : {1.0 / 1024, 1.0 / 256, 1.0 / 64, 1.0 / 16, 0.5}) {
                        for (int dir = 0; dir < 64 && found > shift; ++dir) {
                            const double ang = dir * 3.141592653589793 / 32;
                            const dvec3 d = glm::normalize(
                                faceDirection(frame, face, sc + shift * px * std::cos(ang),
                                              wc + shift * px * std::sin(ang)));
                            if (bvh.nearestPatch(frame.origin, d, 0.0, inf) == b) found = shift;
                        }
                        if (found <= shift) break;
                    }
                    c.worstShift = std::max(c.worstShift, found);

                }
            }
    }
    std::vector<float> rowCpu, rowGl;
    accumulate(cpu, table, n, patch, rowCpu);
    accumulate(glItems, table, n, patch, rowGl);
    for (int j = 0; j < n; ++j) {
        c.rowSumCpu += double(rowCpu[size_t(j)]);
        c.rowSumGl += double(rowGl[size_t(j)]);
        // float rows: 1e-7 absolute covers their rounding (values <= 1, float ulp 6e-8).
        const double excess = std::abs(double(rowGl[size_t(j)]) - double(rowCpu[size_t(j)])) -
                              touch[size_t(j)] - 1e-7;
        c.worstRowExcess = std::max(c.worstRowExcess, excess);
    }
    return c;
}

// Renders the GL and CPU hemicubes of every 7th patch (floor in and beside the box's
// shadow, walls, the box) at 16², every 14th at 64², one at 256², checks (1) and (2) per patch
// and returns the totals per resolution.
std::vector<Comparison> compareScene(bool aligned) {
    Context ctx(64, 64);
    const wb::rad::PatchMesh mesh = wb::rad::meshScene(roomWithBox(aligned), {0.25});
    const wb::rad::PatchBvh bvh(mesh);
    wb::GlHemicube gl;
    std::vector<glm::vec3> verts;
    std::vector<uint32_t> items;
    wb::patchFans(mesh, verts, items);
    std::string err;
    REQUIRE(gl.setGeometry(verts, items, err));
    std::vector<int> patches;
    for (int p = 0; p < int(mesh.patches.size()); p += 7) patches.push_back(p);
    std::vector<Comparison> totals;
    for (int res : {16, 64, 256}) {
        Comparison total;
        // Fewer patches as the pixels grow (the boundary test casts 5 CPU rays a pixel):
        // the binary stays under ~15 s under ASan.
        std::vector<int> chosen;
        for (size_t k = 0; k < patches.size(); k += (res == 16 ? 1 : 2)) chosen.push_back(patches[k]);
        if (res == 256) chosen = {patches[3]};
        for (int p : chosen) {
            const Comparison c = compare(gl, mesh, bvh, p, res);
            INFO((aligned ? "aligned" : "generic")
                 << " scene, patch " << p << " on "
                 << mesh.surfaces[size_t(mesh.patches[size_t(p)].surface)].name << ", hemicube "
                 << res);
            CHECK(c.mismatchedInterior == 0);                      // (1)
            CHECK(c.worstRowExcess <= 0.0);                        // (2)
            CHECK(c.rowSumGl == Approx(c.rowSumCpu).margin(c.boundaryMass));
            total.pixels += c.pixels;
            total.boundary += c.boundary;
            total.mismatched += c.mismatched;
            total.boundaryMass += c.boundaryMass;
            total.mismatchedMass += c.mismatchedMass;
            total.worstShift = std::max(total.worstShift, c.worstShift);
        }
        WARN((aligned ? "aligned" : "generic")
             << " scene, hemicube " << res << ": " << total.mismatched << " of " << total.pixels
             << " pixels differ (" << total.boundary << " boundary pixels); weight "
             << total.mismatchedMass << " of boundary weight " << total.boundaryMass
             << "; largest sample shift " << total.worstShift << " px");
        totals.push_back(total);
    }
    return totals;
}

} // namespace

TEST_CASE("lab 08: GL hemicube = CPU hemicube up to edge pixels, generic scene with occlusion",
          "[gl]") {
    for (const Comparison& t : compareScene(false)) {
        // (3) llvmpipe snaps vertices to 1/256 px, so a GL edge is within ~1/256·√2 px of the
        // exact one; 1/64 px leaves 4× for float projection. A mis-oriented face, a wrong near
        // plane or depth order would need shifts of whole pixels.
        CHECK(t.worstShift <= 1.0 / 64);
        CHECK(t.mismatchedMass <= 0.02 * t.boundaryMass);
    }
}

// Axis-aligned geometry on a dyadic grid: projected edges and vertices fall exactly on pixel
// centres, where GL (top-left rule) and the CPU ray (which patch the BVH reports on a shared
// edge, or a silhouette corner) legitimately decide differently. (1) and (2) still hold; the
// share of such ties is reported (WARN) and bounded loosely.
TEST_CASE("lab 08: GL hemicube = CPU hemicube up to edge pixels, aligned scene with exact ties",
          "[gl]") {
    for (const Comparison& t : compareScene(true))
        CHECK(t.mismatchedMass <= 0.1 * t.boundaryMass); // measured 3-5%: ties, see WARN
}

TEST_CASE("lab 08: GL hemicube rejects bad input with a message", "[gl]") {
    Context ctx(16, 16);
    wb::GlHemicube gl;
    std::string err;
    CHECK_FALSE(gl.setGeometry({glm::vec3(0), glm::vec3(1, 0, 0)}, {0}, err));
    CHECK(err.find("3 vertices") != std::string::npos);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(gl.setGeometry({glm::vec3(nan), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}, {0}, err));
    CHECK(err.find("non-finite") != std::string::npos);
    CHECK_FALSE(gl.setGeometry({glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)},
                               {(1u << 24) - 1}, err));
    REQUIRE(gl.setGeometry({glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}, {0}, err));
    wb::rad::ItemBuffer out;
    CHECK_FALSE(gl.render({}, 15, 1e-3, out, err)); // odd
    CHECK_FALSE(gl.render({}, 16, 0.0, out, err));  // no near plane
    REQUIRE(gl.render({}, 16, 1e-3, out, err));
}

TEST_CASE("lab 08: item colours round-trip for every bit of a 24-bit id", "[gl]") {
    for (uint32_t id : {0u, 1u, 255u, 256u, 65535u, 65536u, (1u << 24) - 2}) {
        uint8_t rgb[3];
        wb::GlHemicube::encode(id, rgb);
        CHECK(wb::GlHemicube::decode(rgb) == int32_t(id));
    }
    const uint8_t black[3] = {0, 0, 0};
    CHECK(wb::GlHemicube::decode(black) == -1);
}
