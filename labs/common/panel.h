#pragma once
// The ImGui panel every lab shows at the right edge of its window: the shell's line
// (frame time, "measure fps", screenshot), the lab's widgets, the View settings (UI
// scale) and the keys. Pure ImGui: the window path draws it with OpenGL, the headless
// --check-panel path only lays it out to look for clipped text (panel_check.h).
#include "lab.h"

#include <string>

struct ImFont;

namespace wb {

// What the panel shows besides the lab and what the user set in it.
struct PanelState {
    float width = 0.0f;      // current width in window pixels (0: the default for the scale)
    bool resetWidth = false; // apply `width` to the panel on the next frame (after a new UI scale)
    float uiScale = 1.0f;    // the scale the fonts and style are built for
    float requestedScale =
        1.0f; // set by the slider / Ctrl+= Ctrl+-; the shell rebuilds between frames
    bool scaleSliderActive =
        false;               // the UI scale slider is being dragged (rebuilding fonts would jump)
    bool measureFps = false; // redraw continuously so the frame time means frames per second
    double frameMs = 0.0; // CPU time of the last frame (smoothed while measuring fps), milliseconds
    std::string lastScreenshot; // path or error of the last screenshot
    std::string scaleNote;      // why the UI scale is lower than asked (empty when it is not)
    bool screenshotRequested = false;
    bool keysLikeShell = true; // false for the launcher: no drag / zoom / h lines
};

// Loads DejaVu Sans (and DejaVu Sans Mono for tables of numbers) at `scale` into ImGui's
// font atlas and scales the style; when the fonts are missing it keeps ImGui's built-in font
// and returns a message saying so (empty when all is well). Call outside a frame; the
// window path re-creates the font texture afterwards.
std::string setupImGuiFonts(float scale);
// The scale setupImGuiFonts() last built for, exactly: ImGui::GetFontSize() / 15 is the
// rounded pixel size's (1.5 builds a 23-px font: 1.53).
float builtUiScale();

// DejaVu Sans Mono when loaded (for aligned numbers: ImGui::PushFont(panelMonoFont())), else the
// default font.
ImFont* panelMonoFont();

// The panel's width for a scale, window pixels (kPanelWidth at 1).
float defaultPanelWidth(float scale);

// Draws the panel docked at the right edge of a windowWidth x windowHeight window (or
// filling it when the lab asks). alwaysScrollbar keeps the vertical scrollbar's room
// reserved (the check lays out a tall panel but must see the width a short one has).
void drawPanel(Lab& lab, PanelState& state, float windowWidth, float windowHeight,
               bool alwaysScrollbar = false);

// `label` shown, `id` as ImGui's id ("label###id"): a header or window keeps its state (open,
// size, scroll) when the language switches and its label changes.
std::string idLabel(const char* label, const char* id);

// ImGui::SameLine() when a checkbox or radio button labelled `nextLabel` still fits on the line,
// else nothing (it starts the next line): a row of options that fits in English may not in
// Russian, whose words run 20-30% longer.
void sameLineIfFits(const char* nextLabel);

// Ctrl+= / Ctrl+- / Ctrl+0 steps of the UI scale, clamped to kMinUiScale..kMaxUiScale.
float stepUiScale(float scale, int direction);

} // namespace wb
