# Integrators (reference generator): temperature error against cost, 95 % CIs (PNHLN: T_conf; within 10 %)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" accuracy_cost_integrators.gp
set title "Integrators (reference generator): temperature error against cost, 95 % CIs (PNHLN: T_conf; within 10 %)" noenhanced
set xlabel "wall seconds per unit of simulated time"
set ylabel "<T> - 1 (%)"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x 2
set xrange [0.00345799:*]
set grid
set arrow from graph 0, first 1.000000 to graph 1, first 1.000000 nohead dt 2
set arrow from graph 0, first -1.000000 to graph 1, first -1.000000 nohead dt 2
set key outside right
plot "data/accuracy_cost_integrators_0.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 1 title "scmvv:1", \
     "data/accuracy_cost_integrators_1.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 2 title "mvv:0.65", \
     "data/accuracy_cost_integrators_2.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 3 title "pnhln:10 (T_conf)", \
     "data/accuracy_cost_integrators_3.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 4 title "shardlow", \
     "data/accuracy_cost_integrators_4.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 5 title "mvv:0.5", \
     "data/accuracy_cost_integrators_5.dat" using 1:2:3 with yerrorlines pt 7 lw 2 lc 6 title "scmvv:5"
