#include "panel.h"

#include "options.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
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

bool isFile(const char* path) {
    struct stat st {};
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
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
    std::string message;
    ImFontConfig config;
    config.OversampleH = 2; // sharper glyph edges at fractional positions
    const float pixels = std::round(kFontPixels * scale);
    if (isFile(kSansPath) && io.Fonts->AddFontFromFileTTF(kSansPath, pixels, &config)) {
        if (isFile(kMonoPath)) g_mono = io.Fonts->AddFontFromFileTTF(kMonoPath, pixels, &config);
    } else {
        message = std::string(kSansPath) +
                  " not found (Debian package fonts-dejavu-core): using ImGui's built-in font";
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

ImFont* panelMonoFont() {
    return g_mono ? g_mono : ImGui::GetFont();
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
    ImGui::Begin(lab.title().c_str(), nullptr, flags);
    if (!fills) p.width = ImGui::GetWindowWidth();

    if (p.measureFps)
        ImGui::Text("%.2f ms/frame (%.0f fps)", p.frameMs,
                    p.frameMs > 0 ? 1000.0 / p.frameMs : 0.0);
    else
        ImGui::Text("%.2f ms/frame", p.frameMs);
    ImGui::SameLine();
    ImGui::Checkbox("measure fps", &p.measureFps);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Redraw continuously (one core busy); off, the window redraws only on a change");
    if (ImGui::Button("Screenshot (PNG)")) p.screenshotRequested = true;
    if (!p.lastScreenshot.empty()) ImGui::TextWrapped("%s", p.lastScreenshot.c_str());

    if (fills)
        lab.gui(); // the panel is the whole program (the launcher): no header above it
    else if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen))
        lab.gui();
    if (ImGui::CollapsingHeader("View")) {
        ImGui::TextUnformatted("UI scale (Ctrl+= / Ctrl+-)");
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::SliderFloat("##uiscale", &p.requestedScale, kMinUiScale, kMaxUiScale, "%.2f");
        p.scaleSliderActive =
            ImGui::IsItemActive(); // the shell applies the scale when it is let go
        if (!p.scaleNote.empty()) ImGui::TextWrapped("%s", p.scaleNote.c_str());
        if (!fills)
            ImGui::TextWrapped("Drag the panel's left edge to make it wider (now %.0f px).",
                               p.width);
    }
    // The launcher's keys are the numbers on its cards: its list starts closed.
    if (ImGui::CollapsingHeader("Keys", fills ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
        std::vector<KeyHelp> keys = lab.keys();
        if (p.keysLikeShell && !fills) {
            keys.push_back({"h", "hide/show this panel"});
            keys.push_back({"+ -", "zoom (also the wheel)"});
            keys.push_back({"drag", "rotate the scene"});
        }
        keys.push_back({"Ctrl+= Ctrl+-", "larger / smaller panel text"});
        keys.push_back({"Esc", "quit"});
        keyTable(keys);
    }
    ImGui::End();
}

} // namespace wb
