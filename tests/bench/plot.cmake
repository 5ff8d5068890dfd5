# Bench reports with gnuplot plots (docs/bench/README.md). A bench program writes its
# Markdown report and its data as CSV into docs/bench/; scripts/plot/<name>.gp draws
# docs/bench/<name>.png from the CSV. wb_bench_plot(<name> BENCH <target> [ARGS ...]) adds
#   plot_<name>   the plot alone from the CSV already in docs/bench (fast; gnuplot only)
#   report_<name> run the bench (slow, on a quiet machine), then the plot
# Neither is part of `all` or of the tests: only these targets need gnuplot.
function(wb_bench_plot name)
  cmake_parse_arguments(P "" "BENCH" "ARGS" ${ARGN})
  set(plot ${PROJECT_SOURCE_DIR}/scripts/plot/plot.sh)
  set(out ${PROJECT_SOURCE_DIR}/docs/bench)
  add_custom_target(plot_${name}
    COMMAND ${plot} ${name} ${out}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    COMMENT "gnuplot: scripts/plot/${name}.gp -> docs/bench/${name}.png"
    VERBATIM)
  add_custom_target(report_${name}
    COMMAND $<TARGET_FILE:${P_BENCH}> ${P_ARGS}
    COMMAND ${plot} ${name} ${out}
    DEPENDS ${P_BENCH}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    COMMENT "bench ${P_BENCH}, then gnuplot -> docs/bench/${name}.png"
    VERBATIM USES_TERMINAL)
endfunction()
