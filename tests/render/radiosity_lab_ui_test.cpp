// Lab 08 as the student and a careless user meet it (issue 19 items 8, 9, 13; issue 20 items
// 4, 7, 10, 14, 17): never an unsolved picture, a display that looks like the Cornell box,
// headless runs within a budget, one check for every way of setting the patch size, a
// refused click outside the picture, threads capped at the hardware, a summary that forgets
// the previous scene's run.
#include "render_check.h"

#include "radiosity_lab.h"

#include <algorithm>
#include <string>
#include <thread>

namespace {

constexpr int kW = 160, kH = 120;

bool contains(const std::string& s, const char* what) {
    return s.find(what) != std::string::npos;
}

// A small Cornell box (0.1 m patches, ~390) so a solve takes a fraction of a second.
std::unique_ptr<wb::Lab> smallCornell(const char* method = "gl") {
    auto lab = wb::makeRadiosityLab();
    std::string err;
    REQUIRE(lab->setOption("patch-size", "0.1", err));
    REQUIRE(lab->setOption("method", method, err));
    return lab;
}

} // namespace

// Issue 19 item 8: the unlit box (B = E: every wall one flat ambient colour) was what the
// headless render, the launcher's thumbnail and keys 1 2 3 [ ] left. Now every change is
// solved before a picture is drawn, to the default tolerance; --steps 0 shows the unsolved
// state on purpose.
TEST_CASE("lab 08: a headless render is solved unless --steps 0 says otherwise", "[gl]") {
    {
        auto lab = smallCornell();
        wb::test::renderLab(*lab, kW, kH);
        CHECK(wb::radiosityStepCount(*lab) > 0);
        CHECK(wb::radiosityResidual(*lab) < 1e-3); // the default tolerance (RadiosityState)
    }
    {
        auto lab = smallCornell();
        std::string err;
        REQUIRE(lab->setOption("steps", "0", err));
        wb::test::renderLab(*lab, kW, kH);
        CHECK(wb::radiosityStepCount(*lab) == 0);
    }
    // Each key that changes the model restarts the solve (today: 0 steps after it).
    for (const char* keys : {"1", "2", "3", "[", "]", "n"}) {
        INFO("keys " << keys);
        auto lab = smallCornell("cpu");
        wb::test::renderLab(*lab, kW, kH, keys);
        CHECK(wb::radiosityStepCount(*lab) > 0);
        CHECK(wb::radiosityResidual(*lab) < 1e-3);
    }
}

// Issue 19 item 9: the white back wall read mustard (184,154,89) with a fixed exposure and
// no white balance. With the light's white balance and auto exposure it reads as a light,
// near-neutral grey. Bounds: channels within 0.10 of each other and a mean above 0.55 (sRGB
// 140) — the mustard wall fails both (spread 0.37). Where 0.10 comes from: the converged
// answer is not neutral, the white paint reflects less blue and every bounce compounds it.
// Cycles' back wall (docs/bench/radiosity.md, B = 0.1695, 0.1121, 0.0315 under the light's
// 17.0, 11.8, 4.0), white-balanced and sRGB-encoded at this exposure, reads 0.823 0.805
// 0.740: spread 0.083. The merged lab (lab08phys's mesh, 0.1 m groups) reads 0.823 0.804
// 0.740, the reference to 0.001; lab08ui alone was under 0.08 only by being further from
// it. 0.10 = the reference's 0.083 + ~4 levels for the test's coarse 0.1 m mesh.
TEST_CASE("lab 08: the white back wall displays white, not mustard", "[gl]") {
    auto lab = smallCornell();
    wb::test::renderLab(*lab, kW, kH);
    const auto surf = wb::radiosityPatchSurfaces(*lab);
    const auto names = wb::radiositySurfaceNames(*lab);
    glm::vec3 sum(0.0f);
    int n = 0;
    for (size_t i = 0; i < surf.size(); ++i)
        if (names[size_t(surf[i])] == "back wall") {
            sum += wb::radiosityPatchColour(*lab, int(i));
            ++n;
        }
    REQUIRE(n > 0);
    const glm::vec3 mean = sum / float(n);
    INFO("back wall mean sRGB " << mean.r << " " << mean.g << " " << mean.b);
    CHECK(std::max({mean.r, mean.g, mean.b}) - std::min({mean.r, mean.g, mean.b}) < 0.10f);
    CHECK((mean.r + mean.g + mean.b) / 3.0f > 0.55f);
}

// Issue 20 item 4: headless runs without bounds (`raaa` took 53 s, 20k patches minutes). A
// budget (--budget, seconds) stops the work; the picture shows what there is and the
// summary says so. A zero budget stops before the first step of a 1024² CPU hemicube run.
TEST_CASE("lab 08: a headless run stops at its budget and says so", "[gl]") {
    auto lab = smallCornell("cpu");
    std::string err;
    REQUIRE(lab->setOption("hemicube", "1024", err));
    REQUIRE(lab->setOption("budget", "0", err));
    wb::test::renderLab(*lab, kW, kH, "raaaaaaaaaa");
    CHECK(wb::radiosityBudgetHit(*lab));
    CHECK(wb::radiosityResidual(*lab) > 1e-3);
    CHECK(contains(wb::radiositySummary(*lab), "budget"));
    CHECK(wb::radiosityPatchCount(*lab) <= wb::kMaxPatches);
    CHECK_FALSE(lab->headlessFailed()); // what there is, is drawn
}

// Issue 20 items 7 and 10: --patch-size 0.001 meshed 2.85 M patches (3 GB) before anything
// looked at the count; the classroom at 0.001 printed a meshing error and wrote a one-colour
// PNG with exit 0. One check (meshChecked) refuses both before meshing, and headless fails.
TEST_CASE("lab 08: a patch size the lab cannot take is refused before meshing", "[gl]") {
    for (const char* scene : {"cornell", "classroom", "floorlamp"}) {
        INFO(scene);
        auto lab = wb::makeRadiosityLab();
        std::string err;
        REQUIRE(lab->setOption("scene", scene, err));
        REQUIRE(lab->setOption("patch-size", "0.001", err));
        wb::test::renderLab(*lab, kW, kH);
        CHECK(lab->headlessFailed());
        CHECK(wb::radiosityPatchCount(*lab) == 0);
    }
    // The key takes the same road: [ from 0.1 m halves the area per patch each time; the
    // count stays under the cap and the last size refused leaves the mesh as it was.
    auto lab = smallCornell();
    std::string err;
    REQUIRE(lab->setOption("steps", "0", err)); // no solving: only the meshing is looked at
    wb::test::renderLab(*lab, kW, kH, "[[[[[[[[[[[[[[[[");
    CHECK(wb::radiosityPatchCount(*lab) <= wb::kMaxPatches);
    CHECK(wb::radiosityPatchCount(*lab) > 10000); // it did refine until the cap was near
    CHECK(wb::radiosityState(*lab).patchSize > 0.005);
}

// Issue 20 item 14: lab 07 refuses an --inspect outside the image; lab 08 ignored a click
// there. Refused now: no PNG, exit 1.
TEST_CASE("lab 08: --click outside the picture is refused", "[gl]") {
    auto lab = smallCornell();
    std::string err;
    REQUIRE(lab->setOption("click", "99999,99999", err));
    wb::test::renderLab(*lab, kW, kH);
    CHECK(lab->headlessFailed());
    auto inside = smallCornell();
    REQUIRE(inside->setOption("click", "80,60", err));
    wb::test::renderLab(*inside, kW, kH);
    CHECK_FALSE(inside->headlessFailed());
    CHECK(wb::radiositySelected(*inside) >= 0);
}

// Issue 20 item 17: --threads 1024 made TBB warn and cost 730 MB for nothing: capped at the
// hardware's threads (the lab says so on stderr).
TEST_CASE("lab 08: --threads is capped at the hardware", "[gl]") {
    auto lab = wb::makeRadiosityLab();
    std::string err;
    REQUIRE(lab->setOption("threads", "1024", err));
    const int hw = std::max(1, int(std::thread::hardware_concurrency()));
    CHECK(wb::radiosityState(*lab).threads == hw);
    REQUIRE(lab->setOption("threads", "0", err)); // 0 = all cores stays allowed
    CHECK(wb::radiosityState(*lab).threads == 0);
}

// Issue 19 item 13 / issue 20 item 17: after r then n, the summary showed the previous
// scene's "last run 3.01 s".
TEST_CASE("lab 08: the next scene's summary has no run of the previous one", "[gl]") {
    auto lab = smallCornell();
    std::string err;
    REQUIRE(lab->setOption("steps", "0", err));
    wb::test::renderLab(*lab, kW, kH, "r");
    CHECK(contains(wb::radiositySummary(*lab), "last run"));
    auto next = smallCornell();
    REQUIRE(next->setOption("steps", "0", err));
    wb::test::renderLab(*next, kW, kH, "rn");
    CHECK_FALSE(contains(wb::radiositySummary(*next), "last run"));
}
