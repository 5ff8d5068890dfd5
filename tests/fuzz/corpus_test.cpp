// The saved fuzz corpus and every kept crasher, run through both readers in the
// normal (g++) build: each file must be read or rejected with SceneFileError, never
// crash (the sanitizer build checks memory errors too).
#include "scene_fuzz.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace fs = std::filesystem;

namespace {

int runDir(const fs::path& dir, void (*fn)(const std::uint8_t*, std::size_t)) {
    int n = 0;
    if (!fs::exists(dir)) return 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                      std::istreambuf_iterator<char>());
        INFO(e.path().string());
        fn(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        ++n;
    }
    return n;
}

} // namespace

TEST_CASE("rt_fuzz_corpus: NFF corpus and crashers", "[raytrace][fuzz]") {
    const fs::path root = WB_FUZZ_DIR;
    const int n =
        runDir(root / "corpus" / "nff", fuzzNff) + runDir(root / "crashers" / "nff", fuzzNff);
    CHECK(n > 0);
}

TEST_CASE("rt_fuzz_corpus: OBJ corpus and crashers", "[raytrace][fuzz]") {
    const fs::path root = WB_FUZZ_DIR;
    const int n =
        runDir(root / "corpus" / "obj", fuzzObj) + runDir(root / "crashers" / "obj", fuzzObj);
    CHECK(n > 0);
}
