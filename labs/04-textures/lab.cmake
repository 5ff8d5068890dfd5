add_lab(04-textures lab04-textures "Textures: flat, hand-made sphere and torus, sphere-map mirror, bump-mapped torus"
  SOURCES textures_lab.cpp texture_file.cpp environment.cpp exercise_view.cpp LIBS PkgConfig::STB)
add_exercises(04 04-textures CHECKS exercise_checks.cpp)
