# Lab 02: the lighting equation against OSMesa, the two cubes, goldens.
wb_test(lighting_render_test SOURCES lighting_equation_test.cpp lighting_lab_test.cpp
  LIBS lab02-lighting_headless)
