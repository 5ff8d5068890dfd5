// Lab 07's ray inspector on seed 000's worked example: clicking pixel P(50, 0) shows
// the very numbers the seed prints (see docs/raytrace.md for the list). Printed figures
// are compared to 1 unit of their last printed digit; colours exactly.
#include "render_check.h"

#include "raytrace_lab.h"

#include <cmath>

namespace {

constexpr int kSize = 160; // seed 000: one world unit per pixel, homeX = homeY = 80
// seed000-part1 is framed at 4 pixels per unit: P(50, 0) is pixel (W/2 + 200, H/2).
constexpr int kPart1Size = 480, kPart1X = 440, kPart1Y = 240;

void near(double v, double printed, double unit) {
    INFO("value " << v << " printed " << printed);
    CHECK(std::fabs(v - printed) <= unit * (1 + 1e-9));
}
void near(const glm::dvec3& v, const glm::dvec3& printed, double unit) {
    for (int i = 0; i < 3; ++i)
        near(v[i], printed[i], unit);
}
void colour(const glm::dvec3& c, int r, int g, int b) {
    INFO("colour (" << c.x << ", " << c.y << ", " << c.z << ")");
    CHECK(c.x == r);
    CHECK(c.y == g);
    CHECK(c.z == b);
}

// Renders the scene traced at size×size and clicks P(50, 0): pixel (80 + 50, 80) at the
// seed's scale, (x, y) for the framed part 1.
std::unique_ptr<wb::Lab> clickP50(const std::string& scene, wb::Image& img, int size = kSize,
                                  int x = 130, int y = 80) {
    auto lab = wb::makeRaytraceLab();
    std::string err;
    REQUIRE(lab->setOption("scene", scene, err));
    img = wb::test::renderLab(*lab, size, size, "G");
    wb::View v;
    v.width = v.height = size;
    v.headless = true;
    REQUIRE(lab->click(x, y, v));
    REQUIRE(wb::raytraceInspected(*lab));
    return lab;
}

} // namespace

TEST_CASE("lab 07 inspector: seed 000 part 2, P(50,0) with the reflected ray", "[gl]") {
    wb::Image img;
    auto lab = clickP50("seed000-part2", img);
    const wb::RayTree& t = *wb::raytraceInspected(*lab);
    CHECK(img.at(130, 80)[0] == 168);
    CHECK(img.at(130, 80)[1] == 233);
    CHECK(img.at(130, 80)[2] == 86);
    REQUIRE(t.nodes.size() == 2);
    CHECK(t.matchesTracer);
    const wb::RayNode& p = t.nodes[0];
    CHECK(p.ray.origin == glm::dvec3(0, 0, 100));
    near(p.ray.direction, {0.447, 0, -0.894}, 1e-3);
    REQUIRE(p.hit);
    CHECK(p.primitiveKind == "rectangle");
    CHECK(p.primitive == 1); // the green one
    near(p.t, 89.443, 1e-3);
    near(p.point, {40, 0, 20}, 1e-9);
    near(p.uv.x, 0.8, 1e-9);
    near(p.cosVN, -0.894, 1e-3);
    CHECK_FALSE(p.entering); // an open rectangle: never "entering" (seed 000)
    colour(p.ambient, 10, 117, 10);
    REQUIRE(p.feelers.size() == 1);
    const wb::FeelerRecord& f = p.feelers[0];
    near(f.distance, 56.57, 1e-2);
    near(f.toLight, {-0.707, 0, 0.707}, 1e-3);
    CHECK(f.transmittance == 1.0);
    CHECK(f.blockers.empty());
    near(f.sh, 0.530, 1e-3);
    near(f.ln, 0.707, 1e-3);
    near(f.diffuseFactor, 0.187, 1e-3);
    colour(f.diffuse, 4, 44, 4);
    near(f.halfVector, {-0.584, 0, 0.811}, 1e-3);
    near(f.nn, 0.811, 1e-3);
    near(f.nnp, 0.533, 1e-3);
    near(f.specularFactor, 0.142, 1e-3);
    colour(f.specular, 36, 36, 36);
    colour(p.direct, 50, 197, 50);
    CHECK(p.kr == 0.5);
    REQUIRE(p.reflected == 1);

    const wb::RayNode& q = t.nodes[1];
    CHECK(q.kind == "reflected");
    near(q.ray.direction, {0.447, 0, 0.894}, 1e-3);
    CHECK(q.ray.weight == 0.5);
    REQUIRE(q.hit);
    CHECK(q.primitive == 0); // the red one in x = 50
    near(q.t, 22.36, 1e-2);
    // The reflected ray starts 2^20 ULPs off the surface (offsetRayOrigin, ~1e-8 here).
    near(q.point, {50, 0, 40}, 1e-6);
    near(q.uv.x, 0.4, 1e-9);
    near(q.cosVN, -0.447, 1e-3);
    colour(q.ambient, 117, 10, 10);
    REQUIRE(q.feelers.size() == 1);
    near(q.feelers[0].distance, 53.85, 1e-2);
    near(q.feelers[0].toLight, {-0.928, 0, 0.371}, 1e-3);
    near(q.feelers[0].sh, 0.557, 1e-3);
    near(q.feelers[0].ln, 0.928, 1e-3);
    near(q.feelers[0].diffuseFactor, 0.259, 1e-3);
    colour(q.feelers[0].diffuse, 61, 5, 5);
    near(q.feelers[0].halfVector, {-0.935, 0, -0.355}, 1e-3);
    near(q.feelers[0].nn, 0.935, 1e-3);
    near(q.feelers[0].nnp, 0.817, 1e-3);
    near(q.feelers[0].specularFactor, 0.227, 1e-3);
    colour(q.feelers[0].specular, 58, 58, 58);
    colour(q.colour, 236, 73, 73);
    CHECK(q.reflected == -1); // the red rectangle's kr is 0: the tree ends here
    colour(p.reflectedColour, 236, 73, 73);
    colour(p.colour, 168, 233, 86); // (50,197,50) + (236,73,73)·0.5 → (118,36,36)
    CHECK(t.rgb[0] == 168);
    CHECK(t.rgb[1] == 233);
    CHECK(t.rgb[2] == 86);
}

TEST_CASE("lab 07 inspector: seed 000 part 1, P(50,0) in the shadow of rectangle 1", "[gl]") {
    wb::Image img;
    auto lab = clickP50("seed000-part1", img, kPart1Size, kPart1X, kPart1Y);
    const wb::RayTree& t = *wb::raytraceInspected(*lab);
    CHECK(t.matchesTracer);
    REQUIRE(t.nodes.size() == 1);
    const wb::RayNode& p = t.nodes[0];
    REQUIRE(p.hit);
    CHECK(p.primitive == 1);
    near(p.point, {40, 0, 20}, 1e-9);
    REQUIRE(p.feelers.size() == 1);
    const wb::FeelerRecord& f = p.feelers[0];
    CHECK(f.transmittance == 0.0);
    // The feeler meets rectangle 1 exactly on its border: T = 28.28 at (20, 0, 40).
    REQUIRE(f.blockers.size() == 1);
    CHECK(f.blockers[0].primitive == 0);
    CHECK(f.blockers[0].kind == "rectangle");
    near(f.blockers[0].t, 28.28, 1e-2);
    near(f.blockers[0].point, {20, 0, 40}, 1e-9);
    CHECK(f.blockers[0].kt == 0.0);
    colour(p.ambient, 10, 117, 10);
    colour(f.diffuse, 0, 0, 0);
    colour(f.specular, 0, 0, 0);
    colour(p.colour, 10, 117, 10);
    CHECK(img.at(kPart1X, kPart1Y)[0] == 10);
    CHECK(img.at(kPart1X, kPart1Y)[1] == 117);
    CHECK(img.at(kPart1X, kPart1Y)[2] == 10);
    // The same pixel with rectangle 1 removed is lit: (50, 197, 50).
    wb::Image lit;
    auto lab2 = clickP50("seed000-part1-lit", lit, kPart1Size, kPart1X, kPart1Y);
    colour(wb::raytraceInspected(*lab2)->nodes[0].colour, 50, 197, 50);
}

TEST_CASE("lab 07 inspector: its replay equals the tracer on every pixel of several scenes",
          "[gl]") {
    // The inspector's tree comes from the observed Tracer::trace; if observing ever
    // changed a colour, matchesTracer (against the unobserved trace) turns false.
    for (const char* scene : {"glass-cube", "seed001-table", "two-spheres"}) {
        auto lab = wb::makeRaytraceLab();
        std::string err;
        REQUIRE(lab->setOption("scene", scene, err));
        const wb::Image img = wb::test::renderLab(*lab, 48, 36, "G");
        int mismatches = 0, deep = 0;
        for (int y = 0; y < 36; ++y)
            for (int x = 0; x < 48; ++x) {
                wb::raytraceInspectPixel(*lab, x, y);
                const wb::RayTree* t = wb::raytraceInspected(*lab);
                REQUIRE(t);
                mismatches += !t->matchesTracer;
                deep += t->nodes.size() > 2;
                for (int c = 0; c < 3; ++c)
                    mismatches += t->rgb[c] != img.at(x, y)[c];
            }
        INFO(scene << ": " << deep << " pixels with more than 2 rays");
        CHECK(mismatches == 0);
        if (std::string(scene) != "two-spheres") CHECK(deep > 0); // recursion is exercised
    }
}
