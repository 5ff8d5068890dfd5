#pragma once
// An OSMesa context for the headless path and the GL tests: a compatibility profile (the
// labs use the fixed-function pipeline next to GLSL), RGBA, 24-bit depth and 8-bit stencil
// (lab 05), rendering into a buffer of its own. Current from construction until
// destruction, which finishes GL first (OSMesa crashed destroying a context with work
// still queued).
#include <GL/osmesa.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wb {

class HeadlessContext {
  public:
    HeadlessContext(int width, int height);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    bool ok() const { return ok_; }
    const std::string& error() const { return error_; } // why not ok()

  private:
    OSMesaContext ctx_ = nullptr;
    std::vector<uint8_t> buffer_;
    bool ok_ = false;
    std::string error_;
};

} // namespace wb
