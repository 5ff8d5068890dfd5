// wb-check: the course's graded tasks checked with no window (`./wb check [labNN]`).
// One line per task (✓ / ✗ / · not done, and the first failing case for ✗), then the grade
// the course gives per lab: the highest mark whose task and all lower ones pass.
// Exit 0 only when at least one task was attempted and every attempted task passes.
//
//   wb-check [labNN ...] [--student NN=FILE.so] [--set student|reference]
//            [--expected FILE] [--record FILE] [--machine] [--ci stubs|reference|mutants]
// --ci is CI's three-way build (issue 18 item 6): stubs (every task not done, and the plain
// run exits non-zero), reference (every task passes, grade ⑤ everywhere), mutants (each
// typical mistake of the lab's Mutant list makes its task fail naming a case).
#include "common/exercise_run.h"
#include "common/headless_context.h"
#include "core/i18n.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <string>

using namespace wb;
using namespace wb::ex;

namespace {

std::string labOf(std::string a) {
    if (a.rfind("lab", 0) == 0) a = a.substr(3);
    return a.substr(0, 2);
}

void printResult(const Task& t, const TaskResult& r) {
    std::printf("  %s %s %-18s %s  [%s]", statusMark(r.status), gradeMark(t.grade), t.id.c_str(),
                tr(t.title), t.section);
    if (r.status == Status::NotDone) std::printf("  %s", tr("not done"));
    if (r.status == Status::Passes) std::printf("  %s", trf("%d cases", r.casesRun).c_str());
    std::printf("\n");
    if (r.status != Status::Fails) return;
    if (!r.caseName.empty())
        std::printf("      %s\n", trf("case \"%s\"", caseLabel(r.caseName).c_str()).c_str());
    if (!r.input.empty()) std::printf("        %-9s %s\n", tr("input"), r.input.c_str());
    if (!r.expected.empty()) std::printf("        %-9s %s\n", tr("expected"), r.expected.c_str());
    if (!r.got.empty()) std::printf("        %-9s %s\n", tr("got"), r.got.c_str());
    std::printf("        -> %s\n", r.why.c_str());
}

} // namespace

int main(int argc, char** argv) {
    std::set<std::string> only;
    std::map<std::string, std::string> studentPath;
    std::string set = "student", expectedFile, recordFile, ci;
    bool machine = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "wb-check: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--student") {
            const std::string v = value();
            const size_t eq = v.find('=');
            if (eq == std::string::npos) {
                std::fprintf(stderr, "wb-check: --student NN=FILE.so\n");
                return 2;
            }
            studentPath[labOf(v.substr(0, eq))] = v.substr(eq + 1);
        } else if (a == "--set") {
            set = value();
        } else if (a == "--expected") {
            expectedFile = value();
        } else if (a == "--record") {
            recordFile = value();
        } else if (a == "--machine") {
            machine = true;
        } else if (a == "--ci") {
            ci = value();
        } else if (a == "-h" || a == "--help") {
            std::printf(
                "usage: wb-check [labNN ...] [--student NN=FILE.so] [--set student|reference]\n"
                "                [--expected FILE] [--record FILE] [--machine]\n"
                "                [--ci stubs|reference|mutants]\n");
            return 0;
        } else if (!a.empty() && a[0] != '-') {
            only.insert(labOf(a));
        } else {
            std::fprintf(stderr, "wb-check: unknown option %s\n", a.c_str());
            return 2;
        }
    }
#ifdef WB_HANDOUT_EXPECTED
    // A handout has no reference answers: the outputs recorded from them when it was made.
    if (expectedFile.empty()) expectedFile = WB_HANDOUT_EXPECTED;
#endif
    if (ci == "reference") set = "reference";
    if (ci == "mutants") set = "mutants";

    // Handout: expected outputs recorded from the reference at handout time.
    Recording recorded;
    if (!expectedFile.empty()) {
        std::string error;
        if (!readRecording(expectedFile, recorded, error)) {
            std::fprintf(stderr, "wb-check: %s\n", error.c_str());
            return 2;
        }
    }
    if (!recordFile.empty()) {
        Recording rec;
        for (const LabExercises* lab : allLabExercises()) {
            if (!lab->reference) {
                std::fprintf(stderr, "wb-check: lab %s has no reference to record\n",
                             lab->lab.c_str());
                return 2;
            }
            recordLab(*lab, rec);
        }
        std::string error;
        if (!writeRecording(recordFile, rec, error)) {
            std::fprintf(stderr, "wb-check: %s\n", error.c_str());
            return 2;
        }
        std::printf("recorded %zu tasks to %s\n", rec.size(), recordFile.c_str());
        return 0;
    }

    RunOptions opt;
    if (!expectedFile.empty()) opt.expected = &recorded;
    std::unique_ptr<HeadlessContext> gl;
    opt.childSetup = [&gl] { gl = std::make_unique<HeadlessContext>(64, 64); };

    int attempted = 0, failed = 0, ciProblems = 0, labsSeen = 0;
    for (const LabExercises* lab : allLabExercises()) {
        if (!only.empty() && !only.count(lab->lab)) continue;
        ++labsSeen;
        std::string path = std::string(WB_EXERCISE_DIR) + "/lab" + lab->lab +
                           (set == "student" ? "" : "-" + set) + ".so";
        if (studentPath.count(lab->lab)) path = studentPath[lab->lab];
        StudentObject obj;
        const bool loaded = obj.load(path);
        if (!machine) std::printf("%s  (%s)\n", tr(lab->title), lab->file.c_str());
        if (!loaded) {
            if (machine)
                std::printf("E\t%s\n", obj.error().c_str());
            else
                std::printf("  %s\n",
                            trf("cannot load your code: %s", obj.error().c_str()).c_str());
            ++failed;
            ++ciProblems;
            continue;
        }
        opt.object = &obj;
        if (ci == "mutants") {
            for (const Task& t : lab->tasks) {
                int n = 0;
                for (const Mutant& m : lab->mutants)
                    if (m.task == t.id) ++n;
                if (n < 3) {
                    std::printf("  %s: only %d mutants (3 needed)\n", t.id.c_str(), n);
                    ++ciProblems;
                }
            }
            for (const Mutant& m : lab->mutants) {
                const Task* task = nullptr;
                for (const Task& t : lab->tasks)
                    if (t.id == m.task) task = &t;
                if (!task) {
                    std::printf("  mutant %d names no task %s\n", m.id, m.task.c_str());
                    ++ciProblems;
                    continue;
                }
                opt.mutant = m.id;
                const TaskResult r = runTask(*lab, *task, obj.table(), opt);
                const bool caught = r.status == Status::Fails && !r.caseName.empty();
                std::printf("  %s mutant %2d %-18s %-34s %s%s%s\n", caught ? "caught " : "MISSED ",
                            m.id, m.task.c_str(), m.what, caught ? "case \"" : "",
                            caught ? r.caseName.c_str() : "", caught ? "\"" : "");
                if (caught) std::printf("             -> %s\n", r.why.c_str());
                if (!caught) ++ciProblems;
            }
            opt.mutant = 0;
        }
        std::vector<TaskResult> results;
        for (const Task& t : lab->tasks) {
            const TaskResult r = runTask(*lab, t, obj.table(), opt);
            results.push_back(r);
            if (r.status != Status::NotDone) ++attempted;
            if (r.status == Status::Fails) ++failed;
            if (ci == "stubs" && r.status != Status::NotDone) ++ciProblems;
            if ((ci == "reference" || ci == "mutants") && r.status != Status::Passes) ++ciProblems;
            if (machine)
                std::printf("T\t%s\n", encodeResult(r).c_str());
            else if (ci != "mutants")
                printResult(t, r);
        }
        const int grade = labGrade(*lab, results);
        if (ci == "reference" && grade != 5) ++ciProblems;
        if (!machine) std::printf("  %s %s\n\n", tr("grade:"), gradeMark(grade));
    }
    if (labsSeen == 0) {
        std::fprintf(stderr, "wb-check: no such lab with exercises\n");
        return 2;
    }
    if (!ci.empty()) {
        std::printf("CI %s: %s\n", ci.c_str(), ciProblems == 0 ? "as expected" : "NOT as expected");
        return ciProblems == 0 ? 0 : 1;
    }
    if (machine) return 0;
    if (attempted == 0) {
        std::printf("%s\n", tr("Nothing attempted yet: every task is not done."));
        return 1;
    }
    return failed == 0 ? 0 : 1;
}
