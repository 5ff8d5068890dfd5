// Graphics lab workbench - the launcher.
// Shows every lab with its picture, course topic and docs page; choosing one starts its executable.
// With no display (or with --headless) it renders every lab headless to PNG files instead.
//
// Keys:
//   1..9   start lab N of the list (or click its picture)
//   Ctrl+= Ctrl+-  larger / smaller text
//   Esc    quit
#include "common/shell.h"
#include "launcher.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
    const char* display = std::getenv("DISPLAY");
    bool headless = !display || !*display;
    std::string outDir = "out", size = "640x480";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--headless")) {
            headless = true;
        } else if (!std::strcmp(argv[i], "--out-dir") && i + 1 < argc) {
            outDir = argv[++i];
        } else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) {
            size = argv[++i];
        } else if (headless || !std::strcmp(argv[i], "--help")) {
            std::printf("usage: %s [--headless] [--out-dir DIR] [--size WxH] [--ui-scale X]\n"
                        "  with a display: opens the launcher window, 800x600 unless --size says otherwise\n"
                        "  (also takes the lab shell's flags, e.g. --ui-scale 2 for a projector)\n"
                        "  without one (or with --headless): renders every lab to DIR (default out/)\n",
                        argv[0]);
            return std::strcmp(argv[i], "--help") ? 2 : 0;
        }
    }
    if (!headless) {
        wb::setLabFlags(wb::labFlagsFrom(argc, argv));
        return wb::runLab(argc, argv, wb::makeLauncher);
    }
    std::printf("No display: rendering every lab headless into %s/\n", outDir.c_str());
    int failed = wb::renderAllHeadless(outDir, size);
    return failed ? 1 : 0;
}
