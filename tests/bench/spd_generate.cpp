// Writes an SPD scene as NFF: spd_generate NAME SIZE [FILE] (stdout without FILE).
// The generators are core's (core/raytrace/spd.h); NAME is one of spdSceneNames()
// (balls, jacks, gears, ...), sizes 1..6. Example:
//   build/bin/spd_generate balls 4 balls4.nff
#include "core/i18n.h"
#include "core/raytrace/spd.h"

#include <cerrno>
#include <cstring>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
    std::string names;
    for (const std::string& n : wb::rt::spdSceneNames())
        names += (names.empty() ? "" : "|") + n;
    bool known = false;
    if (argc >= 2)
        for (const std::string& n : wb::rt::spdSceneNames())
            known = known || n == argv[1];
    if (argc < 3 || argc > 4 || !known) {
        std::fprintf(stderr, wb::tr("usage: %s %s SIZE(1..6) [FILE]\n"), argv[0], names.c_str());
        return 2;
    }
    char* end = nullptr;
    const long size = std::strtol(argv[2], &end, 10);
    if (*end != '\0' || size < 1 || size > 6) {
        std::fprintf(stderr, wb::tr("%s: SIZE must be 1..6, got '%s'\n"), argv[0], argv[2]);
        return 2;
    }
    try {
        const wb::rt::NffDocument doc = wb::rt::spdScene(argv[1], int(size));
        if (argc == 4)
            wb::rt::writeNffFile(argv[3], doc);
        else {
            // stdout may be /dev/full or a closed pipe: a lost write is an error, not exit
            // 0 (issue 20 point 13). cout shares stdout's buffer (sync_with_stdio).
            errno = 0;
            wb::rt::writeNff(std::cout, doc);
            std::cout.flush();
            if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) ||
                std::fclose(stdout) != 0) {
                std::fprintf(stderr, "%s: %s\n", argv[0],
                             wb::trf("cannot write the scene to standard output (%s)",
                                     errno ? std::strerror(errno) : "write error")
                                 .c_str());
                return 1;
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
        return 1;
    }
    return 0;
}
