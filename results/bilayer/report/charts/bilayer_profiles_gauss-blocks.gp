# Number density across the bilayer, replica means (gauss-blocks)
# Data: bilayer_profiles_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'bilayer_profiles_gauss-blocks.svg'" bilayer_profiles_gauss-blocks.gp
# small multiples: 3 panels
set xlabel "z relative to the bilayer midplane [r_c]" noenhanced
set ylabel "number density [r_c⁻³]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set multiplot layout 1,3 title "Number density across the bilayer, replica means (gauss-blocks)" noenhanced
set title "heads (H)" noenhanced
unset colorbox
plot "bilayer_profiles_gauss-blocks.csv" index 0 using 2:3 with lines dt 1 lw 4 lc rgb '#000000' title "mt19937 gauss-blocks", \
     "bilayer_profiles_gauss-blocks.csv" index 3 using 2:3 with lines dt 1 lw 2 lc rgb '#0072B2' title "tea32(1) distance gauss-blocks", \
     "bilayer_profiles_gauss-blocks.csv" index 6 using 2:3 with lines dt 2 lw 2 lc rgb '#0072B2' title "tea32(32) distance gauss-blocks"
set title "tails (T)" noenhanced
unset colorbox
plot "bilayer_profiles_gauss-blocks.csv" index 1 using 2:3 with lines dt 1 lw 4 lc rgb '#000000' title "mt19937 gauss-blocks", \
     "bilayer_profiles_gauss-blocks.csv" index 4 using 2:3 with lines dt 1 lw 2 lc rgb '#0072B2' title "tea32(1) distance gauss-blocks", \
     "bilayer_profiles_gauss-blocks.csv" index 7 using 2:3 with lines dt 2 lw 2 lc rgb '#0072B2' title "tea32(32) distance gauss-blocks"
set title "water (W)" noenhanced
set key inside center center noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "bilayer_profiles_gauss-blocks.csv" index 2 using 2:3 with lines dt 1 lw 4 lc rgb '#000000' title "mt19937 gauss-blocks", \
     "bilayer_profiles_gauss-blocks.csv" index 5 using 2:3 with lines dt 1 lw 2 lc rgb '#0072B2' title "tea32(1) distance gauss-blocks", \
     "bilayer_profiles_gauss-blocks.csv" index 8 using 2:3 with lines dt 2 lw 2 lc rgb '#0072B2' title "tea32(32) distance gauss-blocks"
unset multiplot
