# Error rate of the diffusion coefficient against MT, |shift| with its 95 % CI (uniform; the paper's Fig. 5b)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" diffusion_shift_vs_rounds_uniform.gp
set title "Error rate of the diffusion coefficient against MT, |shift| with its 95 % CI (uniform; the paper's Fig. 5b)" noenhanced
set xlabel "rounds"
set ylabel "|(D − D_{MT}) / D_{MT}| in % (log scale; floor 0.001 %: CI holds 0)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set logscale y
set xrange [0.8:*]
set yrange [0.001:*]
plot "data/diffusion_shift_vs_rounds_uniform_0.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea32 distance", \
     "data/diffusion_shift_vs_rounds_uniform_1.dat" using 1:2:3:4 with yerrorlines lw 2 pt 7 title "tea64 distance"
