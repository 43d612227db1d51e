# tension L_z[P_zz − (P_xx+P_yy)/2]: replica mean ± 95 % CI (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" bilayer_tension_gauss.gp
set title "tension L_z[P_zz − (P_xx+P_yy)/2]: replica mean ± 95 % CI (gauss)" noenhanced
set xlabel ""
set ylabel "Σ"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set arrow from graph 0, first -0.120166 to graph 1, first -0.120166 nohead dt 2 lw 2 lc rgb 'black'
set xrange [-0.5:2.5]
set xtics rotate by -20
plot "data/bilayer_tension_gauss_0.dat" using 1:2:3:xtic(4) with yerrorbars pt 7 ps 1.5 lw 2 title "replica mean ± 95 % CI"
