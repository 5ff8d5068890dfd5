add_lab(07-raytrace lab07-raytrace "Ray tracing vs rasterization: g = OpenGL Phong, G = background ray trace, timing, difference, ray inspector"
  SOURCES raytrace_lab.cpp lab_scenes.cpp view_camera.cpp trace_job.cpp ray_inspector.cpp raster_mesh.cpp exercise_view.cpp)
add_exercises(07 07-raytrace CHECKS exercise_checks.cpp)
