#pragma once
// The exercise mode of a lab in its window (issue 18, items 2 and 3): everything every lab
// needs once, so that a lab's own file gains only its tasks.
//
// A lab holds one ExerciseMode built from its LabExercises and:
//   - forwards key() to it first (`e` switches between the reference and your code);
//   - calls poll() at the start of draw(), and ORs busy() into its own busy();
//   - in draw(): when on(), takes studentTable<T>() (nullptr while not built / a compile
//     error) and calls the student's functions through call(taskId, f, drawn inputs...), which
//     returns std::nullopt when the task is not done, threw here, or crashed/timed out in the
//     isolated check or on the drawn input (each new drawn input is tried in a forked child
//     first, so a crashing function is never called inside the lab); draws the
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

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

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
    // f() calls the student's function for drawing; `drawn...` are the inputs it reads
    // (numbers, glm vectors and matrices, vectors of them). The first time a task meets an
    // input, f runs once in a forked child with a time limit: a function that passes every
    // check but crashes or loops on what the window draws then fails in the panel ("crashed
    // on the drawn input: SIGSEGV") and is not called again until the file is saved, instead
    // of taking the lab down. nullopt when the task is not done, crashed/timed out in its
    // check or on a drawn input, or f throws (NotDone or anything else).
    template <class F, class... In>
    auto call(const std::string& taskId, F&& f, const In&... drawn) const
        -> std::optional<decltype(f())> {
        if (!callable(taskId)) return std::nullopt;
        if (!tryInChild(taskId, inputKey(drawn...), [&] { (void)f(); })) return std::nullopt;
        return callTried(taskId, f);
    }
    // The same without the child: only for calls whose inputs a tryInChild() of the same
    // frame already ran (a loop over a mesh or a picture, tried once as a whole).
    template <class F>
    auto callTried(const std::string& taskId, F&& f) const -> std::optional<decltype(f())> {
        if (!callable(taskId)) return std::nullopt;
        try {
            return f();
        } catch (...) {
            return std::nullopt;
        }
    }
    // Runs body() in a forked child (at most kDrawnTimeLimitS); true when it returned or
    // threw. Cached per task and `key` until the next reload; false (and the task failing in
    // the panel) after a signal, a timeout or exit(). body must not touch GL or ImGui.
    bool tryInChild(const std::string& taskId, uint64_t key,
                    const std::function<void()>& body) const;
    // A key for tryInChild(): the bytes of plain values (FNV-1a); hashBytes() adds an array.
    static void hashBytes(uint64_t& h, const void* p, size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (size_t i = 0; i < n; ++i)
            h = (h ^ b[i]) * 1099511628211ull;
    }

    template <class... In> static uint64_t inputKey(const In&... in) {
        uint64_t h = 1469598103934665603ull;
        (hashValue(h, in), ...);
        return h;
    }
    // A drawn input takes microseconds; the longest drawn call (lab 07's picture, ~0.3 s on
    // a loaded 2-core machine) times 5 leaves room, and the window stalls at most this once.
    static constexpr double kDrawnTimeLimitS = 2.0;
    const TaskResult* result(const std::string& taskId) const; // nullptr before the first check

    // The reference drawn as a ghost: translucent (alpha kGhostAlpha), lines dashed.
    static void ghostBegin();
    static void ghostEnd();
    static constexpr float kGhostAlpha = 0.35f;

  private:
    template <class T> static void hashValue(uint64_t& h, const T& v) {
        static_assert(std::is_trivially_copyable_v<T>, "pass plain values as the drawn input");
        hashBytes(h, &v, sizeof v);
    }
    template <class T> static void hashValue(uint64_t& h, const std::vector<T>& v) {
        const size_t n = v.size();
        hashBytes(h, &n, sizeof n);
        for (const T& x : v)
            hashValue(h, x);
    }
    const void* studentRaw() const;
    bool callable(const std::string& taskId) const;
    const LabExercises& lab_;
    char key_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace wb::ex
