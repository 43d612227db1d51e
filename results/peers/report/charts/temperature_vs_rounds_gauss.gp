# Mean temperature ± replica s.d. (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_vs_rounds_gauss.gp
set title "Mean temperature ± replica s.d. (gauss)" noenhanced
set xlabel "rounds"
set ylabel "k_BT (kinetic)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set arrow from graph 0, first 1.03345 to graph 1, first 1.03345 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937 mean" at graph 0.01, first 1.03345 offset 0,0.6 tc rgb 'black'
set arrow from graph 0, first 1.03631 to graph 1, first 1.03631 nohead dt 2 lw 2 lc rgb 'gray50'
set label "" at graph 0.01, first 1.03631 offset 0,0.6 tc rgb 'gray50'
set arrow from graph 0, first 1.0306 to graph 1, first 1.0306 nohead dt 2 lw 2 lc rgb 'gray50'
set label "" at graph 0.01, first 1.0306 offset 0,0.6 tc rgb 'gray50'
plot "data/temperature_vs_rounds_gauss_0.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "philox4x32 distance", \
     "data/temperature_vs_rounds_gauss_1.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step", \
     "data/temperature_vs_rounds_gauss_2.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "saru distance", \
     "data/temperature_vs_rounds_gauss_3.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "saru pair-step", \
     "data/temperature_vs_rounds_gauss_4.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "splitmix64 distance", \
     "data/temperature_vs_rounds_gauss_5.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step", \
     "data/temperature_vs_rounds_gauss_6.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "tea32 distance", \
     "data/temperature_vs_rounds_gauss_7.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "tea32 pair-step", \
     "data/temperature_vs_rounds_gauss_8.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "tea64 distance", \
     "data/temperature_vs_rounds_gauss_9.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "tea64 pair-step", \
     "data/temperature_vs_rounds_gauss_10.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "threefry2x64 distance", \
     "data/temperature_vs_rounds_gauss_11.dat" using 1:2:3 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step"
