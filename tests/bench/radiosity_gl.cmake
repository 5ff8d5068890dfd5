# Lab 08's GL hemicube against core's CPU hemicube and the closed forms, 16² ... 1024²:
# writes its section of docs/bench/radiosity.md (run bin/radiosity_gl_bench --write docs/bench/radiosity.md).
add_executable(radiosity_gl_bench radiosity_gl_bench.cpp)
target_compile_options(radiosity_gl_bench PRIVATE ${WB_WARNINGS})
# core comes through the lab (naming it first would put libstb.so before libimgui.a, which needs it).
target_link_libraries(radiosity_gl_bench PRIVATE lab08-radiosity_headless)
