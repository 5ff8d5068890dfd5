#include "common/exercise_run.h"

#include "core/i18n.h"

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <sstream>

namespace wb::ex {

StudentObject::~StudentObject() {
    // Not dlclose()d: a table pointer may still be held by a caller, and the objects are
    // small (one per reload).
}

bool StudentObject::load(const std::string& path) {
    handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* e = dlerror();
        error_ = path + ": " + (e ? e : "cannot load");
        return false;
    }
    auto abi = reinterpret_cast<int (*)()>(dlsym(handle_, "wb_exercise_abi"));
    auto table = reinterpret_cast<const void* (*)()>(dlsym(handle_, "wb_exercise_table"));
    if (!abi || !table) {
        error_ = path + ": no WB_EXERCISE_TABLE(...) line (see labs/common/exercise.h)";
        return false;
    }
    if (abi() != WB_EXERCISE_ABI) {
        error_ = path + ": built for another version of exercise.h; rebuild it";
        return false;
    }
    setMutant_ = reinterpret_cast<void (*)(int)>(dlsym(handle_, "wb_exercise_set_mutant"));
    table_ = table();
    return true;
}

namespace {

std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '\t')
            o += "\\t";
        else if (c == '\n')
            o += "\\n";
        else if (c == '\\')
            o += "\\\\";
        else
            o += c;
    }
    return o;
}

std::string unescape(const std::string& s) {
    std::string o;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size()) {
            const char n = s[++i];
            o += n == 't' ? '\t' : n == 'n' ? '\n' : n;
        } else {
            o += s[i];
        }
    }
    return o;
}

std::vector<std::string> splitTabs(const std::string& line) {
    std::vector<std::string> f;
    size_t start = 0;
    for (;;) {
        const size_t t = line.find('\t', start);
        f.push_back(line.substr(start, t == std::string::npos ? std::string::npos : t - start));
        if (t == std::string::npos) break;
        start = t + 1;
    }
    return f;
}

void writeAll(int fd, const std::string& s) {
    size_t done = 0;
    while (done < s.size()) {
        const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += size_t(n);
    }
}

std::string show(const std::function<std::string(const Values&)>& f, const Values& v) {
    return f ? f(v) : showNumbers(v);
}

// The cases, in this process (the child): progress lines "C\t<case>" and the result "R\t...".
TaskResult runCases(const LabExercises& lab, const Task& task, const void* student,
                    const RunOptions& opt, int fd) {
    TaskResult r;
    r.id = task.id;
    auto fail = [&](const Case& c, const Values& exp, const std::string& got, std::string why) {
        r.status = Status::Fails;
        r.caseName = c.name;
        r.input = show(task.showIn, c.in);
        r.expected = show(task.showOut, exp);
        r.got = got;
        r.why = std::move(why);
        return r;
    };
    for (const Case& c : task.cases()) {
        if (fd >= 0) writeAll(fd, "C\t" + escape(c.name) + "\n");
        Values exp;
        if (!task.needsExpected) {
            // compare() needs only the input and got.
        } else if (opt.expected) {
            const auto t = opt.expected->find(task.id);
            const bool found = t != opt.expected->end() && t->second.count(c.name);
            if (!found)
                return fail(c, {}, "-",
                            "no expected output recorded for this case (the handout is older than "
                            "the check)");
            exp = t->second.at(c.name);
        } else {
            exp = task.run(lab.reference, c.in);
            if (task.expectedDigest) exp = task.expectedDigest(exp);
        }
        Values got;
        try {
            got = task.run(student, c.in);
        } catch (const NotDone&) {
            r.status = Status::NotDone;
            return r;
        } catch (const std::exception& e) {
            return fail(c, exp, "-", std::string("threw an exception: ") + e.what());
        } catch (...) {
            return fail(c, exp, "-", "threw an exception");
        }
        ++r.casesRun;
        const Verdict v = task.compare(c.in, exp, got);
        if (!v.ok) return fail(c, exp, show(task.showOut, got), v.why);
    }
    r.status = Status::Passes;
    return r;
}

} // namespace

TaskResult runTask(const LabExercises& lab, const Task& task, const void* studentTable,
                   const RunOptions& opt) {
    TaskResult r;
    r.id = task.id;
    if (!studentTable) return r; // nothing built: not done
    if (!opt.expected && !lab.reference && task.needsExpected) {
        r.status = Status::Fails;
        r.why = "no reference and no recorded outputs to compare with";
        return r;
    }
    int fds[2];
    if (pipe(fds) != 0) {
        r.status = Status::Fails;
        r.why = std::string("cannot start the check: ") + std::strerror(errno);
        return r;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid == 0) {
        ::close(fds[0]);
        dup2(2, 1); // the student's prints must not mix with --machine lines
        // A crash is reported by its signal, also where a sanitizer would catch it and exit 1.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
            signal(sig, SIG_DFL);
        if (task.needsGl && opt.childSetup) opt.childSetup();
        if (opt.object) opt.object->setMutant(opt.mutant);
        TaskResult res;
        try {
            res = runCases(lab, task, studentTable, opt, fds[1]);
        } catch (const std::exception& e) {
            res.id = task.id;
            res.status = Status::Fails;
            res.why = std::string("the check itself threw: ") + e.what();
        } catch (...) {
            res.id = task.id;
            res.status = Status::Fails;
            res.why = "the check itself threw";
        }
        writeAll(fds[1], "R\t" + encodeResult(res) + "\n");
        ::close(fds[1]);
        _exit(0);
    }
    ::close(fds[1]);
    if (pid < 0) {
        ::close(fds[0]);
        r.status = Status::Fails;
        r.why = std::string("cannot start the check: ") + std::strerror(errno);
        return r;
    }
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::milliseconds(long(task.timeLimitSeconds * 1000));
    std::string out;
    bool timedOut = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                              deadline - std::chrono::steady_clock::now())
                              .count();
        if (left <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int n = ::poll(&p, 1, int(left));
        if (n < 0 && errno == EINTR) continue;
        if (n == 0) continue;
        char buf[4096];
        const ssize_t got = ::read(fds[0], buf, sizeof buf);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        out.append(buf, size_t(got));
    }
    ::close(fds[0]);
    if (timedOut) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    std::string lastCase;
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("C\t", 0) == 0) lastCase = unescape(line.substr(2));
        if (line.rfind("R\t", 0) == 0 && decodeResult(line.substr(2), r)) return r;
    }
    r.status = Status::Fails;
    r.caseName = lastCase;
    try { // the case's input, from the (deterministic) case list
        for (const Case& c : task.cases())
            if (c.name == lastCase) r.input = show(task.showIn, c.in);
    } catch (...) {
    }
    if (timedOut) {
        char buf[120];
        std::snprintf(
            buf, sizeof buf,
            "no answer within %.0f s: an endless loop (a loop whose condition never changes?)",
            task.timeLimitSeconds);
        r.why = buf;
    } else if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        r.why = std::string("crashed with signal ") + std::to_string(sig) + " (" + strsignal(sig) +
                ")" + (sig == SIGSEGV ? ": an index out of range or a null pointer?" : "");
    } else {
        r.why = "the check ended without a result (exit status " +
                std::to_string(WEXITSTATUS(status)) + "; exit() called in the exercise?)";
    }
    return r;
}

std::string encodeResult(const TaskResult& r) {
    const char* s = r.status == Status::Passes  ? "pass"
                    : r.status == Status::Fails ? "fail"
                                                : "notdone";
    return escape(r.id) + "\t" + s + "\t" + std::to_string(r.casesRun) + "\t" + escape(r.caseName) +
           "\t" + escape(r.input) + "\t" + escape(r.expected) + "\t" + escape(r.got) + "\t" +
           escape(r.why);
}

bool decodeResult(const std::string& line, TaskResult& r) {
    const std::vector<std::string> f = splitTabs(line);
    if (f.size() != 8) return false;
    r.id = unescape(f[0]);
    r.status = f[1] == "pass" ? Status::Passes : f[1] == "fail" ? Status::Fails : Status::NotDone;
    r.casesRun = std::atoi(f[2].c_str());
    r.caseName = unescape(f[3]);
    r.input = unescape(f[4]);
    r.expected = unescape(f[5]);
    r.got = unescape(f[6]);
    r.why = unescape(f[7]);
    return true;
}

void recordLab(const LabExercises& lab, Recording& rec) {
    for (const Task& t : lab.tasks)
        if (t.needsExpected)
            for (const Case& c : t.cases())
                rec[t.id][c.name] = t.expectedDigest ? t.expectedDigest(t.run(lab.reference, c.in))
                                                     : t.run(lab.reference, c.in);
}

bool writeRecording(const std::string& path, const Recording& rec, std::string& error) {
    std::ofstream f(path);
    if (!f) {
        error = path + ": cannot write";
        return false;
    }
    f << "# Expected outputs recorded from the reference answers (wb-check --record).\n";
    char buf[40];
    for (const auto& [task, cases] : rec)
        for (const auto& [name, values] : cases) {
            f << escape(task) << '\t' << escape(name);
            for (double v : values) {
                std::snprintf(buf, sizeof buf, "\t%.17g", v);
                f << buf;
            }
            f << '\n';
        }
    if (!f) {
        error = path + ": write failed";
        return false;
    }
    return true;
}

bool readRecording(const std::string& path, Recording& rec, std::string& error) {
    std::ifstream f(path);
    if (!f) {
        error = path + ": cannot read";
        return false;
    }
    std::string line;
    int n = 0;
    while (std::getline(f, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> fields = splitTabs(line);
        if (fields.size() < 2) {
            error = path + ":" + std::to_string(n) + ": expected task<TAB>case<TAB>values";
            return false;
        }
        Values v;
        for (size_t i = 2; i < fields.size(); ++i) {
            char* end = nullptr;
            v.push_back(std::strtod(fields[i].c_str(), &end));
            if (end == fields[i].c_str()) {
                error = path + ":" + std::to_string(n) + ": not a number: " + fields[i];
                return false;
            }
        }
        rec[unescape(fields[0])][unescape(fields[1])] = v;
    }
    return true;
}

std::string caseLabel(const std::string& name) {
    if (const char* t = tr(name.c_str()); t != name.c_str()) return t;
    std::string out, rest = name;
    size_t i = 0;
    // "seed 7", "seed 7: ...", "seed 7 (...)": the number kept, the words translated.
    if (rest.rfind("seed ", 0) == 0 && rest.size() > 5 && std::isdigit((unsigned char)rest[5])) {
        i = 5;
        while (i < rest.size() && std::isdigit((unsigned char)rest[i]))
            ++i;
        out = trf("seed %s", rest.substr(5, i - 5).c_str());
        const size_t sep = rest.compare(i, 2, ": ") == 0 ? 2 : rest.compare(i, 1, " ") == 0 ? 1 : 0;
        out += rest.substr(i, sep);
        rest = rest.substr(i + sep);
    }
    if (rest.empty()) return out;
    const char* whole = tr(rest.c_str());
    if (whole != rest.c_str()) return out + whole;
    // One number in the words ("degree 4", "5 patches"): the words with %s, the number kept.
    const size_t a = rest.find_first_of("0123456789");
    if (a != std::string::npos) {
        size_t b = a;
        while (b < rest.size() && (std::isdigit((unsigned char)rest[b]) || rest[b] == '.' ||
                                   rest[b] == 'e' || rest[b] == '-'))
            ++b;
        const std::string pattern = rest.substr(0, a) + "%s" + rest.substr(b);
        const char* t = tr(pattern.c_str());
        if (t != pattern.c_str()) {
            std::string r = t;
            const size_t at = r.find("%s");
            if (at != std::string::npos) r.replace(at, 2, rest.substr(a, b - a));
            return out + r;
        }
    }
    return out + rest; // not in the catalogue: as written
}

const char* statusMark(Status s) {
    return s == Status::Passes ? "\u2713" : s == Status::Fails ? "\u2717" : "\u00b7";
}

const char* gradeMark(int grade) {
    switch (grade) {
    case 3:
        return "\u2462";
    case 4:
        return "\u2463";
    case 5:
        return "\u2464";
    default:
        return "-";
    }
}

} // namespace wb::ex
