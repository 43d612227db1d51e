# Cost of one random number inside the DPD run (uniform)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" cost_vs_rounds_uniform.gp
set title "Cost of one random number inside the DPD run (uniform)" noenhanced
set xlabel "rounds"
set ylabel "ns per number (generator + distribution)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set arrow from graph 0, first 4.47134 to graph 1, first 4.47134 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937" at graph 0.01, first 4.47134 offset 0,0.6 tc rgb 'black'
plot "data/cost_vs_rounds_uniform_0.dat" using 1:2 with linespoints lw 2 pt 7 title "tea32 distance", \
     "data/cost_vs_rounds_uniform_1.dat" using 1:2 with linespoints lw 2 pt 7 title "tea64 distance"
