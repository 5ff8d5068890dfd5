# Texturing (lab 4): the sphere-map formula and the hand-made sphere and torus meshes.
target_sources(core PRIVATE src/sphere_map.cpp src/mesh.cpp)
