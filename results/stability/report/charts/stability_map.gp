# Fraction of replicas stable against dt
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" stability_map.gp
set title "Fraction of replicas stable against dt" noenhanced
set xlabel "dt"
set ylabel "fraction stable"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set yrange [-0.05:1.05]
set key outside right
plot "data/stability_map_0.dat" using 1:2 with linespoints pt 1 lw 2 title "mvv:0.5 mt19937 gauss", \
     "data/stability_map_1.dat" using 1:2 with linespoints pt 2 lw 2 title "mvv:0.5 tea32(1) gauss", \
     "data/stability_map_2.dat" using 1:2 with linespoints pt 3 lw 2 title "mvv:0.5 mt19937 gauss-blocks", \
     "data/stability_map_3.dat" using 1:2 with linespoints pt 4 lw 2 title "mvv:0.5 tea32(1) gauss-blocks", \
     "data/stability_map_4.dat" using 1:2 with linespoints pt 5 lw 2 title "mvv:0.5 mt19937 gauss γ4.5", \
     "data/stability_map_5.dat" using 1:2 with linespoints pt 6 lw 2 title "mvv:0.65 mt19937 gauss", \
     "data/stability_map_6.dat" using 1:2 with linespoints pt 7 lw 2 title "mvv:0.65 tea32(1) gauss", \
     "data/stability_map_7.dat" using 1:2 with linespoints pt 8 lw 2 title "mvv:0.65 mt19937 gauss-blocks", \
     "data/stability_map_8.dat" using 1:2 with linespoints pt 9 lw 2 title "mvv:0.65 tea32(1) gauss-blocks", \
     "data/stability_map_9.dat" using 1:2 with linespoints pt 10 lw 2 title "mvv:0.65 mt19937 gauss γ4.5", \
     "data/stability_map_10.dat" using 1:2 with linespoints pt 11 lw 2 title "shardlow mt19937 gauss", \
     "data/stability_map_11.dat" using 1:2 with linespoints pt 12 lw 2 title "shardlow tea32(1) gauss", \
     "data/stability_map_12.dat" using 1:2 with linespoints pt 1 lw 2 title "shardlow mt19937 gauss-blocks", \
     "data/stability_map_13.dat" using 1:2 with linespoints pt 2 lw 2 title "shardlow tea32(1) gauss-blocks", \
     "data/stability_map_14.dat" using 1:2 with linespoints pt 3 lw 2 title "shardlow mt19937 gauss γ4.5", \
     "data/stability_map_15.dat" using 1:2 with linespoints pt 4 lw 2 title "scmvv:1 mt19937 gauss", \
     "data/stability_map_16.dat" using 1:2 with linespoints pt 5 lw 2 title "scmvv:1 tea32(1) gauss", \
     "data/stability_map_17.dat" using 1:2 with linespoints pt 6 lw 2 title "scmvv:1 mt19937 gauss-blocks", \
     "data/stability_map_18.dat" using 1:2 with linespoints pt 7 lw 2 title "scmvv:1 tea32(1) gauss-blocks", \
     "data/stability_map_19.dat" using 1:2 with linespoints pt 8 lw 2 title "scmvv:1 mt19937 gauss γ4.5", \
     "data/stability_map_20.dat" using 1:2 with linespoints pt 9 lw 2 title "scmvv:5 mt19937 gauss", \
     "data/stability_map_21.dat" using 1:2 with linespoints pt 10 lw 2 title "scmvv:5 tea32(1) gauss", \
     "data/stability_map_22.dat" using 1:2 with linespoints pt 11 lw 2 title "scmvv:5 mt19937 gauss-blocks", \
     "data/stability_map_23.dat" using 1:2 with linespoints pt 12 lw 2 title "scmvv:5 tea32(1) gauss-blocks", \
     "data/stability_map_24.dat" using 1:2 with linespoints pt 1 lw 2 title "scmvv:5 mt19937 gauss γ4.5", \
     "data/stability_map_25.dat" using 1:2 with linespoints pt 2 lw 2 title "pnhln:10 mt19937 gauss", \
     "data/stability_map_26.dat" using 1:2 with linespoints pt 3 lw 2 title "pnhln:10 mt19937 gauss γ4.5"
