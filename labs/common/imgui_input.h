#pragma once
// GLUT input for Dear ImGui 1.86, which reads its input as state once per frame
// (io.MouseDown, io.KeysDown, io.KeyShift...). Two things go wrong when GLUT events are
// written into that state as they arrive (as Debian's imgui_impl_glut does):
//  - a press and a release that arrive between two frames cancel out, and ImGui never
//    sees the click (`xdotool click 1`);
//  - GLUT reports the modifiers only with key and mouse events, and in the event of the
//    Shift key's own release it still says Shift is down, so io.KeyShift stays true and the
//    next wheel event scrolls the panel sideways.
// ImGuiInput queues the events with their modifiers and hands ImGui, before each frame,
// the events up to the first that would overwrite a change ImGui has not seen yet.
// No GLUT calls here: the shell's callbacks pass glutGetModifiers() in, tests pass their own.
#include <deque>

struct ImGuiIO;

namespace wb {

class ImGuiInput {
  public:
    // The GLUT callbacks' arguments; `mods` is glutGetModifiers() (GLUT_ACTIVE_* bits).
    void keyboard(unsigned char c, bool down, int mods);
    void special(int key, bool down, int mods);
    void mouse(int button, int state, int x, int y, int mods);
    void wheel(int direction, int x, int y, int mods);
    void motion(int x, int y);
    // A typed character GLUT cannot give (beyond Latin-1: Cyrillic), read from X (x_keyboard.h).
    void character(unsigned c) { push({Type::Char, int(c), true, 0, 0, 0.0f, -1}); }

    // Before ImGui::NewFrame(): applies queued events to io (see above).
    void applyToFrame(ImGuiIO& io);
    // Events still waiting for a frame (the shell then draws another one).
    bool pending() const { return !queue_.empty(); }

  private:
    enum class Type { Char, Key, Button, Wheel, Motion };
    struct Event {
        Type type;
        int code = 0; // Char: character; Key: io.KeysDown index; Button: 0 left, 1 right, 2 middle
        bool down = false;  // Key, Button
        int x = 0, y = 0;   // Button, Wheel, Motion
        float wheel = 0.0f; // Wheel: +1 up, -1 down
        int mods = -1;      // GLUT_ACTIVE_* bits after the event; -1: unknown (motion)
    };
    void push(const Event& e) { queue_.push_back(e); }
    std::deque<Event> queue_;
};

} // namespace wb
