# Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss; Fig. 4d; floor 0.001 % where the CI holds 0)
# Data: temperature_components_shift_vs_rounds_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'temperature_components_shift_vs_rounds_gauss.svg'" temperature_components_shift_vs_rounds_gauss.gp
# small multiples: 3 panels
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "|shift| against MT19937 [%]" noenhanced
set logscale y 10
set format y "%g"
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set yrange [0.001:*]
set multiplot layout 1,3 title "Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss; Fig. 4d; floor 0.001 % where the CI holds 0)" noenhanced
set title "T_x" noenhanced
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
set title "T_y" noenhanced
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 4 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
set title "T_z" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 2 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 5 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
unset multiplot
