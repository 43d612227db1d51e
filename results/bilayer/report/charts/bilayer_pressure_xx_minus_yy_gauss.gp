# in-plane anisotropy P_xx − P_yy (0 by symmetry about z): replica mean ± 95 % CI (gauss)
# Data: bilayer_pressure_xx_minus_yy_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'bilayer_pressure_xx_minus_yy_gauss.svg'" bilayer_pressure_xx_minus_yy_gauss.gp
set xlabel "generator" noenhanced
# x axis: categories
set ylabel "P_xx − P_yy [k_BT/r_c³]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set arrow from graph 0, first -0.00102291 to graph 1, first -0.00102291 nohead dt 2 lw 2 lc rgb 'black'
set xrange [-0.5:2.5]
set xtics rotate by -20
set title "in-plane anisotropy P_xx − P_yy (0 by symmetry about z): replica mean ± 95 % CI (gauss)" noenhanced
plot "bilayer_pressure_xx_minus_yy_gauss.csv" index 0 using 2:3:4:xtic(5) with yerrorbars pt 7 ps 1.5 lw 2 title "replica mean ± 95 % CI"
