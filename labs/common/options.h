#pragma once
// Command-line parsing shared by every lab executable; pure code, unit-tested.
#include "lab.h"

#include <string>
#include <utility>
#include <vector>

namespace wb {

// Default --size of the headless image (a window without --size fits the screen: fitWindow).
constexpr int kDefaultWidth = 800;
constexpr int kDefaultHeight = 600;
// The panel's default width at --ui-scale 1, window pixels; it scales with the UI and can be
// dragged.
constexpr int kPanelWidth = 420;
// --ui-scale range: 0.5 is the smallest legible text, 4 fills a 1280-px projector with the panel.
constexpr float kMinUiScale = 0.5f;
constexpr float kMaxUiScale = 4.0f;

struct ShellOptions {
    bool headless = false;     // --headless: render with OSMesa to --out and exit
    bool help = false;         // --help
    std::string out;           // --out FILE.png (required with --headless)
    int width = kDefaultWidth; // --size WxH: headless image, or the scene part of the window
    int height = kDefaultHeight;
    std::string keys; // --keys "1g{left}": replayed before drawing
    std::string root; // --root DIR: asset/shader root (else WORKBENCH_ROOT, else build-time)
    int frames = 0;   // --frames N: windowed smoke run, quit after N frames (0 = run until Esc)
    std::string screenshot; // --screenshot FILE.png: windowed, save the last frame before quitting
    bool smoke = false;   // --smoke: windowed, press every one-character key of the lab twice, one
                          // press per frame
    float uiScale = 1.0f; // --ui-scale X: panel text and widgets X times the normal size
    bool checkPanel = false; // --check-panel: headless, lay the panel out and fail on clipped text
    std::string lang;       // --lang ru|en|qps: the language (else the environment's, else English)
    bool sizeGiven = false; // --size was on the command line (else the window fits the screen)
    std::vector<std::pair<std::string, std::string>> labOptions; // the lab's own --name value pairs
};

// The screens the panel check lays the panel out for (a classroom's projectors and laptops).
struct ScreenSize {
    int width, height;
};
constexpr ScreenSize kCheckedScreens[] = {{1024, 768}, {1280, 800}, {1600, 1000}, {1920, 1080}};
// Room left on a screen for window decorations and a taskbar, pixels.
constexpr int kScreenMarginX = 20;
constexpr int kScreenMarginY = 80;
// The panel takes at most this share of the window's width; the scene keeps the rest.
constexpr float kMaxPanelShare = 0.55f;
// The scene is drawn no narrower than this aspect (the labs frame their subject for 800x600):
// in a narrower scene area it is drawn as wide as the area and this much high, at the bottom.
constexpr float kMinSceneAspect = 4.0f / 3.0f;

// A window that fits its screen: the size it opens at, the panel's width and the UI scale
// actually used (the requested one, or smaller when a panel that large would not leave the
// scene kMaxPanelShare of the window: the panel's layout needs kPanelWidth x scale pixels).
struct WindowFit {
    int width = 0, height = 0; // the whole window
    int panelWidth = 0;        // 0 for a lab whose panel fills the window
    float uiScale = 1.0f;
};
// Without --size the window is the screen's height less kScreenMarginY (the panel shows the
// most lines it can, the scene its largest 4:3) and as wide as the scene at 4:3 plus the panel,
// capped by the screen's width less kScreenMarginX; scene and panel share that width. An
// explicit --size asks for that scene size (capped the same way). The launcher (its panel
// fills the window) opens at 800x600 x the UI scale, capped the same way: its cards do not grow.
WindowFit fitWindow(const ShellOptions& opts, bool panelFillsWindow, int screenWidth,
                    int screenHeight, float uiScale);

// The largest UI scale whose panel fits a window `width` pixels wide (see WindowFit).
float maxUiScaleFor(int width);

// The part of a sceneWidth x sceneHeight area the scene is drawn in: its whole width and at
// most the height kMinSceneAspect allows (see kMinSceneAspect).
int sceneViewHeight(int sceneWidth, int sceneHeight);

// Parses argv with CLI11; returns false with a message naming the problem on bad input.
bool parseOptions(int argc, const char* const* argv, const std::vector<OptionHelp>& labOptions,
                  ShellOptions& out, std::string& error);

// Sets the language from --lang (or --lang=X) if argv has it, before anything else is parsed, so
// that even the messages about bad flags are in the user's language. False for a code we have no
// catalogue for (the language is then the environment's, and parseOptions says so).
bool applyLanguageFlag(int argc, const char* const* argv);

// Splits a --keys string into key codes: characters stand for themselves, and
// {left} {right} {up} {down} {pgup} {pgdn} {home} {end} {f1}..{f12} {esc} {space} {{ name the
// others.
bool parseKeys(const std::string& keys, std::vector<int>& codes, std::string& error);

// The --help text: usage, shell flags, the lab's options and its keys.
std::string usageText(const std::string& program, const Lab& lab);

} // namespace wb
