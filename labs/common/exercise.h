#pragma once
// The student's side of the graded exercises (issue 18). Included by a lab's
// exercises.cpp (the stubs a student edits) and exercises_reference.cpp (the answers);
// header-only and free of core, GL and ImGui, because exercises.cpp is compiled on its own
// into a shared object that the running lab reloads (live edit) and wb-check loads.
//
// ---------------------------------------------------------------------------------------
// THE CONTRACT FOR A LAB-WRITER (read with exercise_check.h, which has the check side)
//
// Files of lab NN in labs/NN-name/:
//   exercises.h            the task functions' declarations in namespace wb::labNN, each
//                          with its course comment (what, §/formula, input ranges,
//                          degenerate cases), and `struct Table` of plain function
//                          pointers to them, in task order. Includes only glm/std and this
//                          header. No core: the student's shared object links nothing.
//   exercises.cpp          the student's file: the same functions whose bodies are
//                          WB_NOT_DONE(); (never a plausible wrong value), then once, at
//                          global scope:  WB_EXERCISE_TABLE(wb::labNN::Table, labNN, {&f1, &f2})
//   exercises_reference.cpp the same functions answered, the same WB_EXERCISE_TABLE line,
//                          and the mutants (typical mistakes) inside the answers:
//                              if (WB_MUTANT(1)) return glm::transpose(m); // transposed
//                          WB_MUTANT(n) is `false` except in the CI's mutant build, where
//                          wb-check switches on one n at a time. Each n is listed in the
//                          lab's checks (Mutant{n, "task id", "what mistake"}), >= 3 per task.
//   exercise_checks.cpp    the tasks and their checks (exercise_check.h):
//                              const wb::ex::LabExercises& wbExercises_labNN();
//   lab.cmake              after add_lab():  add_exercises(NN <dir> CHECKS exercise_checks.cpp)
//                          (labs/CMakeLists.txt) builds the student's shared object, the
//                          reference and mutant objects for CI, registers the lab with
//                          wb-check and links the reference + checks into the lab.
// How the lab uses them (exercise_mode.h): an ExerciseMode member handles the key `e`
// (reference <-> your code), the task panel, the file watch and reload; draw() asks it for
// the student's table and draws the student's result, and the reference through
// ghostBegin()/ghostEnd() (translucent, dashed) so the difference shows.
// ---------------------------------------------------------------------------------------

// Bumped when Table layouts or the loader's symbols change in a way that needs a rebuild.
#define WB_EXERCISE_ABI 1

namespace wb::ex {

// Thrown by a stub: the task is reported "not done", never "fails".
struct NotDone {};

} // namespace wb::ex

#define WB_NOT_DONE()                                                                              \
    throw ::wb::ex::NotDone {}

#if defined(WB_EXERCISE_MUTANTS)
// Only in the CI's mutant build of exercises_reference.cpp: the mutant wb-check switched on.
inline int wbExerciseMutant = 0;
#define WB_MUTANT(n) (wbExerciseMutant == (n))
#define WB_EXERCISE_MUTANT_SETTER                                                                  \
    extern "C" __attribute__((visibility("default"))) void wb_exercise_set_mutant(int n) {         \
        wbExerciseMutant = n;                                                                      \
    }
#else
#define WB_MUTANT(n) false
#define WB_EXERCISE_MUTANT_SETTER
#endif

#if defined(WB_EXERCISE_MODULE)
// The shared object's two entry points (found with dlsym; the rest is hidden by
// -fvisibility=hidden, so a reloaded object never binds to the lab's own copies).
#define WB_EXERCISE_TABLE(Type, lab, ...)                                                          \
    extern "C" __attribute__((visibility("default"))) const void* wb_exercise_table() {            \
        static const Type table = __VA_ARGS__;                                                     \
        return &table;                                                                             \
    }                                                                                              \
    extern "C" __attribute__((visibility("default"))) int wb_exercise_abi() {                      \
        return WB_EXERCISE_ABI;                                                                    \
    }                                                                                              \
    WB_EXERCISE_MUTANT_SETTER
#else
// Linked into the lab and into wb-check: the reference table, reached as
// wbExerciseReference_labNN() (nullptr in a handout, where the answers are not shipped).
#define WB_EXERCISE_TABLE(Type, lab, ...)                                                          \
    const void* wbExerciseReference_##lab();                                                       \
    const void* wbExerciseReference_##lab() {                                                      \
        static const Type table = __VA_ARGS__;                                                     \
        return &table;                                                                             \
    }
#endif
