// wb-check's own definitions of the OpenGL and GLU matrix functions (gl_call_log.h): exported
// from the executable (labs/common/gl_call_interpose.list), so a student's shared object,
// which links nothing and finds its GL symbols in the process, binds to these first. Each
// notes the call in the open log and goes on to the real function (the next definition:
// OSMesa's or GLU's, found with dlsym(RTLD_NEXT)). wb-check's own GL calls pass through too,
// unnoted, as no log is open then.
#include "common/gl_call_log.h"

#include <GL/gl.h>
#include <GL/glu.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace {

[[maybe_unused]] const bool kInterposed = (wb::ex::glCallLogSetAvailable(), true);

void* realFunction(const char* name) {
    void* f = dlsym(RTLD_NEXT, name);
    // GLU: the linker drops libGLU from wb-check when these definitions are all it used.
    if (!f && name[2] == 'u')
        if (void* glu = dlopen("libGLU.so.1", RTLD_NOW | RTLD_GLOBAL)) f = dlsym(glu, name);
    if (!f) {
        std::fprintf(stderr, "wb-check: no %s after the interposed one\n", name);
        std::abort();
    }
    return f;
}

} // namespace

#define WB_INTERPOSE(name, params, args)                                                           \
    extern "C" __attribute__((visibility("default"))) void name params {                           \
        static_assert(wb::ex::glMatrixCallIndex(#name) >= 0, #name " is not in kGlMatrixCalls");   \
        static auto* const real = reinterpret_cast<void(*) params>(realFunction(#name));           \
        const bool noted = wb::ex::glCallLogEnter(wb::ex::glMatrixCallIndex(#name));               \
        real args;                                                                                 \
        if (noted) wb::ex::glCallLogLeave();                                                       \
    }

WB_INTERPOSE(glTranslatef, (GLfloat x, GLfloat y, GLfloat z), (x, y, z))
WB_INTERPOSE(glTranslated, (GLdouble x, GLdouble y, GLdouble z), (x, y, z))
WB_INTERPOSE(glScalef, (GLfloat x, GLfloat y, GLfloat z), (x, y, z))
WB_INTERPOSE(glScaled, (GLdouble x, GLdouble y, GLdouble z), (x, y, z))
WB_INTERPOSE(glRotatef, (GLfloat a, GLfloat x, GLfloat y, GLfloat z), (a, x, y, z))
WB_INTERPOSE(glRotated, (GLdouble a, GLdouble x, GLdouble y, GLdouble z), (a, x, y, z))
WB_INTERPOSE(glPushMatrix, (void), ())
WB_INTERPOSE(glPopMatrix, (void), ())
WB_INTERPOSE(glLoadIdentity, (void), ())
WB_INTERPOSE(glLoadMatrixf, (const GLfloat* m), (m))
WB_INTERPOSE(glLoadMatrixd, (const GLdouble* m), (m))
WB_INTERPOSE(glMultMatrixf, (const GLfloat* m), (m))
WB_INTERPOSE(glMultMatrixd, (const GLdouble* m), (m))
WB_INTERPOSE(glLoadTransposeMatrixf, (const GLfloat* m), (m))
WB_INTERPOSE(glLoadTransposeMatrixd, (const GLdouble* m), (m))
WB_INTERPOSE(glMultTransposeMatrixf, (const GLfloat* m), (m))
WB_INTERPOSE(glMultTransposeMatrixd, (const GLdouble* m), (m))
WB_INTERPOSE(glMatrixMode, (GLenum mode), (mode))
WB_INTERPOSE(glFrustum, (GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f),
             (l, r, b, t, n, f))
WB_INTERPOSE(glOrtho, (GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f),
             (l, r, b, t, n, f))
WB_INTERPOSE(gluLookAt,
             (GLdouble ex, GLdouble ey, GLdouble ez, GLdouble cx, GLdouble cy, GLdouble cz,
              GLdouble ux, GLdouble uy, GLdouble uz),
             (ex, ey, ez, cx, cy, cz, ux, uy, uz))
WB_INTERPOSE(gluPerspective, (GLdouble fovy, GLdouble aspect, GLdouble n, GLdouble f),
             (fovy, aspect, n, f))
WB_INTERPOSE(gluOrtho2D, (GLdouble l, GLdouble r, GLdouble b, GLdouble t), (l, r, b, t))
WB_INTERPOSE(gluPickMatrix, (GLdouble x, GLdouble y, GLdouble w, GLdouble h, GLint* viewport),
             (x, y, w, h, viewport))
