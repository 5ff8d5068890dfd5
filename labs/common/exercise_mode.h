#pragma once
// The exercise mode of a lab in its window (issue 18, items 2 and 3): everything every lab
// needs once, so that a lab's own file gains only its tasks.
//
// A lab holds one ExerciseMode built from its LabExercises and:
//   - forwards key() to it first (`e` switches between the reference and your code);
//   - calls poll() at the start of draw(), and ORs busy() into its own busy();
//   - in draw(): when on(), takes studentTable<T>() (nullptr while not built / a compile
//     error) and calls the student's functions through call(taskId, f), which returns
//     std::nullopt when the task is not done, threw here, or crashed/timed out in the
//     isolated check (so a crashing function is never called inside the lab); draws the
//     student's result as the lab drew the answer, then the reference between
//     ghostBegin() and ghostEnd() (translucent, dashed lines) so the difference shows;
//   - calls gui() in its panel: the task list ③④⑤ with not done / passes / fails, the first
//     failing case (input, expected, got, what it usually means), the build state and a
//     compile error with file:line and message.
// Live edit: ExerciseMode watches the lab's exercises.cpp (mtime, polled every 0.5 s while
// the window is open); on a change it compiles it alone into a new shared object with the
// flags of the build (build/exercises/labNN.compile), loads it and re-runs the checks in a
// child process (wb-check --lab NN --student SO --machine), without restarting the lab.
#include "common/exercise_check.h"
#include "common/lab.h"

#include <memory>
#include <optional>
#include <string>

namespace wb::ex {

class ExerciseMode {
  public:
    // `key` toggles the mode: 'e' unless the lab already uses it ('E' in labs 02 and 05).
    explicit ExerciseMode(const LabExercises& lab, char key = 'e');
    ~ExerciseMode();
    ExerciseMode(const ExerciseMode&) = delete;
    ExerciseMode& operator=(const ExerciseMode&) = delete;

    bool key(int key);       // the mode's key: toggle; true when used
    KeyHelp keyHelp() const; // the line for the lab's keys()
    bool on() const;         // drawing your code (false: the reference, as the lab always did)
    void setOn(bool on);
    // File watch, compile and check progress; true when something changed. `watch`: keep
    // watching the file (false in headless renders, which must come to an end).
    bool poll(bool watch = true);
    bool busy() const; // compiling or checking, or on and watching (see pollMs)
    // For the lab's Lab::pollMs() / poll(): the window then watches the file every 0.5 s
    // without redrawing (busy() stops counting the watch once the shell polls).
    int pollMs() const;
    bool shellPoll();
    void gui(); // the panel section

    // The student's table (Table of the lab's exercises.h), nullptr when none is loaded.
    template <class Table> const Table* studentTable() const {
        return static_cast<const Table*>(studentRaw());
    }
    template <class Table> const Table* referenceTable() const {
        return static_cast<const Table*>(lab_.reference);
    }
    // f() calls the student's function for drawing; nullopt when the task's check said not
    // done / crashed / timed out, or f throws (NotDone or anything else).
    template <class F>
    auto call(const std::string& taskId, F&& f) const -> std::optional<decltype(f())> {
        if (!callable(taskId)) return std::nullopt;
        try {
            return f();
        } catch (...) {
            return std::nullopt;
        }
    }
    const TaskResult* result(const std::string& taskId) const; // nullptr before the first check

    // The reference drawn as a ghost: translucent (alpha kGhostAlpha), lines dashed.
    static void ghostBegin();
    static void ghostEnd();
    static constexpr float kGhostAlpha = 0.35f;

  private:
    const void* studentRaw() const;
    bool callable(const std::string& taskId) const;
    const LabExercises& lab_;
    char key_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace wb::ex
