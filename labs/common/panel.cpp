#include "panel.h"

#include "keyboard_layout.h"
#include "options.h"

#include "core/i18n.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sys/stat.h>

namespace wb {
namespace {

// Debian's fonts-dejavu-core (scripts/setup.sh installs it).
constexpr const char* kSansPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kMonoPath = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
// Text height at --ui-scale 1, pixels: DejaVu Sans at 15 px reads like a desktop's 11 pt
// UI text, a little larger than ImGui's 13-px bitmap font.
constexpr float kFontPixels = 15.0f;

ImFont* g_mono = nullptr;
// The scale setupImGuiFonts() last built for (the font is that times 15 px, rounded).
float g_builtScale = 1.0f;

bool isFile(const char* path) {
    struct stat st {};
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

// Every character a panel may show in any language: ASCII and Latin-1, the Cyrillic alphabet
// (file names, typed text), and each character of every catalogue string, its English and its
// translations (③, ×, —, ≤, ², arrows...; the pseudo-language's accents). Taken from the
// catalogues themselves, so a new string cannot bring a character the font lacks (the glyph test
// checks the atlas against the same catalogues).
const ImWchar* glyphRanges() {
    static std::vector<ImWchar> ranges;
    if (!ranges.empty()) return ranges.data();
    std::set<char32_t> chars;
    for (char32_t c = 0x20; c <= 0xFF; ++c)
        chars.insert(c);
    for (char32_t c = 0x400; c <= 0x45F; ++c)
        chars.insert(c);
    chars.insert(0xFFFD); // ImGui's fallback for what is still missing
    // The exercise panel's marks (exercise_run.cpp gradeMark/statusMark), not all of them in
    // a catalogue string: the course's grades ③④⑤ and ✓ ✗.
    for (char32_t c : {U'③', U'④', U'⑤', U'✓', U'✗'})
        chars.insert(c);
    auto add = [&](std::string_view text) {
        const std::string s(text);
        for (size_t i = 0; i < s.size();)
            chars.insert(decodeUtf8(s, i));
    };
    for (const auto& code : languages())
        for (const auto& m : i18n::messages(code)) {
            add(m.id);
            add(m.str);
        }
    for (char32_t c : chars) {
        if (c < 0x20 || c > 0xFFFF) continue; // ImWchar is 16 bits in Debian's ImGui
        if (ranges.size() >= 2 && ranges.back() + 1 == ImWchar(c))
            ranges.back() = ImWchar(c);
        else
            ranges.insert(ranges.end(), {ImWchar(c), ImWchar(c)});
    }
    ranges.push_back(0);
    return ranges.data();
}

} // namespace

float defaultPanelWidth(float scale) {
    return std::floor(float(kPanelWidth) * scale + 0.5f);
}

float stepUiScale(float scale, int direction) {
    if (direction == 0) return 1.0f;
    // Steps of 1.25 (0.5, 0.64, 0.8, 1, 1.25, 1.56, 2, 2.5, 3.1, 3.9 and the limits).
    const float s = direction > 0 ? scale * 1.25f : scale / 1.25f;
    return std::clamp(std::round(s * 100.0f) / 100.0f, kMinUiScale, kMaxUiScale);
}

std::string setupImGuiFonts(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    g_mono = nullptr;
    g_builtScale = scale;
    std::string message;
    ImFontConfig config;
    config.OversampleH = 2; // sharper glyph edges at fractional positions
    const float pixels = std::round(kFontPixels * scale);
    const ImWchar* ranges = glyphRanges();
    if (isFile(kSansPath) && io.Fonts->AddFontFromFileTTF(kSansPath, pixels, &config, ranges)) {
        if (isFile(kMonoPath))
            g_mono = io.Fonts->AddFontFromFileTTF(kMonoPath, pixels, &config, ranges);
        if (g_mono) {
            // DejaVu Sans Mono has no circled digits: the grade marks ③④⑤ from DejaVu Sans,
            // merged into it (ImGui skips what the font has already).
            static const ImWchar kMarks[] = {0x2462, 0x2464, 0};
            ImFontConfig merge = config;
            merge.MergeMode = true;
            io.Fonts->AddFontFromFileTTF(kSansPath, pixels, &merge, kMarks);
        }
    } else {
        message = trf("%s not found (Debian package fonts-dejavu-core): using ImGui's built-in "
                      "font",
                      kSansPath);
        ImFontConfig builtIn;
        builtIn.SizePixels = std::round(13.0f * scale);
        io.Fonts->AddFontDefault(&builtIn);
    }
    io.Fonts->Build();
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
    return message;
}

float builtUiScale() {
    return g_builtScale;
}

ImFont* panelMonoFont() {
    return g_mono ? g_mono : ImGui::GetFont();
}

std::string idLabel(const char* label, const char* id) {
    return std::string(label) + "###" + id;
}

void sameLineIfFits(const char* nextLabel) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
                        ImGui::CalcTextSize(nextLabel, nullptr, true).x;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
}

namespace {

// Keys as a two-column table: the key, then what it does, wrapped to the panel.
void keyTable(const std::vector<KeyHelp>& keys) {
    if (!ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const auto& k : keys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(k.key.c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", k.what.c_str());
    }
    ImGui::EndTable();
}

} // namespace

void drawPanel(Lab& lab, PanelState& p, float windowWidth, float windowHeight,
               bool alwaysScrollbar) {
    const bool fills = lab.panelFillsWindow();
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
    if (alwaysScrollbar) flags |= ImGuiWindowFlags_AlwaysVerticalScrollbar;
    ImGui::SetNextWindowPos(ImVec2(windowWidth, 0), ImGuiCond_Always, ImVec2(1, 0));
    if (fills) {
        flags |= ImGuiWindowFlags_NoResize;
        ImGui::SetNextWindowSize(ImVec2(windowWidth, windowHeight), ImGuiCond_Always);
    } else {
        // Resizable by its left edge (or the lower corner); always the window's height, and
        // never so wide that the scene disappears.
        const float minWidth = std::min(defaultPanelWidth(p.uiScale * 0.5f), windowWidth);
        const float maxWidth = std::max(minWidth, windowWidth - 64.0f);
        ImGui::SetNextWindowSizeConstraints(ImVec2(minWidth, windowHeight),
                                            ImVec2(maxWidth, windowHeight));
        if (p.width <= 0.0f || p.resetWidth) {
            p.width = std::clamp(p.width > 0.0f ? p.width : defaultPanelWidth(p.uiScale), minWidth,
                                 maxWidth);
            p.resetWidth = false;
            ImGui::SetNextWindowSize(ImVec2(p.width, windowHeight), ImGuiCond_Always);
        }
    }
    // "###panel": the same ImGui window (size, scroll) whatever language the title is in.
    ImGui::Begin((lab.title() + "###panel").c_str(), nullptr, flags);
    if (!fills) p.width = ImGui::GetWindowWidth();

    if (p.measureFps)
        ImGui::Text(tr("%.2f ms/frame (%.0f fps)"), p.frameMs,
                    p.frameMs > 0 ? 1000.0 / p.frameMs : 0.0);
    else
        ImGui::Text(tr("%.2f ms/frame"), p.frameMs);
    sameLineIfFits(tr("measure fps"));
    ImGui::Checkbox(tr("measure fps"), &p.measureFps);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", tr("Redraw continuously (one core busy); off, the window redraws "
                                   "only on a change"));
    if (ImGui::Button(tr("Screenshot (PNG)"))) p.screenshotRequested = true;
    if (!p.lastScreenshot.empty()) ImGui::TextWrapped("%s", p.lastScreenshot.c_str());

    // Half the width for a widget, half for its label (ImGui's default gives the label a third,
    // too little for the Russian labels).
    ImGui::PushItemWidth(std::floor(ImGui::GetContentRegionAvail().x * 0.5f));
    if (fills)
        lab.gui(); // the panel is the whole program (the launcher): no header above it
    else if (ImGui::CollapsingHeader(idLabel(tr("Parameters"), "params").c_str(),
                                     ImGuiTreeNodeFlags_DefaultOpen))
        lab.gui();
    ImGui::PopItemWidth();
    if (ImGui::CollapsingHeader(idLabel(tr("View"), "view").c_str())) {
        ImGui::TextUnformatted(tr("UI scale (Ctrl+= / Ctrl+-)"));
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::SliderFloat("##uiscale", &p.requestedScale, kMinUiScale, kMaxUiScale, "%.2f");
        p.scaleSliderActive =
            ImGui::IsItemActive(); // the shell applies the scale when it is let go
        if (!p.scaleNote.empty()) ImGui::TextWrapped("%s", p.scaleNote.c_str());
        if (!fills)
            ImGui::TextWrapped(tr("Drag the panel's left edge to make it wider (now %.0f px)."),
                               double(p.width));
        // The language switches at once: every string is looked up again in the next frame.
        ImGui::TextUnformatted(tr("Language"));
        for (const auto& code : languages()) {
            if (ImGui::RadioButton(languageName(code), language() == code)) setLanguage(code);
            ImGui::SameLine();
        }
        ImGui::NewLine();
    }
    // The launcher's keys are the numbers on its cards: its list starts closed.
    if (ImGui::CollapsingHeader(idLabel(tr("Keys"), "keys").c_str(),
                                fills ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
        std::vector<KeyHelp> keys = lab.keys();
        if (p.keysLikeShell && !fills) {
            keys.push_back({"h", tr("hide/show this panel")});
            keys.push_back({"+ -", tr("zoom (also the wheel)")});
            keys.push_back({tr("drag"), tr("rotate the scene")});
        }
        keys.push_back({"Ctrl+= Ctrl+-", tr("larger / smaller panel text")});
        keys.push_back({"Esc", tr("quit")});
        keyTable(keys);
    }
    ImGui::End();
}

} // namespace wb
