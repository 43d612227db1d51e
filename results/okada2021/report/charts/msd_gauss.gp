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
plot "data/msd_gauss_0.dat" using 1:2 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 16 replicas)", \
     "data/msd_gauss_1.dat" using 1:2 with lines lw 2 title "tea32(1) distance", \
     "data/msd_gauss_2.dat" using 1:2 with lines lw 2 dt 3 title "tea32(32) distance", \
     "data/msd_gauss_3.dat" using 1:2 with lines lw 2 title "tea64(1) distance", \
     "data/msd_gauss_4.dat" using 1:2 with lines lw 2 dt 3 title "tea64(32) distance"
