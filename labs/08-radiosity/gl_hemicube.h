#pragma once
// The hemicube of §1.15.2 drawn by OpenGL (issue 10, form factors (c)): every patch is
// drawn in its item colour (id + 1 in 24-bit RGB, 0 = nothing) with flat shading, no
// lighting, no dithering, no blending and no multisampling, into an off-screen
// framebuffer object, once per hemicube face, and read back with glReadPixels. The
// delta form factors and the row sums are core's (core/radiosity): this class only
// fills core's rad::ItemBuffer, in core's layout, and core's accumulate() makes the row,
// so the GL and CPU rows differ only where the two rasterizers decide a pixel
// differently (GL: the pixel centre inside the projected triangle by the top-left fill
// rule on float window coordinates; CPU: a ray per pixel centre against the patch in
// double).
//
// Depth: a 32-bit float depth buffer with reversed depth (glClipControl ZERO_TO_ONE,
// depth = near / distance, cleared to 0, GL_GREATER) and no far plane, so surfaces a
// millimetre apart at the far end of the room still sort; without ARB_clip_control it
// falls back to the usual mapping with a far plane (coarser, stated in gui()).
#include "common/gl.h"
#include "core/radiosity/hemicube.h"
#include "core/radiosity/mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace wb {

class GlHemicube {
  public:
    static constexpr double kNearFraction = 1e-3; // near distance / scene radius, see render()
    GlHemicube() = default;
    GlHemicube(const GlHemicube&) = delete;
    GlHemicube& operator=(const GlHemicube&) = delete;
    ~GlHemicube(); // a GL context must be current (the lab's, as for every GL object)

    // Uploads the scene: triangles (3 vertices each, counter-clockwise seen from the front)
    // with the item id of each. Ids must be < 2^24 − 1 (one colour is "nothing").
    bool setGeometry(const std::vector<glm::vec3>& vertices, const std::vector<uint32_t>& items,
                     std::string& error);
    // Draws the five faces of a hemicube of `res` pixels per full face (even, 2..4096)
    // at `frame` into `out` in core's layout (core/radiosity/hemicube.h: face order, rows
    // bottom-to-top, pixel directions); `nearDistance` is the near clipping distance
    // (scene units, > 0). Reversed depth makes it free for depth precision, but NOT for
    // clipping: a polygon crossing the patch's plane (a box face meeting the patch's
    // edge) is cut at the near plane in float, and the cut vertex's height is off by about
    // 1e-8 (float rounding of the scene coordinates) / nearDistance in units of the face;
    // at 1e-6 that put slivers of back faces over the horizon rows. kNearFraction × the
    // scene's radius keeps that under 0.01 pixel at 1024² and clips only what lies within
    // it of the patch centre (less than half the smallest patch the lab makes).
    bool render(const rad::HemicubeFrame& frame, int res, double nearDistance,
                rad::ItemBuffer& out, std::string& error);
    bool reversedDepth() const { return reversedDepth_; }
    size_t triangles() const { return vertexCount_ / 3; }

    // 24-bit colour of an item id and back (id + 1, so black is "nothing" = −1).
    static void encode(uint32_t item, uint8_t rgb[3]);
    static int32_t decode(const uint8_t rgb[3]);

  private:
    bool ensureTarget(int res, std::string& error);
    void release();

    GLuint fbo_ = 0, colour_ = 0, depth_ = 0, vbo_ = 0, cbo_ = 0;
    int targetRes_ = 0;
    GLsizei vertexCount_ = 0;
    bool reversedDepth_ = false;
    double sceneRadius_ = 1.0; // far plane of the fallback mapping
    glm::dvec3 sceneCentre_{0.0};
    std::vector<uint8_t> readBack_; // RGBA of the whole target
};

// Each patch of `mesh` as a fan of triangles from its first corner, its index the item id:
// the geometry the GL hemicube tests and bench upload (the lab uploads its conforming
// display mesh instead, PatchView::hemicubeGeometry).
void patchFans(const rad::PatchMesh& mesh, std::vector<glm::vec3>& vertices,
               std::vector<uint32_t>& items);

} // namespace wb
