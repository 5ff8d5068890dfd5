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
    xkb_keymap_unref(static_cast<xkb_keymap*>(usKeymap_));
}

// The US layout's ASCII key at X keycode `keycode` and shift level `level`, or 0. From the
// keyboard's first group when that is Latin (us,ru: the usual set-up); with no Latin layout
// at all (`setxkbmap ru` alone) from xkbcommon's own US keymap (xkeyboard-config's evdev
// rules: X keycodes are xkb keycodes there), compiled once, at the first such press.
unsigned XKeyboard::usKey(unsigned keycode, int level) {
    Display* d = dpy(display_);
    const KeySym first = XkbKeycodeToKeysym(d, KeyCode(keycode), 0, level);
    if (first >= 0x20 && first <= 0x7e) return unsigned(first); // Latin keysyms are ASCII
    if (!usKeymap_ && !usKeymapFailed_) {
        xkb_context* ctx = xkb_context_new(XKB_CONTEXT_NO_FLAGS);
        const xkb_rule_names names{"evdev", "pc105", "us", "", ""};
        usKeymap_ = ctx ? xkb_keymap_new_from_names(ctx, &names, XKB_KEYMAP_COMPILE_NO_FLAGS)
                        : nullptr;
        xkb_context_unref(ctx); // the keymap holds its own reference
        usKeymapFailed_ = usKeymap_ == nullptr;
    }
    if (!usKeymap_) return 0;
    const xkb_keysym_t* syms = nullptr;
    const int n = xkb_keymap_key_get_syms_by_level(static_cast<xkb_keymap*>(usKeymap_), keycode,
                                                   0, xkb_level_index_t(level), &syms);
    return n == 1 && syms[0] >= 0x20 && syms[0] <= 0x7e ? unsigned(syms[0]) : 0;
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
        // A press in a second group, or of a key that types no ASCII character (the
        // Russian layout as the only one: its group is the first), is the US key at that
        // place. Ctrl/Alt: GLUT's.
        bool acted = false;
        const bool ascii = typed >= 0x20 && typed <= 0x7e;
        if ((group != 0 || !ascii) && !(state & (ControlMask | Mod1Mask))) {
            if (const unsigned us = usKey(keycode, level)) {
                queue_.push_back({Action::LabKey, us, now});
                acted = true;
            }
        }
        char chars[8];
        KeySym looked = 0;
        if (XLookupString(&e.xkey, chars, sizeof chars, &looked, nullptr) > 0)
            queue_.push_back({Action::GlutCharacter, acted ? 1u : 0u, now});
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
    const bool acted = queue_.front().value != 0;
    queue_.pop_front();
    return !acted;
}

} // namespace wb
