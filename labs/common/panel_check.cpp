#include "panel_check.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace wb::panelcheck {
namespace {

// Text may end this far past the clip edge and still show whole: a glyph's advance
// includes its right side bearing (about 1 px for DejaVu Sans at 15 px), and ImGui
// rounds text positions to whole pixels.
constexpr float kTolerancePx = 1.0f;

bool g_recording = false;
std::vector<ClippedText> g_found;
std::vector<std::string> g_drawn;

void drawn(const char* text, const char* end) {
    std::string s(text, size_t(end - text));
    if (std::find(g_drawn.begin(), g_drawn.end(), s) == g_drawn.end()) g_drawn.push_back(s);
}

// Words that stay as they are in every language: what is printed on the keys and the languages'
// own names in View > Language.
const char* const kAllowedWords[] = {"Esc",  "Ctrl", "Shift", "Alt",   "PgUp",    "PgDn",
                                     "Home", "End",  "Tab",   "Enter", "English", "Pseudo"};

void record(const char* text, const char* end, float left, float right, float clipMin,
            float clipMax, float top, float bottom) {
    const ImGuiWindow* window = GImGui->CurrentWindow;
    if (!g_recording || !window || end <= text) return;
    drawn(text, end);
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
    g_drawn.clear();
    g_recording = true;
}

const std::vector<std::string>& drawnTexts() {
    return g_drawn;
}

std::string untranslatedWords(const std::string& text) {
    // Outside brackets only (they nest: "[a [b] c]" is one catalogue string holding another).
    std::string outside;
    int depth = 0;
    for (char c : text) {
        if (c == '[') ++depth;
        if (depth == 0) outside += c;
        if (c == ']' && depth > 0) {
            --depth;
            outside += ' ';
        }
    }
    auto isLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    std::string found;
    size_t i = 0;
    while (i < outside.size()) {
        // A token: up to white space.
        while (i < outside.size() && std::isspace(static_cast<unsigned char>(outside[i])))
            ++i;
        size_t j = i;
        while (j < outside.size() && !std::isspace(static_cast<unsigned char>(outside[j])))
            ++j;
        const std::string token = outside.substr(i, j - i);
        i = j;
        if (token.find_first_of("0123456789_.\\") != std::string::npos) continue; // a value
        // An identifier the user types (a scene name: two-spheres, glass-cube).
        bool hyphenated = false;
        for (size_t k = 1; k + 1 < token.size(); ++k)
            hyphenated = hyphenated || (token[k] == '-' && isLetter(token[k - 1]) && isLetter(token[k + 1]));
        if (hyphenated) continue;
        // A word of a pseudo-translation (accented) whose brackets are on another line.
        bool nonAscii = false;
        for (char c : token)
            nonAscii = nonAscii || static_cast<unsigned char>(c) >= 0x80;
        if (nonAscii) continue;
        for (size_t k = 0; k < token.size();) {
            if (!isLetter(token[k])) {
                ++k;
                continue;
            }
            size_t e = k;
            while (e < token.size() && isLetter(token[e]))
                ++e;
            const std::string word = token.substr(k, e - k);
            k = e;
            if (word.size() == 1) continue;
            bool allowed = false;
            for (const char* w : kAllowedWords)
                allowed = allowed || word == w;
            if (!allowed) found += (found.empty() ? "" : " ") + word;
        }
    }
    return found;
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
