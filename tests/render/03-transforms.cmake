# Lab 03: the mirror image, near/far clipping, goldens of the projections.
wb_test(transforms_render_test SOURCES transforms_lab_test.cpp LIBS lab03-transforms_headless)
