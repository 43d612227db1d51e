# Pass fractions with 99 % CIs (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" pass_vs_rounds_gauss.gp
set title "Pass fractions with 99 % CIs (gauss)" noenhanced
set xlabel "rounds"
set ylabel "fraction of tests passed"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set xrange [0.8:*]
set arrow from graph 0, first 0.99 to graph 1, first 0.99 nohead dt 2 lw 2 lc rgb 'gray30'
set label "1 − α" at graph 0.01, first 0.99 offset 0,0.6 tc rgb 'gray30'
set yrange [*:1.005]
plot "data/pass_vs_rounds_gauss_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance lag-1 t a", \
     "data/pass_vs_rounds_gauss_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance lag-1 t b", \
     "data/pass_vs_rounds_gauss_2.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance χ² a", \
     "data/pass_vs_rounds_gauss_3.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance χ² b", \
     "data/pass_vs_rounds_gauss_4.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step lag-1 t a", \
     "data/pass_vs_rounds_gauss_5.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step lag-1 t b", \
     "data/pass_vs_rounds_gauss_6.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step χ² a", \
     "data/pass_vs_rounds_gauss_7.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step χ² b", \
     "data/pass_vs_rounds_gauss_8.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance lag-1 t", \
     "data/pass_vs_rounds_gauss_9.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance χ²", \
     "data/pass_vs_rounds_gauss_10.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step lag-1 t", \
     "data/pass_vs_rounds_gauss_11.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step χ²", \
     "data/pass_vs_rounds_gauss_12.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance lag-1 t", \
     "data/pass_vs_rounds_gauss_13.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance χ²", \
     "data/pass_vs_rounds_gauss_14.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step lag-1 t", \
     "data/pass_vs_rounds_gauss_15.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step χ²", \
     "data/pass_vs_rounds_gauss_16.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance lag-1 t", \
     "data/pass_vs_rounds_gauss_17.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance χ²", \
     "data/pass_vs_rounds_gauss_18.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step lag-1 t", \
     "data/pass_vs_rounds_gauss_19.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step χ²", \
     "data/pass_vs_rounds_gauss_20.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance lag-1 t a", \
     "data/pass_vs_rounds_gauss_21.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance lag-1 t b", \
     "data/pass_vs_rounds_gauss_22.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance χ² a", \
     "data/pass_vs_rounds_gauss_23.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance χ² b", \
     "data/pass_vs_rounds_gauss_24.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step lag-1 t a", \
     "data/pass_vs_rounds_gauss_25.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step lag-1 t b", \
     "data/pass_vs_rounds_gauss_26.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step χ² a", \
     "data/pass_vs_rounds_gauss_27.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step χ² b", \
     "data/pass_vs_rounds_gauss_28.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance lag-1 t a", \
     "data/pass_vs_rounds_gauss_29.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance lag-1 t b", \
     "data/pass_vs_rounds_gauss_30.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance χ² a", \
     "data/pass_vs_rounds_gauss_31.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance χ² b", \
     "data/pass_vs_rounds_gauss_32.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step lag-1 t a", \
     "data/pass_vs_rounds_gauss_33.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step lag-1 t b", \
     "data/pass_vs_rounds_gauss_34.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step χ² a", \
     "data/pass_vs_rounds_gauss_35.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step χ² b", \
     "data/pass_vs_rounds_gauss_36.dat" using 1:2 with lines lw 3 dt 2 lc rgb 'black' title "mt19937 lag-1 t", \
     "data/pass_vs_rounds_gauss_37.dat" using 1:2 with lines lw 3 dt 2 lc rgb 'black' title "mt19937 χ²"
