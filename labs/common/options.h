#pragma once
// Command-line parsing shared by every lab executable; pure code, unit-tested.
#include "lab.h"

#include <string>
#include <utility>
#include <vector>

namespace wb {

// Default --size: the headless image, or in a window the scene beside the panel.
constexpr int kDefaultWidth = 800;
constexpr int kDefaultHeight = 600;
// The panel's default width at --ui-scale 1, window pixels; it scales with the UI and can be dragged.
constexpr int kPanelWidth = 420;
// --ui-scale range: 0.5 is the smallest legible text, 4 fills a 1280-px projector with the panel.
constexpr float kMinUiScale = 0.5f;
constexpr float kMaxUiScale = 4.0f;

struct ShellOptions {
    bool headless = false;    // --headless: render with OSMesa to --out and exit
    bool help = false;        // --help
    std::string out;          // --out FILE.png (required with --headless)
    int width = kDefaultWidth;   // --size WxH: headless image, or the scene part of the window
    int height = kDefaultHeight;
    std::string keys;         // --keys "1g{left}": replayed before drawing
    std::string root;         // --root DIR: asset/shader root (else WORKBENCH_ROOT, else build-time)
    int frames = 0;           // --frames N: windowed smoke run, quit after N frames (0 = run until Esc)
    std::string screenshot;   // --screenshot FILE.png: windowed, save the last frame before quitting
    bool smoke = false;       // --smoke: windowed, press every one-character key of the lab twice, one press per frame
    float uiScale = 1.0f;     // --ui-scale X: panel text and widgets X times the normal size
    bool checkPanel = false;  // --check-panel: headless, lay the panel out and fail on clipped text
    std::string lang;         // --lang ru|en|qps: the language (else the environment's, else English)
    std::vector<std::pair<std::string, std::string>> labOptions; // the lab's own --name value pairs
};

// The window's size with the panel beside a scene of opts.width x opts.height (what --help states).
int windowWidth(const ShellOptions& opts, bool panelFillsWindow);

// Parses argv with CLI11; returns false with a message naming the problem on bad input.
bool parseOptions(int argc, const char* const* argv, const std::vector<OptionHelp>& labOptions,
                  ShellOptions& out, std::string& error);

// Sets the language from --lang (or --lang=X) if argv has it, before anything else is parsed, so
// that even the messages about bad flags are in the user's language. False for a code we have no
// catalogue for (the language is then the environment's, and parseOptions says so).
bool applyLanguageFlag(int argc, const char* const* argv);

// Splits a --keys string into key codes: characters stand for themselves, and
// {left} {right} {up} {down} {pgup} {pgdn} {home} {end} {f1}..{f12} {esc} {space} {{ name the others.
bool parseKeys(const std::string& keys, std::vector<int>& codes, std::string& error);

// The --help text: usage, shell flags, the lab's options and its keys.
std::string usageText(const std::string& program, const Lab& lab);

} // namespace wb
