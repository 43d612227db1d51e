# Error rate of the diffusion coefficient against MT, |shift| with its 95 % CI (gauss; Fig. 5b; floor 0.001 % where the CI holds 0)
# Data: diffusion_shift_vs_rounds_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'diffusion_shift_vs_rounds_gauss.svg'" diffusion_shift_vs_rounds_gauss.gp
# small multiples: 4 panels
# canvas: 900,800
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
set multiplot layout 2,2 title "Error rate of the diffusion coefficient against MT, |shift| with its 95 % CI (gauss; Fig. 5b; floor 0.001 % where the CI holds 0)" noenhanced
set title "distance seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "diffusion_shift_vs_rounds_gauss.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "diffusion_shift_vs_rounds_gauss.csv" index 2 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "diffusion_shift_vs_rounds_gauss.csv" index 4 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "diffusion_shift_vs_rounds_gauss.csv" index 6 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "distance seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "diffusion_shift_vs_rounds_gauss.csv" index 8 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "diffusion_shift_vs_rounds_gauss.csv" index 10 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "diffusion_shift_vs_rounds_gauss.csv" index 12 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "pair-step seeding, generators 1 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "diffusion_shift_vs_rounds_gauss.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "diffusion_shift_vs_rounds_gauss.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "diffusion_shift_vs_rounds_gauss.csv" index 5 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "diffusion_shift_vs_rounds_gauss.csv" index 7 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "pair-step seeding, generators 2 of 2" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "diffusion_shift_vs_rounds_gauss.csv" index 9 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "diffusion_shift_vs_rounds_gauss.csv" index 11 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "diffusion_shift_vs_rounds_gauss.csv" index 13 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
unset multiplot
