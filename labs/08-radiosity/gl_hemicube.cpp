#include "gl_hemicube.h"

#include "core/i18n.h"

#if defined(WB_HEADLESS)
#include <GL/osmesa.h>
#endif

#include <algorithm>
#include <cmath>

namespace wb {

namespace {

// The five faces: forward direction, up direction, and the axes along which core's layout
// counts columns and rows (core/radiosity/hemicube.h: pixel (col, row) of the top face looks
// along s·u + t·v + n, of side +U along u − s·v + z·n, −U −u + s·v + z·n, +V v + s·u + z·n,
// −V −v − s·u + z·n).
struct FaceSpec {
    glm::dvec3 forward, up, horizontal, vertical;
    bool side; // half height: only the half above the horizon
};

FaceSpec faceSpec(const rad::HemicubeFrame& f, int face) {
    switch (face) {
    case 0: return {f.n, f.v, f.u, f.v, false};
    case 1: return {f.u, f.n, -f.v, f.n, true};
    case 2: return {-f.u, f.n, f.v, f.n, true};
    case 3: return {f.v, f.n, f.u, f.n, true};
    default: return {-f.v, f.n, -f.u, f.n, true};
    }
}

// glClipControl (GL 4.5 / ARB_clip_control): GLEW's pointer in a window; libOSMesa does
// not export it as a symbol, so the headless path asks OSMesa for it.
PFNGLCLIPCONTROLPROC clipControl() {
#if defined(WB_HEADLESS)
    static const auto fn = reinterpret_cast<PFNGLCLIPCONTROLPROC>(
        reinterpret_cast<void*>(OSMesaGetProcAddress("glClipControl")));
    return fn;
#else
    return (GLEW_ARB_clip_control || GLEW_VERSION_4_5) ? glClipControl : nullptr;
#endif
}

} // namespace

void GlHemicube::encode(uint32_t item, uint8_t rgb[3]) {
    const uint32_t c = item + 1;
    rgb[0] = uint8_t(c >> 16);
    rgb[1] = uint8_t(c >> 8);
    rgb[2] = uint8_t(c);
}

int32_t GlHemicube::decode(const uint8_t rgb[3]) {
    const uint32_t c = (uint32_t(rgb[0]) << 16) | (uint32_t(rgb[1]) << 8) | uint32_t(rgb[2]);
    return int32_t(c) - 1;
}

GlHemicube::~GlHemicube() { release(); }

void GlHemicube::release() {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (colour_) glDeleteRenderbuffers(1, &colour_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (cbo_) glDeleteBuffers(1, &cbo_);
    fbo_ = colour_ = depth_ = vbo_ = cbo_ = 0;
    targetRes_ = 0;
}

bool GlHemicube::setGeometry(const std::vector<glm::vec3>& vertices,
                             const std::vector<uint32_t>& items, std::string& error) {
    if (vertices.size() % 3 != 0 || items.size() != vertices.size() / 3) {
        error = wb::trf("GL hemicube: %zu vertices and %zu items (need 3 vertices per item "
                        "triangle)",
                        vertices.size(), items.size());
        return false;
    }
    if (vertices.size() > size_t(1) << 30) {
        error = wb::tr("GL hemicube: too many triangles");
        return false;
    }
    std::vector<uint8_t> colours(vertices.size() * 3);
    glm::dvec3 lo(1e300), hi(-1e300);
    for (size_t t = 0; t < items.size(); ++t) {
        if (items[t] >= (1u << 24) - 1) {
            error = wb::trf("GL hemicube: item id %u does not fit 24-bit colour (at most "
                            "16,777,214 patches)",
                            unsigned(items[t]));
            return false;
        }
        for (int k = 0; k < 3; ++k) {
            encode(items[t], &colours[(3 * t + size_t(k)) * 3]);
            const glm::dvec3 p(vertices[3 * t + size_t(k)]);
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                error = wb::trf("GL hemicube: non-finite vertex in triangle %zu", t);
                return false;
            }
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    if (!vbo_) glGenBuffers(1, &vbo_);
    if (!cbo_) glGenBuffers(1, &cbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(glm::vec3)),
                 vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, cbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(colours.size()), colours.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    vertexCount_ = GLsizei(vertices.size());
    sceneCentre_ = vertices.empty() ? glm::dvec3(0.0) : 0.5 * (lo + hi);
    sceneRadius_ = vertices.empty() ? 1.0 : std::max(0.5 * glm::length(hi - lo), 1e-30);
    return true;
}

bool GlHemicube::ensureTarget(int res, std::string& error) {
    if (fbo_ && targetRes_ == res) return true;
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (colour_) glDeleteRenderbuffers(1, &colour_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    // One target for all five faces: the top face in rows [0, res), the four half-height
    // sides stacked above it (res + 4·res/2 = 3·res rows), read back in one call.
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &colour_);
    glGenRenderbuffers(1, &depth_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, res, 3 * res);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, res, 3 * res);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        // GL's status codes are read in hex (GL_FRAMEBUFFER_UNSUPPORTED is 0x8CDD).
        error = wb::trf("GL hemicube: framebuffer %dx%d incomplete (status 0x%04X)", res, 3 * res,
                        unsigned(status));
        release();
        return false;
    }
    targetRes_ = res;
    return true;
}

bool GlHemicube::render(const rad::HemicubeFrame& frame, int res, double nearDistance,
                        rad::ItemBuffer& out, std::string& error) {
    if (res < 2 || res > 4096 || res % 2 != 0) {
        error = wb::trf("GL hemicube: resolution %d (need an even 2..4096)", res);
        return false;
    }
    if (!(nearDistance > 0) || !std::isfinite(nearDistance)) {
        error = wb::tr("GL hemicube: near distance must be positive and finite");
        return false;
    }
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (3 * res > maxSize) {
        error = wb::trf("GL hemicube: %d rows exceed this GL's renderbuffer limit %d", 3 * res,
                        int(maxSize));
        return false;
    }
    if (!ensureTarget(res, error)) return false;

    // 1. GL state: only what the item buffer needs, restored at the end.
    GLint previousFbo = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFbo);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glDisable(GL_DITHER);      // the ids must arrive bit-exact
    glDisable(GL_LIGHTING);    // colour = the id, not a lit colour
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    glDisable(GL_MULTISAMPLE); // one sample per pixel centre, as the CPU hemicube
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_POLYGON_SMOOTH);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glShadeModel(GL_FLAT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    // Reversed float depth (see the header): depth = near / distance.
    const PFNGLCLIPCONTROLPROC setClip = clipControl();
    reversedDepth_ = setClip != nullptr;
    if (reversedDepth_) setClip(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearColor(0, 0, 0, 0);
    glClearDepth(reversedDepth_ ? 0.0 : 1.0);
    glDepthFunc(reversedDepth_ ? GL_GREATER : GL_LESS);
    glViewport(0, 0, res, 3 * res);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, cbo_);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    const double nd = nearDistance;
    const double farDistance =
        glm::length(frame.origin - sceneCentre_) + 1.01 * sceneRadius_ + 2 * nd;
    const int half = res / 2;
    for (int face = 0; face < 5; ++face) {
        const FaceSpec fs = faceSpec(frame, face);
        // 2. Viewport: face 0 in rows [0, res), side k in [res + (k−1)·res/2, …).
        const int y0 = face == 0 ? 0 : res + (face - 1) * half;
        glViewport(0, y0, res, fs.side ? half : res);
        // 3. Projection: the face's square of side 2 at distance 1 (sides: its upper half).
        const double l = -nd, r = nd, b = fs.side ? 0.0 : -nd, t = nd;
        double P[16] = {};
        P[0] = 2 * nd / (r - l);
        P[5] = 2 * nd / (t - b);
        P[8] = (r + l) / (r - l);
        P[9] = (t + b) / (t - b);
        P[11] = -1;
        if (reversedDepth_) {
            P[14] = nd; // z_clip = near, w_clip = distance: depth = near / distance
        } else {
            P[10] = -(farDistance + nd) / (farDistance - nd);
            P[14] = -2 * farDistance * nd / (farDistance - nd);
        }
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixd(P);
        // 4. View: rows right, up, −forward; the eye at the patch centre.
        const glm::dvec3 f = fs.forward, w = fs.up, rt = glm::cross(f, w);
        const glm::dvec3 o = frame.origin;
        const double M[16] = {rt.x, w.x, -f.x, 0, rt.y, w.y, -f.y, 0, rt.z, w.z, -f.z, 0,
                              -glm::dot(rt, o), -glm::dot(w, o), glm::dot(f, o), 1};
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixd(M);
        // 5. Front faces in their item colours, back faces in "nothing": a patch seen
        // from behind hides what is behind it but receives no form factor.
        glCullFace(GL_BACK);
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
        glDisableClientState(GL_COLOR_ARRAY);
        glColor3ub(0, 0, 0);
        glCullFace(GL_FRONT);
        glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
    }

    // 6. One read-back of all faces.
    readBack_.resize(size_t(res) * size_t(3 * res) * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, res, 3 * res, GL_RGBA, GL_UNSIGNED_BYTE, readBack_.data());

    glDisableClientState(GL_VERTEX_ARRAY);
    if (reversedDepth_) setClip(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFbo));
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glPopClientAttrib();
    glPopAttrib();

    // 7. GL rows to the layout: flip an axis where the camera's right/up point against
    // the layout's horizontal/vertical axis.
    out.resize(res);
    for (int face = 0; face < 5; ++face) {
        const FaceSpec fs = faceSpec(frame, face);
        const glm::dvec3 rt = glm::cross(fs.forward, fs.up);
        const bool flipI = glm::dot(rt, fs.horizontal) < 0;
        const bool flipJ = glm::dot(fs.up, fs.vertical) < 0;
        const int h = fs.side ? half : res;
        const int y0 = face == 0 ? 0 : res + (face - 1) * half;
        std::vector<int32_t>& dst = out.faces[size_t(face)];
        for (int jg = 0; jg < h; ++jg)
            for (int ig = 0; ig < res; ++ig) {
                const uint8_t* px = &readBack_[(size_t(y0 + jg) * size_t(res) + size_t(ig)) * 4];
                const int i = flipI ? res - 1 - ig : ig, j = flipJ ? h - 1 - jg : jg;
                dst[size_t(j) * size_t(res) + size_t(i)] = decode(px);
            }
    }
    const GLenum err = glGetError();
    if (err != GL_NO_ERROR) {
        error = wb::trf("GL hemicube: GL error 0x%04X", unsigned(err));
        return false;
    }
    return true;
}

void patchFans(const rad::PatchMesh& mesh, std::vector<glm::vec3>& vertices,
               std::vector<uint32_t>& items) {
    vertices.clear();
    items.clear();
    for (size_t p = 0; p < mesh.patches.size(); ++p) {
        const auto c = mesh.cornersOf(int(p));
        for (size_t k = 1; k + 1 < c.size(); ++k) {
            vertices.push_back(glm::vec3(c[0]));
            vertices.push_back(glm::vec3(c[k]));
            vertices.push_back(glm::vec3(c[k + 1]));
            items.push_back(uint32_t(p));
        }
    }
}

} // namespace wb
