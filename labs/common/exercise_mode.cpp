#include "common/exercise_mode.h"

#include "common/exercise_run.h"
#include "common/gl.h"
#include "common/lab.h"
#include "common/paths.h"
#include "core/i18n.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <imgui.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_set>
#include <vector>

namespace wb::ex {
namespace {

using Clock = std::chrono::steady_clock;

// Seconds since the epoch of a file's last change with nanoseconds, 0 when missing.
double modifiedTime(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return 0;
    return double(st.st_mtim.tv_sec) + 1e-9 * double(st.st_mtim.tv_nsec);
}

// Starts argv[0] with stdout (and stderr when errPath is empty) to a pipe; stderr to
// errPath otherwise. Returns the pid, -1 on failure.
pid_t spawn(const std::vector<std::string>& argv, int& outFd, const std::string& errPath) {
    int fds[2];
    if (pipe(fds) != 0) return -1;
    const pid_t pid = fork();
    if (pid == 0) {
        ::close(fds[0]);
        dup2(fds[1], 1);
        if (!errPath.empty()) {
            const int e = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (e >= 0) dup2(e, 2);
        } else {
            dup2(fds[1], 2);
        }
        setenv("LC_ALL", "C", 1); // plain ASCII quotes in the compiler's messages
        // wb-check's messages (the failing case, what it usually means) in the lab's language.
        setenv("LANGUAGE", language().c_str(), 1);
        std::vector<char*> args;
        for (const std::string& a : argv)
            args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    ::close(fds[1]);
    if (pid < 0) {
        ::close(fds[0]);
        return -1;
    }
    fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);
    outFd = fds[0];
    return pid;
}

// The first compiler diagnostic as "file:line: message" (the student's file's errors first).
std::string firstError(const std::string& log, const std::string& file) {
    std::istringstream in(log);
    std::string line, any;
    while (std::getline(in, line)) {
        if (line.find("error") == std::string::npos) continue;
        if (line.find(file) != std::string::npos) return line;
        if (any.empty()) any = line;
    }
    return any.empty() ? log.substr(0, 400) : any;
}

} // namespace

struct ExerciseMode::Impl {
    enum class Step { Idle, Compiling, Checking };
    bool on = false;
    bool started = false;
    bool watch = true;
    int extraFrames =
        0; // frames still to draw after a change (the panel is laid out before draw())
    bool shellPolls = false; // the window polls on a timer (it asked pollMs()): no redraws to watch
    std::string source, compileScript, checker, liveDir, builtObject;
    double sourceTime = 0; // mtime of the source the current object was built from
    Step step = Step::Idle;
    pid_t pid = -1;
    int fd = -1;
    bool reaped = false; // pid ended and was waited for; its status is in `status`
    int status = 0;
    std::string output, object, errLog;
    Clock::time_point lastPoll{}, changeSeen{}, stepStart{};
    double lastCompileS = 0, lastCheckS = 0, lastTotalS = 0;
    int generation = 0;
    int reloads = 0;                                     // changes of the file seen while running
    std::vector<std::unique_ptr<StudentObject>> objects; // kept loaded: pointers stay valid
    const StudentObject* current = nullptr;
    std::string compileError, loadError;
    std::map<std::string, TaskResult> results;
    bool checked = false;
    // Drawn inputs tried in a child (task id and input hashed) that returned, and the tasks
    // that crashed or looped on one, with the panel's sentence; both until the next reload.
    std::unordered_set<uint64_t> triedOk;
    std::map<std::string, std::string> drawnFailures;

    void useObject(std::unique_ptr<StudentObject> obj) {
        current = obj.get();
        objects.push_back(std::move(obj));
        triedOk.clear();
        drawnFailures.clear();
    }

    ~Impl() {
        if (pid > 0 && !reaped) {
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
        }
        if (fd >= 0) ::close(fd);
    }

    void startCheck(const std::string& lab) {
        std::vector<std::string> argv = {checker, "lab" + lab, "--machine", "--student",
                                         lab + "=" + object};
        fd = -1;
        output.clear();
        pid = spawn(argv, fd, "");
        step = pid > 0 ? Step::Checking : Step::Idle;
        stepStart = Clock::now();
        if (pid <= 0) loadError = tr("cannot start wb-check");
    }

    void startCompile() {
        ++generation;
        object =
            liveDir + "/lab-" + std::to_string(getpid()) + "-" + std::to_string(generation) + ".so";
        errLog = object + ".log";
        fd = -1;
        output.clear();
        pid = spawn({"/bin/sh", compileScript, source, object}, fd, errLog);
        step = pid > 0 ? Step::Compiling : Step::Idle;
        stepStart = Clock::now();
        if (pid <= 0) compileError = tr("cannot start the compiler");
    }
};

ExerciseMode::ExerciseMode(const LabExercises& lab, char key)
    : lab_(lab), key_(key), impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.source = assetPath(lab.file);
    m.compileScript = std::string(WB_EXERCISE_DIR) + "/lab" + lab.lab + ".compile";
    m.checker = std::string(WB_BIN_DIR) + "/wb-check";
    m.liveDir = std::string(WB_EXERCISE_DIR) + "/live";
    m.builtObject = std::string(WB_EXERCISE_DIR) + "/lab" + lab.lab + ".so";
#ifdef WB_HANDOUT
    setOn(true); // a handout has no reference to show: the lab draws your code
#endif
}

ExerciseMode::~ExerciseMode() = default;

KeyHelp ExerciseMode::keyHelp() const {
    return {std::string(1, key_), trf("your code (%s) / the reference", lab_.file.c_str())};
}

bool ExerciseMode::key(int k) {
    if (k != key_) return false;
#ifdef WB_HANDOUT
    return true; // always your code in a handout
#endif
    setOn(!on());
    return true;
}

bool ExerciseMode::on() const {
    return impl_->on;
}

void ExerciseMode::setOn(bool value) {
    impl_->on = value;
    if (value && !impl_->started) {
        impl_->started = true;
        // Resolved now, not in the constructor: --root is applied after the lab is built.
        impl_->source = assetPath(lab_.file);
        ::mkdir(impl_->liveDir.c_str(), 0755);
        // The object the build made, when it is not older than the file; else build now.
        const double src = modifiedTime(impl_->source);
        impl_->sourceTime = src;
        if (modifiedTime(impl_->builtObject) >= src) {
            impl_->object = impl_->builtObject;
            auto obj = std::make_unique<StudentObject>();
            if (obj->load(impl_->object)) {
                impl_->useObject(std::move(obj));
                impl_->startCheck(lab_.lab);
            } else {
                impl_->loadError = obj->error();
                impl_->startCompile();
            }
        } else {
            impl_->changeSeen = Clock::now();
            impl_->startCompile();
        }
    }
}

bool ExerciseMode::busy() const {
    // While on: the file is watched (poll() from draw), so the window keeps drawing.
    return (impl_->on && impl_->watch && !impl_->shellPolls) || impl_->step != Impl::Step::Idle ||
           impl_->extraFrames > 0;
}

bool ExerciseMode::poll(bool watch) {
    Impl& m = *impl_;
    m.watch = watch;
    if (m.extraFrames > 0) --m.extraFrames;
    if (!m.started) return false;
    bool changed = false;
    const auto now = Clock::now();
    // Read what the child wrote so far (non-blocking), then see whether it ended.
    if (m.fd >= 0) {
        char buf[4096];
        for (;;) {
            const ssize_t n = ::read(m.fd, buf, sizeof buf);
            if (n > 0) {
                m.output.append(buf, size_t(n));
                continue;
            }
            if (n == 0) {
                ::close(m.fd);
                m.fd = -1;
            }
            break;
        }
    }
    if (m.pid > 0) {
        // The child can end between the read above and this wait, with its last output still
        // in the pipe: its status is kept until the pipe is read to the end (waitpid reaps it
        // once; asked again it fails, and the step would never end - a headless lab 07 spun
        // for 10 minutes at load 12 that way).
        if (!m.reaped && waitpid(m.pid, &m.status, WNOHANG) == m.pid) m.reaped = true;
        if (m.reaped && m.fd < 0) {
            const int status = m.status;
            m.reaped = false;
            m.pid = -1;
            const double took = std::chrono::duration<double>(now - m.stepStart).count();
            if (m.step == Impl::Step::Compiling) {
                m.lastCompileS = took;
                if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
                    m.compileError.clear();
                    auto obj = std::make_unique<StudentObject>();
                    if (obj->load(m.object)) {
                        m.loadError.clear();
                        m.useObject(std::move(obj));
                        m.startCheck(lab_.lab);
                    } else {
                        m.loadError = obj->error();
                        m.step = Impl::Step::Idle;
                    }
                } else {
                    std::ifstream f(m.errLog);
                    std::stringstream ss;
                    ss << f.rdbuf();
                    m.compileError = firstError(ss.str(), m.source);
                    // The path as the student knows it, from the repository's root.
                    const std::string root = assetRoot() + "/";
                    if (m.compileError.rfind(root, 0) == 0) m.compileError.erase(0, root.size());
                    m.step = Impl::Step::Idle;
                }
            } else if (m.step == Impl::Step::Checking) {
                m.lastCheckS = took;
                // From the file's save (its mtime, wall clock) to the results: what the student
                // waits.
                const double wall = std::chrono::duration<double>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count();
                m.lastTotalS = m.sourceTime > 0 && m.reloads > 0
                                   ? wall - m.sourceTime
                                   : std::chrono::duration<double>(now - m.changeSeen).count();
                std::istringstream in(m.output);
                std::string line;
                while (std::getline(in, line)) {
                    TaskResult res;
                    if (line.rfind("T\t", 0) == 0 && decodeResult(line.substr(2), res))
                        m.results[res.id] = res;
                    if (line.rfind("E\t", 0) == 0) m.loadError = line.substr(2);
                }
                m.checked = true;
                m.step = Impl::Step::Idle;
            }
            changed = true;
        }
    }
    // The file watch, twice a second.
    if (m.step == Impl::Step::Idle && now - m.lastPoll > std::chrono::milliseconds(500)) {
        m.lastPoll = now;
        const double t = modifiedTime(m.source);
        if (t != m.sourceTime && t != 0) {
            m.sourceTime = t;
            m.changeSeen = now;
            ++m.reloads;
            m.startCompile();
            changed = true;
        }
    }
    // The window lays the panel out before draw() polls: one more frame shows the change.
    if (changed) m.extraFrames = 2;
    return changed;
}

int ExerciseMode::pollMs() const {
    impl_->shellPolls = true; // the window asks this before busy(), and then polls
    return impl_->on ? 500 : 0;
}

bool ExerciseMode::shellPoll() {
    return poll(impl_->watch);
}

const void* ExerciseMode::studentRaw() const {
    return impl_->current ? impl_->current->table() : nullptr;
}

bool ExerciseMode::callable(const std::string& taskId) const {
    if (!impl_->current) return false;
    if (impl_->drawnFailures.count(taskId)) return false;
    const auto it = impl_->results.find(taskId);
    if (it == impl_->results.end()) return impl_->checked; // checked: not a task of this lab
    const TaskResult& r = it->second;
    if (r.status == Status::NotDone) return false;
    // A crash or an endless loop in the isolated check: never call it inside the lab.
    return !(r.status == Status::Fails && r.got.empty() && r.expected.empty());
}

bool ExerciseMode::tryInChild(const std::string& taskId, uint64_t key,
                              const std::function<void()>& body) const {
    Impl& m = *impl_;
    if (m.drawnFailures.count(taskId)) return false;
    uint64_t k = key;
    hashBytes(k, taskId.data(), taskId.size());
    if (m.triedOk.count(k)) return true;
    if (m.triedOk.size() > 100000) m.triedOk.clear(); // a long drag: forget, try again
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid == 0) {
        // The child: only the student's function, then out without the lab's atexit work.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
            signal(sig, SIG_DFL);
        alarm(unsigned(kDrawnTimeLimitS) + 2); // if the lab itself is gone
        try {
            body();
        } catch (...) {
        }
        _exit(0);
    }
    if (pid < 0) return true; // no child to try it in: call it here, as before
    const auto deadline = Clock::now() + std::chrono::milliseconds(long(kDrawnTimeLimitS * 1000));
    int status = 0;
    bool timedOut = false;
    auto nap = std::chrono::microseconds(50);
    for (;;) {
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid) break;
        if (r < 0 && errno != EINTR) return true;
        if (Clock::now() > deadline) {
            timedOut = true;
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        usleep(useconds_t(nap.count()));
        nap = std::min(nap * 2, std::chrono::microseconds(5000));
    }
    if (!timedOut && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        m.triedOk.insert(k);
        return true;
    }
    std::string why;
    if (timedOut)
        why = trf("no answer within %.0f s on the drawn input: an endless loop?", kDrawnTimeLimitS);
    else if (WIFSIGNALED(status)) {
        const char* abbrev = sigabbrev_np(WTERMSIG(status));
        why = trf("crashed on the drawn input: SIG%s",
                  abbrev ? abbrev : std::to_string(WTERMSIG(status)).c_str());
    } else
        why = trf("ended the program on the drawn input (exit status %d)", WEXITSTATUS(status));
    m.drawnFailures[taskId] = why;
    m.extraFrames = 2; // the panel shows it on the next frames
    std::fprintf(stderr, "%s: %s\n", taskId.c_str(), why.c_str());
    return false;
}

const TaskResult* ExerciseMode::result(const std::string& taskId) const {
    const auto it = impl_->results.find(taskId);
    return it == impl_->results.end() ? nullptr : &it->second;
}

void ExerciseMode::ghostBegin() {
    glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_LINE_BIT | GL_POLYGON_BIT);
    glEnable(GL_BLEND);
    // Constant alpha: translucent whatever colours the lab's drawing code sets.
    glBlendColor(0, 0, 0, kGhostAlpha);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(3, 0x5555);
}

void ExerciseMode::ghostEnd() {
    glPopAttrib();
}

void ExerciseMode::gui() {
    Impl& m = *impl_;
    if (!ImGui::CollapsingHeader(tr("Exercises"), ImGuiTreeNodeFlags_DefaultOpen)) return;
    bool onNow = m.on;
    // The label wraps beside the box (a checkbox's own label does not, and a longer language
    // ran it past the panel's edge).
    if (ImGui::Checkbox("##exercise-on", &onNow)) setOn(onNow);
    ImGui::SameLine();
    ImGui::TextWrapped("%s", trf("your code (%c); the reference as a ghost", key_).c_str());
    ImGui::TextWrapped("%s", trf("your file: %s", lab_.file.c_str()).c_str());
    if (!m.started) {
        ImGui::TextWrapped("%s",
                           trf("Press %c to draw your answers and check them.", key_).c_str());
        return;
    }
    const ImVec4 red(0.85f, 0.1f, 0.1f, 1), green(0.1f, 0.55f, 0.1f, 1),
        grey(0.45f, 0.45f, 0.45f, 1);
    if (m.step == Impl::Step::Compiling)
        ImGui::TextWrapped("%s", tr("compiling your file..."));
    else if (m.step == Impl::Step::Checking)
        ImGui::TextWrapped("%s", tr("checking..."));
    else if (m.reloads == 0 && m.checked)
        ImGui::TextWrapped("%s", trf("checked in %.1f s", m.lastCheckS).c_str());
    else if (m.lastTotalS > 0)
        ImGui::TextWrapped("%s", trf("reloaded %.1f s after saving (compile %.1f s, check %.1f s)",
                                     m.lastTotalS, m.lastCompileS, m.lastCheckS)
                                     .c_str());
    if (!m.compileError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, red);
        ImGui::TextWrapped("%s", tr("Compile error (the picture shows your last good build):"));
        ImGui::TextWrapped("%s", m.compileError.c_str());
        ImGui::PopStyleColor();
    }
    if (!m.loadError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, red);
        ImGui::TextWrapped("%s", m.loadError.c_str());
        ImGui::PopStyleColor();
    }
    std::vector<TaskResult> all;
    for (const Task& t : lab_.tasks) {
        const TaskResult* r = result(t.id);
        TaskResult shown;
        shown.id = t.id;
        if (r) shown = *r;
        // Passed its checks, but crashed or looped on what the window draws: fails.
        const auto drawn = m.drawnFailures.find(t.id);
        if (r && drawn != m.drawnFailures.end()) {
            shown.status = Status::Fails;
            shown.caseName = tr("the input the window draws");
            shown.input = shown.expected = shown.got = "";
            shown.why = drawn->second;
            r = &shown;
        }
        all.push_back(shown);
        const char* state = !r                            ? tr("not checked")
                            : r->status == Status::Passes ? tr("passes")
                            : r->status == Status::Fails  ? tr("FAILS")
                                                          : tr("not done");
        ImGui::PushStyleColor(ImGuiCol_Text, !r                            ? grey
                                             : r->status == Status::Passes ? green
                                             : r->status == Status::Fails  ? red
                                                                           : grey);
        ImGui::TextWrapped("%s %s - %s", gradeMark(t.grade), tr(t.title), state);
        ImGui::PopStyleColor();
        if (r && r->status == Status::Fails) {
            ImGui::Indent();
            if (!r->caseName.empty())
                ImGui::TextWrapped("%s",
                                   trf("case \"%s\"", caseLabel(r->caseName).c_str()).c_str());
            if (!r->input.empty()) ImGui::TextWrapped("%s %s", tr("input:"), r->input.c_str());
            if (!r->expected.empty())
                ImGui::TextWrapped("%s %s", tr("expected:"), r->expected.c_str());
            if (!r->got.empty()) ImGui::TextWrapped("%s %s", tr("got:"), r->got.c_str());
            ImGui::PushStyleColor(ImGuiCol_Text, red);
            ImGui::TextWrapped("%s", r->why.c_str());
            ImGui::PopStyleColor();
            ImGui::Unindent();
        }
    }
    if (m.checked) {
        const int g = labGrade(lab_, all);
        ImGui::TextWrapped("%s",
                           g ? trf("grade: %s", gradeMark(g)).c_str() : tr("grade: none yet"));
    }
}

} // namespace wb::ex
