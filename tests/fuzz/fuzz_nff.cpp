// libFuzzer target for the NFF reader/writer (clang, -DWORKBENCH_FUZZ=ON).
#include "scene_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzzNff(data, size);
    return 0;
}
