# Lab 05 - stencil: shadow and mirror properties against independent geometry, and goldens.
wb_test(stencil_render_test SOURCES stencil_lab_test.cpp LIBS lab05-stencil_headless)
