# Cost of one random number inside the DPD run (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" cost_vs_rounds_gauss.gp
set title "Cost of one random number inside the DPD run (gauss)" noenhanced
set xlabel "rounds"
set ylabel "ns per number (generator + distribution)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set arrow from graph 0, first 4.77454 to graph 1, first 4.77454 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937" at graph 0.01, first 4.77454 offset 0,0.6 tc rgb 'black'
plot "data/cost_vs_rounds_gauss_0.dat" using 1:2 with linespoints lw 2 pt 7 title "philox4x32 distance", \
     "data/cost_vs_rounds_gauss_1.dat" using 1:2 with linespoints lw 2 pt 7 title "philox4x32 pair-step", \
     "data/cost_vs_rounds_gauss_2.dat" using 1:2 with linespoints lw 2 pt 7 title "saru distance", \
     "data/cost_vs_rounds_gauss_3.dat" using 1:2 with linespoints lw 2 pt 7 title "saru pair-step", \
     "data/cost_vs_rounds_gauss_4.dat" using 1:2 with linespoints lw 2 pt 7 title "splitmix64 distance", \
     "data/cost_vs_rounds_gauss_5.dat" using 1:2 with linespoints lw 2 pt 7 title "splitmix64 pair-step", \
     "data/cost_vs_rounds_gauss_6.dat" using 1:2 with linespoints lw 2 pt 7 title "tea32 distance", \
     "data/cost_vs_rounds_gauss_7.dat" using 1:2 with linespoints lw 2 pt 7 title "tea32 pair-step", \
     "data/cost_vs_rounds_gauss_8.dat" using 1:2 with linespoints lw 2 pt 7 title "tea64 distance", \
     "data/cost_vs_rounds_gauss_9.dat" using 1:2 with linespoints lw 2 pt 7 title "tea64 pair-step", \
     "data/cost_vs_rounds_gauss_10.dat" using 1:2 with linespoints lw 2 pt 7 title "threefry2x64 distance", \
     "data/cost_vs_rounds_gauss_11.dat" using 1:2 with linespoints lw 2 pt 7 title "threefry2x64 pair-step"
