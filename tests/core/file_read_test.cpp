// readRegularFile and readImage on what a careless or hostile user may name (issue 12,
// point 2): a FIFO must be refused at once (it used to block open() forever), a
// directory, a device (/dev/zero never ends) and an over-large file are refused with the
// path in the message; message text from a file is escaped.
#include "core/file_read.h"
#include "core/image.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

using Catch::Matchers::Contains;

namespace {

std::string tempDir() {
    static std::string dir = [] {
        char tmpl[] = "/tmp/wb_file_read_XXXXXX";
        const char* d = ::mkdtemp(tmpl);
        REQUIRE(d != nullptr);
        return std::string(d);
    }();
    return dir;
}

std::string readError(const std::string& path, std::size_t cap = 1 << 20) {
    std::string out, err;
    if (wb::readRegularFile(path, cap, out, err)) return "";
    return err;
}

} // namespace

TEST_CASE("file_read: a regular file is read whole, up to its cap", "[file_read]") {
    const std::string p = tempDir() + "/a.txt";
    {
        std::ofstream f(p, std::ios::binary);
        f << std::string("ab\0cd", 5);
    }
    std::string out, err;
    REQUIRE(wb::readRegularFile(p, 5, out, err));
    CHECK(out == std::string("ab\0cd", 5)); // NUL bytes kept
    CHECK_FALSE(wb::readRegularFile(p, 4, out, err));
    CHECK_THAT(err, Contains(p) && Contains("larger than 4 bytes"));
    CHECK(out.empty());
    std::remove(p.c_str());
    // A file whose size stat cannot tell (/proc: 0 bytes) is read to its end, and its cap
    // still holds (the bytes past the stat size are read through a small buffer).
    REQUIRE(wb::readRegularFile("/proc/self/status", 1 << 20, out, err));
    CHECK(out.find("Name:") == 0);
    CHECK_FALSE(wb::readRegularFile("/proc/self/status", 10, out, err));
    CHECK_THAT(err, Contains("larger than 10 bytes"));
}

TEST_CASE("file_read: FIFO, directory, device and missing files are refused at once",
          "[file_read]") {
    const std::string fifo = tempDir() + "/scene.nff";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_THAT(readError(fifo), Contains(fifo) && Contains("FIFO"));
    // Not a timing assertion of speed: a blocked open() would never return at all, and
    // the test would hang; this only documents that it returned.
    CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(30));
    std::remove(fifo.c_str());

    const std::string dir = tempDir() + "/x.obj";
    REQUIRE(::mkdir(dir.c_str(), 0700) == 0);
    CHECK_THAT(readError(dir), Contains(dir) && Contains("is a directory"));
    ::rmdir(dir.c_str());

    CHECK_THAT(readError("/dev/zero"), Contains("/dev/zero: is a device"));
    CHECK_THAT(readError("/dev/urandom"), Contains("/dev/urandom: is a device"));
    CHECK_THAT(readError(tempDir() + "/missing"), Contains("missing: cannot open the file"));
    CHECK_THAT(readError(std::string("a\0b", 3)), Contains("NUL"));
}

TEST_CASE("file_read: readImage refuses a FIFO and a device and names the path", "[file_read]") {
    const std::string fifo = tempDir() + "/tex.png";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    wb::Image img;
    std::string err;
    CHECK_FALSE(wb::readImage(fifo, img, 3, &err));
    CHECK_THAT(err, Contains(fifo) && Contains("FIFO"));
    std::remove(fifo.c_str());
    CHECK_FALSE(wb::readImage("/dev/urandom", img, 3, &err));
    CHECK_THAT(err, Contains("/dev/urandom: is a device"));
    // A PNG header that claims 100000 x 100000 pixels is refused before decoding.
    const std::string big = tempDir() + "/big.png";
    {
        const unsigned char png[] = {0x89, 'P',  'N', 'G', '\r', '\n', 0x1a, '\n', 0,    0, 0,
                                     13,   'I',  'H', 'D', 'R',  0,    1,    0x86, 0xa0, 0, 1,
                                     0x86, 0xa0, 8,   2,   0,    0,    0,    0,    0,    0, 0};
        std::ofstream f(big, std::ios::binary);
        f.write(reinterpret_cast<const char*>(png), sizeof png);
    }
    CHECK_FALSE(wb::readImage(big, img, 3, &err));
    CHECK_THAT(err, Contains(big));
    std::remove(big.c_str());
}

TEST_CASE("file_read: message text is escaped and cut", "[file_read]") {
    CHECK(wb::escapeForMessage("v") == "v");
    CHECK(wb::escapeForMessage(std::string("v\0x", 3)) == "v\\x00x");
    CHECK(wb::escapeForMessage("\x1b[2J") == "\\x1b[2J");
    CHECK(wb::escapeForMessage("\xef\xbb\xbfv") == "\\xef\\xbb\\xbfv");
    CHECK(wb::escapeForMessage(std::string(100, 'a'), 10) == "aaaaaaaaaa...");
}
