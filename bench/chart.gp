# Speed-against-accuracy chart for `tidepool sweep` (gnuplot 5.4, called by src/sweep/sweep.cpp):
#   gnuplot -c bench/chart.gp DATA OUTBASE TITLE XLABEL YLABEL FLAGS METHODS MARKERX MARKERLABEL
# FLAGS is three digits: log x, log y, draw the Pareto front (e.g. 111). MARKERX 0: no marker.
# DATA holds one block per method (first line: its title), then one block with the Pareto front.
data = ARG1; base = ARG2
set title ARG3 font ",13"
set xlabel ARG4; set ylabel ARG5
if (ARG6[1:1] eq "1") { set logscale x; set format x "10^{%T}" }
if (ARG6[2:2] eq "1") { set logscale y; set format y "10^{%T}" }
methods = int(ARG7)
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key below box opaque
entries = methods + (ARG6[3:3] eq "1" ? 1 : 0)
set bmargin (entries > 4 ? 4 + (entries + 1) / 2 : 7)  # the key's rows, two or more entries a row
set border lc rgb "#555555"
set style line 100 lc rgb "#222222" lw 2 dt 2 pt 6 ps 2.2
colors = "#1b9e77 #d95f02 #7570b3 #e7298a #66a61e #e6ab02 #a6761d #666666"
if (ARG8 + 0 > 0) { set arrow from first ARG8, graph 0 to first ARG8, graph 1 nohead lc rgb "#aa0000" dt 3 lw 2
  set label ARG9 at first ARG8, graph 0.96 offset 0.6,0 tc rgb "#aa0000" }
plot_cmd = "plot for [i=0:methods-1] data index i using 1:2 with linespoints lw 2 pt 7 ps 1.1 lc rgb word(colors, i % 8 + 1) title columnheader(1)"
if (ARG6[3:3] eq "1") { plot_cmd = plot_cmd . ", data index methods using 1:2 with linespoints ls 100 title columnheader(1)" }
set terminal pngcairo size 1000,620 enhanced font "DejaVu Sans,11"
set output base . ".png"
eval plot_cmd
set terminal svg size 1000,620 enhanced font "DejaVu Sans,11" background rgb "white"
set output base . ".svg"
eval plot_cmd
