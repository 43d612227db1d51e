# Momentum drift per bead, max |P(t) − P(0)|/N, domains 2x1x1
# Data: drift_2x1x1.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'drift_2x1x1.svg'" drift_2x1x1.gp
set xlabel "seeding" noenhanced
# x axis: categories
set ylabel "momentum drift per bead [m r_c/τ]" noenhanced
set logscale y 10
set format y "%g"
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set xtics noenhanced rotate by -30
set title "Momentum drift per bead, max |P(t) − P(0)|/N, domains 2x1x1" noenhanced
plot "drift_2x1x1.csv" index 0 using 3:xtic(4) lc rgb '#0072B2' title "tea32(1) gauss", \
     "drift_2x1x1.csv" index 1 using 3:xtic(4) lc rgb '#0072B2' title "tea32(8) gauss", \
     "drift_2x1x1.csv" index 2 using 3:xtic(4) lc rgb '#E69F00' title "tea64(1) gauss", \
     "drift_2x1x1.csv" index 3 using 3:xtic(4) lc rgb '#009E73' title "philox4x32(10) gauss"
