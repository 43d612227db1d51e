# False alarms of good generators (okada2021)
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" false_alarms.gp
set title "False alarms of good generators (okada2021)" noenhanced
set xlabel "replicas"
set ylabel "rate"
set grid
set key outside right top noenhanced
set datafile missing "nan"
set xrange [0:*]
set yrange [0:*]
plot "data/false_alarms_0.dat" using 1:2:3:4 with yerrorbars pt 7 ps 1.2 title "null verdicts \"differs\"", \
     "data/false_alarms_1.dat" using 1:2:3:4 with yerrorbars pt 5 ps 1.2 title "studies with any \"differs\"", \
     "data/false_alarms_2.dat" using 1:2 with lines dt 2 lc rgb 'red' title "α"
