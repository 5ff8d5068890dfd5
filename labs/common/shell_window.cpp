// The windowed path of the shell: freeglut window, GLEW, Dear ImGui panel.
// GLUT events go to ImGui first and are dropped when ImGui wants them
// (as in Dear ImGui's GLUT + OpenGL2 example).
#include "gl_util.h"
#include "shell.h"

#include <GL/freeglut.h>
#include <imgui.h>
#include <imgui_impl_glut.h>
#include <imgui_impl_opengl2.h>

#include <chrono>
#include <climits>
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
    View view;                    // the scene's part of the window (left of the panel)
    int windowWidth = 800;        // whole window, pixels
    int windowHeight = 600;
    bool panelVisible = true;
    int frame = 0;
    std::vector<int> smokeKeys;   // --smoke: keys still to press, one per frame
    double frameMs = 0.0;         // CPU time of the last draw() + panel, milliseconds
    double smoothMs = 0.0;        // the same, exponentially smoothed for reading
    std::string lastScreenshot;   // path or error of the last screenshot, shown in the panel
    bool screenshotRequested = false;
    bool screenshotFailed = false; // --screenshot could not be written: exit 1
    bool dragging = false;        // left button down outside the panel
    bool moved = false;           // the drag moved far enough to be a rotation, not a click
    int downX = 0, downY = 0, lastX = 0, lastY = 0;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};
WindowState* g = nullptr;

// The panel is docked at the right edge and the scene gets the rest of the window, so
// nothing of the scene hides behind it (an instructor demoing keys 1-4 needs both).
constexpr int kPanelWidth = 380;

int panelWidth() { return g->lab->panelFillsWindow() ? g->windowWidth : kPanelWidth; }

void layout() {
    int sceneWidth = g->panelVisible ? g->windowWidth - panelWidth() : g->windowWidth;
    g->view.width = sceneWidth > 1 ? sceneWidth : 1;
    g->view.height = g->windowHeight > 1 ? g->windowHeight : 1;
}

void quit() { glutLeaveMainLoop(); }

void labKey(int code) {
    if (code == 27) return quit();
    if (!shellKey(code, g->view, g->panelVisible)) g->lab->key(code);
    glutPostRedisplay();
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
    g->lastScreenshot = ok ? "saved " + path : error;
    std::fprintf(stderr, "%s\n", g->lastScreenshot.c_str());
    return ok;
}

void drawPanel() {
    ImGui::SetNextWindowPos(ImVec2(float(g->windowWidth - panelWidth()), 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(panelWidth()), float(g->windowHeight)), ImGuiCond_Always);
    ImGui::Begin(g->lab->title().c_str(), nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::Text("frame %.2f ms (%.0f fps)", g->smoothMs, g->smoothMs > 0 ? 1000.0 / g->smoothMs : 0.0);
    if (ImGui::Button("Screenshot (PNG)")) g->screenshotRequested = true;
    if (!g->lastScreenshot.empty()) ImGui::TextWrapped("%s", g->lastScreenshot.c_str());
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) g->lab->gui();
    if (ImGui::CollapsingHeader("Keys", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const auto& k : g->lab->keys()) ImGui::BulletText("%-6s %s", k.key.c_str(), k.what.c_str());
        ImGui::BulletText("%-6s %s", "h", "hide/show this panel");
        ImGui::BulletText("%-6s %s", "+/-", "zoom (also the wheel)");
        ImGui::BulletText("%-6s %s", "drag", "rotate the scene");
        ImGui::BulletText("%-6s %s", "Esc", "quit");
    }
    ImGui::End();
}

void display() {
    auto t0 = std::chrono::steady_clock::now();
    if (!g->smokeKeys.empty()) { // as if typed, through the same path as real key presses
        labKey(g->smokeKeys.front());
        g->smokeKeys.erase(g->smokeKeys.begin());
    }
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGLUT_NewFrame();
    if (g->panelVisible) drawPanel();
    ImGui::Render();

    g->view.time = std::chrono::duration<double>(t0 - g->start).count();
    layout();
    glViewport(0, 0, g->view.width, g->view.height);
    g->lab->draw(g->view);
    // --frames counts on until every --smoke key has been pressed.
    bool lastFrame = g->opts.frames > 0 && g->frame + 1 >= g->opts.frames && g->smokeKeys.empty();
    if (g->panelVisible) {
        // The panel draws with its own GL state; keep the lab's.
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glUseProgram(0);
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        glPopAttrib();
    }
    // --screenshot and the button save what the user sees, panel included (`h` hides it).
    if (lastFrame && !g->opts.screenshot.empty() && !saveScreenshot(g->opts.screenshot))
        g->screenshotFailed = true;
    if (g->screenshotRequested) {
        g->screenshotRequested = false;
        saveScreenshot(timestampedName());
    }
    glutSwapBuffers();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    g->frameMs = ms;
    g->smoothMs = g->frame == 0 ? ms : 0.9 * g->smoothMs + 0.1 * ms;
    ++g->frame;
    if (lastFrame) return quit();
    glutPostRedisplay();
}

void reshape(int w, int h) {
    ImGui_ImplGLUT_ReshapeFunc(w, h);
    g->windowWidth = w;
    g->windowHeight = h;
    layout();
}

void keyboard(unsigned char c, int x, int y) {
    ImGui_ImplGLUT_KeyboardFunc(c, x, y);
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    labKey(c);
}

void special(int key, int x, int y) {
    ImGui_ImplGLUT_SpecialFunc(key, x, y);
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    labKey(kKeySpecial + key);
}

void mouse(int button, int state, int x, int y) {
    ImGui_ImplGLUT_MouseFunc(button, state, x, y);
    if (ImGui::GetIO().WantCaptureMouse && !g->dragging) return;
    if (button != GLUT_LEFT_BUTTON) return;
    if (state == GLUT_DOWN) {
        g->dragging = true;
        g->moved = false;
        g->downX = g->lastX = x;
        g->downY = g->lastY = y;
    } else {
        if (g->dragging && !g->moved) g->lab->click(x, y, g->view);
        g->dragging = false;
    }
    glutPostRedisplay();
}

void motion(int x, int y) {
    ImGui_ImplGLUT_MotionFunc(x, y);
    if (!g->dragging) return;
    if (std::abs(x - g->downX) + std::abs(y - g->downY) > 3) g->moved = true;
    if (g->moved) {
        g->view.yaw += 0.5f * float(x - g->lastX);
        g->view.pitch += 0.5f * float(y - g->lastY);
    }
    g->lastX = x;
    g->lastY = y;
    glutPostRedisplay();
}

void wheel(int button, int dir, int x, int y) {
    ImGui_ImplGLUT_MouseWheelFunc(button, dir, x, y);
    if (ImGui::GetIO().WantCaptureMouse) return;
    g->view.zoom *= dir > 0 ? 1.1f : 1.0f / 1.1f;
    glutPostRedisplay();
}

// The headless renderer is the same lab compiled against OSMesa, installed next to us.
int execHeadless(char** argv) {
    char self[PATH_MAX] = {};
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) {
        std::fprintf(stderr, "%s: cannot find my own executable\n", argv[0]);
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
    if (state.opts.headless) return execHeadless(argv);
    const char* displayEnv = std::getenv("DISPLAY");
    if (!displayEnv || !*displayEnv) {
        std::fprintf(stderr, "%s: no display (DISPLAY is not set); render to a file with --headless --out FILE.png\n",
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
    // --size is the scene's size; the panel is added beside it.
    state.windowWidth = state.opts.width + (state.lab->panelFillsWindow() ? 0 : kPanelWidth);
    state.windowHeight = state.opts.height;
    glutInitWindowSize(state.windowWidth, state.windowHeight);
    glutCreateWindow(state.lab->title().c_str());
    layout();
    GLenum glewStatus = glewInit();
    if (glewStatus != GLEW_OK) {
        std::fprintf(stderr, "%s: GLEW: %s\n", argv[0], reinterpret_cast<const char*>(glewGetErrorString(glewStatus)));
        return 1;
    }

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini littering the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGLUT_Init();
    ImGui_ImplOpenGL2_Init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(ImGui_ImplGLUT_KeyboardUpFunc);
    glutSpecialFunc(special);
    glutSpecialUpFunc(ImGui_ImplGLUT_SpecialUpFunc);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutPassiveMotionFunc(ImGui_ImplGLUT_MotionFunc);
    glutMouseWheelFunc(wheel);

    state.lab->init();
    for (int k : keys) labKey(k);
    if (state.opts.smoke)
        for (const auto& k : state.lab->keys())
            if (k.key.size() == 1 && k.key[0] != 27) // twice: a toggle shows its other state, then returns
                state.smokeKeys.insert(state.smokeKeys.end(), 2, static_cast<unsigned char>(k.key[0]));
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
