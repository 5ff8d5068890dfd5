#pragma once
// The one way lab code includes OpenGL. The windowed build loads entry points
// through GLEW (which resolves them via GLX); the headless build links
// libOSMesa, which exports every entry point itself, so it takes the prototypes
// directly. Lab sources are compiled once per path (see add_lab in labs/CMakeLists.txt).
#if defined(WB_HEADLESS)
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#else
#include <GL/glew.h>
#endif
#include <GL/glu.h>
