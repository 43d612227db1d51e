# Radial distribution function (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" rdf_gauss.gp
set title "Radial distribution function (gauss)" noenhanced
set xlabel "r"
set ylabel "g(r)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
plot "data/rdf_gauss_0.dat" using 1:2 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "data/rdf_gauss_1.dat" using 1:2 with lines lw 2 title "philox4x32(7) distance", \
     "data/rdf_gauss_2.dat" using 1:2 with lines lw 2 dt 3 title "philox4x32(10) distance", \
     "data/rdf_gauss_3.dat" using 1:2 with lines lw 2 title "philox4x32(7) pair-step", \
     "data/rdf_gauss_4.dat" using 1:2 with lines lw 2 dt 3 title "philox4x32(10) pair-step", \
     "data/rdf_gauss_5.dat" using 1:2 with lines lw 2 title "saru distance", \
     "data/rdf_gauss_6.dat" using 1:2 with lines lw 2 title "saru pair-step", \
     "data/rdf_gauss_7.dat" using 1:2 with lines lw 2 title "splitmix64 distance", \
     "data/rdf_gauss_8.dat" using 1:2 with lines lw 2 title "splitmix64 pair-step", \
     "data/rdf_gauss_9.dat" using 1:2 with lines lw 2 title "tea32(1) distance", \
     "data/rdf_gauss_10.dat" using 1:2 with lines lw 2 dt 3 title "tea32(8) distance", \
     "data/rdf_gauss_11.dat" using 1:2 with lines lw 2 title "tea32(1) pair-step", \
     "data/rdf_gauss_12.dat" using 1:2 with lines lw 2 dt 3 title "tea32(8) pair-step", \
     "data/rdf_gauss_13.dat" using 1:2 with lines lw 2 title "tea64(1) distance", \
     "data/rdf_gauss_14.dat" using 1:2 with lines lw 2 dt 3 title "tea64(8) distance", \
     "data/rdf_gauss_15.dat" using 1:2 with lines lw 2 title "tea64(1) pair-step", \
     "data/rdf_gauss_16.dat" using 1:2 with lines lw 2 dt 3 title "tea64(8) pair-step", \
     "data/rdf_gauss_17.dat" using 1:2 with lines lw 2 title "threefry2x64(13) distance", \
     "data/rdf_gauss_18.dat" using 1:2 with lines lw 2 dt 3 title "threefry2x64(20) distance", \
     "data/rdf_gauss_19.dat" using 1:2 with lines lw 2 title "threefry2x64(13) pair-step", \
     "data/rdf_gauss_20.dat" using 1:2 with lines lw 2 dt 3 title "threefry2x64(20) pair-step"
