# Decomposition check, domains 2x1x1. Render: gnuplot -e "set terminal svg; set output 'decomposition_2x1x1.svg'" decomposition_2x1x1.gp
set datafile missing 'nan'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set grid ytics
set key top right noenhanced
set xtics noenhanced rotate by -30
set multiplot layout 1,2 title 'domains 2x1x1' noenhanced
set title 'boundary pairs whose two {/Symbol z} differ'
set ylabel '%'
set yrange [0:*]
plot for [k=0:3] 'decomposition_2x1x1.dat' using (column(2+2*k)):xtic(1) title columnheader(2+2*k)
set title 'momentum drift per bead, max |P(t)-P(0)|/N'
set ylabel ''
set logscale y
set yrange [*:*]
plot for [k=0:3] 'decomposition_2x1x1.dat' using (column(3+2*k)):xtic(1) title columnheader(3+2*k)
unset multiplot
