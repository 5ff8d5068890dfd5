#pragma once
// Running the checks of exercise_check.h: loading a student's shared object, running one
// task isolated in a forked child with a time limit, recorded expected outputs (handout),
// and the machine-readable lines the window reads from `wb-check --machine`.
#include "common/exercise_check.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace wb::ex {

// A student's (or reference / mutant) shared object, loaded with dlopen.
class StudentObject {
  public:
    StudentObject() = default;
    ~StudentObject();
    StudentObject(const StudentObject&) = delete;
    StudentObject& operator=(const StudentObject&) = delete;
    // Loads `path`; false with error() naming it and why (missing, no table, old ABI).
    bool load(const std::string& path);
    const void* table() const { return table_; }
    bool hasMutants() const { return setMutant_ != nullptr; }
    void setMutant(int n) const {
        if (setMutant_) setMutant_(n);
    }
    const std::string& error() const { return error_; }

  private:
    void* handle_ = nullptr;
    const void* table_ = nullptr;
    void (*setMutant_)(int) = nullptr;
    std::string error_;
};

// Expected outputs recorded from the reference: task id -> case name -> values.
using Recording = std::map<std::string, std::map<std::string, Values>>;
bool writeRecording(const std::string& path, const Recording& rec, std::string& error);
bool readRecording(const std::string& path, Recording& rec, std::string& error);
// Runs the reference on every case of every task of `lab` (in this process).
void recordLab(const LabExercises& lab, Recording& rec);

struct RunOptions {
    const Recording* expected = nullptr; // use these instead of lab.reference (handout)
    std::function<void()> childSetup;    // in the child before a needsGl task (a GL context)
    int mutant = 0;                      // set in the child before running (mutant objects)
    const StudentObject* object = nullptr;
};

// Runs `task` of `lab` against the student's `table` in a forked child with the task's
// time limit; a signal, a timeout or an exception outside the cases becomes Fails.
TaskResult runTask(const LabExercises& lab, const Task& task, const void* studentTable,
                   const RunOptions& options);

// One line per result for `wb-check --machine` and back (fields tab-separated, escaped).
std::string encodeResult(const TaskResult& r);
bool decodeResult(const std::string& line, TaskResult& r);

// A case's name as the student reads it: names are English keys (the handout's recordings
// are looked up by them), marked N_() in the checks and translated here when shown; "seed N"
// and one number among the words ("degree %s") are kept as numbers.
std::string caseLabel(const std::string& name);

const char* statusMark(Status s); // "✓", "✗", "·"
const char* gradeMark(int grade); // "③" "④" "⑤", "-" for 0

} // namespace wb::ex
