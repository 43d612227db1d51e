# mvv:0.5: kinetic temperature against dt, 95 % CIs (within 10 %)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" crossing_kinetic_mvv_0.5.gp
set title "mvv:0.5: kinetic temperature against dt, 95 % CIs (within 10 %)" noenhanced
set xlabel "dt (DPD time units)"
set ylabel "<k_BT> - 1 (%)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set grid
set key outside right
plot "data/crossing_kinetic_mvv_0.5_0.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 1 title "mt19937 gauss", \
     "data/crossing_kinetic_mvv_0.5_1.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 2 title "tea32(1) gauss", \
     "data/crossing_kinetic_mvv_0.5_2.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 3 title "mt19937 gauss-blocks", \
     "data/crossing_kinetic_mvv_0.5_3.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 4 title "tea32(1) gauss-blocks"
