#pragma once
// The lab shell: runs a lab in a GLUT window with an ImGui panel, or headless
// through OSMesa (--headless --out FILE.png). See DESIGN.md.
#include "core/image.h"
#include "lab.h"
#include "options.h"

#include <string>
#include <vector>

namespace wb {

// Entry point of every lab executable: parses argv and runs the lab. Returns the exit code.
int runLab(int argc, char** argv, LabFactory factory);

// Keys the shell keeps for itself (before the lab sees them): + - zoom and h (panel).
// Returns true when used. Esc is handled by each path (quit).
bool shellKey(int code, View& view, bool& panelVisible);

// Zoom is kept within kMinZoom..kMaxZoom (48 steps of 1.1 either way): unbounded, ~930
// presses of + overflow it to infinity and - can never bring it back.
constexpr float kMinZoom = 0.01f;
constexpr float kMaxZoom = 100.0f;
float clampZoom(float zoom);

// Checks before any work that `path` can be written (creating it, then removing it if it
// did not exist), so a long render never ends in "cannot write". False with a message naming it.
bool checkWritable(const std::string& path, std::string& error);

// Applies --root and the lab's own options; false with a message on a rejected option.
bool applyOptions(const ShellOptions& opts, Lab& lab, std::string& error);

// Headless path only: creates an OSMesa context of w×h, calls lab.init(), replays
// `keys` (shell keys included), draws until the lab is not busy, and reads the image.
bool renderHeadless(Lab& lab, int width, int height, const std::vector<int>& keys, Image& out,
                    std::string& error);

} // namespace wb
