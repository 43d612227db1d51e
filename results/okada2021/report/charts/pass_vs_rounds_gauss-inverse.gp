# Pass fractions with 99 % CIs (gauss-inverse)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" pass_vs_rounds_gauss-inverse.gp
set title "Pass fractions with 99 % CIs (gauss-inverse)" noenhanced
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
plot "data/pass_vs_rounds_gauss-inverse_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance lag-1 t", \
     "data/pass_vs_rounds_gauss-inverse_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance χ²", \
     "data/pass_vs_rounds_gauss-inverse_2.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance lag-1 t a", \
     "data/pass_vs_rounds_gauss-inverse_3.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance lag-1 t b", \
     "data/pass_vs_rounds_gauss-inverse_4.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance χ² a", \
     "data/pass_vs_rounds_gauss-inverse_5.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance χ² b", \
     "data/pass_vs_rounds_gauss-inverse_6.dat" using 1:2 with lines lw 3 dt 2 lc rgb 'black' title "mt19937 lag-1 t", \
     "data/pass_vs_rounds_gauss-inverse_7.dat" using 1:2 with lines lw 3 dt 2 lc rgb 'black' title "mt19937 χ²"
