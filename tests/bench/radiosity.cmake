# Radiosity (issue 10): writes docs/bench/radiosity.md, radiosity_ff.png, radiosity_solvers.png
# (run bin/radiosity_bench; --quick for a small smoke run, which ctest runs into the build dir).
add_executable(radiosity_bench radiosity_bench.cpp)
target_compile_options(radiosity_bench PRIVATE ${WB_WARNINGS})
target_compile_definitions(radiosity_bench PRIVATE WB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                   WB_BINARY_DIR="${CMAKE_BINARY_DIR}")
target_include_directories(radiosity_bench PRIVATE ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(radiosity_bench PRIVATE core)
# The smoke run (~6 s) is skipped under the sanitizers, where it would take minutes; the
# same code paths run there through radiosity_test.
if(NOT WORKBENCH_SANITIZE)
  add_test(NAME "radiosity_bench --quick"
           COMMAND radiosity_bench --quick --out-dir ${CMAKE_BINARY_DIR}/bench-out/radiosity-quick)
endif()

# Issue 19 item 12: our per-surface means of the converged Cornell box, for the Blender/Cycles
# reference (scripts/bench/radiosity_reference.sh). A bench, not a test: blender is no CI dependency.
add_executable(radiosity_reference radiosity_reference.cpp)
target_compile_options(radiosity_reference PRIVATE ${WB_WARNINGS})
# core comes through the lab (its GL hemicube draws key 3's column: the lab's own code).
target_link_libraries(radiosity_reference PRIVATE lab08-radiosity_headless)
# A second, independent estimate for that comparison: brute-force Monte Carlo path tracing on
# the scene's polygons (tests/bench/radiosity_mc.cpp). A bench, not a test.
add_executable(radiosity_mc radiosity_mc.cpp)
target_compile_options(radiosity_mc PRIVATE ${WB_WARNINGS})
target_link_libraries(radiosity_mc PRIVATE core)
