# Maths module: one target_sources line per part (affine/barycentric/bilinear; Bezier).
target_sources(core PRIVATE src/affine.cpp)
target_sources(core PRIVATE src/bezier.cpp src/bezier_shapes.cpp)
