# Kinetic temperature against MT19937 (gauss-blocks)
# Data: temperature_shift_vs_rounds_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'temperature_shift_vs_rounds_gauss-blocks.svg'" temperature_shift_vs_rounds_gauss-blocks.gp
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "k_BT shift against MT19937, 95 % CI [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set object 1 rectangle from graph 0, first -1 to graph 1, first 1 behind fillcolor rgb '#DDEEDD' fillstyle solid 1.0 noborder
set label 1 "equivalence margin ±1" at graph 0.01, first 1 offset 0,-0.8 font ',10' tc rgb '#336633' front
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set yrange [-2.3:2.3]
set title "Kinetic temperature against MT19937 (gauss-blocks)" noenhanced
plot "temperature_shift_vs_rounds_gauss-blocks.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 2 using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333' title "", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 3 using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333' title ""
