# Mean squared displacement: relative difference from MT19937, 95 % CI (gauss); beyond ±20 %, not drawn: tea64(1) distance
# Data: msd_difference_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'msd_difference_gauss.svg'" msd_difference_gauss.gp
set xlabel "lag time t [τ]" noenhanced
set logscale x 10
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "difference from MT19937 [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set title "Mean squared displacement: relative difference from MT19937, 95 % CI (gauss); beyond ±20 %, not drawn: tea64(1) distance" noenhanced
plot "msd_difference_gauss.csv" index 0 using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 pt 7 lc rgb '#0072B2' title "tea32(1) distance", \
     "msd_difference_gauss.csv" index 1 using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 dt 2 pt 6 lc rgb '#0072B2' title "tea32(32) distance", \
     "msd_difference_gauss.csv" index 2 using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 dt 2 pt 6 lc rgb '#E69F00' title "tea64(32) distance"
