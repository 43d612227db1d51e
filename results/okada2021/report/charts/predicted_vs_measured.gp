# k_BT shift predicted from the noise's effective power (w_R²-weighted ⟨ζ²⟩ and its lag correlations) against measured (8 beyond ±10 % not drawn)
# Data: predicted_vs_measured.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'predicted_vs_measured.svg'" predicted_vs_measured.gp
set xlabel "predicted shift, 95 % CI [%]" noenhanced
set ylabel "measured k_BT shift against MT19937, 95 % CI [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside top left noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set xrange [-4.43681:1.58974]
set yrange [-4.43681:1.58974]
set size ratio -1
set arrow from -4.43681,-4.43681 to 1.58974,1.58974 nohead dt 2 lc rgb 'black'
set label "dashed: identity (prediction exact)" at graph 0.98, graph 0.04 right font ',10'
set title "k_BT shift predicted from the noise's effective power (w_R²-weighted ⟨ζ²⟩ and its lag correlations) against measured (8 beyond ±10 % not drawn)" noenhanced
plot "predicted_vs_measured.csv" index 0 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#0072B2' title "tea32", \
     "predicted_vs_measured.csv" index 0 using 2:3:8 with points pt variable ps 1.3 lc rgb '#0072B2' notitle, \
     "predicted_vs_measured.csv" index 1 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#E69F00' title "tea64", \
     "predicted_vs_measured.csv" index 1 using 2:3:8 with points pt variable ps 1.3 lc rgb '#E69F00' notitle, \
     "predicted_vs_measured.csv" index 2 using 2:3:9 with labels offset 1,-0.6 left font ',10' tc rgb '#333333' title "", \
     keyentry with points pt 7 lc rgb 'black' title "1 round", \
     keyentry with points pt 5 lc rgb 'black' title "2 rounds", \
     keyentry with points pt 9 lc rgb 'black' title "3 rounds", \
     keyentry with points pt 13 lc rgb 'black' title "4 rounds", \
     keyentry with points pt 11 lc rgb 'black' title "5 rounds", \
     keyentry with points pt 15 lc rgb 'black' title "6 rounds", \
     keyentry with points pt 6 lc rgb 'black' title "8 rounds", \
     keyentry with points pt 4 lc rgb 'black' title "16 rounds", \
     keyentry with points pt 8 lc rgb 'black' title "32 rounds"
