# Radial distribution function (gauss)
# Data: rdf_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'rdf_gauss.svg'" rdf_gauss.gp
set xlabel "pair distance r [r_c]" noenhanced
set ylabel "g(r) [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set title "Radial distribution function (gauss)" noenhanced
plot "rdf_gauss.csv" index 0 using 2:3 with lines lw 4 lc rgb 'black' title "mt19937 (reference, 4 replicas)", \
     "rdf_gauss.csv" index 1 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) distance", \
     "rdf_gauss.csv" index 2 using 2:3 with lines lw 2 dt 1 lc rgb '#009E73' title "philox4x32(7) pair-step", \
     "rdf_gauss.csv" index 3 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru distance", \
     "rdf_gauss.csv" index 4 using 2:3 with lines lw 2 dt 1 lc rgb '#D55E00' title "saru pair-step", \
     "rdf_gauss.csv" index 5 using 2:3 with lines lw 2 dt 1 lc rgb '#56B4E9' title "splitmix64 distance"
