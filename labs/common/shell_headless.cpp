// The headless path of the shell: OSMesa, no window, no GLUT, no ImGui drawing.
#include "gl_util.h"
#include "headless_context.h"
#include "panel.h"
#include "panel_check.h"
#include "shell.h"

#include "core/i18n.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

namespace wb {

bool renderHeadless(Lab& lab, int width, int height, const std::vector<int>& keys, Image& out,
                    std::string& error) {
    const HeadlessContext context(width, height);
    if (!context.ok()) {
        error = context.error();
        return false;
    }
    View view;
    view.width = width;
    view.height = height;
    view.headless = true;
    bool panel = false;
    glViewport(0, 0, width, height);
    lab.init();
    for (int k : keys)
        if (!shellKey(k, view, panel)) lab.key(k);
    // A lab that works in the background (lab 7's tracer) is drawn until it is done.
    do {
        glViewport(0, 0, width, height);
        lab.draw(view);
    } while (lab.busy());
    glFinish();
    out = readFramebuffer(width, height);
    return true;
}

namespace {

// --check-panel: the lab in an OSMesa context of the scene's size, its panel laid out by
// ImGui (no GL drawing) as a window opened on each screen of kCheckedScreens has it (the
// width, panel width and UI scale fitWindow gives there for --ui-scale), once after --keys
// and once after each one-letter key of the lab; every clipped text is printed. Exit 0 when
// none.
int checkPanel(const char* program, Lab& lab, const ShellOptions& opts,
               const std::vector<int>& keys) {
    const int width = opts.width, height = opts.height;
    const HeadlessContext context(width, height);
    if (!context.ok()) {
        std::fprintf(stderr, tr("%s: OSMesa: cannot create a %dx%d context\n"), program, width,
                     height);
        return 1;
    }
    View view;
    view.width = width;
    view.height = height;
    view.headless = true;
    bool panelShown = true;
    lab.init();
    for (int k : keys)
        if (!shellKey(k, view, panelShown)) lab.key(k);

    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    std::vector<std::string> reported; // each text once, with the first state it was seen in
    int clipped = 0, untranslated = 0;
    // --lang qps: every text must have come through the catalogue (panel_check.h).
    const bool pseudo = language() == "qps";
    // The window a user opens (default scene size); --size only sizes the context here.
    ShellOptions asOpened;
    asOpened.uiScale = opts.uiScale;
    for (const ScreenSize& screen : kCheckedScreens) {
        const WindowFit fit =
            fitWindow(asOpened, lab.panelFillsWindow(), screen.width, screen.height, opts.uiScale);
        const std::string fontMessage = setupImGuiFonts(fit.uiScale);
        if (!fontMessage.empty() && &screen == kCheckedScreens)
            std::fprintf(stderr, "%s: %s\n", program, fontMessage.c_str());
        unsigned char* pixels = nullptr;
        int tw = 0, th = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &tw, &th); // builds the atlas; no texture needed
        const float windowW = float(fit.width);
        // Tall enough that no widget is scrolled out of view (ImGui draws only what is
        // visible); the scrollbar's room is kept as in the real, shorter window.
        const float tall = 20000.0f;
        io.DisplaySize = ImVec2(windowW, tall);
        PanelState panel;
        panel.uiScale = panel.requestedScale = fit.uiScale;
        panel.width = float(fit.panelWidth);
        panel.resetWidth = true;
        const std::string where =
            trf("on a %dx%d screen (window %dx%d, UI scale %.2f)", screen.width, screen.height,
                fit.width, fit.height, double(fit.uiScale));
        auto check = [&](const std::string& state) {
            glViewport(0, 0, width, height);
            lab.draw(view);
            // Three frames: the first sizes the window, the second adds the scrollbar, the
            // third is checked.
            for (int frame = 0; frame < 3; ++frame) {
                io.DeltaTime = 1.0f / 60.0f;
                ImGui::NewFrame();
                if (frame == 2) panelcheck::start();
                drawPanel(lab, panel, windowW, tall, true);
                ImGui::Render();
            }
            for (const auto& c : panelcheck::stop()) {
                if (std::find(reported.begin(), reported.end(), c.text) != reported.end()) continue;
                reported.push_back(c.text);
                std::printf(tr("%s: clipped %s: \"%s\" runs %.0f px past the edge (%s) %s\n"),
                            program, state.c_str(), c.text.c_str(), double(c.overflow),
                            c.window.c_str(), where.c_str());
                ++clipped;
            }
            for (const auto& text :
                 pseudo ? panelcheck::drawnTexts() : std::vector<std::string>{}) {
                const std::string words = panelcheck::untranslatedWords(text);
                if (words.empty() ||
                    std::find(reported.begin(), reported.end(), text) != reported.end())
                    continue;
                reported.push_back(text);
                std::printf(tr("%s: untranslated %s: \"%s\" (English: %s)\n"), program,
                            state.c_str(), text.c_str(), words.c_str());
                ++untranslated;
            }
        };
        check(keys.empty() ? "at start" : "after --keys");
        for (const auto& k : lab.keys()) {
            if (k.key.size() != 1) continue;
            const int code = static_cast<unsigned char>(k.key[0]);
            if (!shellKey(code, view, panelShown)) lab.key(code);
            check("after key '" + k.key + "'");
        }
        std::printf(tr("%s: panel check %s: done\n"), program, where.c_str());
    }
    ImGui::DestroyContext(); // the GL context finishes and goes at the end of the scope
    std::printf(tr("%s: panel check on %zu screen sizes, UI scale %.2f asked: %d clipped text%s "
                   "(language %s)"),
                program, std::size(kCheckedScreens), double(opts.uiScale), clipped,
                clipped == 1 ? "" : "s", language().c_str());
    if (pseudo) std::printf(tr(", %d untranslated"), untranslated);
    std::printf("\n");
    return clipped || untranslated ? 1 : 0;
}

} // namespace

int runLab(int argc, char** argv, LabFactory factory) {
    applyLanguageFlag(argc, argv); // first: every message below is in the user's language
    auto lab = factory();
    ShellOptions opts;
    std::string error;
    if (!parseOptions(argc, argv, lab->options(), opts, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 2;
    }
    if (opts.help) {
        std::fputs(usageText(argv[0], *lab).c_str(), stdout);
        return 0;
    }
    if (opts.checkPanel) {
        std::vector<int> keys;
        if (!parseKeys(opts.keys, keys, error) || !applyOptions(opts, *lab, error)) {
            std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
            return 2;
        }
        return checkPanel(argv[0], *lab, opts, keys);
    }
    if (opts.out.empty()) {
        std::fprintf(stderr, tr("%s: the headless renderer needs --out FILE.png\n"), argv[0]);
        return 2;
    }
    std::vector<int> keys;
    if (!parseKeys(opts.keys, keys, error) || !checkWritable(opts.out, error) ||
        !applyOptions(opts, *lab, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 2;
    }
    Image img;
    if (!renderHeadless(*lab, opts.width, opts.height, keys, img, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 1;
    }
    if (lab->headlessFailed()) {
        std::fprintf(stderr, tr("%s: %s not written\n"), argv[0], opts.out.c_str());
        return 1;
    }
    if (!writePng(opts.out, img, &error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 1;
    }
    return 0;
}

} // namespace wb
