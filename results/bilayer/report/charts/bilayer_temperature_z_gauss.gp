# kinetic temperature of the z components (normal to the membrane): replica mean ± 95 % CI (gauss)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" bilayer_temperature_z_gauss.gp
set title "kinetic temperature of the z components (normal to the membrane): replica mean ± 95 % CI (gauss)" noenhanced
set xlabel ""
set ylabel "T_z"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set arrow from graph 0, first 1.00345 to graph 1, first 1.00345 nohead dt 2 lw 2 lc rgb 'black'
set xrange [-0.5:2.5]
set xtics rotate by -20
plot "data/bilayer_temperature_z_gauss_0.dat" using 1:2:3:xtic(4) with yerrorbars pt 7 ps 1.5 lw 2 title "replica mean ± 95 % CI"
