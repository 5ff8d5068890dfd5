# Lab 6 speed against error: writes docs/bench/bezier.md and bezier.csv; bezier.png is drawn
# from the CSV by scripts/plot/bezier.gp (targets report_bezier, plot_bezier).
add_executable(bezier_bench bezier_bench.cpp)
target_compile_options(bezier_bench PRIVATE ${WB_WARNINGS})
target_compile_definitions(bezier_bench PRIVATE WB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(bezier_bench PRIVATE wb_shell_headless core)
wb_bench_plot(bezier BENCH bezier_bench)
