# OBJ load (issue 13 item 5): writes docs/bench/obj_load.md (run bin/obj_load_bench;
# --quick for a smoke run, --once for one load under callgrind).
find_package(tinyobjloader REQUIRED) # the bench calls the library alone too
add_executable(obj_load_bench obj_load_bench.cpp)
target_compile_options(obj_load_bench PRIVATE ${WB_WARNINGS})
target_compile_definitions(obj_load_bench PRIVATE WB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                  WB_BINARY_DIR="${CMAKE_BINARY_DIR}")
target_link_libraries(obj_load_bench PRIVATE core tinyobjloader::tinyobjloader)
