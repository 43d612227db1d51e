# Error rate of g(r) against MT: |shift| of the bin whose 95 % CI reaches furthest from 0 (gauss; the paper's Fig. 6b)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" rdf_shift_vs_rounds_gauss.gp
set title "Error rate of g(r) against MT: |shift| of the bin whose 95 % CI reaches furthest from 0 (gauss; the paper's Fig. 6b)" noenhanced
set xlabel "rounds"
set ylabel "|(g − g_{MT}) / g_{MT} in that bin| in % (log scale; floor 0.001 %: CI holds 0)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set yrange [0.001:*]
plot "data/rdf_shift_vs_rounds_gauss_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance", \
     "data/rdf_shift_vs_rounds_gauss_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance"
