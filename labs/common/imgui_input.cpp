#include "imgui_input.h"

#include <GL/freeglut.h> // constants only (GLUT_ACTIVE_*, GLUT_KEY_*, buttons); no GLUT calls

#include <imgui.h>

#include <bitset>

namespace wb {
namespace {

// Debian's imgui_impl_glut maps special keys to io.KeysDown[256 + key]; we keep its io.KeyMap.
constexpr int kSpecialBase = 256;

// The modifier bit a GLUT special key is, or 0.
int modifierBit(int key) {
    switch (key) {
    case GLUT_KEY_SHIFT_L:
    case GLUT_KEY_SHIFT_R:
        return GLUT_ACTIVE_SHIFT;
    case GLUT_KEY_CTRL_L:
    case GLUT_KEY_CTRL_R:
        return GLUT_ACTIVE_CTRL;
    case GLUT_KEY_ALT_L:
    case GLUT_KEY_ALT_R:
        return GLUT_ACTIVE_ALT;
    default:
        return 0;
    }
}

// GLUT turns Ctrl+A..Ctrl+Z into 1..26; ImGui's shortcuts look for the letter (as the backend
// does).
int keyIndex(unsigned char c) {
    if (c >= 1 && c <= 26) return 'A' + c - 1;
    if (c >= 'a' && c <= 'z') return c - 'a' + 'A';
    return c;
}

} // namespace

void ImGuiInput::keyboard(unsigned char c, bool down, int mods) {
    if (down && c >= 32 && c != 127) push({Type::Char, c, true, 0, 0, 0.0f, mods});
    push({Type::Key, keyIndex(c), down, 0, 0, 0.0f, mods});
}

void ImGuiInput::special(int key, bool down, int mods) {
    // In the event of a modifier key, GLUT gives the modifiers from before it: apply the
    // key itself, so a released Shift reads as released.
    if (int bit = modifierBit(key)) mods = down ? (mods | bit) : (mods & ~bit);
    if (kSpecialBase + key < 512) push({Type::Key, kSpecialBase + key, down, 0, 0, 0.0f, mods});
}

void ImGuiInput::mouse(int button, int state, int x, int y, int mods) {
    int b = button == GLUT_LEFT_BUTTON     ? 0
            : button == GLUT_RIGHT_BUTTON  ? 1
            : button == GLUT_MIDDLE_BUTTON ? 2
                                           : -1;
    if (b < 0) return;
    push({Type::Button, b, state == GLUT_DOWN, x, y, 0.0f, mods});
}

void ImGuiInput::wheel(int direction, int x, int y, int mods) {
    push({Type::Wheel, 0, false, x, y, direction > 0 ? 1.0f : -1.0f, mods});
}

void ImGuiInput::motion(int x, int y) {
    push({Type::Motion, 0, false, x, y, 0.0f, -1});
}

void ImGuiInput::applyToFrame(ImGuiIO& io) {
    // What this frame already changed; an event that would change it again waits for the next
    // frame.
    std::bitset<512> keys;
    std::bitset<5> buttons;
    bool anyButton = false, wheeled = false;
    auto setMods = [&](int mods) {
        if (mods < 0) return;
        io.KeyShift = (mods & GLUT_ACTIVE_SHIFT) != 0;
        io.KeyCtrl = (mods & GLUT_ACTIVE_CTRL) != 0;
        io.KeyAlt = (mods & GLUT_ACTIVE_ALT) != 0;
    };
    auto modsDiffer = [&](int mods) {
        return mods >= 0 && (io.KeyShift != ((mods & GLUT_ACTIVE_SHIFT) != 0) ||
                             io.KeyCtrl != ((mods & GLUT_ACTIVE_CTRL) != 0) ||
                             io.KeyAlt != ((mods & GLUT_ACTIVE_ALT) != 0));
    };
    while (!queue_.empty()) {
        const Event& e = queue_.front();
        // A wheel step already taken this frame was read with the modifiers as they are now.
        if (wheeled && modsDiffer(e.mods)) break;
        switch (e.type) {
        case Type::Char:
            io.AddInputCharacter(unsigned(e.code));
            break;
        case Type::Key:
            if (keys[size_t(e.code)]) return;
            keys[size_t(e.code)] = true;
            io.KeysDown[e.code] = e.down;
            break;
        case Type::Button:
            if (buttons[size_t(e.code)]) return;
            buttons[size_t(e.code)] = true;
            anyButton = true;
            io.MousePos = ImVec2(float(e.x), float(e.y));
            io.MouseDown[e.code] = e.down;
            break;
        case Type::Wheel:
            // Clicked where it was: a wheel or motion after a press waits for the frame that sees
            // the press.
            if (anyButton && (io.MousePos.x != float(e.x) || io.MousePos.y != float(e.y))) return;
            io.MousePos = ImVec2(float(e.x), float(e.y));
            io.MouseWheel += e.wheel;
            wheeled = true;
            break;
        case Type::Motion:
            if (anyButton) return;
            io.MousePos = ImVec2(float(e.x), float(e.y));
            break;
        }
        setMods(e.mods);
        queue_.pop_front();
    }
}

} // namespace wb
