set datafile separator ','
set terminal pngcairo size 1000,640 font 'DejaVu Sans,10'
set output 'radiosity_ff.png'
set logscale xy
set grid
set key outside right noenhanced
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 'time per form-factor row, 1 thread (ms)'
set ylabel 'relative error against the exact F_{ij}'
set title 'Form factors: time against max (solid) and mean (dashed) error, 4x4-patch unit plates'
f='radiosity_ff.csv'
plot f using (strcol(1) eq 'rays auto' ? $3 : NaN):4 with linespoints lw 2 lc 1 title 'rays auto max', f using (strcol(1) eq 'rays auto' ? $3 : NaN):5 with linespoints dt 2 lc 1 title 'rays auto mean', f using (strcol(1) eq 'rays centres (15.20)' ? $3 : NaN):4 with linespoints lw 2 lc 2 title 'rays centres (15.20) max', f using (strcol(1) eq 'rays centres (15.20)' ? $3 : NaN):5 with linespoints dt 2 lc 2 title 'rays centres (15.20) mean', f using (strcol(1) eq 'rays point pairs' ? $3 : NaN):4 with linespoints lw 2 lc 3 title 'rays point pairs max', f using (strcol(1) eq 'rays point pairs' ? $3 : NaN):5 with linespoints dt 2 lc 3 title 'rays point pairs mean', f using (strcol(1) eq 'CPU hemicube' ? $3 : NaN):4 with linespoints lw 2 lc 4 title 'CPU hemicube max', f using (strcol(1) eq 'CPU hemicube' ? $3 : NaN):5 with linespoints dt 2 lc 4 title 'CPU hemicube mean'
set output 'radiosity_solvers.png'
set multiplot layout 1,2
set xlabel 'solve time (s), F precomputed'
set key inside bottom left noenhanced box opaque
s='radiosity_solvers.csv'
set title 'Residual (fraction of the emitted power)'
set ylabel 'residual'
plot s using (strcol(1) eq 'Jacobi' ? $2 : NaN):3 with linespoints pt 7 ps 0.4 lw 2 lc 1 title 'Jacobi', s using (strcol(1) eq 'Gauss-Seidel' ? $2 : NaN):3 with linespoints pt 7 ps 0.4 lw 2 lc 2 title 'Gauss-Seidel', s using (strcol(1) eq 'progressive (per patch)' ? $2 : NaN):3 with linespoints pt 7 ps 0.4 lw 2 lc 3 title 'progressive (per patch)', s using (strcol(1) eq 'progressive (groups)' ? $2 : NaN):3 with linespoints pt 7 ps 0.4 lw 2 lc 4 title 'progressive (groups)'
set title 'Image error against the converged solution'
set ylabel 'relative RMS of B (displayed)'
plot s using (strcol(1) eq 'Jacobi' ? $2 : NaN):4 with linespoints pt 7 ps 0.4 lw 2 lc 1 title 'Jacobi', s using (strcol(1) eq 'Gauss-Seidel' ? $2 : NaN):4 with linespoints pt 7 ps 0.4 lw 2 lc 2 title 'Gauss-Seidel', s using (strcol(1) eq 'progressive (per patch)' ? $2 : NaN):4 with linespoints pt 7 ps 0.4 lw 2 lc 3 title 'progressive (per patch)', s using (strcol(1) eq 'progressive (groups)' ? $2 : NaN):4 with linespoints pt 7 ps 0.4 lw 2 lc 4 title 'progressive (groups)'
unset multiplot
