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
  LIBS core)
if(WORKBENCH_SANITIZE)
  target_compile_definitions(raytrace_test PRIVATE WB_SANITIZED=1)
endif()
# Ray tracer at scale (issue 6, engineer F): BVH, NFF/OBJ, SPD generators, parallel render.
wb_test(raytrace_scale_test
  SOURCES
    raytrace_scale/bvh_test.cpp
    raytrace_scale/nff_test.cpp
    raytrace_scale/parallel_test.cpp
  LIBS core)
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/test-out)
target_compile_definitions(raytrace_scale_test PRIVATE WB_TEST_TMP="${CMAKE_BINARY_DIR}/test-out")
