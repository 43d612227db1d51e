# Mean squared displacement (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" msd_gauss.gp
set title "Mean squared displacement (gauss)" noenhanced
set xlabel "τ"
set ylabel "MSD"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.32:*]
plot "data/msd_gauss_0.dat" using 1:2 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "data/msd_gauss_1.dat" using 1:2 with lines lw 2 title "philox4x32(7) distance", \
     "data/msd_gauss_2.dat" using 1:2 with lines lw 2 dt 3 title "philox4x32(10) distance", \
     "data/msd_gauss_3.dat" using 1:2 with lines lw 2 title "philox4x32(7) pair-step", \
     "data/msd_gauss_4.dat" using 1:2 with lines lw 2 dt 3 title "philox4x32(10) pair-step", \
     "data/msd_gauss_5.dat" using 1:2 with lines lw 2 title "saru distance", \
     "data/msd_gauss_6.dat" using 1:2 with lines lw 2 title "saru pair-step", \
     "data/msd_gauss_7.dat" using 1:2 with lines lw 2 title "splitmix64 distance", \
     "data/msd_gauss_8.dat" using 1:2 with lines lw 2 title "splitmix64 pair-step", \
     "data/msd_gauss_9.dat" using 1:2 with lines lw 2 title "tea32(1) distance", \
     "data/msd_gauss_10.dat" using 1:2 with lines lw 2 dt 3 title "tea32(8) distance", \
     "data/msd_gauss_11.dat" using 1:2 with lines lw 2 title "tea32(1) pair-step", \
     "data/msd_gauss_12.dat" using 1:2 with lines lw 2 dt 3 title "tea32(8) pair-step", \
     "data/msd_gauss_13.dat" using 1:2 with lines lw 2 title "tea64(1) distance", \
     "data/msd_gauss_14.dat" using 1:2 with lines lw 2 dt 3 title "tea64(8) distance", \
     "data/msd_gauss_15.dat" using 1:2 with lines lw 2 title "tea64(1) pair-step", \
     "data/msd_gauss_16.dat" using 1:2 with lines lw 2 dt 3 title "tea64(8) pair-step", \
     "data/msd_gauss_17.dat" using 1:2 with lines lw 2 title "threefry2x64(13) distance", \
     "data/msd_gauss_18.dat" using 1:2 with lines lw 2 dt 3 title "threefry2x64(20) distance", \
     "data/msd_gauss_19.dat" using 1:2 with lines lw 2 title "threefry2x64(13) pair-step", \
     "data/msd_gauss_20.dat" using 1:2 with lines lw 2 dt 3 title "threefry2x64(20) pair-step"
