# Integrators (reference generator): temperature error against cost, 95 % CIs (PNHLN: T_conf; within 10 %)
# Data: accuracy_cost_integrators.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'accuracy_cost_integrators.svg'" accuracy_cost_integrators.gp
set xlabel "wall time per unit of simulated time (two cells at a time) [s/τ]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "temperature − 1 [% of k_BT]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set object 1 rectangle from graph 0, first -1 to graph 1, first 1 behind fillcolor rgb '#DDEEDD' fillstyle solid 1.0 noborder
set label 1 "tolerance ±1" at graph 0.01, first 1 offset 0,-0.8 font ',10' tc rgb '#336633' front
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set title "Integrators (reference generator): temperature error against cost, 95 % CIs (PNHLN: T_conf; within 10 %)" noenhanced
plot "accuracy_cost_integrators.csv" index 0 using 2:3:4 with yerrorlines pt 7 lw 2 lc 1 title "scmvv:1", \
     "accuracy_cost_integrators.csv" index 1 using 2:3:4 with yerrorlines pt 7 lw 2 lc 2 title "mvv:0.65", \
     "accuracy_cost_integrators.csv" index 2 using 2:3:4 with yerrorlines pt 7 lw 2 lc 3 title "pnhln:10 (T_conf)", \
     "accuracy_cost_integrators.csv" index 3 using 2:3:4 with yerrorlines pt 7 lw 2 lc 4 title "shardlow", \
     "accuracy_cost_integrators.csv" index 4 using 2:3:4 with yerrorlines pt 7 lw 2 lc 5 title "mvv:0.5", \
     "accuracy_cost_integrators.csv" index 5 using 2:3:4 with yerrorlines pt 7 lw 2 lc 6 title "scmvv:5"
