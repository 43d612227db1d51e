# Cost (best of 5 × 4096 calls in the run) against temperature shift (gauss-inverse; AMD EPYC (family 25, model 17))
# Data: speed_vs_accuracy_gauss-inverse.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'speed_vs_accuracy_gauss-inverse.svg'" speed_vs_accuracy_gauss-inverse.gp
set xlabel "cost per random number [ns]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "k_BT shift against MT19937, 95 % CI [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key outside right top noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set object 1 rectangle from graph 0, first -1 to graph 1, first 1 behind fillcolor rgb '#DDEEDD' fillstyle solid 1.0 noborder
set label 1 "equivalence margin ±1" at graph 0.01, first 1 offset 0,-0.8 font ',10' tc rgb '#336633' front
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set arrow from first 0.666214, graph 0 to first 0.666214, graph 1 nohead dt 2 lc rgb 'black'
set label "mt19937" at first 0.666214, graph 0.96 offset 0.5,0 font ',10'
set yrange [-2.3:2.3]
set xrange [0.20259:19.0036]
set title "Cost (best of 5 × 4096 calls in the run) against temperature shift (gauss-inverse; AMD EPYC (family 25, model 17))" noenhanced
plot "speed_vs_accuracy_gauss-inverse.csv" index 0 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#0072B2' title "tea32 distance", \
     "speed_vs_accuracy_gauss-inverse.csv" index 1 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#E69F00' title "tea64 distance", \
     "speed_vs_accuracy_gauss-inverse.csv" index 2 using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333' title "", \
     "speed_vs_accuracy_gauss-inverse.csv" index 3 using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333' title "", \
     "speed_vs_accuracy_gauss-inverse.csv" index 4 using 2:3 with steps dt 2 lw 1 lc rgb '#555555' title "", \
     keyentry with steps dt 2 lw 1 lc rgb '#555555' title "Pareto front", \
     keyentry with points pt 7 lc rgb 'black' title "1 round", \
     keyentry with points pt 5 lc rgb 'black' title "2 rounds", \
     keyentry with points pt 9 lc rgb 'black' title "3 rounds", \
     keyentry with points pt 13 lc rgb 'black' title "4 rounds", \
     keyentry with points pt 11 lc rgb 'black' title "5 rounds", \
     keyentry with points pt 15 lc rgb 'black' title "6 rounds", \
     keyentry with points pt 6 lc rgb 'black' title "8 rounds", \
     keyentry with points pt 4 lc rgb 'black' title "16 rounds", \
     keyentry with points pt 8 lc rgb 'black' title "32 rounds"
