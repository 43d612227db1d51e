# Kinetic temperature against the step, replica mean (uniform)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_series_uniform.gp
set title "Kinetic temperature against the step, replica mean (uniform)" noenhanced
set xlabel "step"
set ylabel "k_BT (kinetic)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
plot "data/temperature_series_uniform_0.dat" using 1:2 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 16 replicas)", \
     "data/temperature_series_uniform_1.dat" using 1:2 with lines lw 2 title "tea32(1) distance", \
     "data/temperature_series_uniform_2.dat" using 1:2 with lines lw 2 dt 3 title "tea32(32) distance", \
     "data/temperature_series_uniform_3.dat" using 1:2 with lines lw 2 title "tea64(1) distance", \
     "data/temperature_series_uniform_4.dat" using 1:2 with lines lw 2 dt 3 title "tea64(32) distance"
