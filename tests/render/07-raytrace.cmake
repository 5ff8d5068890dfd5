# Lab 07: goldens of both modes, GLSL raster vs phong tracer, ray inspector on seed 000,
# cancel during a trace.
wb_test(raytrace_lab_test SOURCES raytrace_lab_render_test.cpp raytrace_lab_inspector_test.cpp
  raytrace_lab_cancel_test.cpp LIBS lab07-raytrace_headless)
