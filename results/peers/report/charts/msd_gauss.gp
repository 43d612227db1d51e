# Mean squared displacement (gauss)
# Data: msd_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'msd_gauss.svg'" msd_gauss.gp
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
set title "Mean squared displacement (gauss)" noenhanced
plot "msd_gauss.csv" index 0 using 2:3 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "msd_gauss.csv" index 1 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) distance", \
     "msd_gauss.csv" index 2 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) pair-step", \
     "msd_gauss.csv" index 3 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru distance", \
     "msd_gauss.csv" index 4 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru pair-step", \
     "msd_gauss.csv" index 5 using 2:3 with lines lw 2 dt 1 lc rgb '#56B4E9' title "splitmix64 distance"
