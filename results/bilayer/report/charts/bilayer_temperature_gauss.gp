# kinetic temperature k_BT: replica mean ± 95 % CI (gauss)
# Data: bilayer_temperature_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'bilayer_temperature_gauss.svg'" bilayer_temperature_gauss.gp
set xlabel "generator" noenhanced
# x axis: categories
set ylabel "T [k_BT]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set arrow from graph 0, first 1.00346 to graph 1, first 1.00346 nohead dt 2 lw 2 lc rgb 'black'
set xrange [-0.5:2.5]
set xtics rotate by -20
set title "kinetic temperature k_BT: replica mean ± 95 % CI (gauss)" noenhanced
plot "bilayer_temperature_gauss.csv" index 0 using 2:3:4:xtic(5) with yerrorbars pt 7 ps 1.5 lw 2 title "replica mean ± 95 % CI"
