# Kinetic temperature per component, replica mean ± 95 % CI (gauss-blocks; the paper's Fig. 4b)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_components_vs_rounds_gauss-blocks.gp
set title "Kinetic temperature per component, replica mean ± 95 % CI (gauss-blocks; the paper's Fig. 4b)" noenhanced
set xlabel "rounds"
set ylabel "k_BT_α = Σv_α²/(N − 1) (k_BT units)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set arrow from graph 0, first 1.03762 to graph 1, first 1.03762 nohead dt 2 lw 1 lc rgb 'gray40'
set label "mt19937 T_x" at graph 0.01, first 1.03762 offset 0,0.6 tc rgb 'gray40'
set arrow from graph 0, first 1.03292 to graph 1, first 1.03292 nohead dt 2 lw 1 lc rgb 'gray40'
set label "mt19937 T_y" at graph 0.31, first 1.03292 offset 0,0.6 tc rgb 'gray40'
set arrow from graph 0, first 1.03407 to graph 1, first 1.03407 nohead dt 2 lw 1 lc rgb 'gray40'
set label "mt19937 T_z" at graph 0.61, first 1.03407 offset 0,0.6 tc rgb 'gray40'
plot "data/temperature_components_vs_rounds_gauss-blocks_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_2.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_3.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_4.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_5.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_6.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_7.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_8.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_9.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_10.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_11.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_12.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_13.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_14.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_15.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_16.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_17.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_18.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_19.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_20.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_21.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_22.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_23.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_24.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_25.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_26.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_27.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_28.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_29.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_30.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_31.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_32.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance T_z", \
     "data/temperature_components_vs_rounds_gauss-blocks_33.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step T_x", \
     "data/temperature_components_vs_rounds_gauss-blocks_34.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step T_y", \
     "data/temperature_components_vs_rounds_gauss-blocks_35.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step T_z"
