add_lab(06-bezier lab06-bezier "Bezier curves and patches: circle from two curves, sphere from two patches, error vs grid"
  SOURCES bezier_lab.cpp exercise_view.cpp
  # Launcher thumbnail: the sphere from two patches on its control net.
  THUMBNAIL_KEYS "2cz-")
add_exercises(06 06-bezier CHECKS exercise_checks.cpp)
