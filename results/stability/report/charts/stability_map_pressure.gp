# Stability map: |P_c − 23.64| / 23.64 by Δt and integrator (cross: every replica blew up)
# Data: stability_map_pressure.csv (column 1 the series; one block per series)
# Redraw: gnuplot -e "set terminal svg; set output 'stability_map_pressure.svg'" stability_map_pressure.gp
# small multiples: 5 panels
set xlabel "time step Δt [τ]" noenhanced
set logscale x 10
set format x "%g"
set offsets graph 0.03, graph 0.03, 0, 0
set ylabel "integrator" noenhanced
# y axis: categories
set grid
set datafile separator comma
set datafile missing "nan"
unset key
set cblabel "|P_c − 23.64| / 23.64 [%]" noenhanced
set cbrange [0:10]
set palette defined (0 '#F7F7F7', 10 '#B2182B')
set yrange [-0.5:5.5]
max(a, b) = a > b ? a : b
min(a, b) = a < b ? a : b
set multiplot layout 2,3 title "Stability map: |P_c − 23.64| / 23.64 by Δt and integrator (cross: every replica blew up)" noenhanced
set title "mt19937 gauss" noenhanced
unset colorbox
plot "stability_map_pressure.csv" index 0 using 2:3:(max(0, min(10, $4))):ytic(6) with points pt 5 ps 1.4 palette title "error (colour)", \
     "stability_map_pressure.csv" index 1 using 2:3:ytic(6) with points pt 2 ps 1.4 lw 2 lc rgb 'black' title "every replica blew up"
set title "tea32(1) gauss" noenhanced
unset colorbox
plot "stability_map_pressure.csv" index 2 using 2:3:(max(0, min(10, $4))):ytic(6) with points pt 5 ps 1.4 palette title "error (colour)", \
     "stability_map_pressure.csv" index 3 using 2:3:ytic(6) with points pt 2 ps 1.4 lw 2 lc rgb 'black' title "every replica blew up"
set title "mt19937 gauss-blocks" noenhanced
unset colorbox
plot "stability_map_pressure.csv" index 4 using 2:3:(max(0, min(10, $4))):ytic(6) with points pt 5 ps 1.4 palette title "error (colour)", \
     "stability_map_pressure.csv" index 5 using 2:3:ytic(6) with points pt 2 ps 1.4 lw 2 lc rgb 'black' title "every replica blew up"
set title "tea32(1) gauss-blocks" noenhanced
unset colorbox
plot "stability_map_pressure.csv" index 6 using 2:3:(max(0, min(10, $4))):ytic(6) with points pt 5 ps 1.4 palette title "error (colour)", \
     "stability_map_pressure.csv" index 7 using 2:3:ytic(6) with points pt 2 ps 1.4 lw 2 lc rgb 'black' title "every replica blew up"
set title "mt19937 gauss γ=4.5" noenhanced
unset key
set colorbox
plot "stability_map_pressure.csv" index 8 using 2:3:(max(0, min(10, $4))):ytic(6) with points pt 5 ps 1.4 palette title "error (colour)", \
     "stability_map_pressure.csv" index 9 using 2:3:ytic(6) with points pt 2 ps 1.4 lw 2 lc rgb 'black' title "every replica blew up"
unset multiplot
