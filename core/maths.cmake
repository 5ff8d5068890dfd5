# Maths module: one target_sources line per part (affine/barycentric/bilinear; Bezier).
target_sources(core PRIVATE src/affine.cpp src/homogeneous.cpp src/barycentric.cpp src/bilinear.cpp)
target_sources(core PRIVATE src/bezier.cpp src/bezier_shapes.cpp)
target_sources(core PRIVATE src/i18n.cpp) # user-visible text through the catalogues (issue 17)
