# False alarms of good generators (okada2021)
# Data: false_alarms.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'false_alarms.svg'" false_alarms.gp
set xlabel "replicas per variant [1]" noenhanced
set ylabel "false-alarm rate, 95 % CI [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set xrange [0:5]
set yrange [0:*]
set arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 2 lw 2 lc rgb '#B2182B'
set label "α" at graph 0.01, first 0.01 offset 0,0.6 font ',10' tc rgb '#B2182B'
set title "False alarms of good generators (okada2021)" noenhanced
plot "false_alarms.csv" index 0 using 2:3:4:5 with yerrorbars pt 7 ps 1.2 title "null verdicts \"differs\"", \
     "false_alarms.csv" index 1 using 2:3:4:5 with yerrorbars pt 5 ps 1.2 title "studies with any \"differs\""
