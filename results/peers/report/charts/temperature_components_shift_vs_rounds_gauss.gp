# Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss; Fig. 4d; floor 0.001 % where the CI holds 0)
# Data: temperature_components_shift_vs_rounds_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'temperature_components_shift_vs_rounds_gauss.svg'" temperature_components_shift_vs_rounds_gauss.gp
# small multiples: 12 panels
# canvas: 900,2400
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
set xrange [0.833333:24]
set multiplot layout 6,2 title "Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss; Fig. 4d; floor 0.001 % where the CI holds 0)" noenhanced
set title "T_x, distance seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 6 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 12 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 18 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "T_x, distance seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 24 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 30 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 36 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "T_x, pair-step seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 9 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 15 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 21 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "T_x, pair-step seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 27 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 33 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 39 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "T_y, distance seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 7 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 13 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 19 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "T_y, distance seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 25 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 31 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 37 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "T_y, pair-step seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 4 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 10 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 16 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 22 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "T_y, pair-step seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 28 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 34 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 40 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "T_z, distance seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 2 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 8 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 14 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 20 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "T_z, distance seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 26 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 32 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 38 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "T_z, pair-step seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 5 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 11 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 17 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 23 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "T_z, pair-step seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "temperature_components_shift_vs_rounds_gauss.csv" index 29 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 35 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "temperature_components_shift_vs_rounds_gauss.csv" index 41 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
unset multiplot
