# Null P-values against uniform (okada2021, 4 replicas, 4536 tests), 95 % simultaneous band
# Rendered by: gnuplot -e "set terminal svg; set output 'x.svg'" null_p_qq.gp
set title "Null P-values against uniform (okada2021, 4 replicas, 4536 tests), 95 % simultaneous band" noenhanced
set xlabel "expected -log10 p"
set ylabel "observed -log10 p"
set grid
set key outside right top noenhanced
set datafile missing "nan"
plot "data/null_p_qq_0.dat" using 1:2 with points pt 7 ps 0.4 title "null tests", \
     "data/null_p_qq_1.dat" using 1:2 with lines dt 2 lc rgb 'gray40' title "band", \
     "data/null_p_qq_2.dat" using 1:2 with lines dt 2 lc rgb 'gray40' title "", \
     "data/null_p_qq_3.dat" using 1:2 with lines lc rgb 'red' title "uniform"
