# Accuracy against cost per unit simulated time: |P_c - 23.64| / 23.64 (blown-up points on the top edge)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" accuracy_cost_pressure.gp
set title "Accuracy against cost per unit simulated time: |P_c - 23.64| / 23.64 (blown-up points on the top edge)" noenhanced
set xlabel "wall seconds per unit of simulated time"
set ylabel "|P_c - 23.64| / 23.64"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale y
set logscale x
plot "data/accuracy_cost_pressure_0.dat" using 1:2 with linespoints pt 7 lw 2 lc 1 title "mvv:0.5 mt19937 gauss", \
     "data/accuracy_cost_pressure_1.dat" using 1:2 with linespoints pt 7 lw 2 lc 2 title "mvv:0.5 tea32(1) gauss", \
     "data/accuracy_cost_pressure_2.dat" using 1:2 with linespoints pt 7 lw 2 lc 3 title "mvv:0.5 mt19937 gauss-blocks", \
     "data/accuracy_cost_pressure_3.dat" using 1:2 with linespoints pt 7 lw 2 lc 4 title "mvv:0.5 tea32(1) gauss-blocks", \
     "data/accuracy_cost_pressure_4.dat" using 1:2 with linespoints pt 7 lw 2 lc 5 title "mvv:0.5 mt19937 gauss γ4.5", \
     "data/accuracy_cost_pressure_5.dat" using 1:2 with linespoints pt 7 lw 2 lc 6 title "mvv:0.65 mt19937 gauss", \
     "data/accuracy_cost_pressure_6.dat" using 1:2 with linespoints pt 7 lw 2 lc 7 title "mvv:0.65 tea32(1) gauss", \
     "data/accuracy_cost_pressure_7.dat" using 1:2 with linespoints pt 7 lw 2 lc 8 title "mvv:0.65 mt19937 gauss-blocks", \
     "data/accuracy_cost_pressure_8.dat" using 1:2 with linespoints pt 7 lw 2 lc 9 title "mvv:0.65 tea32(1) gauss-blocks", \
     "data/accuracy_cost_pressure_9.dat" using 1:2 with linespoints pt 7 lw 2 lc 10 title "mvv:0.65 mt19937 gauss γ4.5", \
     "data/accuracy_cost_pressure_10.dat" using 1:2 with linespoints pt 7 lw 2 lc 11 title "shardlow mt19937 gauss", \
     "data/accuracy_cost_pressure_11.dat" using 1:2 with linespoints pt 7 lw 2 lc 12 title "shardlow tea32(1) gauss", \
     "data/accuracy_cost_pressure_12.dat" using 1:2 with linespoints pt 7 lw 2 lc 13 title "shardlow mt19937 gauss-blocks", \
     "data/accuracy_cost_pressure_13.dat" using 1:2 with linespoints pt 7 lw 2 lc 14 title "shardlow tea32(1) gauss-blocks", \
     "data/accuracy_cost_pressure_14.dat" using 1:2 with linespoints pt 7 lw 2 lc 15 title "shardlow mt19937 gauss γ4.5", \
     "data/accuracy_cost_pressure_15.dat" using 1:2 with linespoints pt 7 lw 2 lc 16 title "scmvv:1 mt19937 gauss", \
     "data/accuracy_cost_pressure_16.dat" using 1:2 with linespoints pt 7 lw 2 lc 17 title "scmvv:1 tea32(1) gauss", \
     "data/accuracy_cost_pressure_17.dat" using 1:2 with linespoints pt 7 lw 2 lc 18 title "scmvv:1 mt19937 gauss-blocks", \
     "data/accuracy_cost_pressure_18.dat" using 1:2 with linespoints pt 7 lw 2 lc 19 title "scmvv:1 tea32(1) gauss-blocks", \
     "data/accuracy_cost_pressure_19.dat" using 1:2 with linespoints pt 7 lw 2 lc 20 title "scmvv:1 mt19937 gauss γ4.5", \
     "data/accuracy_cost_pressure_20.dat" using 1:2 with linespoints pt 7 lw 2 lc 21 title "scmvv:5 mt19937 gauss", \
     "data/accuracy_cost_pressure_21.dat" using 1:2 with linespoints pt 7 lw 2 lc 22 title "scmvv:5 tea32(1) gauss", \
     "data/accuracy_cost_pressure_22.dat" using 1:2 with linespoints pt 7 lw 2 lc 23 title "scmvv:5 mt19937 gauss-blocks", \
     "data/accuracy_cost_pressure_23.dat" using 1:2 with linespoints pt 7 lw 2 lc 24 title "scmvv:5 tea32(1) gauss-blocks", \
     "data/accuracy_cost_pressure_24.dat" using 1:2 with linespoints pt 7 lw 2 lc 25 title "scmvv:5 mt19937 gauss γ4.5", \
     "data/accuracy_cost_pressure_25.dat" using 1:2 with linespoints pt 7 lw 2 lc 26 title "pnhln:10 mt19937 gauss", \
     "data/accuracy_cost_pressure_26.dat" using 1:2 with linespoints pt 7 lw 2 lc 27 title "pnhln:10 mt19937 gauss γ4.5", \
     "data/accuracy_cost_pressure_27.dat" using 1:2 with points pt 2 ps 2 lw 2 lc rgb 'red' title "all replicas blew up"
