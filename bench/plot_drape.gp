# Time against error and time against size, from drape_bench's CSVs: cold starts (csv) and,
# when given, warm starts (warm).
# Usage: gnuplot -e "csv='bench/drape_bench.csv'; warm='bench/drape_bench_warm.csv'; out='bench/drape_bench.png'" bench/plot_drape.gp
if (!exists("warm")) warm = ''
set datafile separator ','
# The warm-start lines, appended to each plot when there is a warm CSV.
warm_error = warm eq '' ? '' : sprintf(", '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::0 with linespoints dashtype 2 title 'accurate, warm', '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::1 with linespoints dashtype 2 title 'fast, warm'", warm, warm)
warm_size = warm eq '' ? '' : sprintf(", '%s' using 1:3 skip 1 every 2::0 with linespoints dashtype 2 title 'accurate, warm', '%s' using 1:3 skip 1 every 2::1 with linespoints dashtype 2 title 'fast, warm'", warm, warm)
set terminal pngcairo size 1100,450 font ',10'
set output out
set multiplot layout 1,2
set logscale xy
set grid
# Keep points off the frame (log axes autoscale to the data).
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set key top left
set title 'Skirt drape: wall time against error (vs tight reference)'
set xlabel 'mean vertex error [mm]'
set ylabel 'median wall time [s]'
# drape_bench writes the presets in alternating rows (accurate, fast), so `every 2` picks one
# preset and the points of a preset join into one line (a 1/0 filter would break the line).
plot csv using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::0 with linespoints title 'accurate, cold', \
     csv using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::1 with linespoints title 'fast, cold' @warm_error
set title 'Skirt drape: wall time against size'
set xlabel 'triangles'
set ylabel 'median wall time [s]'
plot csv using 1:3 skip 1 every 2::0 with linespoints title 'accurate, cold', \
     csv using 1:3 skip 1 every 2::1 with linespoints title 'fast, cold' @warm_size
unset multiplot
