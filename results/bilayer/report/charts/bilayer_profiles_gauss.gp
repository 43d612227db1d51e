# Number density across the bilayer, replica means (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" bilayer_profiles_gauss.gp
set title "Number density across the bilayer, replica means (gauss)" noenhanced
set xlabel "z relative to the bilayer midplane"
set ylabel "beads per unit volume"
set grid
set key outside right top noenhanced
set datafile missing "nan"
plot "data/bilayer_profiles_gauss_0.dat" using 1:2 with lines dt 1 lw 4 lc rgb 'black' title "mt19937 H", \
     "data/bilayer_profiles_gauss_1.dat" using 1:2 with lines dt 2 lw 4 lc rgb 'black' title "mt19937 T", \
     "data/bilayer_profiles_gauss_2.dat" using 1:2 with lines dt 3 lw 4 lc rgb 'black' title "mt19937 W", \
     "data/bilayer_profiles_gauss_3.dat" using 1:2 with lines dt 1 lw 2 lc 1 title "tea32(1) distance H", \
     "data/bilayer_profiles_gauss_4.dat" using 1:2 with lines dt 2 lw 2 lc 1 title "tea32(1) distance T", \
     "data/bilayer_profiles_gauss_5.dat" using 1:2 with lines dt 3 lw 2 lc 1 title "tea32(1) distance W", \
     "data/bilayer_profiles_gauss_6.dat" using 1:2 with lines dt 1 lw 2 lc 2 title "tea32(32) distance H", \
     "data/bilayer_profiles_gauss_7.dat" using 1:2 with lines dt 2 lw 2 lc 2 title "tea32(32) distance T", \
     "data/bilayer_profiles_gauss_8.dat" using 1:2 with lines dt 3 lw 2 lc 2 title "tea32(32) distance W"
