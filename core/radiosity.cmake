# Radiosity core (issue 10): patches, form factors by rays and by the CPU hemicube, closed
# forms, Jacobi / Gauss–Seidel / progressive solvers, smoothing, scenes. No GL.
target_sources(core PRIVATE
  src/radiosity/closed_forms.cpp
  src/radiosity/flatland.cpp
  src/radiosity/form_factors.cpp
  src/radiosity/hemicube.cpp
  src/radiosity/mesh.cpp
  src/radiosity/patch_bvh.cpp
  src/radiosity/point_rays.cpp
  src/radiosity/ray_form_factors.cpp
  src/radiosity/scene.cpp
  src/radiosity/scenes.cpp
  src/radiosity/smoothing.cpp
  src/radiosity/solver.cpp
)

# The constrained Delaunay mesher (CGAL, header-only, Debian's libcgal-dev) in its own object
# library: CGAL needs -frounding-math (its interval arithmetic), which must not change how the
# rest of core is compiled. Exact fallbacks use Boost.Multiprecision (no GMP to link).
find_path(WB_CGAL_INCLUDE CGAL/Delaunay_mesher_2.h REQUIRED)
add_library(core_cdt OBJECT src/radiosity/cdt2.cpp)
target_include_directories(core_cdt SYSTEM PRIVATE ${WB_CGAL_INCLUDE})
target_compile_definitions(core_cdt PRIVATE CGAL_DISABLE_GMP=1 CGAL_NO_GMP=1)
target_compile_options(core_cdt PRIVATE ${WB_WARNINGS} -frounding-math)
target_link_libraries(core_cdt PRIVATE glm::glm)
target_sources(core PRIVATE $<TARGET_OBJECTS:core_cdt>)
