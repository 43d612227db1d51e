# Kinetic temperature against MT19937 (gauss-blocks)
# Data: temperature_shift_vs_rounds_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'temperature_shift_vs_rounds_gauss-blocks.svg'" temperature_shift_vs_rounds_gauss-blocks.gp
# small multiples: 4 panels
# canvas: 900,800
set xlabel "hash rounds [1]" noenhanced
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
set yrange [-2.82356:2.82356]
set xrange [0.833333:24]
set multiplot layout 2,2 title "Kinetic temperature against MT19937 (gauss-blocks)" noenhanced
set title "distance seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_shift_vs_rounds_gauss-blocks.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 2 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 4 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 6 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "distance seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_shift_vs_rounds_gauss-blocks.csv" index 8 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 10 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 12 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 14 using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333' title "", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 15 using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333' title ""
set title "pair-step seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_shift_vs_rounds_gauss-blocks.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 5 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 7 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "pair-step seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "temperature_shift_vs_rounds_gauss-blocks.csv" index 9 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 11 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 13 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 16 using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333' title "", \
     "temperature_shift_vs_rounds_gauss-blocks.csv" index 17 using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333' title ""
unset multiplot
