# Cost of one random number inside the DPD run (gauss-blocks)
# Data: cost_vs_rounds_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'cost_vs_rounds_gauss-blocks.svg'" cost_vs_rounds_gauss-blocks.gp
# small multiples: 4 panels
# canvas: 900,800
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
unset key
set arrow from graph 0, first 6.33624 to graph 1, first 6.33624 nohead dt 2 lw 2 lc rgb 'black'
set label "mt19937" at graph 0.01, first 6.33624 offset 0,0.6 font ',10' tc rgb 'black'
set yrange [0.304718:7.60349]
set xrange [0.833333:24]
set multiplot layout 2,2 title "Cost of one random number inside the DPD run (gauss-blocks)" noenhanced
set title "distance seeding, generators 1 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "cost_vs_rounds_gauss-blocks.csv" index 0 using 2:3 with linespoints lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "cost_vs_rounds_gauss-blocks.csv" index 2 using 2:3 with linespoints lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "cost_vs_rounds_gauss-blocks.csv" index 4 using 2:3 with linespoints lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "cost_vs_rounds_gauss-blocks.csv" index 6 using 2:3 with linespoints lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "distance seeding, generators 2 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "cost_vs_rounds_gauss-blocks.csv" index 8 using 2:3 with linespoints lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "cost_vs_rounds_gauss-blocks.csv" index 10 using 2:3 with linespoints lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "cost_vs_rounds_gauss-blocks.csv" index 12 using 2:3 with linespoints lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "pair-step seeding, generators 1 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "cost_vs_rounds_gauss-blocks.csv" index 1 using 2:3 with linespoints lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "cost_vs_rounds_gauss-blocks.csv" index 3 using 2:3 with linespoints lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "cost_vs_rounds_gauss-blocks.csv" index 5 using 2:3 with linespoints lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "cost_vs_rounds_gauss-blocks.csv" index 7 using 2:3 with linespoints lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "pair-step seeding, generators 2 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "cost_vs_rounds_gauss-blocks.csv" index 9 using 2:3 with linespoints lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "cost_vs_rounds_gauss-blocks.csv" index 11 using 2:3 with linespoints lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "cost_vs_rounds_gauss-blocks.csv" index 13 using 2:3 with linespoints lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
unset multiplot
