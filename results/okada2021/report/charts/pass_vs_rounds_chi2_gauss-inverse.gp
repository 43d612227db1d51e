# Pass fraction of χ² per step, worst output word, CI at 1 − α (gauss-inverse; the paper's Fig. 2)
# Data: pass_vs_rounds_chi2_gauss-inverse.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'pass_vs_rounds_chi2_gauss-inverse.svg'" pass_vs_rounds_chi2_gauss-inverse.gp
set xlabel "hash rounds [1]" noenhanced
set logscale x 2
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "fraction of tests passed [1]" noenhanced
set grid
set datafile separator comma
set datafile missing "nan"
set key inside bottom right noenhanced opaque box samplen 2 spacing 1.1 font ',10'
set arrow from graph 0, first 0.99 to graph 1, first 0.99 nohead dt 2 lw 2 lc rgb '#555555'
set label "1 − α" at graph 0.01, first 0.99 offset 0,0.6 font ',10' tc rgb '#555555'
set arrow from graph 0, first 0.989688 to graph 1, first 0.989688 nohead dt 2 lw 2 lc rgb 'black'
set title "Pass fraction of χ² per step, worst output word, CI at 1 − α (gauss-inverse; the paper's Fig. 2)" noenhanced
plot "pass_vs_rounds_chi2_gauss-inverse.csv" index 0 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#0072B2' title "tea32 distance", \
     "pass_vs_rounds_chi2_gauss-inverse.csv" index 1 using 2:3:4:5 with yerrorlines lw 2 pt 7 lc rgb '#E69F00' title "tea64 distance"
