add_lab(02-lighting lab02-lighting "Phong lighting: two cubes, keys 1-4, ambient, local viewer, emission, spot, subdivided faces, GLSL Phong"
<<<<<<< HEAD
  SOURCES lighting_lab.cpp
  # Launcher thumbnail: the GLSL Phong highlight on the right cube, none on the face-normal one.
  THUMBNAIL_KEYS "g++")
=======
  SOURCES lighting_lab.cpp)
add_exercises(02 02-lighting CHECKS exercise_checks.cpp)
>>>>>>> exframe
