# mvv:0.65: kinetic temperature against Δt, 95 % CIs (within 10 %)
# Data: crossing_kinetic_mvv_0.65.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'crossing_kinetic_mvv_0.65.svg'" crossing_kinetic_mvv_0.65.gp
set xlabel "time step Δt [τ]" noenhanced
set ylabel "k_BT − 1 [% of k_BT]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top left noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set title "mvv:0.65: kinetic temperature against Δt, 95 % CIs (within 10 %)" noenhanced
plot "crossing_kinetic_mvv_0.65.csv" index 0 using 2:3:4 with yerrorlines pt 7 lw 2 lc rgb '#000000' dt 1 title "mt19937 gauss", \
     "crossing_kinetic_mvv_0.65.csv" index 1 using 2:3:4 with yerrorlines pt 7 lw 2 lc rgb '#0072B2' dt 1 title "tea32(1) gauss", \
     "crossing_kinetic_mvv_0.65.csv" index 2 using 2:3:4 with yerrorlines pt 7 lw 2 lc rgb '#000000' dt 2 title "mt19937 gauss-blocks", \
     "crossing_kinetic_mvv_0.65.csv" index 3 using 2:3:4 with yerrorlines pt 7 lw 2 lc rgb '#0072B2' dt 2 title "tea32(1) gauss-blocks"
