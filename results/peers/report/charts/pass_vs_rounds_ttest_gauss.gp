# Pass fraction of lag-1 t per pair, worst output word, CI at 1 − α (gauss; the paper's Fig. 2)
# Data: pass_vs_rounds_ttest_gauss.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'pass_vs_rounds_ttest_gauss.svg'" pass_vs_rounds_ttest_gauss.gp
# small multiples: 4 panels
# canvas: 900,800
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "fraction of tests passed [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set arrow from graph 0, first 0.99 to graph 1, first 0.99 nohead dt 2 lw 2 lc rgb '#555555'
set label "1 − α" at graph 0.01, first 0.99 offset 0,0.6 font ',10' tc rgb '#555555'
set arrow from graph 0, first 0.9925 to graph 1, first 0.9925 nohead dt 2 lw 2 lc rgb 'black'
set xrange [0.833333:24]
set yrange [-0.0499994:1.04999]
set multiplot layout 2,2 title "Pass fraction of lag-1 t per pair, worst output word, CI at 1 − α (gauss; the paper's Fig. 2)" noenhanced
set title "distance seeding, generators 1 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "pass_vs_rounds_ttest_gauss.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "pass_vs_rounds_ttest_gauss.csv" index 2 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "pass_vs_rounds_ttest_gauss.csv" index 4 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "pass_vs_rounds_ttest_gauss.csv" index 6 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "distance seeding, generators 2 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "pass_vs_rounds_ttest_gauss.csv" index 8 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "pass_vs_rounds_ttest_gauss.csv" index 10 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "pass_vs_rounds_ttest_gauss.csv" index 12 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
set title "pair-step seeding, generators 1 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
unset colorbox
plot "pass_vs_rounds_ttest_gauss.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#009E73' title "philox4x32", \
     "pass_vs_rounds_ttest_gauss.csv" index 3 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#D55E00' title "saru", \
     "pass_vs_rounds_ttest_gauss.csv" index 5 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#56B4E9' title "splitmix64", \
     "pass_vs_rounds_ttest_gauss.csv" index 7 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#999933' title "squares64"
set title "pair-step seeding, generators 2 of 2" noenhanced
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set colorbox
plot "pass_vs_rounds_ttest_gauss.csv" index 9 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32", \
     "pass_vs_rounds_ttest_gauss.csv" index 11 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64", \
     "pass_vs_rounds_ttest_gauss.csv" index 13 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#CC79A7' title "threefry2x64"
unset multiplot
