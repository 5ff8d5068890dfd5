#pragma once
// Keys and typed text the way X sees them, beside GLUT (window path only; issue 17).
// freeglut hands a program only what XLookupString gives, Latin-1 at most: with the Russian
// layout active a Cyrillic letter is dropped, and a lab key arrives as nothing. A second
// connection to the same X server selects KeyPress on the lab's window (several clients may)
// and reads each press's keycode itself:
//   - characters beyond Latin-1 (Cyrillic...) go to ImGui's text input; GLUT delivers the
//     Latin-1 ones, so each character arrives once;
//   - a press in a second group (layout), or one that types no ASCII character (the Russian
//     layout alone, `setxkbmap ru`), is the lab key the US layout has at that physical key and
//     shift level (the first group's keysym at the same keycode when that is Latin, else
//     xkbcommon's US keymap), and GLUT's own character for it is ignored, so each key acts
//     once. The group is the one in the event itself (as in
//     XLookupString), not the keyboard's state when we get to it.
// Order: the X server writes a press to every client that selected it in one go, so when GLUT
// reports a character, read() finds the same press on this connection. Each press is queued
// here in X's order, with a marker where GLUT will report a character (XLookupString gives one,
// as in freeglut); what comes before a marker is only done once GLUT has reported it, so keys
// act in the order they were pressed even when they come faster than frames.
#include <chrono>
#include <deque>
#include <functional>

namespace wb {

class XKeyboard {
  public:
    XKeyboard() = default;
    ~XKeyboard();
    XKeyboard(const XKeyboard&) = delete;
    XKeyboard& operator=(const XKeyboard&) = delete;

    // Opens the second connection to `displayName` and listens to `window`'s key presses.
    // False when X or its keyboard extension is not there (then GLUT alone is used, as before).
    bool open(const char* displayName, unsigned long window);

    // Reads the pending key events and does what is due, in order, up to the first press GLUT
    // has yet to report: text(c) for a typed character beyond Latin-1, labKey(c) for a press in
    // a second group or of a key typing no ASCII character, with `c` the US layout's ASCII
    // character at that key.
    void poll(const std::function<void(unsigned)>& text, const std::function<void(int)>& labKey);

    // GLUT reports a character: does what came before its press (as poll()) and returns true
    // when the X side made no lab key of that press, or when there is no X reader: the
    // character is then the lab key; false: the X side has acted for it.
    bool glutCharacter(const std::function<void(unsigned)>& text,
                       const std::function<void(int)>& labKey);

  private:
    struct Action {
        enum Kind { Text, LabKey, GlutCharacter } kind;
        unsigned value; // Text: the character; LabKey: the ASCII key; GlutCharacter: 1 when
                        // the same press queued a LabKey
        std::chrono::steady_clock::time_point when;
    };
    void read();
    unsigned usKey(unsigned keycode, int level);
    void run(const std::function<void(unsigned)>& text, const std::function<void(int)>& labKey);
    void* display_ = nullptr; // Display*, kept out of this header (X11 macros)
    void* usKeymap_ = nullptr; // xkb_keymap* of the US layout (usKey), made when first needed
    bool usKeymapFailed_ = false; // xkbcommon could not compile it (no xkeyboard-config data)
    std::deque<Action> queue_;
};

} // namespace wb
