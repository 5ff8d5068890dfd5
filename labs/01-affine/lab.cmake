add_lab(01-affine lab01-affine "Affine maps: mirror image and shadows (light at infinity, point light) as one 3x3 / 4x4 matrix, 2D and 3D"
  SOURCES affine_lab.cpp)
add_exercises(01 01-affine CHECKS exercise_checks.cpp)
