# Detection probability against defect size (okada2021, α = 0.01): ε (⟨ζ²⟩ = 1 + ε)
# Data: power.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'power.svg'" power.gp
set xlabel "defect size [1]" noenhanced
set logscale x 10
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "P(verdict \"differs\"), 95 % CI [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set yrange [0:1.05]
set offsets graph 0.1, graph 0.1, 0, 0
set arrow from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lw 2 lc rgb '#555555'
set arrow from graph 0, first 0.9 to graph 1, first 0.9 nohead dt 2 lw 2 lc rgb '#555555'
set title "Detection probability against defect size (okada2021, α = 0.01): ε (⟨ζ²⟩ = 1 + ε)" noenhanced
plot "power.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc 1 title "3 replicas"
