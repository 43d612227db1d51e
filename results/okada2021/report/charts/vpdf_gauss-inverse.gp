# Velocity PDF, pooled components (gauss-inverse)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" vpdf_gauss-inverse.gp
set title "Velocity PDF, pooled components (gauss-inverse)" noenhanced
set xlabel "v"
set ylabel "P(v)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale y
plot "data/vpdf_gauss-inverse_0.dat" using 1:2 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 16 replicas)", \
     "data/vpdf_gauss-inverse_1.dat" using 1:2 with lines dt 2 lw 2 lc rgb 'gray40' title "Maxwell–Boltzmann at k_BT", \
     "data/vpdf_gauss-inverse_2.dat" using 1:2 with lines lw 2 title "tea32(1) distance", \
     "data/vpdf_gauss-inverse_3.dat" using 1:2 with lines lw 2 dt 3 title "tea32(32) distance", \
     "data/vpdf_gauss-inverse_4.dat" using 1:2 with lines lw 2 title "tea64(1) distance", \
     "data/vpdf_gauss-inverse_5.dat" using 1:2 with lines lw 2 dt 3 title "tea64(32) distance"
