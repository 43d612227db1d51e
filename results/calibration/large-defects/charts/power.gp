# Detection probability of a lag1 defect (ci, α = 0.01)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" power.gp
set title "Detection probability of a lag1 defect (ci, α = 0.01)" noenhanced
set xlabel "ρ (lag-1 correlation)"
set ylabel "P(verdict \"differs\")"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set logscale x
set yrange [0:1.05]
set xrange [0.016:0.0625]
plot "data/power_0.dat" using 1:2:3:4 with yerrorlines lw 2 title "3 replicas", \
     "data/power_1.dat" using 1:2 with lines dt 2 lc rgb 'gray40' title "50 %", \
     "data/power_2.dat" using 1:2 with lines dt 2 lc rgb 'gray40' title "90 %"
