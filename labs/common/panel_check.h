#pragma once
// Finds text the panel cuts off. Linked with -Wl,--wrap for ImGui's RenderText,
// RenderTextWrapped and RenderTextClipped (see labs/CMakeLists.txt, wb_panel_check), so
// every label, value and line of text any widget draws passes through here with its
// position; text whose extent runs past the clip rectangle it is drawn into (the panel's
// edge, a table cell, a button or slider frame) is recorded. ImGui's item rectangles alone
// miss text clipped inside a frame; this sees the string itself, so the report names it.
#include <string>
#include <vector>

namespace wb::panelcheck {

struct ClippedText {
    std::string text;   // the string as drawn (shortened)
    std::string window; // the ImGui window it belongs to
    float overflow;     // pixels of it beyond the visible edge (right or left)
};

void start();                    // from now on, record clipped text
std::vector<ClippedText> stop(); // stop recording; what was clipped, each string once

} // namespace wb::panelcheck
