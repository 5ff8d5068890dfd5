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

void XKeyboard::poll(const std::function<void(unsigned)>& text,
                     const std::function<void(int)>& labKey) {
    if (!display_) return;
    Display* d = dpy(display_);
    while (XPending(d) > 0) {
        XEvent e;
        XNextEvent(d, &e);
        if (e.type == MappingNotify) XRefreshKeyboardMapping(&e.xmapping);
        if (e.type != KeyPress) continue;
        const unsigned state = e.xkey.state;
        const auto keycode = KeyCode(e.xkey.keycode);
        const unsigned group = XkbGroupForCoreState(state);
        lastGroup_ = group;
        const int level = (state & ShiftMask) ? 1 : 0;
        const KeySym typed = XkbKeycodeToKeysym(d, keycode, group, level);
        const uint32_t c = xkb_keysym_to_utf32(xkb_keysym_t(typed));
        if (c > 0xFF && c < 0x10000) text(c); // ImGui 1.86 keeps 16-bit characters
        if (group == 0 || (state & (ControlMask | Mod1Mask))) continue; // GLUT has those
        const KeySym us = XkbKeycodeToKeysym(d, keycode, 0, level);
        if (us >= 0x20 && us <= 0x7e) labKey(int(us)); // Latin keysyms are their ASCII codes
    }
}

} // namespace wb
