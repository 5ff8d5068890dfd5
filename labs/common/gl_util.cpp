#include "gl_util.h"

#include "paths.h"

#include <cstring>
#include <fstream>
#include <sstream>

namespace wb {

Image readFramebuffer(int width, int height) {
    Image img(width, height, 3);
    std::vector<uint8_t> rows(img.data.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const size_t stride = size_t(width) * 3;
    for (int y = 0; y < height; ++y) // GL's row 0 is the bottom one
        std::memcpy(&img.data[size_t(y) * stride], &rows[size_t(height - 1 - y) * stride], stride);
    return img;
}

void setPerspective(const View& view, double fovyDegrees, double zNear, double zFar) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    double fovy = fovyDegrees / double(view.zoom > 0.0f ? view.zoom : 1.0f);
    if (fovy > 170.0) fovy = 170.0;
    gluPerspective(fovy, double(view.width) / double(view.height > 0 ? view.height : 1), zNear, zFar);
    glMatrixMode(GL_MODELVIEW);
}

void applyOrbit(const View& view) {
    glRotatef(view.pitch, 1.0f, 0.0f, 0.0f);
    glRotatef(view.yaw, 0.0f, 1.0f, 0.0f);
}

namespace {
bool readText(const std::string& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return true;
}

GLuint compile(GLenum type, const std::string& file, std::string& error) {
    std::string path = assetPath(file), src;
    if (!readText(path, src)) {
        error = path + ": cannot read shader";
        return 0;
    }
    GLuint sh = glCreateShader(type);
    const char* text = src.c_str();
    glShaderSource(sh, 1, &text, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(sh, sizeof log, nullptr, log);
        error = path + ": " + log;
        glDeleteShader(sh);
        return 0;
    }
    return sh;
}
} // namespace

GLuint loadProgram(const std::string& vertexFile, const std::string& fragmentFile, std::string& error) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertexFile, error);
    if (!vs) return 0;
    GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentFile, error);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    glLinkProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(prog, sizeof log, nullptr, log);
        error = vertexFile + " + " + fragmentFile + ": link failed: " + log;
        glDeleteProgram(prog);
        return 0;
    }
    return prog;
}

} // namespace wb
