# Error rate of g(r) against MT: |shift| of the bin whose 95 % CI reaches furthest from 0 (gauss-inverse; Fig. 6b; floor 0.001 % where the CI holds 0)
# Data: rdf_shift_vs_rounds_gauss-inverse.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'rdf_shift_vs_rounds_gauss-inverse.svg'" rdf_shift_vs_rounds_gauss-inverse.gp
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "|shift| against MT19937 [%]" noenhanced
set logscale y 10
set format y "%g"
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set yrange [0.001:*]
set title "Error rate of g(r) against MT: |shift| of the bin whose 95 % CI reaches furthest from 0 (gauss-inverse; Fig. 6b; floor 0.001 % where the CI holds 0)" noenhanced
plot "rdf_shift_vs_rounds_gauss-inverse.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "rdf_shift_vs_rounds_gauss-inverse.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
