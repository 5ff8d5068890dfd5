add_lab(03-transforms lab03-transforms "Transforms and projections: table, book, pen, teapot, classroom 3x4, ortho/perspective/frustum, mirror in the wall"
  SOURCES transforms_lab.cpp exercise_view.cpp)
add_exercises(03 03-transforms CHECKS exercise_checks.cpp)
