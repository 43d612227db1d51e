# Mean temperature ± replica s.d. (gauss-blocks)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_vs_rounds_gauss-blocks.gp
set title "Mean temperature ± replica s.d. (gauss-blocks)" noenhanced
set xlabel "rounds"
set ylabel "k_BT (kinetic)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set xrange [0.8:*]
set arrow from graph 0, first 1.03526 to graph 1, first 1.03526 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937 mean" at graph 0.01, first 1.03526 offset 0,0.6 tc rgb 'black'
set arrow from graph 0, first 1.03776 to graph 1, first 1.03776 nohead dt 2 lw 2 lc rgb 'gray50'
set label "" at graph 0.01, first 1.03776 offset 0,0.6 tc rgb 'gray50'
set arrow from graph 0, first 1.03275 to graph 1, first 1.03275 nohead dt 2 lw 2 lc rgb 'gray50'
set label "" at graph 0.01, first 1.03275 offset 0,0.6 tc rgb 'gray50'
plot "data/temperature_vs_rounds_gauss-blocks_0.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "tea32 distance", \
     "data/temperature_vs_rounds_gauss-blocks_1.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "tea64 distance"
