add_lab(05-stencil lab05-stencil "Stencil buffer: shadow on a staircase, rectangular and elliptical mirrors"
  SOURCES stencil_lab.cpp exercise_view.cpp)
add_exercises(05 05-stencil CHECKS exercise_checks.cpp)
