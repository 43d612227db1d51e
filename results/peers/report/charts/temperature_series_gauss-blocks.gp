# Kinetic temperature against the step, replica mean (gauss-blocks)
# Data: temperature_series_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'temperature_series_gauss-blocks.svg'" temperature_series_gauss-blocks.gp
set xlabel "step [1]" noenhanced
set ylabel "kinetic temperature [k_BT]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set title "Kinetic temperature against the step, replica mean (gauss-blocks)" noenhanced
plot "temperature_series_gauss-blocks.csv" index 0 using 2:3 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "temperature_series_gauss-blocks.csv" index 1 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) distance", \
     "temperature_series_gauss-blocks.csv" index 2 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) pair-step", \
     "temperature_series_gauss-blocks.csv" index 3 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru distance", \
     "temperature_series_gauss-blocks.csv" index 4 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru pair-step", \
     "temperature_series_gauss-blocks.csv" index 5 using 2:3 with lines lw 2 dt 1 lc rgb '#56B4E9' title "splitmix64 distance"
