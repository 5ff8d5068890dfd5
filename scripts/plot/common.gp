# The look every bench plot shares (docs/bench/README.md). A plot script sets `out` (the PNG)
# and `dir` (where its CSV is; plot.sh passes both), then: load dir_scripts.'/common.gp'.
# pngcairo with DejaVu Sans (fonts-dejavu-core), CSV with a header row (columnheader).
set terminal pngcairo size 1100,600 enhanced font 'DejaVu Sans,11' linewidth 1.4
set output out
set datafile separator ','
set key top right box opaque samplen 2.5 spacing 1.1 font ',10'
set grid xtics ytics mxtics mytics lc rgb '#d8d8d8' lw 0.8, lc rgb '#eeeeee' lw 0.5
set border 3 lw 1
set tics nomirror out
set format y '10^{%L}'
# Colours by role, so plots of different benches read alike: course/reference in red,
# improved variants in orange, a second shape in blue/cyan, times in grey shades.
set linetype 1 lc rgb '#d62728' pt 7 ps 0.9
set linetype 2 lc rgb '#ff7f0e' pt 5 ps 0.9
set linetype 3 lc rgb '#1f4fd0' pt 9 ps 1.0
set linetype 4 lc rgb '#17becf' pt 11 ps 1.0
set linetype 5 lc rgb '#444444' pt 13 ps 0.9
set linetype 6 lc rgb '#2ca02c' pt 4 ps 0.9
