// Issue 20, the readers' side: NFF `hither` clips what is nearer (it was read and
// ignored), exact duplicate objects are dropped and counted, one ear-clipping budget per
// file, and the output rule (core/file_read.h) on FIFOs, devices and links.
#include "core/file_read.h"
#include "core/raytrace/nff.h"
#include "core/raytrace/polygon.h"
#include "core/raytrace/scene_file.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

using namespace wb::rt;

namespace {

// A 1-unit sphere at the origin seen from z = 5 (its front at distance 4), and a second
// sphere at z = 3.5 (front at distance 1), both in view; `hither` as given.
std::string twoSpheres(const std::string& hither) {
    return "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither " + hither +
           "\nresolution 8 8\nf 1 1 1 1 0 0 0 1\ns 0 0 0 1\ns 0 0 3.5 0.5\n";
}

// Distance along the centre ray to the nearest hit of the scene, or -1.
double centreHit(const std::string& text) {
    const SceneFile sf = toScene(readNffText(text, "t.nff"));
    const LookAtCamera cam = sf.camera();
    const Ray r = cam.rayAt(4, 4, 8, 8); // the image centre: straight down -z
    Hit h;
    if (!sf.scene->intersect(r, 1e-9, 1e30, h)) return -1;
    return glm::length(r.at(h.t) - cam.eye);
}

} // namespace

TEST_CASE("rt_nff: hither clips what is nearer than the hither plane", "[raytrace][nff]") {
    // Exact in doubles: the hits are at integer distances from the eye along z.
    CHECK(centreHit(twoSpheres("0")) == Approx(1.0).epsilon(1e-12));   // the near sphere
    CHECK(centreHit(twoSpheres("0.5")) == Approx(1.0).epsilon(1e-12)); // plane before it
    CHECK(centreHit(twoSpheres("2.5")) == Approx(4.0).epsilon(1e-12)); // near one clipped
    CHECK(centreHit(twoSpheres("10")) == -1);                          // everything clipped
    CHECK_THROWS_WITH(readNffText(twoSpheres("-1"), "t.nff"),
                      Catch::Contains("t.nff:6: hither -1: the near plane's distance"));
}

TEST_CASE("rt_nff: exact duplicates are dropped and counted, near ones kept", "[raytrace][nff]") {
    std::string text = "f 1 1 1 1 0 0 0 1\n";
    for (int i = 0; i < 1000; ++i)
        text += "s 0 0 0 1\n";
    text += "s 0 0 0 1.0000000000000002\n";   // one ulp larger: not the same sphere
    text += "f 1 0 0 1 0 0 0 1\ns 0 0 0 1\n"; // the same sphere in another surface: kept
    text += "p 3\n0 0 0\n1 0 0\n0 1 0\np 3\n0 0 0\n1 0 0\n0 1 0\n";
    const SceneFile sf = toScene(readNffText(text, "d.nff"));
    CHECK(sf.scene->primitives.size() == 4);
    REQUIRE(sf.warnings.size() == 1);
    CHECK_THAT(sf.warnings[0], Catch::Contains("exact duplicate objects dropped: 1000 "));
}

TEST_CASE("rt_polygon: one ear-clipping budget shared by the polygons of a file",
          "[raytrace][polygon]") {
    // A star polygon of n vertices (every other one reflex) costs about n·n/4 visits.
    auto star = [](int n) {
        std::vector<glm::dvec3> v;
        for (int i = 0; i < n; ++i) {
            const double a = 6.283185307179586 * i / n, r = i % 2 ? 0.5 : 1.0;
            v.push_back({r * std::cos(a), r * std::sin(a), 0});
        }
        return v;
    };
    std::vector<std::array<int, 3>> tris;
    long long budget = 1'000'000;
    REQUIRE(triangulatePolygon(star(200), budget, tris)); // ~10^4 visits
    CHECK(tris.size() == 198);
    const long long left = budget;
    CHECK(left < 1'000'000);
    CHECK(left > 0);
    // The same polygon again and again: the budget runs out, the call says so.
    int cut = 1;
    while (triangulatePolygon(star(200), budget, tris))
        ++cut;
    CHECK(tris.empty());
    CHECK(cut < 1'000'000 / (1'000'000 - left) + 2);
    // The unbudgeted call is unchanged (the fan for a convex polygon, bit for bit).
    CHECK(triangulatePolygon(star(4)).size() == 2);
}

TEST_CASE("output files: FIFOs, devices, directories and broken links are refused", "[file_read]") {
    namespace fs = std::filesystem;
    const std::string dir = std::string(WB_TEST_TMP) + "/hostile_out";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string target, err;
    CHECK(wb::checkOutputFile(dir + "/new.png", target, err));
    CHECK(target == dir + "/new.png");
    REQUIRE(::mkfifo((dir + "/fifo").c_str(), 0600) == 0);
    CHECK_FALSE(wb::checkOutputFile(dir + "/fifo", target, err));
    CHECK_THAT(err, Catch::Contains("is a FIFO"));
    CHECK_FALSE(wb::checkOutputFile("/dev/null", target, err));
    CHECK_THAT(err, Catch::Contains("/dev/null: is a device"));
    CHECK_FALSE(wb::checkOutputFile(dir, target, err));
    CHECK_THAT(err, Catch::Contains("directory"));
    CHECK_FALSE(wb::checkOutputFile(dir + "/no/such/x.png", target, err));
    CHECK_THAT(err, Catch::Contains("does not exist"));
    fs::create_symlink(dir + "/missing.png", dir + "/dangling.png");
    CHECK_FALSE(wb::checkOutputFile(dir + "/dangling.png", target, err));
    CHECK_THAT(err, Catch::Contains("symbolic link to a file that does not exist"));
    fs::create_symlink("loop.png", dir + "/loop.png");
    CHECK_FALSE(wb::checkOutputFile(dir + "/loop.png", target, err));
    CHECK_THAT(err, Catch::Contains("loops"));
    std::ofstream(dir + "/real.png") << "x";
    fs::create_symlink("real.png", dir + "/link.png");
    REQUIRE(wb::checkOutputFile(dir + "/link.png", target, err));
    CHECK(fs::equivalent(target, dir + "/real.png"));
    fs::create_symlink("fifo", dir + "/to-fifo.png"); // a link to a FIFO is a FIFO
    CHECK_FALSE(wb::checkOutputFile(dir + "/to-fifo.png", target, err));
    CHECK_THAT(err, Catch::Contains("is a FIFO"));
    // Escaped in the message: no raw control byte reaches a terminal.
    CHECK_FALSE(wb::checkOutputFile(dir + "/no\x1b[31m/x.png", target, err));
    CHECK(err.find('\x1b') == std::string::npos);
    CHECK_THAT(err, Catch::Contains("\\x1b[31m"));
}

TEST_CASE("firstNulLine counts LF, CR LF and CR line ends", "[file_read]") {
    using namespace std::string_view_literals;
    CHECK(wb::firstNulLine("abc"sv) == 0);
    CHECK(wb::firstNulLine("\0"sv) == 1);
    CHECK(wb::firstNulLine("a\nb\r\nc\rd\0"sv) == 4);
    CHECK(wb::firstNulLine("a\r\n\0"sv) == 2);
}
