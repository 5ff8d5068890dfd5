// The shell's input path into ImGui 1.86 (labs/common/imgui_input.h), fed the events the
// shell's GLUT callbacks receive, in the order X and freeglut deliver them; the panel
// (labs/common/panel.h) is laid out by ImGui without GL.
#include "common/imgui_input.h"
#include "common/options.h"
#include "common/panel.h"
#include "shell/test_lab.h"

#include <GL/freeglut.h> // GLUT's constants, as the callbacks get them

#include <catch2/catch.hpp>
#include <imgui.h>
#include <imgui_internal.h>

namespace {

// An ImGui context with the shell's fonts and a 1220x600 window (--size 800x600), the test
// lab's panel at its right edge.
struct PanelFixture {
    wb::test::TestLabState state;
    std::unique_ptr<wb::Lab> lab = wb::test::makeTestLab(&state);
    wb::PanelState panel;
    wb::ImGuiInput input;
    const float width = float(wb::kDefaultWidth + wb::kPanelWidth),
                height = float(wb::kDefaultHeight);

    PanelFixture() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        wb::setupImGuiFonts(1.0f);
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        io.DisplaySize = ImVec2(width, height);
    }
    ~PanelFixture() { ImGui::DestroyContext(); }

    // One frame as the shell's display() runs it: queued input first, then the panel.
    void frame() {
        input.applyToFrame(ImGui::GetIO());
        ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
        ImGui::NewFrame();
        wb::drawPanel(*lab, panel, width, height);
        ImGui::Render();
    }
    // Frames until the queue is empty, and two more (the shell draws these after any event).
    void settle() {
        for (int i = 0; i < 100 && input.pending(); ++i)
            frame();
        frame();
        frame();
    }
    // The shell names its panel window "title###panel" (a stable id across languages).
    ImGuiWindow* panelWindow() {
        return ImGui::FindWindowByName((lab->title() + "###panel").c_str());
    }
};

} // namespace

TEST_CASE("Shift+letter then the wheel scrolls the panel down, not sideways", "[shell][input]") {
    PanelFixture f;
    f.lab->key('L'); // content wider than the panel: a sideways scroll is possible
    f.settle();
    ImGuiWindow* w = f.panelWindow();
    REQUIRE(w);
    REQUIRE(w->ScrollMax.x > 0.0f);
    const int x = int(f.width) - 100, y = 100; // over the panel

    // `N` typed as X delivers it (xdotool keydown shift key n keyup shift): GLUT reports each
    // modifier key as a special key, and the modifiers from *before* the event, so the Shift
    // key's own release still says Shift.
    f.input.special(GLUT_KEY_SHIFT_L, true, 0);
    f.input.keyboard('N', true, GLUT_ACTIVE_SHIFT);
    f.input.keyboard('N', false, GLUT_ACTIVE_SHIFT);
    f.input.special(GLUT_KEY_SHIFT_L, false, GLUT_ACTIVE_SHIFT);
    f.settle();
    CHECK_FALSE(ImGui::GetIO().KeyShift);
    // The same sequence with no frame in between, then the wheel: still not stuck.
    f.input.special(GLUT_KEY_SHIFT_L, true, 0);
    f.input.keyboard('N', true, GLUT_ACTIVE_SHIFT);
    f.input.keyboard('N', false, GLUT_ACTIVE_SHIFT);
    f.input.special(GLUT_KEY_SHIFT_L, false, GLUT_ACTIVE_SHIFT);
    for (int i = 0; i < 3; ++i)
        f.input.wheel(-1, x, y, 0);
    f.settle();
    CHECK(w->Scroll.x == 0.0f);
    CHECK(w->Scroll.y > 0.0f); // the wheel did scroll, downwards

    // Shift held during the wheel scrolls sideways (ImGui's rule): the check above can fail.
    f.input.special(GLUT_KEY_SHIFT_L, true, 0);
    f.input.wheel(-1, x, y, GLUT_ACTIVE_SHIFT);
    f.settle();
    CHECK(w->Scroll.x > 0.0f);
}

TEST_CASE("a click whose press and release arrive before one frame still clicks",
          "[shell][input]") {
    PanelFixture f;
    f.settle();
    const int x = int(f.state.buttonX), y = int(f.state.buttonY);
    REQUIRE(x > int(f.width) - wb::kPanelWidth);

    // ImGui 1.86 reads the button state once per frame: written directly, press and release
    // cancel out and nothing is clicked (what `xdotool click 1` did to the launcher).
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(float(x), float(y));
    io.MouseDown[0] = true;
    io.MouseDown[0] = false;
    f.settle();
    CHECK(f.state.presses == 0);

    // Through the shell's input queue: one click.
    f.input.motion(x, y);
    f.input.mouse(GLUT_LEFT_BUTTON, GLUT_DOWN, x, y, 0);
    f.input.mouse(GLUT_LEFT_BUTTON, GLUT_UP, x, y, 0);
    f.settle();
    CHECK(f.state.presses == 1);

    // Three fast clicks between two frames: three presses.
    for (int i = 0; i < 3; ++i) {
        f.input.mouse(GLUT_LEFT_BUTTON, GLUT_DOWN, x, y, 0);
        f.input.mouse(GLUT_LEFT_BUTTON, GLUT_UP, x, y, 0);
    }
    f.settle();
    CHECK(f.state.presses == 4);
}
