#include "x_keyboard.h"

#include <X11/XKBlib.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <xkbcommon/xkbcommon.h>

namespace wb {
namespace {

Display* dpy(void* d) {
    return static_cast<Display*>(d);
}

// A GLUT character marker older than this is given up (GLUT did not report that press, e.g. it
// reached the window before the reader opened): the keys behind it must not wait for ever.
constexpr std::chrono::milliseconds kMarkerTimeout{1000};

} // namespace

XKeyboard::~XKeyboard() {
    if (display_) XCloseDisplay(dpy(display_));
}

bool XKeyboard::open(const char* displayName, unsigned long window) {
    int major = XkbMajorVersion, minor = XkbMinorVersion, error = 0;
    Display* d = XkbOpenDisplay(displayName, nullptr, nullptr, &major, &minor, &error);
    if (!d) return false;
    display_ = d;
    XSelectInput(d, Window(window), KeyPressMask);
    XFlush(d);
    return true;
}

void XKeyboard::read() {
    if (!display_) return;
    Display* d = dpy(display_);
    const auto now = std::chrono::steady_clock::now();
    while (XPending(d) > 0) {
        XEvent e;
        XNextEvent(d, &e);
        if (e.type == MappingNotify) XRefreshKeyboardMapping(&e.xmapping);
        if (e.type != KeyPress) continue;
        const unsigned state = e.xkey.state;
        const auto keycode = KeyCode(e.xkey.keycode);
        const unsigned group = XkbGroupForCoreState(state);
        const int level = (state & ShiftMask) ? 1 : 0;
        const KeySym typed = XkbKeycodeToKeysym(d, keycode, group, level);
        const uint32_t c = xkb_keysym_to_utf32(xkb_keysym_t(typed));
        if (c > 0xFF && c < 0x10000) // ImGui 1.86 keeps 16-bit characters
            queue_.push_back({Action::Text, c, now});
        if (group != 0 && !(state & (ControlMask | Mod1Mask))) { // Ctrl/Alt: GLUT's
            const KeySym us = XkbKeycodeToKeysym(d, keycode, 0, level);
            if (us >= 0x20 && us <= 0x7e) // Latin keysyms are their ASCII codes
                queue_.push_back({Action::LabKey, unsigned(us), now});
        }
        char chars[8];
        KeySym looked = 0;
        if (XLookupString(&e.xkey, chars, sizeof chars, &looked, nullptr) > 0)
            queue_.push_back({Action::GlutCharacter, group, now});
    }
}

void XKeyboard::run(const std::function<void(unsigned)>& text,
                    const std::function<void(int)>& labKey) {
    const auto now = std::chrono::steady_clock::now();
    while (!queue_.empty()) {
        const Action a = queue_.front();
        if (a.kind == Action::GlutCharacter) {
            if (now - a.when < kMarkerTimeout) return; // GLUT has yet to report it
            queue_.pop_front();
            continue;
        }
        queue_.pop_front();
        if (a.kind == Action::Text)
            text(a.value);
        else
            labKey(int(a.value));
    }
}

void XKeyboard::poll(const std::function<void(unsigned)>& text,
                     const std::function<void(int)>& labKey) {
    read();
    run(text, labKey);
}

bool XKeyboard::glutCharacter(const std::function<void(unsigned)>& text,
                              const std::function<void(int)>& labKey) {
    if (!display_) return true;
    read();
    // What came before this press, then the press's own marker.
    while (!queue_.empty() && queue_.front().kind != Action::GlutCharacter) {
        const Action a = queue_.front();
        queue_.pop_front();
        if (a.kind == Action::Text)
            text(a.value);
        else
            labKey(int(a.value));
    }
    if (queue_.empty()) return true; // a press this reader never saw
    const unsigned group = queue_.front().value;
    queue_.pop_front();
    return group == 0;
}

} // namespace wb
