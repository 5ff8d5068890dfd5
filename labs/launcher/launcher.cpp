#include "launcher.h"

#include "common/gl.h"
#include "common/panel.h"
#include "common/paths.h"
#include "core/image.h"
#include "lab_list.h"

#include "core/i18n.h"

#include <imgui.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace wb {

std::string binDir() {
    char self[PATH_MAX] = {};
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    std::string path = n > 0 ? std::string(self, size_t(n)) : std::string(".");
    auto slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

namespace {
std::vector<std::string> g_labFlags;
} // namespace

void setLabFlags(std::vector<std::string> flags) {
    g_labFlags = std::move(flags);
}

namespace {

// The labs in kLabs (its last entry is the null terminator). A constant, so the compiler
// sees every kLabs[i] in bounds (GCC's -Warray-bounds under the sanitizers could not).
constexpr int kLabCount = int(sizeof kLabs / sizeof kLabs[0]) - 1;
int labCount() {
    return kLabCount;
}

// Modification time of a file, 0 when it does not exist.
long long mtime(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) ? (long long)st.st_mtime : 0;
}

// Starts argv without waiting; -1 when it could not start.
pid_t spawn(const std::vector<std::string>& args, bool quiet) {
    std::vector<char*> argv;
    for (const auto& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = fork();
    if (pid == 0) {
        if (quiet) {
            if (std::freopen("/dev/null", "w", stdout) == nullptr) _exit(127);
        }
        execv(argv[0], argv.data());
        std::perror(argv[0]);
        _exit(127);
    }
    return pid;
}

// Runs argv to completion; returns its exit status (or -1 when it could not start).
int runAndWait(const std::vector<std::string>& args) {
    pid_t pid = spawn(args, false);
    if (pid < 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Where thumbnails rendered on first start are kept when the build did not make them
// (a lab built on its own): $XDG_CACHE_HOME/workbench, else ~/.cache/workbench.
std::string cacheDir() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    std::string dir = xdg && *xdg     ? std::string(xdg)
                      : home && *home ? std::string(home) + "/.cache"
                                      : "/tmp";
    return dir + "/workbench-thumbs";
}

// One lab's card: its thumbnail as a GL texture once loaded.
struct Card {
    GLuint texture = 0;
    std::string status;  // "rendering the picture..." or why there is none
    pid_t renderer = -1; // a headless render of the thumbnail in progress
    std::string renderPath;
};

class Launcher : public Lab {
  public:
    std::string title() const override { return tr("Graphics lab workbench"); }
    std::vector<KeyHelp> keys() const override {
        std::vector<KeyHelp> k;
        for (int i = 0; i < labCount() && i < 9; ++i)
            k.push_back({std::to_string(i + 1), trf("start %s", kLabs[i].executable)});
        return k;
    }
    bool panelFillsWindow() const override { return true; }
    void init() override {
        cards_.resize(size_t(labCount()));
        for (int i = 0; i < labCount(); ++i)
            loadThumbnail(i);
    }
    ~Launcher() override {
        for (auto& c : cards_) {
            if (c.texture) glDeleteTextures(1, &c.texture);
            if (c.renderer > 0) waitpid(c.renderer, nullptr, 0);
        }
    }
    void draw(const View& view) override {
        if (view.headless) pollRenderers(true); // a headless render shows the finished cards
        glClearColor(0.12f, 0.14f, 0.17f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    // While a thumbnail renders in the background, the shell keeps drawing (and we poll).
    bool busy() const override {
        return std::any_of(cards_.begin(), cards_.end(),
                           [](const Card& c) { return c.renderer > 0; });
    }
    bool key(int code) override {
        int i = code - '1';
        if (i < 0 || i >= labCount() || i >= 9) return false;
        start(i);
        return true;
    }
    void gui() override {
        pollRenderers(false);
        ImGui::TextWrapped(tr(
            "Choose a lab (click its picture or press its number); it opens in its own window."));
        // The UI scale the shell built the fonts for: the labs start with it (not the font's
        // rounded 15 px x scale, which made --ui-scale 1.5 reach the labs as 1.53).
        const float scale = builtUiScale();
        char scaleText[16];
        std::snprintf(scaleText, sizeof scaleText, "%.2f", double(scale));
        scaleNow_ = scaleText;
        const ImVec2 thumb(float(kThumbWidth) * 0.5f * scale, float(kThumbHeight) * 0.5f * scale);
        const int columns =
            ImGui::GetContentRegionAvail().x > 2.0f * (thumb.x + 220.0f * scale) ? 2 : 1;
        if (ImGui::BeginTable("labs", columns,
                              ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_PadOuterX)) {
            for (int i = 0; i < labCount(); ++i) {
                ImGui::TableNextColumn();
                card(i, thumb);
            }
            ImGui::EndTable();
        }
        if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
    }

  private:
    void card(int i, ImVec2 thumb) {
        const LabEntry& lab = kLabs[i];
        Card& c = cards_[size_t(i)];
        ImGui::PushID(i);
        bool clicked = false;
        if (c.texture) {
            clicked = ImGui::ImageButton(
                reinterpret_cast<ImTextureID>(static_cast<intptr_t>(c.texture)), thumb);
        } else {
            clicked =
                ImGui::Button(c.status.empty() ? tr("(no picture)") : tr(c.status.c_str()), thumb);
        }
        ImGui::SameLine();
        ImGui::BeginGroup();
        if (i < 9)
            ImGui::Text("%d  %s", i + 1, lab.executable);
        else
            ImGui::TextUnformatted(lab.executable);
        ImGui::TextWrapped("%s", tr(lab.topic));
        if (*lab.docsPage) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            ImGui::TextWrapped("%s", lab.docsPage);
            ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", assetPath(lab.docsPage).c_str());
        }
        if (ImGui::Button(tr("Start"))) clicked = true;
        ImGui::EndGroup();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(lab.description));
        ImGui::PopID();
        if (clicked) start(i);
    }

    // The build's thumbnail (bin/thumbs/), else one cached from an earlier start if it is not
    // older than the lab, else render it now in the background.
    void loadThumbnail(int i) {
        const LabEntry& lab = kLabs[i];
        const std::string headless = binDir() + "/" + lab.executable + "-headless";
        const std::string built = binDir() + "/thumbs/" + lab.thumbnail;
        const std::string installed = assetPath(std::string("thumbs/") + lab.thumbnail); // .deb
        const std::string cached = cacheDir() + "/" + lab.thumbnail;
        Card& c = cards_[size_t(i)];
        if (mtime(built) >= mtime(headless) && upload(c, built)) return;
        // A package's files come together (stripping at packaging makes the programs newer).
        if (mtime(built) == 0 && mtime(installed) > 0 && upload(c, installed)) return;
        if (mtime(cached) >= mtime(headless) && upload(c, cached)) return;
        mkdir(cacheDir().c_str(), 0755);
        c.renderPath = cached;
        c.renderer = spawn({headless, "--out", cached, "--size",
                            std::to_string(kThumbWidth) + "x" + std::to_string(kThumbHeight)},
                           true);
        c.status = c.renderer > 0 ? N_("rendering...") : N_("(no picture)"); // tr() when shown
    }

    void pollRenderers(bool wait) {
        for (auto& c : cards_) {
            if (c.renderer <= 0) continue;
            int status = 0;
            pid_t r = waitpid(c.renderer, &status, wait ? 0 : WNOHANG);
            if (r == 0) continue;
            c.renderer = -1;
            const bool ok = r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
            if (!ok || !upload(c, c.renderPath)) c.status = N_("(no picture)");
        }
    }

    bool upload(Card& c, const std::string& path) {
        Image img;
        if (!readImage(path, img, 4)) return false;
        if (!c.texture) glGenTextures(1, &c.texture);
        glBindTexture(GL_TEXTURE_2D, c.texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img.data.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        c.status.clear();
        return true;
    }

    // The lab runs on its own: a double fork, so it is never our zombie and we need no SIGCHLD
    // handler.
    void start(int i) {
        std::string exe = binDir() + "/" + kLabs[i].executable;
#if defined(WB_HEADLESS)
        // The headless launcher (workbench-panel-check) has no display to open a lab on.
        status_ = trf("would start %s", exe.c_str());
        return;
#endif
        pid_t pid = fork();
        if (pid == 0) {
            if (fork() == 0) {
                // The launcher's flags (--ui-scale, --lang, ...), with the UI scale and the
                // language it has now (Ctrl+= or View > Language may have changed them) in place
                // of the ones it was started with.
                std::vector<std::string> args = {exe};
                for (size_t k = 0; k < g_labFlags.size(); ++k) {
                    if (g_labFlags[k] == "--ui-scale" || g_labFlags[k] == "--lang") {
                        ++k;
                        continue;
                    }
                    if (g_labFlags[k].rfind("--ui-scale=", 0) == 0 ||
                        g_labFlags[k].rfind("--lang=", 0) == 0)
                        continue;
                    args.push_back(g_labFlags[k]);
                }
                args.push_back("--ui-scale");
                args.push_back(scaleNow_);
                args.push_back("--lang");
                args.push_back(language());
                std::vector<char*> argv;
                for (auto& a : args)
                    argv.push_back(a.data());
                argv.push_back(nullptr);
                execv(exe.c_str(), argv.data());
                std::perror(exe.c_str());
            }
            _exit(0);
        }
        if (pid > 0) waitpid(pid, nullptr, 0);
        status_ = pid > 0 ? trf("started %s", exe.c_str()) : trf("could not start %s", exe.c_str());
        std::fprintf(stderr, "%s\n", status_.c_str());
    }

    std::vector<Card> cards_;
    std::string status_;
    std::string scaleNow_ = "1"; // the UI scale the labs are started with
};

} // namespace

std::unique_ptr<Lab> makeLauncher() {
    return std::make_unique<Launcher>();
}

int renderAllHeadless(const std::string& outDir, const std::string& size) {
    mkdir(outDir.c_str(), 0755);
    char absolute[PATH_MAX] = {};
    const std::string dir = realpath(outDir.c_str(), absolute) ? std::string(absolute) : outDir;
    int failed = 0;
    for (int i = 0; i < labCount(); ++i) {
        std::string exe = binDir() + "/" + kLabs[i].executable + "-headless";
        std::string out = dir + "/" + kLabs[i].executable + ".png";
        int rc = runAndWait({exe, "--out", out, "--size", size, "--lang", language()});
        std::printf("%-16s %-6s  %s\n", kLabs[i].executable, rc == 0 ? tr("ok") : tr("FAILED"),
                    out.c_str());
        if (rc != 0) ++failed;
    }
    return failed;
}

} // namespace wb
