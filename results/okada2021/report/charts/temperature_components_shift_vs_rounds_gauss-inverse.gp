# Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss-inverse; the paper's Fig. 4d)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" temperature_components_shift_vs_rounds_gauss-inverse.gp
set title "Error rate of each temperature component against MT, |shift| with its 95 % CI (gauss-inverse; the paper's Fig. 4d)" noenhanced
set xlabel "rounds"
set ylabel "|(T_α − T_{α,MT}) / T_{α,MT}| in % (log scale; floor 0.001 %: CI holds 0)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set yrange [0.001:*]
plot "data/temperature_components_shift_vs_rounds_gauss-inverse_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss-inverse_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss-inverse_2.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance T_z", \
     "data/temperature_components_shift_vs_rounds_gauss-inverse_3.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_x", \
     "data/temperature_components_shift_vs_rounds_gauss-inverse_4.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_y", \
     "data/temperature_components_shift_vs_rounds_gauss-inverse_5.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance T_z"
