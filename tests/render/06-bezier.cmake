# Lab 06: core Bezier maths against Mesa's evaluators (GL_FEEDBACK), goldens, picture properties.
wb_test(bezier_render_test SOURCES bezier_render_test.cpp LIBS lab06-bezier_headless)
