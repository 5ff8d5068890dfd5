// Writes an SPD scene as NFF: spd_generate balls|jacks SIZE [FILE] (stdout without FILE).
// The generators are core's (core/raytrace/spd.h); sizes 1..6. Example:
//   build/bin/spd_generate balls 4 balls4.nff
#include "core/raytrace/spd.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4 || (std::strcmp(argv[1], "balls") && std::strcmp(argv[1], "jacks"))) {
        std::fprintf(stderr, "usage: %s balls|jacks SIZE(1..6) [FILE]\n", argv[0]);
        return 2;
    }
    char* end = nullptr;
    const long size = std::strtol(argv[2], &end, 10);
    if (*end != '\0' || size < 1 || size > 6) {
        std::fprintf(stderr, "%s: SIZE must be 1..6, got '%s'\n", argv[0], argv[2]);
        return 2;
    }
    try {
        const wb::rt::NffDocument doc = std::strcmp(argv[1], "balls") == 0
                                            ? wb::rt::spdBalls(int(size))
                                            : wb::rt::spdJacks(int(size));
        if (argc == 4)
            wb::rt::writeNffFile(argv[3], doc);
        else
            wb::rt::writeNff(std::cout, doc);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
        return 1;
    }
    return 0;
}
