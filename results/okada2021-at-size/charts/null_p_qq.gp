# Null P-values against uniform (okada2021, 4 replicas, 45360 tests), 95 % simultaneous band
# Data: null_p_qq.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'null_p_qq.svg'" null_p_qq.gp
set xlabel "expected −log₁₀ p [1]" noenhanced
set ylabel "observed −log₁₀ p [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top left noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set title "Null P-values against uniform (okada2021, 4 replicas, 45360 tests), 95 % simultaneous band" noenhanced
plot "null_p_qq.csv" index 0 using 2:3 with points pt 7 ps 0.4 title "null tests", \
     "null_p_qq.csv" index 1 using 2:3 with lines dt 2 lc rgb '#555555' title "95 % band", \
     "null_p_qq.csv" index 2 using 2:3 with lines dt 2 lc rgb '#555555' title "", \
     "null_p_qq.csv" index 3 using 2:3 with lines lc rgb '#B2182B' title "uniform"
