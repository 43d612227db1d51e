# Velocity PDF, pooled components (gauss-blocks)
# Data: vpdf_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'vpdf_gauss-blocks.svg'" vpdf_gauss-blocks.gp
set xlabel "velocity component v_α [√(k_BT/m)]" noenhanced
set ylabel "probability density P(v_α) [√(m/k_BT)]" noenhanced
set logscale y 10
set format y "%g"
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set title "Velocity PDF, pooled components (gauss-blocks)" noenhanced
plot "vpdf_gauss-blocks.csv" index 0 using 2:3 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "vpdf_gauss-blocks.csv" index 1 using 2:3 with lines dt 2 lw 2 lc rgb '#777777' title "Maxwell–Boltzmann at k_BT", \
     "vpdf_gauss-blocks.csv" index 2 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) distance", \
     "vpdf_gauss-blocks.csv" index 3 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) pair-step", \
     "vpdf_gauss-blocks.csv" index 4 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru distance", \
     "vpdf_gauss-blocks.csv" index 5 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru pair-step"
