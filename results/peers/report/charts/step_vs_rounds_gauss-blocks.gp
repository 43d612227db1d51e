# Time per DPD step (gauss-blocks)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" step_vs_rounds_gauss-blocks.gp
set title "Time per DPD step (gauss-blocks)" noenhanced
set xlabel "rounds"
set ylabel "ms per step"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set xrange [0.8:*]
set arrow from graph 0, first 0.748929 to graph 1, first 0.748929 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937" at graph 0.01, first 0.748929 offset 0,0.6 tc rgb 'black'
plot "data/step_vs_rounds_gauss-blocks_0.dat" using 1:2 with linespoints lw 2 pt 7 title "philox4x32 distance", \
     "data/step_vs_rounds_gauss-blocks_1.dat" using 1:2 with linespoints lw 2 pt 7 title "philox4x32 pair-step", \
     "data/step_vs_rounds_gauss-blocks_2.dat" using 1:2 with linespoints lw 2 pt 7 title "saru distance", \
     "data/step_vs_rounds_gauss-blocks_3.dat" using 1:2 with linespoints lw 2 pt 7 title "saru pair-step", \
     "data/step_vs_rounds_gauss-blocks_4.dat" using 1:2 with linespoints lw 2 pt 7 title "splitmix64 distance", \
     "data/step_vs_rounds_gauss-blocks_5.dat" using 1:2 with linespoints lw 2 pt 7 title "splitmix64 pair-step", \
     "data/step_vs_rounds_gauss-blocks_6.dat" using 1:2 with linespoints lw 2 pt 7 title "tea32 distance", \
     "data/step_vs_rounds_gauss-blocks_7.dat" using 1:2 with linespoints lw 2 pt 7 title "tea32 pair-step", \
     "data/step_vs_rounds_gauss-blocks_8.dat" using 1:2 with linespoints lw 2 pt 7 title "tea64 distance", \
     "data/step_vs_rounds_gauss-blocks_9.dat" using 1:2 with linespoints lw 2 pt 7 title "tea64 pair-step", \
     "data/step_vs_rounds_gauss-blocks_10.dat" using 1:2 with linespoints lw 2 pt 7 title "threefry2x64 distance", \
     "data/step_vs_rounds_gauss-blocks_11.dat" using 1:2 with linespoints lw 2 pt 7 title "threefry2x64 pair-step"
