# tension L_z[P_zz − (P_xx+P_yy)/2]: replica mean ± 95 % CI (gauss)
# Data: bilayer_tension_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'bilayer_tension_gauss.svg'" bilayer_tension_gauss.gp
set xlabel "generator" noenhanced
# x axis: categories
set ylabel "Σ [k_BT/r_c²]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set arrow from graph 0, first -0.120166 to graph 1, first -0.120166 nohead dt 2 lw 2 lc rgb 'black'
set xrange [-0.5:2.5]
set xtics rotate by -20
set title "tension L_z[P_zz − (P_xx+P_yy)/2]: replica mean ± 95 % CI (gauss)" noenhanced
plot "bilayer_tension_gauss.csv" index 0 using 2:3:4:xtic(5) with yerrorbars pt 7 ps 1.5 lw 2 title "replica mean ± 95 % CI"
