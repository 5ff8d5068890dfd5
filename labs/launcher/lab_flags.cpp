// The launcher's flags that the labs it starts get (launcher.h); pure, unit-tested in
// tests/shell/options_test.cpp.
#include "launcher.h"

#include <utility>

namespace wb {

std::vector<std::string> labFlagsFrom(int argc, const char* const* argv) {
    // Flags about the launcher's own window or run, with the number of values each takes.
    static const std::pair<const char*, int> kOwn[] = {
        {"--size", 1},    {"--frames", 1}, {"--screenshot", 1}, {"--keys", 1},        {"--out", 1},
        {"--out-dir", 1}, {"--smoke", 0},  {"--headless", 0},   {"--check-panel", 0}, {"--help", 0},
        {"-h", 0}};
    std::vector<std::string> flags;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        int skip = -1;
        for (const auto& [name, values] : kOwn) {
            const std::string n = name;
            if (arg == n)
                skip = values;
            else if (arg.rfind(n + "=", 0) == 0)
                skip = 0; // --size=WxH: one word
        }
        if (skip < 0) {
            flags.push_back(arg);
            continue;
        }
        i += skip;
    }
    return flags;
}

} // namespace wb
