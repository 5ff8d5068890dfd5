#include "panel_check.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstring>

namespace wb::panelcheck {
namespace {

// Text may end this far past the clip edge and still show whole: a glyph's advance
// includes its right side bearing (about 1 px for DejaVu Sans at 15 px), and ImGui
// rounds text positions to whole pixels.
constexpr float kTolerancePx = 1.0f;

bool g_recording = false;
std::vector<ClippedText> g_found;

void record(const char* text, const char* end, float left, float right, float clipMin,
            float clipMax, float top, float bottom) {
    const ImGuiWindow* window = GImGui->CurrentWindow;
    if (!g_recording || !window || end <= text) return;
    const ImVec4 clip = window->DrawList->_CmdHeader.ClipRect; // what the GPU will clip to
    if (bottom <= clip.y || top >= clip.w) return;             // scrolled out of view: not drawn
    const float visibleMax = std::min(clipMax, clip.z), visibleMin = std::max(clipMin, clip.x);
    const float overflow = std::max(right - visibleMax, visibleMin - left);
    if (overflow <= kTolerancePx) return;
    std::string s(text, size_t(end - text));
    if (s.size() > 60) s = s.substr(0, 57) + "...";
    for (auto& f : g_found)
        if (f.text == s) {
            f.overflow = std::max(f.overflow, overflow);
            return;
        }
    g_found.push_back({s, window->Name ? window->Name : "", overflow});
}

const char* endOf(const char* text, const char* end) {
    return end ? end : text + std::strlen(text);
}

} // namespace

void start() {
    g_found.clear();
    g_recording = true;
}

std::vector<ClippedText> stop() {
    g_recording = false;
    return std::move(g_found);
}

} // namespace wb::panelcheck

// The wrapped ImGui functions (mangled names of ImGui 1.86, Debian's libimgui.a). The
// linker sends the widgets' calls here and the __real_ names to ImGui's own code.
extern "C" {
void __real__ZN5ImGui10RenderTextE6ImVec2PKcS2_b(ImVec2 pos, const char* text, const char* end,
                                                 bool hideAfterHash);
void __real__ZN5ImGui17RenderTextWrappedE6ImVec2PKcS2_f(ImVec2 pos, const char* text,
                                                        const char* end, float wrapWidth);
void __real__ZN5ImGui17RenderTextClippedERK6ImVec2S2_PKcS4_PS1_S2_PK6ImRect(
    const ImVec2& posMin, const ImVec2& posMax, const char* text, const char* end,
    const ImVec2* sizeIfKnown, const ImVec2& align, const ImRect* clip);

void __wrap__ZN5ImGui10RenderTextE6ImVec2PKcS2_b(ImVec2 pos, const char* text, const char* end,
                                                 bool hideAfterHash) {
    if (wb::panelcheck::g_recording) {
        const char* shown = hideAfterHash ? ImGui::FindRenderedTextEnd(text, end)
                                          : wb::panelcheck::endOf(text, end);
        const ImVec2 size = ImGui::CalcTextSize(text, shown, false);
        wb::panelcheck::record(text, shown, pos.x, pos.x + size.x, -1e30f, 1e30f, pos.y,
                               pos.y + size.y);
    }
    __real__ZN5ImGui10RenderTextE6ImVec2PKcS2_b(pos, text, end, hideAfterHash);
}

void __wrap__ZN5ImGui17RenderTextWrappedE6ImVec2PKcS2_f(ImVec2 pos, const char* text,
                                                        const char* end, float wrapWidth) {
    if (wb::panelcheck::g_recording) {
        const char* shown = wb::panelcheck::endOf(text, end);
        // A word longer than the wrap width still runs past it: CalcTextSize says how far.
        const ImVec2 size = ImGui::CalcTextSize(text, shown, false, wrapWidth);
        wb::panelcheck::record(text, shown, pos.x, pos.x + size.x, -1e30f, 1e30f, pos.y,
                               pos.y + size.y);
    }
    __real__ZN5ImGui17RenderTextWrappedE6ImVec2PKcS2_f(pos, text, end, wrapWidth);
}

void __wrap__ZN5ImGui17RenderTextClippedERK6ImVec2S2_PKcS4_PS1_S2_PK6ImRect(
    const ImVec2& posMin, const ImVec2& posMax, const char* text, const char* end,
    const ImVec2* sizeIfKnown, const ImVec2& align, const ImRect* clip) {
    if (wb::panelcheck::g_recording) {
        // As ImGui places it: aligned inside [posMin, posMax], clipped to `clip` or to posMax.
        const char* shown = ImGui::FindRenderedTextEnd(text, end);
        const ImVec2 size = ImGui::CalcTextSize(text, shown, false);
        float x = posMin.x;
        if (align.x > 0.0f) x = std::max(x, x + (posMax.x - x - size.x) * align.x);
        const float clipMin = clip ? clip->Min.x : posMin.x,
                    clipMax = clip ? clip->Max.x : posMax.x;
        wb::panelcheck::record(text, shown, x, x + size.x, clipMin, clipMax, posMin.y,
                               posMin.y + size.y);
    }
    __real__ZN5ImGui17RenderTextClippedERK6ImVec2S2_PKcS4_PS1_S2_PK6ImRect(
        posMin, posMax, text, end, sizeIfKnown, align, clip);
}
} // extern "C"
