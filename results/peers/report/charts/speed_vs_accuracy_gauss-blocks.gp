# Speed against evidence of a difference from MT (gauss-blocks)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" speed_vs_accuracy_gauss-blocks.gp
set title "Speed against evidence of a difference from MT (gauss-blocks)" noenhanced
set xlabel "ms per DPD step (cost)"
set ylabel "-log10(smallest corrected p) (log scale, clipped to [0.01, 12])"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale y
set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1
set yrange [0.01:*]
set arrow from graph 0, first 2 to graph 1, first 2 nohead dt 2 lw 2 lc rgb 'red'
set label "α (0.01)" at graph 0.9, first 2 offset 0,0.6 tc rgb 'red'
plot "data/speed_vs_accuracy_gauss-blocks_0.dat" using 1:2:3 with labels point pt 7 ps 1.2 lc rgb 'dark-green' offset 0.8,0.6 left title "does not differ from MT", \
     "data/speed_vs_accuracy_gauss-blocks_1.dat" using 1:2:3 with labels point pt 5 ps 1.2 lc rgb 'red' offset 0.8,0.6 left title "differs from MT"
