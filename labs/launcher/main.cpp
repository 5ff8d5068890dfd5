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

#include "core/file_read.h"
#include "core/i18n.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
    const char* display = std::getenv("DISPLAY");
    bool headless = !display || !*display;
    std::string outDir = "out", size = "640x480";
    wb::applyLanguageFlag(argc, argv); // --lang ru|en|qps, before any message
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--lang") && i + 1 < argc) {
            ++i; // applied above; a bad code is reported by the shell's parser in a window
        } else if (!std::strcmp(argv[i], "--headless")) {
            headless = true;
        } else if (!std::strcmp(argv[i], "--out-dir") && i + 1 < argc) {
            outDir = argv[++i];
        } else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) {
            size = argv[++i];
        } else if (headless && !std::strcmp(argv[i], "--ui-scale") && i + 1 < argc) {
            // Listed in the usage, so taken here too (issue 20 point 15); the thumbnails
            // are pictures without a panel, so the scale does not change them.
            char* end = nullptr;
            const float scale = std::strtof(argv[i + 1], &end);
            if (!*argv[i + 1] || *end || !(scale >= 0.5f && scale <= 4.0f)) {
                std::fprintf(stderr, "%s: %s\n", argv[0],
                             wb::trf("--ui-scale '%s': expected a number from 0.5 to 4",
                                     wb::escapeForMessage(argv[i + 1]).c_str())
                                 .c_str());
                return 2;
            }
            ++i;
        } else if (headless || !std::strcmp(argv[i], "--help")) {
            if (std::strcmp(argv[i], "--help") != 0) // say which flag, then the usage
                std::fprintf(stderr, "%s: %s\n", argv[0],
                             (argv[i][0] == '-'
                                  ? wb::trf("unknown option '%s' (or it needs a value)",
                                            wb::escapeForMessage(argv[i]).c_str())
                                  : wb::trf("unexpected argument '%s'",
                                            wb::escapeForMessage(argv[i]).c_str()))
                                 .c_str());
            std::printf(wb::tr("usage: %s [--headless] [--out-dir DIR] [--size WxH] [--ui-scale X] "
                               "[--lang ru|en]\n"
                               "  with a display: opens the launcher window, 800x600 unless --size "
                               "says otherwise\n"
                               "  (also takes the lab shell's flags, e.g. --ui-scale 2 for a "
                               "projector);\n"
                               "  the labs it starts open in its language\n"
                               "  without one (or with --headless): renders every lab to DIR "
                               "(default out/)\n"),
                        argv[0]);
            return std::strcmp(argv[i], "--help") ? 2 : 0;
        }
    }
    if (!headless) {
        wb::setLabFlags(wb::labFlagsFrom(argc, argv));
        return wb::runLab(argc, argv, wb::makeLauncher);
    }
    std::printf(wb::tr("No display: rendering every lab headless into %s/\n"), outDir.c_str());
    int failed = wb::renderAllHeadless(outDir, size);
    return failed ? 1 : 0;
}
