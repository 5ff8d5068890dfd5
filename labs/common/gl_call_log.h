#pragma once
// OpenGL matrix calls made by student code while a check runs (issue 18: lab 03 task 5 must
// build the mirror "with glScalef/glTranslatef/glRotatef calls only"). wb-check interposes
// the GL and GLU matrix functions (gl_call_interpose.cpp: it defines them and exports them,
// so the student's shared object binds to them before libGL/OSMesa) and notes each call here
// while a log is open; the calls go on to the real functions. GLU's own inner GL calls
// (gluLookAt multiplies with glMultMatrixf) are not noted: the GLU call is.
#include <vector>

namespace wb::ex {

// Every matrix call wb-check can see, by index (the index is what a check's Values carry).
inline constexpr const char* kGlMatrixCalls[] = {"glTranslatef",
                                                 "glTranslated",
                                                 "glScalef",
                                                 "glScaled",
                                                 "glRotatef",
                                                 "glRotated",
                                                 "glPushMatrix",
                                                 "glPopMatrix",
                                                 "glLoadIdentity",
                                                 "glLoadMatrixf",
                                                 "glLoadMatrixd",
                                                 "glMultMatrixf",
                                                 "glMultMatrixd",
                                                 "glLoadTransposeMatrixf",
                                                 "glLoadTransposeMatrixd",
                                                 "glMultTransposeMatrixf",
                                                 "glMultTransposeMatrixd",
                                                 "glMatrixMode",
                                                 "glFrustum",
                                                 "glOrtho",
                                                 "gluLookAt",
                                                 "gluPerspective",
                                                 "gluOrtho2D",
                                                 "gluPickMatrix"};
inline constexpr int kGlMatrixCallCount = int(sizeof kGlMatrixCalls / sizeof kGlMatrixCalls[0]);
// The index of a call by its name (-1: none), at compile time.
constexpr int glMatrixCallIndex(const char* name) {
    for (int i = 0; i < kGlMatrixCallCount; ++i) {
        const char *a = kGlMatrixCalls[i], *b = name;
        while (*a && *a == *b)
            ++a, ++b;
        if (*a == *b) return i;
    }
    return -1;
}

// True in a process that interposes the calls (wb-check); elsewhere a log stays empty.
bool glCallLogAvailable();
// Opens the log (clears it): from now on each interposed call is noted.
void glCallLogStart();
// Closes the log and returns the calls noted since glCallLogStart, as kGlMatrixCalls indices.
std::vector<int> glCallLogStop();

// For gl_call_interpose.cpp.
void glCallLogSetAvailable();
// Notes call `index` if a log is open and no outer noted call is running; returns true when
// the caller must leave the nesting with glCallLogLeave() after the real call.
bool glCallLogEnter(int index);
void glCallLogLeave();

// Opens the log for a scope (closed on exceptions too); calls() closes it and returns them.
class GlCallLog {
  public:
    GlCallLog() { glCallLogStart(); }
    ~GlCallLog() {
        if (open_) glCallLogStop();
    }
    GlCallLog(const GlCallLog&) = delete;
    GlCallLog& operator=(const GlCallLog&) = delete;
    std::vector<int> calls() {
        open_ = false;
        return glCallLogStop();
    }

  private:
    bool open_ = true;
};

} // namespace wb::ex
