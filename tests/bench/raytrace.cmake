# Ray tracer at scale (issue 6): writes docs/bench/raytrace.md and raytrace.png
# (run bin/raytrace_scale_bench; --quick for a smoke run).
add_executable(raytrace_scale_bench raytrace_scale_bench.cpp)
target_compile_options(raytrace_scale_bench PRIVATE ${WB_WARNINGS})
target_compile_definitions(raytrace_scale_bench PRIVATE WB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                        WB_BINARY_DIR="${CMAKE_BINARY_DIR}")
target_link_libraries(raytrace_scale_bench PRIVATE core)
