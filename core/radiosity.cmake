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
