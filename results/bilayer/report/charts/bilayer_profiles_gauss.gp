# Number density across the bilayer, replica means (gauss)
# Data: bilayer_profiles_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'bilayer_profiles_gauss.svg'" bilayer_profiles_gauss.gp
# small multiples: 3 panels
set xlabel "z relative to the bilayer midplane [r_c]" noenhanced
set ylabel "number density [r_c⁻³]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set multiplot layout 1,3 title "Number density across the bilayer, replica means (gauss)" noenhanced
set title "heads (H)" noenhanced
unset colorbox
plot "bilayer_profiles_gauss.csv" index 0 using 2:3 with lines dt 1 lw 4 lc rgb '#000000' title "mt19937 gauss", \
     "bilayer_profiles_gauss.csv" index 3 using 2:3 with lines dt 1 lw 2 lc rgb '#0072B2' title "tea32(1) distance gauss", \
     "bilayer_profiles_gauss.csv" index 6 using 2:3 with lines dt 2 lw 2 lc rgb '#0072B2' title "tea32(32) distance gauss"
set title "tails (T)" noenhanced
unset colorbox
plot "bilayer_profiles_gauss.csv" index 1 using 2:3 with lines dt 1 lw 4 lc rgb '#000000' title "mt19937 gauss", \
     "bilayer_profiles_gauss.csv" index 4 using 2:3 with lines dt 1 lw 2 lc rgb '#0072B2' title "tea32(1) distance gauss", \
     "bilayer_profiles_gauss.csv" index 7 using 2:3 with lines dt 2 lw 2 lc rgb '#0072B2' title "tea32(32) distance gauss"
set title "water (W)" noenhanced
set key inside center center noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "bilayer_profiles_gauss.csv" index 2 using 2:3 with lines dt 1 lw 4 lc rgb '#000000' title "mt19937 gauss", \
     "bilayer_profiles_gauss.csv" index 5 using 2:3 with lines dt 1 lw 2 lc rgb '#0072B2' title "tea32(1) distance gauss", \
     "bilayer_profiles_gauss.csv" index 8 using 2:3 with lines dt 2 lw 2 lc rgb '#0072B2' title "tea32(32) distance gauss"
unset multiplot
