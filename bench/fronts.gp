# The dam break run by both water models on one chart (issue 18): the surge front and the density
# error over time, from `tidepool validate` CSVs (columns by name):
#   tidepool validate dam-break       --probe front,density --every 25 --until 1 --csv bench/results/dam-break-front-balls.csv
#   tidepool validate dam-break-fluid --probe front,density --every 5  --until 1 --csv bench/results/dam-break-front-fluid.csv
#   gnuplot -c bench/fronts.gp bench/results/dam-break-front-balls.csv bench/results/dam-break-front-fluid.csv docs/charts/dam-break-fronts
# Time is scaled as T = t·sqrt(2g/a) (a = 0.25 m, the column's width), the front as x/a. The
# dashed line is the shallow-water (Ritter) front of a frictionless dry-bed release, 1 + 2T for a
# column twice as high as wide: an upper bound the measured fronts stay below.
balls = ARG1; fluid = ARG2; base = ARG3
set datafile separator ","
set key autotitle columnhead
scale = sqrt(2 * 9.81 / 0.25)
set terminal pngcairo size 1100,420 font ",11"
set output base.".png"
set multiplot layout 1,2 title "Dam break, balls and fluid on one metric (a = 0.25 m, column 2a high)" font ",13"
set grid lc rgb "#dddddd"
set border lc rgb "#555555"
set key top left box opaque
set xlabel "T = t sqrt(2g/a)"; set ylabel "surge front x / a"
set xrange [0:4]; set yrange [1:4.2]
plot balls using (column("time_s") * scale):(column("front_over_a")) with lines lw 2 lc rgb "#d95f02" title "balls (spring-dashpot, r = 1 cm)", \
     fluid using (column("time_s") * scale):(column("front_over_a")) with lines lw 2 lc rgb "#1b9e77" title "fluid (PBF, 4 iterations, d = 2 cm)", \
     1 + 2 * x with lines dt 2 lw 2 lc rgb "#555555" title "shallow water (Ritter): 1 + 2T"
set xlabel "t (s)"; set ylabel "mean density error (%)"
set xrange [0:1]; set autoscale y; set logscale y; set format y "10^{%T}"
plot balls using "time_s":(100 * column("density_error_mean")) with lines lw 2 lc rgb "#d95f02" title "balls, read with the fluid's kernel", \
     fluid using "time_s":(100 * column("density_error_mean")) with lines lw 2 lc rgb "#1b9e77" title "fluid"
unset multiplot
