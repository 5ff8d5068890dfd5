# Lab 04 - textures: goldens, mirror and sphere-map checks, bad texture files, and the
# core sphere-map formula against OSMesa's GL_SPHERE_MAP texgen.
wb_test(textures_render_test SOURCES textures_lab_test.cpp textures_spheremap_test.cpp
  LIBS lab04-textures_headless)
