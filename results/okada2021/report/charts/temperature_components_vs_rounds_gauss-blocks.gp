# Kinetic temperature per component, replica mean ± 95 % CI (gauss-blocks; the paper's Fig. 4b)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_components_vs_rounds_gauss-blocks.gp
set title "Kinetic temperature per component, replica mean ± 95 % CI (gauss-blocks; the paper's Fig. 4b)" noenhanced
set xlabel "rounds"
set ylabel "k_BT_α = Σv_α²/(N − 1) (k_BT units)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set xrange [0.8:*]
set arrow from graph 0, first 1.03673 to graph 1, first 1.03673 nohead dt 2 lw 1 lc rgb 'gray40'
set label "mt19937 T_x" at graph 0.01, first 1.03673 offset 0,0.6 tc rgb 'gray40'
set arrow from graph 0, first 1.03527 to graph 1, first 1.03527 nohead dt 2 lw 1 lc rgb 'gray40'
set label "mt19937 T_y" at graph 0.31, first 1.03527 offset 0,0.6 tc rgb 'gray40'
set arrow from graph 0, first 1.03377 to graph 1, first 1.03377 nohead dt 2 lw 1 lc rgb 'gray40'
set label "mt19937 T_z" at graph 0.61, first 1.03377 offset 0,0.6 tc rgb 'gray40'
plot "data/temperature_components_vs_rounds_gauss-blocks_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_2.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_3.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_4.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_5.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_z"
