# Kinetic temperature per component, replica mean ± 95 % CI (gauss-blocks; Fig. 4b)
# Data: temperature_components_vs_rounds_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'temperature_components_vs_rounds_gauss-blocks.svg'" temperature_components_vs_rounds_gauss-blocks.gp
# small multiples: 3 panels
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "k_BT_α = Σv_α²/(N − 1) [k_BT]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set multiplot layout 1,3 title "Kinetic temperature per component, replica mean ± 95 % CI (gauss-blocks; Fig. 4b)" noenhanced
set title "T_x" noenhanced
unset colorbox
plot "temperature_components_vs_rounds_gauss-blocks.csv" index 0 using 2:3 with lines dt 2 lw 2 lc rgb 'black' title "", \
     "temperature_components_vs_rounds_gauss-blocks.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_components_vs_rounds_gauss-blocks.csv" index 6 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
set title "T_y" noenhanced
unset colorbox
plot "temperature_components_vs_rounds_gauss-blocks.csv" index 1 using 2:3 with lines dt 2 lw 2 lc rgb 'black' title "", \
     "temperature_components_vs_rounds_gauss-blocks.csv" index 4 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_components_vs_rounds_gauss-blocks.csv" index 7 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
set title "T_z" noenhanced
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "temperature_components_vs_rounds_gauss-blocks.csv" index 2 using 2:3 with lines dt 2 lw 2 lc rgb 'black' title "", \
     "temperature_components_vs_rounds_gauss-blocks.csv" index 5 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "temperature_components_vs_rounds_gauss-blocks.csv" index 8 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance", \
     keyentry with lines dt 2 lw 2 lc rgb 'black' title "mt19937 (reference)"
unset multiplot
