// Tests of core/image: PNG round trip, checked writes (issue 12.6) and the image
// comparison used by golden tests.
#include "core/image.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <random>

#include <sys/resource.h>
#include <unistd.h>

using wb::Image;

TEST_CASE("PNG round trip keeps every byte", "[image]") {
    Image img(7, 5, 3); // odd sizes catch row-stride mistakes
    for (size_t i = 0; i < img.data.size(); ++i)
        img.data[i] = uint8_t(i * 37 % 256);
    std::string path = std::string(WB_TEST_OUT_DIR) + "/image_roundtrip.png", err;
    REQUIRE(wb::writePng(path, img, &err));
    Image back;
    REQUIRE(wb::readImage(path, back, 3, &err));
    REQUIRE(back.width == 7);
    REQUIRE(back.height == 5);
    CHECK(back.data == img.data);
}

TEST_CASE("compareImages reports max and mean channel difference", "[image]") {
    Image a(2, 1, 3), b(2, 1, 3);
    b.data[0] = 10; // one channel of six differs by 10
    auto d = wb::compareImages(a, b);
    CHECK(d.sameSize);
    CHECK(d.maxDiff == 10);
    CHECK(d.meanDiff == Approx(10.0 / 6.0));
    CHECK_FALSE(wb::compareImages(a, Image(1, 2, 3)).sameSize);
}

TEST_CASE("writing to an unwritable path fails with the path in the message", "[image]") {
    Image img(1, 1, 3);
    std::string err;
    CHECK_FALSE(wb::writePng("/nonexistent-dir/x.png", img, &err));
    CHECK(err.find("/nonexistent-dir/x.png") != std::string::npos);
    CHECK_FALSE(wb::readImage("/nonexistent-dir/x.png", img, 3, &err));
    CHECK(err.find("/nonexistent-dir/x.png") != std::string::npos);
}

namespace {

// Files in `dir` whose name starts with `prefix` (left-over temporary files).
int countFiles(const std::string& dir, const std::string& prefix) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().filename().string().rfind(prefix, 0) == 0) ++n;
    return n;
}

} // namespace

TEST_CASE("a failed write is an error naming the path: /dev/full, /proc", "[image]") {
    Image img(16, 16, 3);
    std::string err;
    // /dev/full accepted open() and failed every write with ENOSPC (stbi_write_png used to
    // report success); a device is now refused before anything is opened (issue 20: the
    // same rule for every output, so a FIFO cannot block either).
    CHECK_FALSE(wb::writePng("/dev/full", img, &err));
    CHECK(err.find("/dev/full") != std::string::npos);
    CHECK(err.find("is a device") != std::string::npos);
    // /proc/self/status has no write handler (root included); /proc itself takes no new
    // files, not even from root (a chmod-555 directory does not stop root, CI's user).
    CHECK_FALSE(wb::writePng("/proc/self/status", img, &err));
    CHECK(err.find("/proc/self/status") != std::string::npos);
    CHECK_FALSE(wb::writePng("/proc/wb-image-test.png", img, &err));
    CHECK(err.find("/proc/wb-image-test.png") != std::string::npos);
    // A directory is refused by name.
    CHECK_FALSE(wb::writePng(WB_TEST_OUT_DIR, img, &err));
    CHECK(err.find("directory") != std::string::npos);
}

TEST_CASE("a read-only directory refuses the write (non-root only)", "[image]") {
    if (::geteuid() == 0) {
        WARN("running as root: a chmod-555 directory does not stop root; /proc covers it");
        return;
    }
    const std::string dir = std::string(WB_TEST_OUT_DIR) + "/image_readonly_dir";
    std::filesystem::create_directories(dir);
    std::filesystem::permissions(dir, std::filesystem::perms::owner_read |
                                          std::filesystem::perms::owner_exec);
    std::string err;
    CHECK_FALSE(wb::writePng(dir + "/x.png", Image(4, 4, 3), &err));
    CHECK(err.find(dir + "/x.png") != std::string::npos);
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
}

TEST_CASE("a write cut short keeps the old PNG under the real name and no temporary file",
          "[image]") {
    const std::string dir = std::string(WB_TEST_OUT_DIR) + "/image_short_write";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/keep.png";
    Image small(4, 4, 3);
    small.data.assign(small.data.size(), 200);
    std::string err;
    REQUIRE(wb::writePng(path, small, &err));
    const auto oldSize = std::filesystem::file_size(path);

    // A file size limit makes the kernel cut the write short (EFBIG), root or not: the
    // same path a full disk takes. The noise image does not compress below 4 KiB.
    Image big(64, 64, 3);
    std::mt19937 rng(12);
    for (auto& b : big.data)
        b = uint8_t(rng() >> 24); // 12 KiB of noise: PNG cannot shrink it
    struct rlimit old {};
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &old) == 0);
    REQUIRE(oldSize < 4096);
    struct rlimit lim = old;
    lim.rlim_cur = 4096;
    auto* previous = std::signal(SIGXFSZ, SIG_IGN); // the write returns EFBIG instead
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &lim) == 0);
    const bool ok = wb::writePng(path, big, &err);
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, previous);
    CHECK_FALSE(ok);
    CHECK(err.find(path) != std::string::npos);
    CHECK(std::filesystem::file_size(path) == oldSize);
    Image back;
    REQUIRE(wb::readImage(path, back, 3, &err));
    CHECK(back.data == small.data);
    CHECK(countFiles(dir, ".keep.png.tmp") == 0);

    // Without the limit the same write replaces the file, with a plain file's mode.
    REQUIRE(wb::writePng(path, big, &err));
    REQUIRE(wb::readImage(path, back, 3, &err));
    CHECK(back.data == big.data);
    CHECK(countFiles(dir, ".keep.png.tmp") == 0);
    const auto perms = std::filesystem::status(path).permissions();
    CHECK((perms & std::filesystem::perms::others_read) != std::filesystem::perms::none);
}
