#pragma once
// The interface every lab implements. The shell (shell.h) owns the window or the
// OSMesa context, ImGui, input and timing; it calls the lab. The same draw()
// runs in the window and in the headless renderer.
#include <memory>
#include <string>
#include <vector>

namespace wb {

// Key codes passed to Lab::key(): plain ASCII characters, or kKeySpecial + a GLUT
// special-key code for arrows, page keys and function keys.
constexpr int kKeySpecial = 0x100;
constexpr int kKeyF1 = kKeySpecial + 1; // F1..F12 are kKeyF1 + 0..11
constexpr int kKeyLeft = kKeySpecial + 100;
constexpr int kKeyUp = kKeySpecial + 101;
constexpr int kKeyRight = kKeySpecial + 102;
constexpr int kKeyDown = kKeySpecial + 103;
constexpr int kKeyPageUp = kKeySpecial + 104;
constexpr int kKeyPageDown = kKeySpecial + 105;
constexpr int kKeyHome = kKeySpecial + 106;
constexpr int kKeyEnd = kKeySpecial + 107;

// What the shell tells draw() about the view; the lab decides how to use it.
struct View {
    int width = 800;       // framebuffer width, pixels
    int height = 600;      // framebuffer height, pixels
    float yaw = 0.0f;      // degrees about the vertical axis, from mouse drag
    float pitch = 0.0f;    // degrees about the horizontal axis, from mouse drag
    float zoom = 1.0f;     // > 0; 1 is the lab's default framing, wheel and +/- scale by 1.1
    bool headless = false; // true when drawing into OSMesa for a PNG
    double time =
        0.0; // seconds since start (0 in headless renders); frames come on change only, see busy()
    // In a window: true when the user's input waits for the shell (a key, a click or the wheel,
    // a resize, a drag's motion). A lab working inside draw() (worksInDraw) ends its slice
    // early then, so the input is answered within a short part of the slice. Null headless.
    bool (*inputWaiting)() = nullptr;
};

// One line of the "Keys:" list shown in the panel and in --help.
struct KeyHelp {
    std::string key;  // as the user types it, e.g. "1", "r", "Left"
    std::string what; // what it does, one short phrase
};

// A lab-specific command-line option such as --scene FILE.
struct OptionHelp {
    std::string name;     // without the dashes, e.g. "scene"
    std::string argument; // placeholder of its value, e.g. "FILE"; empty for a flag
    std::string what;     // one short phrase
};

class Lab {
  public:
    virtual ~Lab() = default;
    virtual std::string title() const = 0;         // e.g. "Lab 01 - affine maps"
    virtual std::vector<KeyHelp> keys() const = 0; // every key the lab reacts to
    virtual std::vector<OptionHelp> options() const { return {}; }
    // Called before init() for each lab option given; return false and set error to reject it.
    virtual bool setOption(const std::string& name, const std::string& value, std::string& error) {
        (void)value;
        error = "unknown option --" + name;
        return false;
    }
    virtual void init() {} // a GL context is current
    virtual void draw(const View& view) = 0;
    virtual bool key(int key) = 0; // true when the key was used
    // Mouse click in window pixels (y down); true when the lab used it (no drag-rotate then).
    virtual bool click(int x, int y, const View& view) {
        (void)x, (void)y, (void)view;
        return false;
    }
    virtual void gui() {} // ImGui widgets for the lab's parameters
    // The colour behind the scene: a scene area taller than 4:3 gets the scene at its bottom
    // (shell: sceneViewHeight) and the band above it in this colour, so the picture does not
    // end in a black edge where a lab draws only its view (lab 07's traced image).
    virtual void background(float& r, float& g, float& b) const { r = g = b = 0.0f; }
    // True when the panel is the whole user interface (the launcher): it fills the window.
    virtual bool panelFillsWindow() const { return false; }
    // True while the picture changes without input (work in the background, an animation):
    // headless renders call draw() until it is false; the window redraws while it is true, at
    // most at 30 Hz and slower when frames are dear (they take <= 10% of the time, at least
    // 4 Hz: shell_window.cpp), and otherwise only on input (an idle lab uses no CPU).
    virtual bool busy() const { return false; }
    // True while busy() work is done inside draw() itself (lab 08's GL hemicube rows need the
    // GL thread): the window then draws the next frame at once, instead of pacing its progress
    // frames to leave the cores to worker threads.
    virtual bool worksInDraw() const { return false; }
    // While busy() (not in draw()): asked every ~10 ms between the paced progress frames; true
    // draws a frame now (lab 08: its preview picture is ready). Called on the GLUT thread.
    virtual bool frameWanted() { return false; }
    // While > 0 (e.g. the exercise mode watching its file), the window calls poll() this often
    // when idle, and redraws only when poll() returns true; 0: never.
    virtual int pollMs() const { return 0; }
    virtual bool poll() { return false; }
    // Headless: true when the render must not be written (e.g. NaN pixels drawn black would
    // pass for a fine picture); the lab has said why on stderr. The shell writes no image
    // and exits 1.
    virtual bool headlessFailed() const { return false; }
};

using LabFactory = std::unique_ptr<Lab> (*)();

} // namespace wb
