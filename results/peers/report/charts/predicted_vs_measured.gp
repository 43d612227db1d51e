# k_BT shift predicted from the noise's effective power (w_R²-weighted ⟨ζ²⟩ and its lag correlations) against measured (7 beyond ±10 % not drawn)
# Data: predicted_vs_measured.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'predicted_vs_measured.svg'" predicted_vs_measured.gp
# small multiples: 2 panels
# canvas: 900,800
set xlabel "predicted shift, 95 % CI [%]" noenhanced
set ylabel "measured k_BT shift against MT19937, 95 % CI [%]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set xrange [-4.35693:4.74552]
set yrange [-4.35693:4.74552]
set size ratio -1
set arrow from -4.35693,-4.35693 to 4.74552,4.74552 nohead dt 2 lc rgb 'black'
set label "dashed: identity (prediction exact)" at graph 0.98, graph 0.04 right font ',10'
set multiplot layout 1,2 title "k_BT shift predicted from the noise's effective power (w_R²-weighted ⟨ζ²⟩ and its lag correlations) against measured (7 beyond ±10 % not drawn)" noenhanced
set title "generators 1 of 2" noenhanced
set key inside top left noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "predicted_vs_measured.csv" index 0 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#009E73' title "philox4x32", \
     "predicted_vs_measured.csv" index 0 using 2:3:8 with points pt variable ps 1.3 lc rgb '#009E73' notitle, \
     "predicted_vs_measured.csv" index 1 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#D55E00' title "saru", \
     "predicted_vs_measured.csv" index 1 using 2:3:8 with points pt variable ps 1.3 lc rgb '#D55E00' notitle, \
     "predicted_vs_measured.csv" index 2 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#56B4E9' title "splitmix64", \
     "predicted_vs_measured.csv" index 2 using 2:3:8 with points pt variable ps 1.3 lc rgb '#56B4E9' notitle, \
     "predicted_vs_measured.csv" index 3 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#999933' title "squares64", \
     "predicted_vs_measured.csv" index 3 using 2:3:8 with points pt variable ps 1.3 lc rgb '#999933' notitle
set title "generators 2 of 2" noenhanced
set key inside top left noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "predicted_vs_measured.csv" index 4 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#0072B2' title "tea32", \
     "predicted_vs_measured.csv" index 4 using 2:3:8 with points pt variable ps 1.3 lc rgb '#0072B2' notitle, \
     "predicted_vs_measured.csv" index 5 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#E69F00' title "tea64", \
     "predicted_vs_measured.csv" index 5 using 2:3:8 with points pt variable ps 1.3 lc rgb '#E69F00' notitle, \
     "predicted_vs_measured.csv" index 6 using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 lc rgb '#CC79A7' title "threefry2x64", \
     "predicted_vs_measured.csv" index 6 using 2:3:8 with points pt variable ps 1.3 lc rgb '#CC79A7' notitle, \
     "predicted_vs_measured.csv" index 7 using 2:3:9 with labels offset 1,-0.6 left font ',10' tc rgb '#333333' title "", \
     keyentry with points pt 7 lc rgb 'black' title "1 round", \
     keyentry with points pt 10 lc rgb 'black' title "7 rounds", \
     keyentry with points pt 6 lc rgb 'black' title "8 rounds", \
     keyentry with points pt 14 lc rgb 'black' title "10 rounds", \
     keyentry with points pt 3 lc rgb 'black' title "13 rounds", \
     keyentry with points pt 1 lc rgb 'black' title "20 rounds"
unset multiplot
