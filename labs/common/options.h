#pragma once
// Command-line parsing shared by every lab executable; pure code, unit-tested.
#include "lab.h"

#include <string>
#include <utility>
#include <vector>

namespace wb {

struct ShellOptions {
    bool headless = false;    // --headless: render with OSMesa to --out and exit
    bool help = false;        // --help
    std::string out;          // --out FILE.png (required with --headless)
    int width = 800;          // --size WxH
    int height = 600;
    std::string keys;         // --keys "1g{left}": replayed before drawing
    std::string root;         // --root DIR: asset/shader root (else WORKBENCH_ROOT, else build-time)
    int frames = 0;           // --frames N: windowed smoke run, quit after N frames (0 = run until Esc)
    std::string screenshot;   // --screenshot FILE.png: windowed, save the last frame before quitting
    bool smoke = false;       // --smoke: windowed, press every one-character key of the lab twice, one press per frame
    std::vector<std::pair<std::string, std::string>> labOptions; // the lab's own --name value pairs
};

// Parses argv; returns false with a message naming the problem on bad input.
bool parseOptions(int argc, const char* const* argv, const std::vector<OptionHelp>& labOptions,
                  ShellOptions& out, std::string& error);

// Splits a --keys string into key codes: characters stand for themselves, and
// {left} {right} {up} {down} {pgup} {pgdn} {home} {end} {f1}..{f12} {esc} {space} {{ name the others.
bool parseKeys(const std::string& keys, std::vector<int>& codes, std::string& error);

// The --help text: usage, shell flags, the lab's options and its keys.
std::string usageText(const std::string& program, const Lab& lab);

} // namespace wb
