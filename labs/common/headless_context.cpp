#include "headless_context.h"

namespace wb {

HeadlessContext::HeadlessContext(int width, int height)
    : buffer_(size_t(width) * size_t(height) * 4) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_COMPAT_PROFILE,
                           0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_) {
        error_ = "OSMesa: cannot create a context";
        return;
    }
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
        error_ = "OSMesa: cannot make the context current at " + std::to_string(width) + "x" +
                 std::to_string(height);
        return;
    }
    ok_ = true;
}

HeadlessContext::~HeadlessContext() {
    if (!ctx_) return;
    if (ok_) glFinish();
    OSMesaDestroyContext(ctx_);
}

} // namespace wb
