// Lab 05 - stencil, headless. The shadow and the mirrors are checked against references
// computed here from the scene's geometry, not from the stencil code: the shadow by
// casting a ray from each stair pixel's world point to the light and testing the torus;
// the mirrors by projecting the true rectangle and ellipse with the frame's camera.
#include "render/render_check.h"
#include "stencil_lab.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>

namespace {

using glm::dvec2;
using glm::dvec3;

constexpr int kW = 320, kH = 240;

struct Shot {
    wb::StencilLabState state;
    wb::Image img;
};

Shot shoot(const std::string& keys, int w = kW, int h = kH) {
    Shot s;
    auto lab = wb::makeStencilLab(&s.state);
    s.img = wb::test::renderLab(*lab, w, h, keys);
    REQUIRE(s.state.width == w);
    REQUIRE(s.state.height == h);
    return s;
}

uint8_t stencilAt(const Shot& s, int x, int y) {
    return s.state.stencil[size_t(y) * size_t(kW) + size_t(x)];
}

// World point of pixel (x, y) (y down) on the plane n·p + d = 0, through the frame's camera.
dvec3 unprojectOnPlane(const wb::StencilLabState& st, int x, int y, const dvec3& n, double d) {
    const glm::dvec4 vp(0, 0, kW, kH);
    const dvec3 win(x + 0.5, kH - y - 0.5, 0.0);
    const dvec3 a = glm::unProject(win, st.modelview, st.projection, vp);
    const dvec3 b = glm::unProject(dvec3(win.x, win.y, 1.0), st.modelview, st.projection, vp);
    const double t = -(glm::dot(n, a) + d) / glm::dot(n, b - a);
    return a + t * (b - a);
}

// Smallest value of the torus' implicit distance (|q| - r, negative inside) along the segment
// from p to the light, sampled every 1 mm (the torus is 0.4 thick: no gap is missed).
double closestToTorus(const wb::StencilLabState& st, const dvec3& p) {
    const glm::dmat4 toLocal = glm::inverse(st.objectModel);
    const dvec3 a(toLocal * glm::dvec4(p, 1.0)), b(toLocal * glm::dvec4(wb::kStencilLight, 1.0));
    const int samples = int(glm::length(b - a) / 0.001) + 1;
    double best = 1e9;
    for (int i = 0; i <= samples; ++i) {
        const dvec3 q = a + (b - a) * (double(i) / samples);
        const double ring = std::hypot(q.x, q.z) - wb::kTorusMajor;
        best = std::min(best, std::hypot(ring, q.y) - wb::kTorusMinor);
    }
    return best;
}

// The receiver plane of a stair stencil value: tread i (y = (i+1)h, normal +y) or riser i
// (x = x0 + i·w, normal -x).
void stairPlane(uint8_t value, dvec3& n, double& d) {
    const int k = value - wb::kStencilFirstStep, i = k / 2;
    if (k % 2 == 0) {
        n = {0, 1, 0};
        d = -(i + 1) * wb::kStepHeight;
    } else {
        n = {-1, 0, 0};
        d = wb::kStairX0 + i * wb::kStepWidth;
    }
}

dvec2 project(const wb::StencilLabState& st, const dvec3& p) {
    const dvec3 w = glm::project(p, st.modelview, st.projection, glm::dvec4(0, 0, kW, kH));
    return {w.x, kH - w.y};
}

bool inside(const std::vector<dvec2>& poly, const dvec2& p) {
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            in = !in;
    return in;
}

double distanceToOutline(const std::vector<dvec2>& poly, const dvec2& p) {
    dvec2 lo(1e9), hi(-1e9); // far outside the bounding box: no need to look at the edges
    for (const dvec2& v : poly)
        lo = glm::min(lo, v), hi = glm::max(hi, v);
    if (p.x < lo.x - 2 || p.y < lo.y - 2 || p.x > hi.x + 2 || p.y > hi.y + 2) return 2.0;
    double best = 1e9;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const dvec2 e = poly[i] - poly[j];
        const double t = std::clamp(glm::dot(p - poly[j], e) / glm::dot(e, e), 0.0, 1.0);
        best = std::min(best, glm::length(p - (poly[j] + t * e)));
    }
    return best;
}

// The true mirror outlines (the rectangle's corners, the ellipse at 0.5° steps) in pixels.
std::vector<dvec2> rectOutline(const wb::StencilLabState& st) {
    const double* r = wb::kRectMirror;
    return {project(st, {r[0], r[1], wb::kMirrorZ}), project(st, {r[2], r[1], wb::kMirrorZ}),
            project(st, {r[2], r[3], wb::kMirrorZ}), project(st, {r[0], r[3], wb::kMirrorZ})};
}
std::vector<dvec2> ellipseOutline(const wb::StencilLabState& st) {
    const double* m = wb::kEllipseMirror;
    std::vector<dvec2> out;
    for (int i = 0; i < 720; ++i) {
        const double a = 2.0 * 3.14159265358979323846 * i / 720;
        out.push_back(
            project(st, {m[0] + m[2] * std::cos(a), m[1] + m[3] * std::sin(a), wb::kMirrorZ}));
    }
    return out;
}

bool samePixel(const wb::Image& a, const wb::Image& b, int x, int y) {
    const uint8_t *p = a.at(x, y), *q = b.at(x, y);
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
}

} // namespace

TEST_CASE("shadow: on the receivers only, darkened exactly once, where the torus blocks the light",
          "[gl][stencil]") {
    // Default position; moved 0.5 right, so that riser 2's plane (x = 0) cuts through the
    // torus; and sunk into the first steps (y = 0.5), where only the part of the torus on the
    // light's side of each tread may cast onto it (the rest would make a false shadow).
    std::string sunk = "{left}{left}{left}{left}";
    for (int i = 0; i < 20; ++i)
        sunk += "{pgdn}";
    const std::string move =
        GENERATE_COPY(std::string(""), std::string("{right}{right}{right}{right}{right}"), sunk);
    INFO("object keys " << move);
    Shot on = shoot(move), off = shoot(move + "s");
    // Blending black with alpha 0.5 keeps dst·(1 - a). llvmpipe blends in 8-bit unorm with a
    // = 128/255, so the kept factor is 127/255; ±1 covers its rounding. A second blend would
    // give dst·0.25 and miss by dst/4 (> 1 wherever dst > 4, i.e. everywhere lit).
    const double keep = 127.0 / 255.0;
    int shadowPixels = 0, stairShadow = 0, reflectedShadow = 0, changedWithoutBit = 0,
        badDarkness = 0, geometryWrong = 0;
    double worstDarkness = 0, worstInside = 0, worstOutside = 0;
    std::set<int> stairReceivers;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const uint8_t v = stencilAt(on, x, y);
            const bool bit = v & wb::kShadowBit;
            if (!bit) {
                if (!samePixel(on.img, off.img, x, y)) ++changedWithoutBit;
            } else {
                ++shadowPixels;
                // Inside a mirror the glass (alpha 51/255 over the reflection) is blended after
                // the shadow: on = g + (off - g)·keep with g = glass·51 per channel.
                const double glass[3] = {0.75 * 51, 0.85 * 51, 1.0 * 51};
                const bool mirror = v & wb::kMirrorMask;
                for (int k = 0; k < 3; ++k) {
                    const double g = mirror ? glass[k] : 0.0;
                    const double e =
                        std::abs(on.img.at(x, y)[k] - (g + (off.img.at(x, y)[k] - g) * keep));
                    worstDarkness = std::max(worstDarkness, e);
                    // ±1 for one 8-bit blend; a second rounding through the glass adds ±0.5.
                    if (e > (mirror ? 1.5 : 1.0)) ++badDarkness;
                }
            }
            if (v & wb::kMirrorMask) { // a reflection: only the darkness checks above apply
                reflectedShadow += bit;
                continue;
            }
            const uint8_t receiver = v & wb::kReceiverMask;
            if (receiver < wb::kStencilFirstStep) continue;
            // Independent geometry: the pixel's world point on its step, a ray to the light.
            dvec3 n;
            double d;
            stairPlane(receiver, n, d);
            const double c = closestToTorus(on.state, unprojectOnPlane(on.state, x, y, n, d));
            // The rasteriser decides at the pixel centre, the point tested here, so only the
            // mesh's facets (inside the true torus by < 0.005) and the 1 mm sampling separate
            // the two; measured: within 0.002 either way.
            const double eps = 0.01;
            if (bit) {
                ++stairShadow;
                stairReceivers.insert(receiver);
                worstInside = std::max(worstInside, c);
                if (c > eps) ++geometryWrong;
            } else {
                worstOutside = std::min(worstOutside, c);
                if (c < -eps) ++geometryWrong;
            }
        }
    WARN("shadow: " << shadowPixels << " pixels, " << stairShadow << " on " << stairReceivers.size()
                    << " stair faces; darkness off by at most " << worstDarkness
                    << "/255; ray-cast margin: shadowed pixels reach " << worstInside
                    << ", lit pixels reach " << worstOutside << " (torus units); "
                    << reflectedShadow << " shadow pixels in the mirrors");
    CHECK(changedWithoutBit == 0); // nothing darkened outside the stencil's shadow bit
    CHECK(badDarkness == 0);       // uniform: every shadow pixel blended exactly once
    CHECK(geometryWrong == 0);     // no leak past a step's edge, no missing shadow
    CHECK(stairShadow > 30); // the shadow really falls on the stairs (401, 316, 44 px measured)
    CHECK(stairReceivers.size() >= 2);
    CHECK(on.state.shadowTriangles > 0);
    if (move.empty()) CHECK(reflectedShadow > 20); // the mirrors show the shadows too
}

TEST_CASE("naive shadow (no stencil) shows what the stencil prevents", "[gl][stencil]") {
    // The same checks have teeth: without the stencil, overlapping flattened triangles
    // darken pixels twice (dst·0.25) and the projection spills off the steps.
    Shot naive = shoot("n"), off = shoot("s");
    int doubled = 0, changed = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (samePixel(naive.img, off.img, x, y)) continue;
            ++changed;
            const uint8_t *p = naive.img.at(x, y), *q = off.img.at(x, y);
            if (q[0] > 40 && p[0] < q[0] * 0.35) ++doubled;
        }
    Shot good = shoot("");
    int goodChanged = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            goodChanged += !samePixel(good.img, off.img, x, y);
    WARN("naive shadow: " << changed << " pixels changed (" << doubled
                          << " darkened twice); stencil shadow: " << goodChanged);
    CHECK(doubled > 100);
    CHECK(changed > goodChanged);
}

TEST_CASE("mirrors: the stencil is exactly each mirror, the reflection stays inside it",
          "[gl][stencil]") {
    // Shadows off ("s") so the stencil holds only the mirrors. Pixels whose centre is within
    // 0.75 px of a true outline may be covered or not (rasterisation rules, and the
    // 72-gon ellipse deviates from the true ellipse by 0.04 px): they are not judged.
    Shot both = shoot("s"), none = shoot("sre"), rectOnly = shoot("se"), ellipseOnly = shoot("sr");
    const std::vector<dvec2> rect = rectOutline(both.state), ell = ellipseOutline(both.state);
    int stencilWrong = 0, outsideChanged = 0, rectReflected = 0, rectArea = 0, ellReflected = 0,
        ellArea = 0, soloLeak = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const dvec2 c(x + 0.5, y + 0.5);
            if (distanceToOutline(rect, c) < 0.75 || distanceToOutline(ell, c) < 0.75) continue;
            const bool inRect = inside(rect, c), inEll = inside(ell, c);
            const uint8_t v = stencilAt(both, x, y);
            const uint8_t expect = inRect  ? wb::kStencilRectMirror
                                   : inEll ? wb::kStencilEllipseMirror
                                           : 0;
            if (v != expect) ++stencilWrong;
            const bool changed = !samePixel(both.img, none.img, x, y);
            if (!inRect && !inEll && changed) ++outsideChanged;
            rectArea += inRect, ellArea += inEll;
            if (inRect && changed) ++rectReflected;
            if (inEll && changed) ++ellReflected;
            // Each mirror alone changes only its own inside.
            if (!inRect && !samePixel(rectOnly.img, none.img, x, y)) ++soloLeak;
            if (!inEll && !samePixel(ellipseOnly.img, none.img, x, y)) ++soloLeak;
        }
    WARN("mirrors: rectangle " << rectArea << " px (" << rectReflected << " changed), ellipse "
                               << ellArea << " px (" << ellReflected << " changed)");
    CHECK(stencilWrong == 0);
    CHECK(outsideChanged == 0); // outside the mirrors the image equals the render without them
    CHECK(soloLeak == 0);
    CHECK(rectArea > 2000);
    CHECK(ellArea > 2000);
    // Inside, only pixels where the real torus stands in front of the mirror may be unchanged.
    CHECK(rectReflected > rectArea * 8 / 10);
    CHECK(ellReflected > ellArea * 9 / 10);
}

TEST_CASE("mirror: the reflection is lit by the reflected light, with its own front faces",
          "[gl][stencil]") {
    // The mirrors show the stairs' back (z = -1.2, facing the wall). In reality that face
    // turns away from the light (z = 2), so it has ambient light only: global ambient 0.3 ×
    // colour (0.55, 0.55, 0.6) = (42.1, 42.1, 45.9)/255, then 20 % of the glass colour
    // (0.75, 0.85, 1)·255 blended over it: (71.9, 77.0, 87.7). With the light left
    // unreflected, the mirrored face would turn towards it and be lit (far brighter); with
    // the front faces not swapped, culling would remove it and show the stairs' inside.
    Shot both = shoot("s"), none = shoot("sre");
    const dvec3 expect(71.9, 77.0, 87.7);
    const double zBack = 2.0 * wb::kMirrorZ + wb::kStairHalfDepth; // the back face, reflected
    std::vector<std::vector<dvec2>> faces;
    for (int i = 0; i < both.state.steps; ++i) {
        const double x0 = wb::kStairX0 + i * wb::kStepWidth, x1 = x0 + wb::kStepWidth,
                     top = (i + 1) * wb::kStepHeight;
        faces.push_back({project(both.state, {x0, 0, zBack}), project(both.state, {x1, 0, zBack}),
                         project(both.state, {x1, top, zBack}),
                         project(both.state, {x0, top, zBack})});
    }
    int pixels = 0, wrong = 0;
    double worst = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const dvec2 c(x + 0.5, y + 0.5);
            if (stencilAt(both, x, y) == 0 || samePixel(both.img, none.img, x, y)) continue;
            bool in = false;
            for (const auto& f : faces)
                if (inside(f, c) && distanceToOutline(f, c) > 1.0) in = true;
            if (!in) continue;
            ++pixels;
            for (int k = 0; k < 3; ++k) {
                const double e = std::abs(both.img.at(x, y)[k] - expect[k]);
                worst = std::max(worst, e);
                // ±3: lighting is rounded to 8 bits, then blended with alpha 51/255.
                if (e > 3.0) ++wrong;
            }
        }
    WARN("reflected stairs' back: " << pixels << " pixels, colour off by at most " << worst
                                    << "/255");
    CHECK(pixels > 50);
    CHECK(wrong == 0);
}

// Goldens: 160×120. Renders repeat bit for bit here (measured max diff 0); the allowance
// (max 64, mean 0.6) is for another llvmpipe rasterising an edge pixel of the torus or a
// shadow boundary differently (one pixel can flip between lit and shadowed, ~60 levels),
// while a shadow or reflection that moved or vanished changes the mean by several units.
TEST_CASE("lab 05 goldens for each key state", "[gl][stencil]") {
    const char* cases[][2] = {{"", "lab05-all"},
                              {"s", "lab05-no-shadow"},
                              {"r", "lab05-no-rect-mirror"},
                              {"e", "lab05-no-ellipse-mirror"},
                              {"re", "lab05-no-mirrors"},
                              {"n", "lab05-naive-shadow"},
                              {"m", "lab05-stencil-mask"},
                              {"{right}{right}{right}{down}{pgup}", "lab05-object-moved"}};
    for (auto& c : cases) {
        SECTION(c[1]) {
            auto lab = wb::makeStencilLab();
            wb::Image img = wb::test::renderLab(*lab, 160, 120, c[0]);
            wb::test::checkGolden(img, c[1], 64, 0.6);
        }
    }
}
