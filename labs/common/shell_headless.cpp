// The headless path of the shell: OSMesa, no window, no GLUT, no ImGui drawing.
#include "gl_util.h"
#include "shell.h"

#include <GL/osmesa.h>

#include <cstdio>

namespace wb {

bool renderHeadless(Lab& lab, int width, int height, const std::vector<int>& keys, Image& out,
                    std::string& error) {
    // A compatibility profile: the labs use the fixed-function pipeline next to GLSL.
    const int attribs[] = {OSMESA_FORMAT,       OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                           OSMESA_PROFILE,      OSMESA_COMPAT_PROFILE, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) {
        error = "OSMesa: cannot create a context";
        return false;
    }
    std::vector<uint8_t> buffer(size_t(width) * height * 4);
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(ctx);
        error = "OSMesa: cannot make the context current at " + std::to_string(width) + "x" +
                std::to_string(height);
        return false;
    }
    View view;
    view.width = width;
    view.height = height;
    view.headless = true;
    bool panel = false;
    glViewport(0, 0, width, height);
    lab.init();
    for (int k : keys)
        if (!shellKey(k, view, panel)) lab.key(k);
    // A lab that works in the background (lab 7's tracer) is drawn until it is done.
    do {
        glViewport(0, 0, width, height);
        lab.draw(view);
    } while (lab.busy());
    glFinish();
    out = readFramebuffer(width, height);
    OSMesaDestroyContext(ctx);
    return true;
}

int runLab(int argc, char** argv, LabFactory factory) {
    auto lab = factory();
    ShellOptions opts;
    std::string error;
    if (!parseOptions(argc, argv, lab->options(), opts, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 2;
    }
    if (opts.help) {
        std::fputs(usageText(argv[0], *lab).c_str(), stdout);
        return 0;
    }
    if (opts.out.empty()) {
        std::fprintf(stderr, "%s: the headless renderer needs --out FILE.png\n", argv[0]);
        return 2;
    }
    std::vector<int> keys;
    if (!parseKeys(opts.keys, keys, error) || !checkWritable(opts.out, error) ||
        !applyOptions(opts, *lab, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 2;
    }
    Image img;
    if (!renderHeadless(*lab, opts.width, opts.height, keys, img, error) || !writePng(opts.out, img, &error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 1;
    }
    return 0;
}

} // namespace wb
