# Radial distribution function (uniform)
# Data: rdf_uniform.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'rdf_uniform.svg'" rdf_uniform.gp
set xlabel "pair distance r [r_c]" noenhanced
set ylabel "g(r) [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set title "Radial distribution function (uniform)" noenhanced
plot "rdf_uniform.csv" index 0 using 2:3 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 16 replicas)", \
     "rdf_uniform.csv" index 1 using 2:3 with lines lw 2 dt 1 lc rgb '#0072B2' title "tea32(1) distance", \
     "rdf_uniform.csv" index 2 using 2:3 with lines lw 2 dt 1 lc rgb '#E69F00' title "tea64(1) distance", \
     "rdf_uniform.csv" index 3 using 2:3 with lines lw 2 dt 3 lc rgb '#0072B2' title "tea32(32) distance", \
     "rdf_uniform.csv" index 4 using 2:3 with lines lw 2 dt 3 lc rgb '#E69F00' title "tea64(32) distance"
