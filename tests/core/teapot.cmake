# The Utah teapot's patches: data, shared edges without cracks, poles, orientation.
wb_test(teapot_test SOURCES teapot_test.cpp LIBS core)
