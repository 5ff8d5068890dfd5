# Lab 6 speed against error (tests/bench/bezier_bench.cpp writes dir/bezier.csv):
# left, the drawn shapes' error against the grid; right, the time per mesh. Both log-log:
# the grid doubles from 4 to 256 and errors/times span five to seven decades.
if (!exists('dir')) dir = 'docs/bench'
if (!exists('out')) out = dir.'/bezier.png'
if (!exists('dir_scripts')) dir_scripts = 'scripts/plot'
load dir_scripts.'/common.gp'
data = dir.'/bezier.csv'

set multiplot layout 1,2 title "Bezier tessellation (lab 6): speed against error, from bezier.csv" font ',13'

set logscale xy
set xrange [3.5:300]
set xtics (4, 8, 16, 32, 64, 128, 256)
set mxtics 1
set xlabel 'grid n (glMapGrid segments per curve / per patch side)'
set ylabel 'max radial error (circle: |r-1|, R = 1; sphere: |r-R|/R)'
set key below horizontal maxcols 2 maxrows 4 width 1
set yrange [1e-6:0.3]
set title 'error: chords and triangles against the true circle / sphere'
plot data using 1:2 with linespoints lt 1 title 'circle, course (2 arcs, k = 4/3)', \
     ''   using 1:6 with lines lt 1 dt 2 title '  its exact Bezier curve', \
     ''   using 1:3 with linespoints lt 2 title 'circle, 8 fitted arcs', \
     ''   using 1:7 with lines lt 2 dt 2 title '  its exact Bezier curves', \
     ''   using 1:4 with linespoints lt 3 title 'sphere, course net', \
     ''   using 1:8 with lines lt 3 dt 2 title '  its exact patches', \
     ''   using 1:5 with linespoints lt 4 title 'sphere, fitted net', \
     ''   using 1:9 with lines lt 4 dt 2 title '  its exact patches'

set ylabel 'time per mesh (ms, median; shared machine: noisy)'
set yrange [*:*]
set title 'time: Mesa glEvalMesh (llvmpipe) and core on the CPU'
set key inside top left vertical width 0 maxcols auto maxrows auto
plot data using 1:10 with linespoints lt 1 title 'circle, GL glEvalMesh1', \
     ''   using 1:11 with linespoints lt 1 dt 3 title 'circle, CPU de Casteljau', \
     ''   using 1:12 with linespoints lt 3 title 'sphere, GL glEvalMesh2 fill', \
     ''   using 1:13 with linespoints lt 4 title 'sphere, GL glEvalMesh2 line', \
     ''   using 1:14 with linespoints lt 5 title 'sphere, CPU points + normals'
unset multiplot
