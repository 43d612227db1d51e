# Boundary pairs whose two ζ differ, domains 2x1x1
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" mismatch_2x1x1.gp
set title "Boundary pairs whose two ζ differ, domains 2x1x1" noenhanced
set xlabel "seeding"
set ylabel "%"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set xtics noenhanced rotate by -30
set yrange [0:*]
plot "data/mismatch_2x1x1_0.dat" using 2:xtic(3) title "tea32(1) gauss", \
     "data/mismatch_2x1x1_1.dat" using 2:xtic(3) title "tea32(8) gauss", \
     "data/mismatch_2x1x1_2.dat" using 2:xtic(3) title "tea64(1) gauss", \
     "data/mismatch_2x1x1_3.dat" using 2:xtic(3) title "philox4x32(10) gauss"
