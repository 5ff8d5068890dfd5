// Issue 20 point 9: lab 07 read a --scene file twice (setOption to check it, init() to
// show it). A file rewritten in between made init() print a message, draw the built-in
// two-spheres scene and exit 0. The scene checked is now the scene shown.
#include "render_check.h"

#include "raytrace_lab.h"

#include <fstream>

TEST_CASE("lab07: --scene is read once; rewriting the file after the check changes nothing",
          "[gl][raytrace]") {
    const std::string path = std::string(WB_TEST_OUT_DIR) + "/lab07_read_once.nff";
    std::ofstream(path) << "b 1 0 0\nl 0 5 5\nf 0 0 1 1 0 0 0 1\ns 0 0 0 1\n";
    auto lab = wb::makeRaytraceLab();
    std::string err;
    REQUIRE(lab->setOption("scene", path, err));
    std::ofstream(path, std::ios::trunc) << "nonsense\n"; // the file changes after the check
    const wb::Image img = wb::test::renderLab(*lab, 32, 24);
    // The corner is the checked file's background (red), not the built-in scene's sky.
    const uint8_t* corner = img.data.data();
    CHECK(int(corner[0]) == 255);
    CHECK(int(corner[1]) == 0);
    CHECK(int(corner[2]) == 0);
    CHECK_FALSE(lab->headlessFailed());
}
