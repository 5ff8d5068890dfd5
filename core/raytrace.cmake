# Ray tracer core (issue 3): primitives, Whitted recursion, course and phong models.
target_sources(core PRIVATE
  src/raytrace/box.cpp
  src/raytrace/camera.cpp
  src/raytrace/course_model.cpp
  src/raytrace/cylinder.cpp
  src/raytrace/phong_model.cpp
  src/raytrace/plane.cpp
  src/raytrace/polygon.cpp # issue 12: concave NFF polygons
  src/raytrace/polyhedron.cpp
  src/raytrace/primitive.cpp
  src/raytrace/quadric.cpp
  src/raytrace/ray.cpp
  src/raytrace/rectangle.cpp
  src/raytrace/render.cpp
  src/raytrace/scene.cpp
  src/raytrace/sphere.cpp
  src/raytrace/texture.cpp
  src/raytrace/tracer.cpp
  src/raytrace/triangle.cpp
)
target_sources(core PRIVATE src/raytrace/bvh.cpp src/raytrace/bvh_wide.cpp
                            src/raytrace/bvh_wide_avx2.cpp src/raytrace/bvh_wide_avx512.cpp) # issues 6, 13, 21: BVH
# AVX-512 implies FMA for GCC: core/CMakeLists.txt's -ffp-contract=off keeps the float tests unfused.
# issue 6 (engineer F): scene files (NFF, OBJ via tinyobjloader), SPD generators, parallel render.
find_package(tinyobjloader REQUIRED)
target_sources(core PRIVATE
  src/raytrace/nff.cpp
  src/raytrace/obj_file.cpp
  src/raytrace/parallel_render.cpp
  src/raytrace/scene_file.cpp
  src/raytrace/smooth_triangle.cpp
  src/raytrace/spd.cpp
)
target_link_libraries(core PRIVATE tinyobjloader::tinyobjloader TBB::tbb)
