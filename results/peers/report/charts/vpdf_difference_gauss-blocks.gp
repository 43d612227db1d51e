# Velocity PDF, pooled components: relative difference from MT19937, 95 % CI (gauss-blocks); beyond ±20 %, not drawn: philox4x32(7) distance, saru distance, splitmix64 distance
# Data: vpdf_difference_gauss-blocks.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'vpdf_difference_gauss-blocks.svg'" vpdf_difference_gauss-blocks.gp
set xlabel "velocity component v_α [√(k_BT/m)]" noenhanced
set ylabel "difference from MT19937 [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'
set title "Velocity PDF, pooled components: relative difference from MT19937, 95 % CI (gauss-blocks); beyond ±20 %, not drawn: philox4x32(7) distance, saru distance, splitmix64 distance" noenhanced
plot "vpdf_difference_gauss-blocks.csv" index 0 using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 pt 7 lc rgb '#009E73' title "philox4x32(7) pair-step", \
     "vpdf_difference_gauss-blocks.csv" index 1 using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 pt 7 lc rgb '#D55E00' title "saru pair-step", \
     "vpdf_difference_gauss-blocks.csv" index 2 using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 pt 7 lc rgb '#56B4E9' title "splitmix64 pair-step"
