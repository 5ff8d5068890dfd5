# Lab 08: the GL hemicube against core's CPU hemicube (occlusion), goldens flat and smooth,
# colour bleeding and smoothness properties of the picture, picking.
wb_test(radiosity_lab_test SOURCES radiosity_gl_hemicube_test.cpp radiosity_lab_render_test.cpp
  LIBS lab08-radiosity_headless)
