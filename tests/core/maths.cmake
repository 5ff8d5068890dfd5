# Maths module tests: one wb_test per part (affine/barycentric/bilinear; Bezier).
wb_test(affine_test SOURCES affine_test.cpp LIBS core)
wb_test(bezier_test SOURCES bezier_test.cpp LIBS core)
wb_test(barycentric_test SOURCES barycentric_test.cpp LIBS core)
wb_test(bilinear_test SOURCES bilinear_test.cpp LIBS core)
