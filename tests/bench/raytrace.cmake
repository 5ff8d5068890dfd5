# Ray tracer at scale (issue 6): writes docs/bench/raytrace.md and raytrace.png
# (run bin/raytrace_scale_bench; --quick for a smoke run).
add_executable(raytrace_scale_bench raytrace_scale_bench.cpp)
target_compile_options(raytrace_scale_bench PRIVATE ${WB_WARNINGS})
target_compile_definitions(raytrace_scale_bench PRIVATE WB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                        WB_BINARY_DIR="${CMAKE_BINARY_DIR}")
target_link_libraries(raytrace_scale_bench PRIVATE core TBB::tbb) # TBB: the build table's ceilings
# -DWORKBENCH_EMBREE=ON: the same eye and shadow rays through Embree 3 (libembree-dev).
option(WORKBENCH_EMBREE "Compare the ray tracer bench with Embree 3" OFF)
if(WORKBENCH_EMBREE)
  find_package(embree 3 REQUIRED)
  target_sources(raytrace_scale_bench PRIVATE embree_compare.cpp)
  target_compile_definitions(raytrace_scale_bench PRIVATE WB_EMBREE=1)
  target_link_libraries(raytrace_scale_bench PRIVATE embree)
endif()
# SPD scenes as NFF files: spd_generate balls|jacks SIZE [FILE].
add_executable(spd_generate spd_generate.cpp)
target_compile_options(spd_generate PRIVATE ${WB_WARNINGS})
target_link_libraries(spd_generate PRIVATE core)
# Command-line renderer: rt_render SCENE.nff|.obj --out FILE.png [--size WxH --threads N --depth D --spd].
add_executable(rt_render rt_render.cpp)
target_compile_options(rt_render PRIVATE ${WB_WARNINGS})
target_link_libraries(rt_render PRIVATE core wb_cli)
