# Lab 01: goldens of the 2D and 3D views and pixel properties of the mirror and shadows.
wb_test(affine_render_test SOURCES affine_render_test.cpp LIBS lab01-affine_headless)
