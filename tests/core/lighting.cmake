wb_test(lighting_test SOURCES lighting_test.cpp LIBS core)
