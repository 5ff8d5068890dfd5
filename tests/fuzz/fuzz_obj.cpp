// libFuzzer target for the OBJ loader (clang, -DWORKBENCH_FUZZ=ON).
#include "scene_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzzObj(data, size);
    return 0;
}
