#include "launcher.h"

#include "common/gl.h"
#include "lab_list.h"

#include <imgui.h>

#include <climits>
#include <cstdlib>
#include <csignal>
#include <cstdio>
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

int labCount() {
    int n = 0;
    while (kLabs[n].executable) ++n;
    return n;
}

// Runs argv to completion; returns its exit status (or -1 when it could not start).
int runAndWait(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        execv(argv[0], argv.data());
        std::perror(argv[0]);
        _exit(127);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class Launcher : public Lab {
public:
    std::string title() const override { return "Graphics lab workbench"; }
    std::vector<KeyHelp> keys() const override {
        std::vector<KeyHelp> k;
        for (int i = 0; i < labCount() && i < 9; ++i)
            k.push_back({std::to_string(i + 1), std::string("start ") + kLabs[i].executable});
        return k;
    }
    bool panelFillsWindow() const override { return true; }
    void init() override {
        signal(SIGCHLD, SIG_IGN); // labs run on their own; no zombies
    }
    void draw(const View&) override {
        glClearColor(0.12f, 0.14f, 0.17f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    bool key(int code) override {
        int i = code - '1';
        if (i < 0 || i >= labCount() || i >= 9) return false;
        start(i);
        return true;
    }
    void gui() override {
        ImGui::TextWrapped("Choose a lab; it opens in its own window.");
        for (int i = 0; i < labCount(); ++i) {
            ImGui::PushID(i);
            if (ImGui::Button(kLabs[i].executable, ImVec2(160, 0))) start(i);
            ImGui::SameLine();
            ImGui::TextWrapped("%s", kLabs[i].description);
            ImGui::PopID();
        }
        if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
    }

private:
    void start(int i) {
        std::string exe = binDir() + "/" + kLabs[i].executable;
        pid_t pid = fork();
        if (pid == 0) {
            execl(exe.c_str(), exe.c_str(), static_cast<char*>(nullptr));
            std::perror(exe.c_str());
            _exit(127);
        }
        status_ = pid > 0 ? "started " + exe : "could not start " + exe;
        std::fprintf(stderr, "%s\n", status_.c_str());
    }
    std::string status_;
};

} // namespace

std::unique_ptr<Lab> makeLauncher() { return std::make_unique<Launcher>(); }

int renderAllHeadless(const std::string& outDir, const std::string& size) {
    mkdir(outDir.c_str(), 0755);
    char absolute[PATH_MAX] = {};
    const std::string dir = realpath(outDir.c_str(), absolute) ? std::string(absolute) : outDir;
    int failed = 0;
    for (int i = 0; i < labCount(); ++i) {
        std::string exe = binDir() + "/" + kLabs[i].executable + "-headless";
        std::string out = dir + "/" + kLabs[i].executable + ".png";
        int rc = runAndWait({exe, "--out", out, "--size", size});
        std::printf("%-16s %s  %s\n", kLabs[i].executable, rc == 0 ? "ok    " : "FAILED", out.c_str());
        if (rc != 0) ++failed;
    }
    return failed;
}

} // namespace wb
