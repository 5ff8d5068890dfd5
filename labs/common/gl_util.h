#pragma once
// Small GL helpers shared by the labs; compiled once per path like lab code.
#include "core/image.h"
#include "gl.h"
#include "lab.h"

#include <string>

namespace wb {

// Reads the current framebuffer (GL_BACK in a window, the OSMesa buffer headless) as RGB, top row first.
Image readFramebuffer(int width, int height);

// Perspective projection for `view` (aspect from its size, zoom narrows the field of view).
void setPerspective(const View& view, double fovyDegrees, double zNear, double zFar);
// Rotates the modelview by the view's pitch, then yaw (the mouse-drag orbit).
void applyOrbit(const View& view);

// Compiles and links a GLSL program from two files under the asset root;
// returns 0 and a message naming the file and the compiler log on failure.
GLuint loadProgram(const std::string& vertexFile, const std::string& fragmentFile, std::string& error);

} // namespace wb
