# Ray tracer core tests (issue 3). The watertightness test shoots 10^6 rays in a
# normal build and 10^5 under the sanitizers (WB_SANITIZED), which are ~20x slower.
wb_test(raytrace_test
  SOURCES
    raytrace/seed000_test.cpp
    raytrace/primitives_test.cpp
    raytrace/watertight_test.cpp
    raytrace/refraction_test.cpp
    raytrace/tracer_test.cpp
    raytrace/render_test.cpp
    raytrace/tracer_observer_test.cpp
    raytrace/polygon_test.cpp
    raytrace/sphere_test.cpp
  LIBS core)
if(WORKBENCH_SANITIZE)
  target_compile_definitions(raytrace_test PRIVATE WB_SANITIZED=1)
endif()
# Ray tracer at scale (issue 6, engineer F): BVH, NFF/OBJ, SPD generators, parallel render.
wb_test(raytrace_scale_test
  SOURCES
    raytrace_scale/bvh_test.cpp
    raytrace_scale/bvh_wide_test.cpp
    raytrace_scale/nff_test.cpp
    raytrace_scale/hostile_scene_test.cpp
    raytrace_scale/obj_file_test.cpp
    raytrace_scale/parallel_test.cpp
    raytrace_scale/scene_file_test.cpp
    raytrace_scale/phong_direct_test.cpp
    raytrace_scale/self_skip_test.cpp
    raytrace_scale/packet_test.cpp
    raytrace_scale/filter_margin_test.cpp
  LIBS core)
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/test-out)
target_compile_definitions(raytrace_scale_test PRIVATE WB_TEST_TMP="${CMAKE_BINARY_DIR}/test-out")
# Fuzzing (issue 6): the saved corpus and kept crashers run through both scene readers
# in every build; -DWORKBENCH_FUZZ=ON (clang) adds the libFuzzer targets fuzz_nff, fuzz_obj.
wb_test(raytrace_fuzz_corpus_test
  SOURCES ../fuzz/corpus_test.cpp ../fuzz/scene_fuzz.cpp
  LIBS core)
target_compile_definitions(raytrace_fuzz_corpus_test PRIVATE
  WB_FUZZ_DIR="${PROJECT_SOURCE_DIR}/tests/fuzz")
option(WORKBENCH_FUZZ "Build the libFuzzer harnesses (needs clang)" OFF)
if(WORKBENCH_FUZZ)
  foreach(reader nff obj)
    add_executable(fuzz_${reader} ../fuzz/fuzz_${reader}.cpp ../fuzz/scene_fuzz.cpp)
    target_link_libraries(fuzz_${reader} PRIVATE core)
    target_compile_options(fuzz_${reader} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_options(fuzz_${reader} PRIVATE -fsanitize=fuzzer,address,undefined)
  endforeach()
endif()
# Issue 12 point 11: rt_render and lab 07's headless front end give the same picture of
# the same file (runs both executables as a user would).
wb_test(raytrace_same_picture_test
  SOURCES raytrace_scale/same_picture_test.cpp
  LIBS core)
add_dependencies(raytrace_same_picture_test rt_render lab07-raytrace lab07-raytrace-headless)
if(WORKBENCH_SANITIZE)
  target_compile_definitions(raytrace_same_picture_test PRIVATE WB_SANITIZED=1)
endif()
# Issue 12 point 12: every SPD generator in the suite (counts, round trip, render smoke)
# and a speckle census (isolated outliers that one exact ray alone carries).
wb_test(raytrace_pictures_test
  SOURCES raytrace_scale/spd_scenes_test.cpp raytrace_scale/speckle_test.cpp
  LIBS core)
if(WORKBENCH_SANITIZE)
  target_compile_definitions(raytrace_pictures_test PRIVATE WB_SANITIZED=1)
endif()
