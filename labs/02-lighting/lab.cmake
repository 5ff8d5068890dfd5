add_lab(02-lighting lab02-lighting "Phong lighting: two cubes, keys 1-4, ambient, local viewer, emission, spot, subdivided faces, GLSL Phong"
  SOURCES lighting_lab.cpp
  # Launcher thumbnail: the GLSL Phong highlight on the right cube, none on the face-normal one.
  THUMBNAIL_KEYS "g++")
add_exercises(02 02-lighting CHECKS exercise_checks.cpp)
