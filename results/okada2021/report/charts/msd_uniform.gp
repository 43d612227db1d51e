# Mean squared displacement (uniform)
# Data: msd_uniform.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'msd_uniform.svg'" msd_uniform.gp
set xlabel "lag time t [τ]" noenhanced
set logscale x 10
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "mean squared displacement [r_c²]" noenhanced
set logscale y 10
set format y "%g"
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set title "Mean squared displacement (uniform)" noenhanced
plot "msd_uniform.csv" index 0 using 2:3 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 16 replicas)", \
     "msd_uniform.csv" index 1 using 2:3 with lines lw 2 dt 1 lc rgb '#0072B2' title "tea32(1) distance", \
     "msd_uniform.csv" index 2 using 2:3 with lines lw 2 dt 1 lc rgb '#E69F00' title "tea64(1) distance", \
     "msd_uniform.csv" index 3 using 2:3 with lines lw 2 dt 3 lc rgb '#0072B2' title "tea32(32) distance", \
     "msd_uniform.csv" index 4 using 2:3 with lines lw 2 dt 3 lc rgb '#E69F00' title "tea64(32) distance"
