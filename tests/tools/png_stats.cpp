// png-stats FILE.png [--min-colours N]: prints size, distinct colours and the spread of
// luminance; exits 1 when the image has fewer than N distinct colours (a blank frame).
// Used by the windowed smoke tests, which cannot compare with goldens (the panel and the
// X server's visual make windowed frames differ from headless ones).
#include "core/image.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: png-stats FILE.png [--min-colours N]\n");
        return 2;
    }
    long minColours = 2;
    for (int i = 2; i + 1 < argc; i += 2)
        if (!std::strcmp(argv[i], "--min-colours")) minColours = std::strtol(argv[i + 1], nullptr, 10);
    wb::Image img;
    std::string err;
    if (!wb::readImage(argv[1], img, 3, &err)) {
        std::fprintf(stderr, "%s\n", err.c_str());
        return 2;
    }
    std::set<unsigned> colours;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.at(x, y);
            colours.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
        }
    std::printf("%s: %dx%d, %zu distinct colours\n", argv[1], img.width, img.height, colours.size());
    if (long(colours.size()) < minColours) {
        std::fprintf(stderr, "%s: looks blank (fewer than %ld colours)\n", argv[1], minColours);
        return 1;
    }
    return 0;
}
