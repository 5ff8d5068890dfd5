#pragma once
// The check side of the graded exercises (issue 18): how a lab declares its tasks and how
// each task is checked. See exercise.h for the files of a lab and the student's side.
//
// A task is data-driven so that the same description serves the window, `./wb check`, CI
// and the handout (which has no reference and compares with outputs recorded from it):
//   cases()   the inputs, deterministic: seeded random ones plus the hard cases of
//             DESIGN.md and the degenerate cases the course defines. Each Case has a name
//             that a student can act on ("seed 3", "light parallel to the line").
//   run()     calls ONE function of the exercise table (the student's or the reference's,
//             same Table type) on a case's inputs and packs its result into Values.
//             The student's NotDone propagates (the runner reports "not done"); any other
//             exception is that case failing ("threw: ...").
//   compare() expected (the reference's Values, or the recorded ones in a handout) against
//             got; ok, or one sentence saying what this kind of difference usually means
//             (transposed, sign of w, forgot to normalise...). Every tolerance it uses
//             carries a comment saying where its number comes from.
//   showIn / showOut  optional: how a case's input / an output reads in a message
//             (default: the numbers, %.6g).
// The runner (wb-check, and the window through it) calls each task in a forked child with a
// time limit: a crash or an endless loop in student code is that task failing with the
// signal or "timeout", never the end of the lab.
//
// Grades: a task has grade 3, 4 or 5 (③④⑤). A lab's grade is the highest mark m such that
// every task of grade <= m passes (several tasks may share a grade).
#include "common/exercise.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace wb::ex {

using Values = std::vector<double>;

struct Case {
    std::string name; // names the case in messages: "seed 7", "S on the line"
    Values in;
};

struct Verdict {
    bool ok = true;
    std::string why; // when !ok: one sentence on what this kind of difference usually means
    static Verdict pass() { return {}; }
    static Verdict fail(std::string sentence) { return {false, std::move(sentence)}; }
};

struct Task {
    std::string id;           // unique in the course, "01.mirror": --task, mutants, recordings
    int grade = 3;            // 3, 4 or 5
    const char* title = "";   // N_("Mirror image in the line KL"); shown through tr()
    const char* section = ""; // where the course asks it: "§2.1 task 1; (1.10)"
    std::function<std::vector<Case>()> cases;
    std::function<Values(const void* table, const Values& in)> run;
    std::function<Verdict(const Values& in, const Values& expected, const Values& got)> compare;
    std::function<std::string(const Values& in)> showIn;   // optional
    std::function<std::string(const Values& out)> showOut; // optional
    bool needsGl = false; // the child gets a current OSMesa context (e.g. lab 03 reads GL matrices)
    // False when compare() judges `got` from the input alone (e.g. lab 02's cubes): nothing is
    // recorded for the handout (the recording would be the answer), expected is empty.
    bool needsExpected = true;
    // Optional: what compare() needs of the reference's output, when less than all of it (e.g.
    // a mesh's area, not its vertices). Applied to the reference's output in every build and
    // to what --record writes, so a handout records only this (the full output would be the
    // answer) and compare() sees the same numbers with or without a reference.
    std::function<Values(const Values& referenceOut)> expectedDigest;
    double timeLimitSeconds = 5.0; // for all cases together; endless loops end here
};

// A typical mistake planted in exercises_reference.cpp behind WB_MUTANT(id): CI checks that
// it makes `task` fail with a message naming a case.
struct Mutant {
    int id = 0;            // the n of WB_MUTANT(n), unique in the lab
    std::string task;      // Task::id it must make fail
    const char* what = ""; // "transposed matrix"
};

struct LabExercises {
    std::string lab;                 // "01"
    const char* title = "";          // N_("Lab 01 - affine maps")
    std::string file;                // the student's file, relative to the repository root
    const void* reference = nullptr; // wbExerciseReference_labNN(); nullptr in a handout
    std::vector<Task> tasks;
    std::vector<Mutant> mutants;
};

// ----- Results (what the runner reports and the panel shows) -----------------------------
enum class Status { NotDone, Passes, Fails };

struct TaskResult {
    std::string id;
    Status status = Status::NotDone;
    // For Fails: the first failing case.
    std::string caseName, input, expected, got,
        why; // why: the Verdict's sentence, a signal, "timeout"
    int casesRun = 0;
};

// The course's grade from a lab's results: the highest m in {3,4,5} with every task of
// grade <= m passing; 0 when even the ③ tasks do not pass (or there are none).
int labGrade(const LabExercises& lab, const std::vector<TaskResult>& results);

// ----- Helpers for compare() and show*() ---------------------------------------------------
// Numbers as "(a, b, c)" / a 3x3 or 4x4 column-major matrix as rows "[a b c; d e f; g h i]".
std::string showNumbers(const Values& v);
std::string showMatrix(const Values& colMajor, int n);

// |a - b| <= tol * max(1, |a|, |b|) for every component (same sizes required).
bool allNear(const Values& a, const Values& b, double tol);
// expected == k * got for some k != 0 (homogeneous matrices / vectors), with the relative
// tolerance tol on the components after scaling by the largest |component|. Zero got is
// never equal to a non-zero expected. Also true for two zero vectors.
bool equalUpToFactor(const Values& expected, const Values& got, double tol);
// A homogeneous n x n matrix (column-major) against the expected one: the steps every lab's
// matrix task takes first. pass() when equal up to a factor (tol as equalUpToFactor);
// fail(nonFinite) for a NaN/Inf entry, fail(transposed) for the transpose of the answer,
// fail(zero) for the zero matrix (no map at all); nullopt when none of these: the lab then
// says what its own kind of difference means.
std::optional<Verdict> compareHomogeneous(const Values& expected, const Values& got, int n,
                                          double tol, const char* nonFinite, const char* transposed,
                                          const char* zero);
// Same, with k > 0 (directions: a normal may not flip).
bool equalUpToPositiveFactor(const Values& expected, const Values& got, double tol);

// ----- Running (wb-check; the window runs wb-check as a child process) ----------------------
// Every lab registered with add_exercises(), in course order.
const std::vector<const LabExercises*>& allLabExercises();

} // namespace wb::ex
