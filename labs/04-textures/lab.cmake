add_lab(04-textures lab04-textures "textures: flat, hand-made sphere and torus, sphere-map mirror"
  SOURCES textures_lab.cpp texture_file.cpp environment.cpp LIBS PkgConfig::STB)
