# Cost (best of 5 × 4096 calls in the run) against temperature shift (gauss; Intel(R) Xeon(R) Processor (family 6, model 207))
# Data: speed_vs_accuracy_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'speed_vs_accuracy_gauss.svg'" speed_vs_accuracy_gauss.gp
# small multiples: 4 panels
# canvas: 900,800
set xlabel "cost per random number [ns]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "k_BT shift against MT19937, 95 % CI [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set object 1 rectangle from graph 0, first -0.5 to graph 1, first 0.5 behind fillcolor rgb '#DDEEDD' fillstyle solid 1.0 noborder
set label 1 "equivalence margin ±0.5" at graph 0.01, first 0.5 offset 0,-0.8 font ',10' tc rgb '#336633' front
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set arrow from first 3.44482, graph 0 to first 3.44482, graph 1 nohead dt 2 lc rgb 'black'
set label "mt19937" at first 3.44482, graph 0.96 offset 0.5,0 font ',10'
set yrange [-4.13815:4.13815]
set xrange [0.284424:7.98979]
set multiplot layout 2,2 title "Cost (best of 5 × 4096 calls in the run) against temperature shift (gauss; Intel(R) Xeon(R) Processor (family 6, model 207))" noenhanced
set title "distance seeding, generators 1 of 2" noenhanced
set key outside right top noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "speed_vs_accuracy_gauss.csv" index 0 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#009E73' title "philox4x32", \
     "speed_vs_accuracy_gauss.csv" index 2 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#D55E00' title "saru", \
     "speed_vs_accuracy_gauss.csv" index 4 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#56B4E9' title "splitmix64", \
     "speed_vs_accuracy_gauss.csv" index 6 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#999933' title "squares64", \
     "speed_vs_accuracy_gauss.csv" index 18 using 2:3 with steps dt 2 lw 1 lc rgb '#555555' title ""
set title "distance seeding, generators 2 of 2" noenhanced
set key outside right top noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "speed_vs_accuracy_gauss.csv" index 8 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#0072B2' title "tea32", \
     "speed_vs_accuracy_gauss.csv" index 10 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#E69F00' title "tea64", \
     "speed_vs_accuracy_gauss.csv" index 12 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#CC79A7' title "threefry2x64", \
     "speed_vs_accuracy_gauss.csv" index 14 using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333' title "", \
     "speed_vs_accuracy_gauss.csv" index 15 using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333' title "", \
     "speed_vs_accuracy_gauss.csv" index 19 using 2:3 with steps dt 2 lw 1 lc rgb '#555555' title "", \
     "speed_vs_accuracy_gauss.csv" index 20 using 2:3:8 with labels offset 0.8,0.6 left font ',10' tc rgb '#333333' title ""
set title "pair-step seeding, generators 1 of 2" noenhanced
set key outside right top noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "speed_vs_accuracy_gauss.csv" index 1 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#009E73' title "philox4x32", \
     "speed_vs_accuracy_gauss.csv" index 3 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#D55E00' title "saru", \
     "speed_vs_accuracy_gauss.csv" index 5 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#56B4E9' title "splitmix64", \
     "speed_vs_accuracy_gauss.csv" index 7 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#999933' title "squares64", \
     "speed_vs_accuracy_gauss.csv" index 21 using 2:3 with steps dt 2 lw 1 lc rgb '#555555' title ""
set title "pair-step seeding, generators 2 of 2" noenhanced
set key outside right top noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "speed_vs_accuracy_gauss.csv" index 9 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#0072B2' title "tea32", \
     "speed_vs_accuracy_gauss.csv" index 11 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#E69F00' title "tea64", \
     "speed_vs_accuracy_gauss.csv" index 13 using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5 lc rgb '#CC79A7' title "threefry2x64", \
     "speed_vs_accuracy_gauss.csv" index 16 using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333' title "", \
     "speed_vs_accuracy_gauss.csv" index 17 using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333' title "", \
     "speed_vs_accuracy_gauss.csv" index 22 using 2:3 with steps dt 2 lw 1 lc rgb '#555555' title "", \
     keyentry with steps dt 2 lw 1 lc rgb '#555555' title "Pareto front", \
     keyentry with points pt 7 lc rgb 'black' title "1 round", \
     keyentry with points pt 10 lc rgb 'black' title "7 rounds", \
     keyentry with points pt 6 lc rgb 'black' title "8 rounds", \
     keyentry with points pt 14 lc rgb 'black' title "10 rounds", \
     keyentry with points pt 3 lc rgb 'black' title "13 rounds", \
     keyentry with points pt 1 lc rgb 'black' title "20 rounds"
unset multiplot
