// The windowed path of the shell: freeglut window, GLEW, Dear ImGui panel.
// GLUT events go to ImGui first and are dropped when ImGui wants them
// (as in Dear ImGui's GLUT + OpenGL2 example).
#include "gl_util.h"
#include "imgui_input.h"
#include "panel.h"
#include "shell.h"
#include "x_keyboard.h"

#include "core/i18n.h"

#include "core/i18n.h"

#include <GL/freeglut.h>
#include <GL/glx.h>
#include <imgui.h>
#include <imgui_impl_glut.h>
#include <imgui_impl_opengl2.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <unistd.h>

namespace wb {
namespace {

struct WindowState {
    std::unique_ptr<Lab> lab;
    ShellOptions opts;
    std::string program;
    View view; // the scene's part of the window (left of the panel)
    int windowWidth = kDefaultWidth + kPanelWidth; // whole window, pixels
    int windowHeight = kDefaultHeight;
    int screenWidth = 0, screenHeight = 0; // GLUT's screen: the window is fitted to it
    bool panelVisible = true;
    PanelState panel; // the panel's own settings (width, UI scale, measure fps)
    ImGuiInput input; // GLUT events queued for ImGui, see imgui_input.h
    int frame = 0;
    std::vector<int> smokeKeys; // --smoke: keys still to press, one per frame
    int settleFrames =
        0; // frames still to draw after an event (ImGui shows hover/press a frame late)
    bool timerPending = false;     // a glutTimerFunc redraw is on its way (busy lab)
    bool pollPending = false;      // a glutTimerFunc lab->poll() is on its way (Lab::pollMs)
    bool wantedPending = false;    // a glutTimerFunc asking lab->frameWanted() is on its way
    bool screenshotFailed = false; // --screenshot could not be written: exit 1
    bool dragging = false;         // left button down outside the panel
    bool moved = false;            // the drag moved far enough to be a rotation, not a click
    int downX = 0, downY = 0, lastX = 0, lastY = 0;
    XKeyboard xkb;          // key presses as X sees them: Cyrillic text, keys on any layout
    bool logKeys = false;   // WB_LOG_KEYS=1: print each lab key (the layout tests read it)
    bool drewFrame = false; // logKeys: the first frame's line is printed
    std::string language;   // the language the window title was last set in
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    // WB_FRAME_LOG=1: where a busy period's frames spent their time, printed when it ends.
    bool frameLog = false;
    double lastFrameMs = 0; // the last frame's time in display() (paces busy redraws)
    struct FrameStats {
        int frames = 0;
        double panel = 0, lab = 0, imgui = 0, swap = 0, total = 0; // ms
    } stats;
};
WindowState* g = nullptr;

// While a lab works in the background (a trace, a radiosity run), its progress is shown at
// most this often, and at least this often...
constexpr double kBusyRedrawMs = 33, kBusyRedrawMaxMs = 250;
// ...with the frames taking at most this share of the time (of the wall clock: llvmpipe
// rasterizes on two threads, so of the CPU up to twice that): a frame here is drawn by Mesa's
// llvmpipe on the same two cores as the lab's worker threads (lab 08's Cornell box: ~30-50 ms
// a frame under load, mostly the rasterization waited for in glutSwapBuffers), so 30 frames a
// second took a third to a half of the machine from the run (docs/bench/radiosity.md).
constexpr double kBusyDrawShare = 0.1;

int panelWidth() {
    if (g->lab->panelFillsWindow()) return g->windowWidth;
    float w = g->panel.width > 0 ? g->panel.width : defaultPanelWidth(g->panel.uiScale);
    return std::min(int(w + 0.5f), g->windowWidth - 1);
}

void layout() {
    int sceneWidth = g->panelVisible ? g->windowWidth - panelWidth() : g->windowWidth;
    g->view.width = sceneWidth > 1 ? sceneWidth : 1;
    // A narrow, tall scene area (a wide panel, a tall screen) gets the scene at the labs'
    // 4:3 at its bottom: they frame the subject by its height, so a narrower view cuts it.
    g->view.height = sceneViewHeight(g->view.width, g->windowHeight > 1 ? g->windowHeight : 1);
}

void quit() {
    glutLeaveMainLoop();
}

// Something changed: draw this frame and a couple more for ImGui to catch up.
void changed() {
    g->settleFrames = 3;
    glutPostRedisplay();
}

void setUiScale(float scale) {
    g->panel.requestedScale = scale;
}

void labKey(int code) {
    if (g->logKeys) {
        std::fprintf(stderr, "lab key %d\n", code); // read by tests/shell/russian_keys.sh
        std::fflush(stderr);
    }
    if (code == 27) return quit();
    // A lab whose panel is its whole window (the launcher) has no scene to zoom or panel to hide.
    if (g->lab->panelFillsWindow() || !shellKey(code, g->view, g->panelVisible)) g->lab->key(code);
    changed();
}

std::string timestampedName() {
    char buf[64];
    std::time_t t = std::time(nullptr);
    std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&t));
    std::string name = g->program;
    auto slash = name.rfind('/');
    if (slash != std::string::npos) name = name.substr(slash + 1);
    return name + "-" + buf + ".png";
}

bool saveScreenshot(const std::string& path) {
    Image img = readFramebuffer(g->windowWidth, g->windowHeight);
    std::string error;
    const bool ok = writePng(path, img, &error);
    g->panel.lastScreenshot = ok ? "saved " + path : error;
    std::fprintf(stderr, "%s\n", g->panel.lastScreenshot.c_str());
    return ok;
}

// A new UI scale: fonts rebuilt at the new size (sharp, not stretched), style scaled, the
// panel's width scaled with it. Between frames only.
// Ctrl+= and the slider do what --ui-scale does: the window is fitted to the screen again
// for the new scale (fitWindow), so the scene keeps its share and the panel its lines; a
// scale whose panel would not fit is lowered to the largest that does, and the panel says so.
void applyUiScale() {
    PanelState& p = g->panel;
    if (p.scaleSliderActive || p.requestedScale == p.uiScale) return;
    const bool fills = g->lab->panelFillsWindow();
    const WindowFit fit =
        fitWindow(g->opts, fills, g->screenWidth, g->screenHeight, p.requestedScale);
    p.scaleNote =
        fit.uiScale < p.requestedScale
            ? trf("UI scale %.2f does not fit beside the scene on this %dx%d screen: "
                  "%.2f is the largest that does.",
                  double(p.requestedScale), g->screenWidth, g->screenHeight, double(fit.uiScale))
            : "";
    p.requestedScale = fit.uiScale;
    if (fit.uiScale == p.uiScale) return;
    p.uiScale = fit.uiScale;
    ImGui_ImplOpenGL2_DestroyFontsTexture(); // re-created by the next ImGui_ImplOpenGL2_NewFrame
    const std::string message = setupImGuiFonts(p.uiScale);
    if (!message.empty()) std::fprintf(stderr, "%s: %s\n", g->program.c_str(), message.c_str());
    p.width = float(fit.panelWidth);
    p.resetWidth = true;
    if (fit.width != g->windowWidth || fit.height != g->windowHeight)
        glutReshapeWindow(fit.width, fit.height);
}

// ImGui's mouse cursor (resize arrows on the panel's edge) as GLUT's.
void updateCursor() {
    int cursor = GLUT_CURSOR_LEFT_ARROW;
    switch (ImGui::GetMouseCursor()) {
    case ImGuiMouseCursor_ResizeEW:
        cursor = GLUT_CURSOR_LEFT_RIGHT;
        break;
    case ImGuiMouseCursor_ResizeNS:
        cursor = GLUT_CURSOR_UP_DOWN;
        break;
    case ImGuiMouseCursor_ResizeNWSE:
        cursor = GLUT_CURSOR_BOTTOM_RIGHT_CORNER;
        break;
    case ImGuiMouseCursor_ResizeNESW:
        cursor = GLUT_CURSOR_BOTTOM_LEFT_CORNER;
        break;
    case ImGuiMouseCursor_TextInput:
        cursor = GLUT_CURSOR_TEXT;
        break;
    case ImGuiMouseCursor_Hand:
        cursor = GLUT_CURSOR_INFO;
        break;
    default:
        break;
    }
    static int current = -1;
    if (cursor != current) glutSetCursor(current = cursor);
}

// View::inputWaiting: looks through GLUT's X connection (the queue and what the server has
// sent) for input a user waits on, without taking any event off it; GLUT handles them after
// the frame. Motion without a button held (hover) does not count: the panel's hover can wait
// for the next paced frame, and a pointer resting on the window would cut every slice short.
Bool isWaitedInput(Display*, XEvent* e, XPointer found) {
    switch (e->type) {
    case KeyPress:
    case ButtonPress:
    case ButtonRelease:
    case ConfigureNotify:
    case ClientMessage: // the window manager's close
        *reinterpret_cast<bool*>(found) = true;
        break;
    case MotionNotify:
        if (e->xmotion.state & (Button1Mask | Button2Mask | Button3Mask))
            *reinterpret_cast<bool*>(found) = true;
        break;
    default:
        break;
    }
    return False; // nothing is removed
}

bool inputWaiting() {
    Display* dpy = glXGetCurrentDisplay();
    if (!dpy) return false;
    bool found = false;
    XEvent e;
    XCheckIfEvent(dpy, &e, isWaitedInput, reinterpret_cast<XPointer>(&found));
    return found;
}

void busyTimer(int) {
    g->timerPending = false;
    glutPostRedisplay();
}

void scheduleNextFrame(bool busyBefore = false);

// Between a busy lab's paced frames (up to 250 ms apart): a picture it wants shown at once
// (Lab::frameWanted, e.g. lab 08's first usable picture) is drawn within ~10 ms.
constexpr unsigned kWantedPollMs = 10;
void wantedTimer(int) {
    g->wantedPending = false;
    if (!g->lab->busy() || g->lab->worksInDraw()) return; // drawn anyway
    if (g->lab->frameWanted()) {
        glutPostRedisplay();
        return;
    }
    g->wantedPending = true;
    glutTimerFunc(kWantedPollMs, wantedTimer, 0);
}

// Lab::pollMs(): the lab looks (e.g. at a file) without a redraw, and asks for one on change.
void pollTimer(int) {
    g->pollPending = false;
    if (g->lab->poll())
        glutPostRedisplay();
    else
        scheduleNextFrame();
}

// Redraw on change only: input (and the frames ImGui needs after it), a queued event, a
// lab working in the background, --frames / --smoke runs, or "measure fps".
// busyBefore: the lab was busy when this frame started; its work may have ended while the
// frame was drawn, so the frame may show a state older than the end: one more frame then.
void scheduleNextFrame(bool busyBefore) {
    const int pollMs = g->lab->pollMs(); // asked first: a lab may stop counting polls as busy
    if (busyBefore && !g->lab->busy()) {
        glutPostRedisplay();
        return;
    }
    const bool continuous = g->panel.measureFps || g->opts.frames > 0 || !g->smokeKeys.empty();
    if (continuous || g->input.pending() || g->settleFrames > 0 || ImGui::GetIO().WantTextInput) {
        if (g->settleFrames > 0) --g->settleFrames;
        glutPostRedisplay();
    } else if (g->lab->busy() && g->lab->worksInDraw()) {
        glutPostRedisplay(); // the work is in the next draw(): no idle wait before it
    } else if (g->lab->busy()) {
        if (!g->wantedPending) {
            g->wantedPending = true;
            glutTimerFunc(kWantedPollMs, wantedTimer, 0);
        }
        if (!g->timerPending) {
            g->timerPending = true;
            const double wait = g->lastFrameMs * (1.0 - kBusyDrawShare) / kBusyDrawShare;
            glutTimerFunc(unsigned(std::clamp(wait, kBusyRedrawMs, kBusyRedrawMaxMs)), busyTimer,
                          0);
        }
    } else if (pollMs > 0 && !g->lab->busy() && !g->pollPending) {
        g->pollPending = true;
        glutTimerFunc(unsigned(pollMs), pollTimer, 0);
    }
}

void display() {
    auto t0 = std::chrono::steady_clock::now();
    const bool busyBefore = g->lab->busy();
    if (!g->smokeKeys.empty()) { // as if typed, through the same path as real key presses
        labKey(g->smokeKeys.front());
        g->smokeKeys.erase(g->smokeKeys.begin());
    }
    applyUiScale();
    if (g->language != language()) { // switched in the panel (View > Language)
        g->language = language();
        glutSetWindowTitle(g->lab->title().c_str());
    }
    g->input.applyToFrame(ImGui::GetIO());
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGLUT_NewFrame();
    auto tPanel = std::chrono::steady_clock::now();
    if (g->panelVisible) {
        const float before = g->panel.width;
        drawPanel(*g->lab, g->panel, float(g->windowWidth), float(g->windowHeight));
        if (g->panel.width != before)
            g->settleFrames = std::max(g->settleFrames, 1); // dragged: scene follows
    }
    ImGui::Render();
    updateCursor();

    g->view.time = std::chrono::duration<double>(t0 - g->start).count();
    layout();
    // The whole window starts black: a lab may clear only its own part (lab 07 draws its
    // traced image), and the panel's background is translucent, so earlier frames would show
    // through it.
    glPushAttrib(GL_COLOR_BUFFER_BIT | GL_SCISSOR_BIT);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    if (g->view.height < g->windowHeight) { // the band above the scene: the lab's background
        float r = 0, gr = 0, b = 0;
        g->lab->background(r, gr, b);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, g->view.height, g->view.width, g->windowHeight - g->view.height);
        glClearColor(r, gr, b, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glPopAttrib();
    glViewport(0, 0, g->view.width, g->view.height);
    auto tLab = std::chrono::steady_clock::now();
    g->lab->draw(g->view);
    auto tImgui = std::chrono::steady_clock::now();
    // --frames counts on until every --smoke key has been pressed.
    bool lastFrame = g->opts.frames > 0 && g->frame + 1 >= g->opts.frames && g->smokeKeys.empty();
    if (g->panelVisible) {
        // The panel draws with its own GL state; keep the lab's.
        glViewport(0, 0, g->windowWidth, g->windowHeight);
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glUseProgram(0);
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        glPopAttrib();
    }
    // --screenshot and the button save what the user sees, panel included (`h` hides it).
    if (lastFrame && !g->opts.screenshot.empty() && !saveScreenshot(g->opts.screenshot))
        g->screenshotFailed = true;
    if (g->panel.screenshotRequested) {
        g->panel.screenshotRequested = false;
        saveScreenshot(timestampedName());
    }
    auto tSwap = std::chrono::steady_clock::now();
    glutSwapBuffers();
    if (g->logKeys && !g->drewFrame) {
        // russian_keys.sh types its keys after this line, not after a fixed sleep: on a loaded
        // machine a lab's first frame (shaders, meshes) can take longer than any sleep.
        std::fprintf(stderr, "shell first frame\n");
        std::fflush(stderr);
        g->drewFrame = true;
    }
    if (g->frameLog) {
        auto msBetween = [](auto a, auto b) {
            return std::chrono::duration<double, std::milli>(b - a).count();
        };
        auto& st = g->stats;
        const auto tEnd = std::chrono::steady_clock::now();
        if (busyBefore || g->lab->busy()) {
            ++st.frames;
            st.panel += msBetween(tPanel, tLab);
            st.lab += msBetween(tLab, tImgui);
            st.imgui += msBetween(tImgui, tSwap);
            st.swap += msBetween(tSwap, tEnd);
            st.total += msBetween(t0, tEnd);
        }
        if (st.frames > 0 && !g->lab->busy()) {
            std::fprintf(stderr,
                         "frames %d: %.0f ms (panel %.0f, lab %.0f, ImGui draw %.0f, swap %.0f)\n",
                         st.frames, st.total, st.panel, st.lab, st.imgui, st.swap);
            st = {};
        }
    }
    double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    // Smoothed while measuring (continuous frames); else the last frame alone, since frames
    // drawn on change are few and the first ones (shaders, meshes) are slow.
    g->panel.frameMs = g->panel.measureFps && g->frame > 0 ? 0.9 * g->panel.frameMs + 0.1 * ms : ms;
    g->lastFrameMs = ms;
    ++g->frame;
    if (lastFrame) return quit();
    scheduleNextFrame(busyBefore);
}

void reshape(int w, int h) {
    ImGui::GetIO().DisplaySize = ImVec2(float(w), float(h));
    g->windowWidth = w;
    g->windowHeight = h;
    layout();
    changed();
}

// Ctrl+= / Ctrl++ / Ctrl+- / Ctrl+0: the UI scale (GLUT gives '=' '+' '-' '0' with Ctrl down).
bool uiScaleKey(unsigned char c, int mods) {
    if (!(mods & GLUT_ACTIVE_CTRL)) return false;
    const int direction = (c == '=' || c == '+') ? 1 : c == '-' ? -1 : c == '0' ? 0 : 2;
    if (direction == 2) return false;
    setUiScale(stepUiScale(g->panel.uiScale, direction));
    return true;
}

// What the X reader does (x_keyboard.h): typed text to ImGui, lab keys to the lab unless a
// text field has the keyboard.
void xText(unsigned c) {
    g->input.character(c);
    changed();
}
void xLabKey(int c) {
    if (!ImGui::GetIO().WantCaptureKeyboard)
        labKey(c);
    else
        changed();
}

void keyboard(unsigned char c, int, int) {
    // The same press read from X first (and what came before it): its group decides. Under a
    // non-Latin layout the X reader sends the key the US layout has there; GLUT's character for
    // it ('.' where US has '/') would act a second time, or as another key.
    const bool latin = g->xkb.glutCharacter(xText, xLabKey);
    const int mods = glutGetModifiers();
    g->input.keyboard(c, true, mods);
    changed();
    if (uiScaleKey(c, mods)) return;
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    if (c >= 0x20 && c < 0x7f && !latin) return;
    labKey(c);
}

// Key presses read from X beside GLUT (x_keyboard.h): polled often enough to feel immediate
// (a wake-up every 20 ms costs no measurable CPU while idle).
constexpr unsigned kKeyPollMs = 20;

void pollKeys(int) {
    g->xkb.poll(xText, xLabKey);
    glutTimerFunc(kKeyPollMs, pollKeys, 0);
}

void keyboardUp(unsigned char c, int, int) {
    g->input.keyboard(c, false, glutGetModifiers());
    changed();
}

void special(int key, int, int) {
    g->input.special(key, true, glutGetModifiers());
    changed();
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    if (key >= GLUT_KEY_SHIFT_L && key <= GLUT_KEY_ALT_R)
        return; // modifiers alone are not lab keys
    labKey(kKeySpecial + key);
}

void specialUp(int key, int, int) {
    g->input.special(key, false, glutGetModifiers());
    changed();
}

void mouse(int button, int state, int x, int y) {
    g->input.mouse(button, state, x, y, glutGetModifiers());
    changed();
    if (ImGui::GetIO().WantCaptureMouse && !g->dragging) return;
    if (button != GLUT_LEFT_BUTTON) return;
    if (state == GLUT_DOWN) {
        g->dragging = true;
        g->moved = false;
        g->downX = g->lastX = x;
        g->downY = g->lastY = y;
    } else {
        // In the scene's coordinates: it is drawn at the bottom of its area (layout()).
        if (g->dragging && !g->moved)
            g->lab->click(x, y - (g->windowHeight - g->view.height), g->view);
        g->dragging = false;
    }
}

void motion(int x, int y) {
    g->input.motion(x, y);
    changed();
    if (!g->dragging) return;
    if (std::abs(x - g->downX) + std::abs(y - g->downY) > 3) g->moved = true;
    if (g->moved) {
        g->view.yaw += 0.5f * float(x - g->lastX);
        g->view.pitch += 0.5f * float(y - g->lastY);
    }
    g->lastX = x;
    g->lastY = y;
}

void passiveMotion(int x, int y) {
    g->input.motion(x, y);
    changed();
}

void wheel(int button, int dir, int x, int y) {
    (void)button;
    g->input.wheel(dir, x, y, glutGetModifiers());
    changed();
    if (ImGui::GetIO().WantCaptureMouse) return;
    g->view.zoom = clampZoom(g->view.zoom * (dir > 0 ? 1.1f : 1.0f / 1.1f));
}

// The headless renderer is the same lab compiled against OSMesa, installed next to us.
int execHeadless(char** argv) {
    char self[PATH_MAX] = {};
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) {
        std::fprintf(stderr, tr("%s: cannot find my own executable\n"), argv[0]);
        return 1;
    }
    std::string path = std::string(self, size_t(n)) + "-headless";
    execv(path.c_str(), argv);
    std::perror((path + ": cannot start the headless renderer").c_str());
    return 1;
}

} // namespace

int runLab(int argc, char** argv, LabFactory factory) {
    WindowState state;
    g = &state;
    applyLanguageFlag(argc, argv); // first: every message below is in the user's language
    state.lab = factory();
    state.program = argv[0];
    std::string error;
    if (!parseOptions(argc, argv, state.lab->options(), state.opts, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 2;
    }
    if (state.opts.help) {
        std::fputs(usageText(argv[0], *state.lab).c_str(), stdout);
        return 0;
    }
    // --check-panel lays the panel out for the screens a class uses, not this one: the same
    // headless check with or without a display.
    if (state.opts.headless || state.opts.checkPanel) return execHeadless(argv);
    const char* displayEnv = std::getenv("DISPLAY");
    if (!displayEnv || !*displayEnv) {
        std::fprintf(
            stderr,
            tr("%s: no display (DISPLAY is not set); render to a file with --headless --out "
               "FILE.png\n"),
            argv[0]);
        return 2;
    }
    std::vector<int> keys;
    if (!parseKeys(state.opts.keys, keys, error) ||
        (!state.opts.screenshot.empty() && !checkWritable(state.opts.screenshot, error)) ||
        !applyOptions(state.opts, *state.lab, error)) {
        std::fprintf(stderr, "%s: %s\n", argv[0], error.c_str());
        return 2;
    }

    glutInit(&argc, argv);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL);
    // The window is fitted to the screen it opens on (fitWindow: its height, a 4:3 scene beside
    // the panel); --size is the scene's size, the panel added beside it (as usageText says).
    // Labs that work inside draw() ask it whether to yield (View::inputWaiting).
    state.view.inputWaiting = inputWaiting;
    state.screenWidth = glutGet(GLUT_SCREEN_WIDTH);
    state.screenHeight = glutGet(GLUT_SCREEN_HEIGHT);
    const WindowFit fit = fitWindow(state.opts, state.lab->panelFillsWindow(), state.screenWidth,
                                    state.screenHeight, state.opts.uiScale);
    if (fit.uiScale < state.opts.uiScale) {
        state.panel.scaleNote = trf(
            "UI scale %.2f does not fit beside the scene on this %dx%d screen: %.2f is the "
            "largest that does.",
            double(state.opts.uiScale), state.screenWidth, state.screenHeight, double(fit.uiScale));
        std::fprintf(stderr, "%s: %s\n", argv[0], state.panel.scaleNote.c_str());
    }
    state.panel.uiScale = state.panel.requestedScale = fit.uiScale;
    state.panel.width = float(fit.panelWidth);
    state.panel.resetWidth = true; // the first frame sizes the panel to it
    state.panel.keysLikeShell = !state.lab->panelFillsWindow();
    state.windowWidth = fit.width;
    state.windowHeight = fit.height;
    glutInitWindowSize(state.windowWidth, state.windowHeight);
    glutCreateWindow(state.lab->title().c_str());
    state.language = language();
    // The window's X id and display, for the second connection that reads keys (x_keyboard.h).
    if (!state.xkb.open(DisplayString(glXGetCurrentDisplay()), glXGetCurrentDrawable()))
        std::fprintf(stderr, "%s: %s\n", argv[0],
                     tr("cannot read the keyboard from X: keys work on the Latin layout only"));
    const char* logKeys = std::getenv("WB_LOG_KEYS");
    state.logKeys = logKeys && *logKeys == '1';
    const char* frameLog = std::getenv("WB_FRAME_LOG");
    state.frameLog = frameLog && *frameLog == '1';
    layout();
    GLenum glewStatus = glewInit();
    if (glewStatus != GLEW_OK) {
        std::fprintf(stderr, tr("%s: GLEW: %s\n"), argv[0],
                     reinterpret_cast<const char*>(glewGetErrorString(glewStatus)));
        return 1;
    }

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini littering the working directory
    io.DisplaySize = ImVec2(float(state.windowWidth), float(state.windowHeight));
    const std::string fontMessage = setupImGuiFonts(state.panel.uiScale);
    if (!fontMessage.empty()) std::fprintf(stderr, "%s: %s\n", argv[0], fontMessage.c_str());
    ImGui_ImplGLUT_Init(); // key map and frame timing only; events go through ImGuiInput
    ImGui_ImplOpenGL2_Init();
    io.BackendFlags |=
        ImGuiBackendFlags_HasMouseCursors; // updateCursor(): the panel's edge can be dragged
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(keyboardUp);
    glutSpecialFunc(special);
    glutSpecialUpFunc(specialUp);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutPassiveMotionFunc(passiveMotion);
    glutMouseWheelFunc(wheel);
    glutTimerFunc(kKeyPollMs, pollKeys, 0);

    state.lab->init();
    for (int k : keys)
        labKey(k);
    if (state.opts.smoke)
        for (const auto& k : state.lab->keys())
            if (k.key.size() == 1 &&
                k.key[0] != 27) // twice: a toggle shows its other state, then returns
                state.smokeKeys.insert(state.smokeKeys.end(), 2,
                                       static_cast<unsigned char>(k.key[0]));
    glutMainLoop();

    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGLUT_Shutdown();
    ImGui::DestroyContext();
    state.lab.reset(); // GL objects go while the context still exists
    glutExit();        // destroys the window and its GL context (Mesa's buffers with them)
    g = nullptr;
    return state.screenshotFailed ? 1 : 0;
}

} // namespace wb
