# Cost of one random number inside the DPD run (gauss-inverse)
# Data: cost_vs_rounds_gauss-inverse.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'cost_vs_rounds_gauss-inverse.svg'" cost_vs_rounds_gauss-inverse.gp
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "cost per random number (generator + distribution) [ns]" noenhanced
set logscale y 2
set format y "%g"
set grid
set datafile separator comma
set datafile missing "nan"
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set arrow from graph 0, first 0.666214 to graph 1, first 0.666214 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937" at graph 0.01, first 0.666214 offset 0,0.6 font ',10' tc rgb 'black'
set title "Cost of one random number inside the DPD run (gauss-inverse)" noenhanced
plot "cost_vs_rounds_gauss-inverse.csv" index 0 using 2:3 with linespoints lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "cost_vs_rounds_gauss-inverse.csv" index 1 using 2:3 with linespoints lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
