# shardlow: kinetic temperature against dt, 95 % CIs (within 10 %)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" crossing_kinetic_shardlow.gp
set title "shardlow: kinetic temperature against dt, 95 % CIs (within 10 %)" noenhanced
set xlabel "dt (DPD time units)"
set ylabel "<k_BT> - 1 (%)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set grid
set key outside right
plot "data/crossing_kinetic_shardlow_0.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 1 title "mt19937 gauss", \
     "data/crossing_kinetic_shardlow_1.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 2 title "tea32(1) gauss", \
     "data/crossing_kinetic_shardlow_2.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 3 title "mt19937 gauss-blocks", \
     "data/crossing_kinetic_shardlow_3.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 4 title "tea32(1) gauss-blocks"
