# Graded exercises (issue 18; contract in common/exercise.h).
#
# add_exercises(<NN> <dir> CHECKS <check sources>) in labs/<dir>/lab.cmake, after add_lab():
#   wb_ex_<NN>          static: the checks + exercises_reference.cpp (the reference table),
#                       linked into lab<dir> (window), lab<dir>_headless and wb-check;
#   wb_ex_<NN>_student  build/exercises/lab<NN>.so from exercises.cpp: the student's code,
#                       loaded at run time by the lab and by wb-check (never linked in);
#   wb_ex_<NN>_reference, wb_ex_<NN>_mutants  the same from exercises_reference.cpp, as CI's
#                       "reference copied in" and "mutants" builds (WB_EXERCISE_MUTANTS);
#   build/exercises/lab<NN>.compile  the student object's compile command with the build's
#                       own flags, which the running lab uses to rebuild it on save.
set(WB_EXERCISE_DIR ${CMAKE_BINARY_DIR}/exercises)
file(MAKE_DIRECTORY ${WB_EXERCISE_DIR})
add_custom_target(exercises-student)
add_custom_target(exercises-ci)

function(add_exercises nn dir)
  cmake_parse_arguments(EX "" "" "CHECKS" ${ARGN})
  set(src ${CMAKE_CURRENT_SOURCE_DIR}/${dir})
  set(exe lab${dir})
  list(TRANSFORM EX_CHECKS PREPEND ${src}/)

  add_library(wb_ex_${nn} STATIC ${EX_CHECKS} ${src}/exercises_reference.cpp)
  target_include_directories(wb_ex_${nn} PUBLIC ${src} ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(wb_ex_${nn} PRIVATE ${WB_WARNINGS})
  target_link_libraries(wb_ex_${nn} PUBLIC wb_exercise)
  target_link_libraries(${exe} PRIVATE wb_ex_${nn})
  target_link_libraries(${exe}_headless PUBLIC wb_ex_${nn})
  target_compile_definitions(${exe} PRIVATE WB_EXERCISES=1)
  target_compile_definitions(${exe}_headless PUBLIC WB_EXERCISES=1)

  set(kinds student reference mutants)
  if(WB_HANDOUT)
    set(kinds student) # no answers to build
  endif()
  foreach(kind IN LISTS kinds)
    if(kind STREQUAL student)
      set(file ${src}/exercises.cpp)
      set(out lab${nn})
    else()
      set(file ${src}/exercises_reference.cpp)
      set(out lab${nn}-${kind})
    endif()
    add_library(wb_ex_${nn}_${kind} MODULE ${file})
    set_target_properties(wb_ex_${nn}_${kind} PROPERTIES PREFIX "" OUTPUT_NAME ${out}
      LIBRARY_OUTPUT_DIRECTORY ${WB_EXERCISE_DIR} CXX_VISIBILITY_PRESET hidden)
    target_include_directories(wb_ex_${nn}_${kind} PRIVATE ${src} ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_definitions(wb_ex_${nn}_${kind} PRIVATE WB_EXERCISE_MODULE=1)
    if(kind STREQUAL mutants)
      target_compile_definitions(wb_ex_${nn}_${kind} PRIVATE WB_EXERCISE_MUTANTS=1)
    endif()
    target_compile_options(wb_ex_${nn}_${kind} PRIVATE ${WB_WARNINGS})
    # glm only, as a system header (no -Werror on it).
    target_link_libraries(wb_ex_${nn}_${kind} PRIVATE glm::glm)
    if(kind STREQUAL student)
      add_dependencies(exercises-student wb_ex_${nn}_${kind})
    else()
      add_dependencies(exercises-ci wb_ex_${nn}_${kind})
    endif()
  endforeach()

  # The student object's compile line, as the build makes it (flags, definitions, includes),
  # for the lab's live reload: `sh lab<NN>.compile SOURCE OUTPUT.so`.
  set(t wb_ex_${nn}_student)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" bt)
  set(flags "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${bt}} ${CMAKE_SHARED_LIBRARY_CXX_FLAGS}")
  string(APPEND flags " -std=c++17 -fvisibility=hidden")
  string(APPEND flags " $<JOIN:$<TARGET_PROPERTY:${t},COMPILE_OPTIONS>, >")
  string(APPEND flags " -D$<JOIN:$<TARGET_PROPERTY:${t},COMPILE_DEFINITIONS>, -D>")
  string(APPEND flags " -I$<JOIN:$<TARGET_PROPERTY:${t},INCLUDE_DIRECTORIES>, -I>")
  # glm and the standard library precompiled once with these flags (common/exercise_pch.h):
  # the reload's compile parses none of it again, about half the time (measured at load 22:
  # lab 08 3.5 -> 1.8 s, lab 07 2.3 -> 1.1 s, lab 01 1.3 -> 0.75 s), for 57 MB in build/
  # and ~9 s of build time once. Every lab's flags are the same but for -I of its own folder.
  set(pchdir ${WB_EXERCISE_DIR}/pch)
  if(NOT TARGET exercise-pch)
    file(MAKE_DIRECTORY ${pchdir})
    configure_file(${CMAKE_CURRENT_SOURCE_DIR}/common/exercise_pch.h ${pchdir}/exercise_pch.h COPYONLY)
    file(GENERATE OUTPUT ${pchdir}/build_pch.sh CONTENT "#!/bin/sh\nexec ${CMAKE_CXX_COMPILER} ${flags} -x c++-header \"${pchdir}/exercise_pch.h\" -o \"${pchdir}/exercise_pch.h.gch\"\n")
    add_custom_command(OUTPUT ${pchdir}/exercise_pch.h.gch
                       COMMAND sh ${pchdir}/build_pch.sh
                       DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/common/exercise_pch.h
                       COMMENT "Precompiling the exercise files' headers (live reload)")
    add_custom_target(exercise-pch DEPENDS ${pchdir}/exercise_pch.h.gch)
  endif()
  add_dependencies(${exe} exercise-pch)
  add_dependencies(${exe}-headless exercise-pch)
  set(line "${CMAKE_CXX_COMPILER} ${flags} -shared -include \"${pchdir}/exercise_pch.h\"")
  string(APPEND line " ${CMAKE_SHARED_LINKER_FLAGS} \"$1\" -o \"$2\"")
  file(GENERATE OUTPUT ${WB_EXERCISE_DIR}/lab${nn}.compile
       CONTENT "#!/bin/sh\n# The student's exercises of lab ${nn}, built alone (see labs/common/exercises.cmake).\nexec ${line}\n")
  add_dependencies(${exe} wb_ex_${nn}_student)
  set_property(GLOBAL APPEND PROPERTY WB_EXERCISE_LABS ${nn})
  set_property(GLOBAL APPEND PROPERTY WB_EXERCISE_EXES ${exe})
endfunction()

# After every lab: wb-check knows each lab's exercises through a generated list.
function(add_exercise_checker)
  get_property(labs GLOBAL PROPERTY WB_EXERCISE_LABS)
  set(decl "")
  set(list "")
  set(libs "")
  foreach(nn IN LISTS labs)
    string(APPEND decl "const wb::ex::LabExercises& wbExercises_lab${nn}();\n")
    string(APPEND list "        &wbExercises_lab${nn}(),\n")
    list(APPEND libs wb_ex_${nn})
  endforeach()
  set(gen ${CMAKE_BINARY_DIR}/generated/exercise_registry.cpp)
  file(GENERATE OUTPUT ${gen} CONTENT "// Generated by labs/common/exercises.cmake: every lab with add_exercises().
#include \"common/exercise_check.h\"
${decl}
namespace wb::ex {
const std::vector<const LabExercises*>& allLabExercises() {
    static const std::vector<const LabExercises*> labs = {
${list}    };
    return labs;
}
} // namespace wb::ex
")
  add_executable(wb-check ${CMAKE_CURRENT_SOURCE_DIR}/common/wb_check.cpp ${gen}
    ${CMAKE_CURRENT_SOURCE_DIR}/common/gl_call_interpose.cpp)
  # The GL/GLU matrix functions wb-check defines are exported, so the student's object binds
  # to them and its matrix calls are seen (common/gl_call_log.h; lab 03 task 5's rule).
  target_link_options(wb-check PRIVATE
    "LINKER:--dynamic-list=${CMAKE_CURRENT_SOURCE_DIR}/common/gl_call_interpose.list")
  set_property(TARGET wb-check APPEND PROPERTY LINK_DEPENDS
    ${CMAKE_CURRENT_SOURCE_DIR}/common/gl_call_interpose.list)
  target_compile_options(wb-check PRIVATE ${WB_WARNINGS})
  target_compile_definitions(wb-check PRIVATE WB_EXERCISE_DIR="${WB_EXERCISE_DIR}"
    WB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  if(WB_HANDOUT)
    target_compile_definitions(wb-check PRIVATE WB_HANDOUT_EXPECTED="${PROJECT_SOURCE_DIR}/labs/handout_expected.tsv")
  endif()
  target_link_libraries(wb-check PRIVATE ${libs} wb_shell_headless)
  add_dependencies(wb-check exercises-student)
  # The window runs wb-check on each reload.
  get_property(exes GLOBAL PROPERTY WB_EXERCISE_EXES)
  foreach(exe IN LISTS exes)
    add_dependencies(${exe} wb-check)
  endforeach()
endfunction()
