# Kinetic temperature against the step, replica mean (gauss-blocks)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_series_gauss-blocks.gp
set title "Kinetic temperature against the step, replica mean (gauss-blocks)" noenhanced
set xlabel "step"
set ylabel "k_BT (kinetic)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
plot "data/temperature_series_gauss-blocks_0.dat" using 1:2 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "data/temperature_series_gauss-blocks_1.dat" using 1:2 with lines lw 2 title "philox4x32(7) distance", \
     "data/temperature_series_gauss-blocks_2.dat" using 1:2 with lines lw 2 dt 3 title "philox4x32(10) distance", \
     "data/temperature_series_gauss-blocks_3.dat" using 1:2 with lines lw 2 title "philox4x32(7) pair-step", \
     "data/temperature_series_gauss-blocks_4.dat" using 1:2 with lines lw 2 dt 3 title "philox4x32(10) pair-step", \
     "data/temperature_series_gauss-blocks_5.dat" using 1:2 with lines lw 2 title "saru distance", \
     "data/temperature_series_gauss-blocks_6.dat" using 1:2 with lines lw 2 title "saru pair-step", \
     "data/temperature_series_gauss-blocks_7.dat" using 1:2 with lines lw 2 title "splitmix64 distance", \
     "data/temperature_series_gauss-blocks_8.dat" using 1:2 with lines lw 2 title "splitmix64 pair-step", \
     "data/temperature_series_gauss-blocks_9.dat" using 1:2 with lines lw 2 title "tea32(1) distance", \
     "data/temperature_series_gauss-blocks_10.dat" using 1:2 with lines lw 2 dt 3 title "tea32(8) distance", \
     "data/temperature_series_gauss-blocks_11.dat" using 1:2 with lines lw 2 title "tea32(1) pair-step", \
     "data/temperature_series_gauss-blocks_12.dat" using 1:2 with lines lw 2 dt 3 title "tea32(8) pair-step", \
     "data/temperature_series_gauss-blocks_13.dat" using 1:2 with lines lw 2 title "tea64(1) distance", \
     "data/temperature_series_gauss-blocks_14.dat" using 1:2 with lines lw 2 dt 3 title "tea64(8) distance", \
     "data/temperature_series_gauss-blocks_15.dat" using 1:2 with lines lw 2 title "tea64(1) pair-step", \
     "data/temperature_series_gauss-blocks_16.dat" using 1:2 with lines lw 2 dt 3 title "tea64(8) pair-step", \
     "data/temperature_series_gauss-blocks_17.dat" using 1:2 with lines lw 2 title "threefry2x64(13) distance", \
     "data/temperature_series_gauss-blocks_18.dat" using 1:2 with lines lw 2 dt 3 title "threefry2x64(20) distance", \
     "data/temperature_series_gauss-blocks_19.dat" using 1:2 with lines lw 2 title "threefry2x64(13) pair-step", \
     "data/temperature_series_gauss-blocks_20.dat" using 1:2 with lines lw 2 dt 3 title "threefry2x64(20) pair-step"
