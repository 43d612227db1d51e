# Detection probability against defect size (ci, α = 0.01)
# Data: power.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'power.svg'" power.gp
# small multiples: 4 panels
set xlabel "defect size [1]" noenhanced
set logscale x 10
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "P(verdict \"differs\"), 95 % CI [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set yrange [0:1.05]
set offsets graph 0.1, graph 0.1, 0, 0
set arrow from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lw 2 lc rgb '#555555'
set arrow from graph 0, first 0.9 to graph 1, first 0.9 nohead dt 2 lw 2 lc rgb '#555555'
set multiplot layout 2,3 title "Detection probability against defect size (ci, α = 0.01)" noenhanced
set title "ε (⟨ζ²⟩ = 1 + ε)" noenhanced
unset colorbox
plot "power.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc 1 title "3 replicas"
set title "ρ (lag-1 correlation)" noenhanced
unset colorbox
plot "power.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc 1 title "3 replicas"
set title "μ (mean shift)" noenhanced
unset colorbox
plot "power.csv" index 2 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc 1 title "3 replicas"
set title "κ (variance × (1 + κ(3cos²θ − 1)))" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "power.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc 1 title "3 replicas"
unset multiplot
