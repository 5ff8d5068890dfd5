# Texturing (lab 4): sphere-map formula and the hand-made meshes.
wb_test(sphere_map_test SOURCES sphere_map_test.cpp LIBS core)
wb_test(mesh_test SOURCES mesh_test.cpp LIBS core)
