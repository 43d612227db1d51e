# Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss; the paper's Fig. 4d)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_components_shift_vs_rounds_gauss.gp
set title "Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss; the paper's Fig. 4d)" noenhanced
set xlabel "rounds"
set ylabel "|(T_α − T_{α,MT}) / T_{α,MT}| in % (log scale; floor 0.001 %: CI holds 0)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set yrange [0.001:*]
plot "data/temperature_components_shift_vs_rounds_gauss_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_2.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_3.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_4.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_5.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "philox4x32 pair-step T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_6.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_7.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_8.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_9.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_10.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_11.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "saru pair-step T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_12.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_13.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_14.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_15.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_16.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_17.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "splitmix64 pair-step T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_18.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_19.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_20.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_21.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_22.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_23.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 pair-step T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_24.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_25.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_26.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_27.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_28.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_29.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 pair-step T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_30.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_31.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_32.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss_33.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step T_x", \
     "data/temperature_components_shift_vs_rounds_gauss_34.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step T_y", \
     "data/temperature_components_shift_vs_rounds_gauss_35.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "threefry2x64 pair-step T_z"
