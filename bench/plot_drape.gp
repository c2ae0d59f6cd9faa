# Time against error and time against size, from drape_bench's CSVs: cold starts (csv) and,
# when given, warm starts (warm); with traj (drape_bench --trajectory), a third panel: the error
# along each solve, i.e. what stopping it at that time would have cost.
# Usage: gnuplot -e "csv='bench/drape_bench.csv'; warm='bench/drape_bench_warm.csv'; warm5='bench/drape_bench_warm5.csv'; traj='bench/drape_trajectory.csv'; c2f='bench/drape_bench_c2f.csv'; out='bench/drape_bench.png'" bench/plot_drape.gp
# (sizes='4836 10080 19908' names the triangle counts of traj to draw; those are the default;
# warm5: warm rows with the patterns 5 % wider, drape_bench --ease 0.05; flare: warm rows after
# a 20 % flare in each panel, drape_bench --flare 0.2, flare='bench/drape_bench_flare20.csv')
if (!exists("warm")) warm = ''
if (!exists("warm5")) warm5 = ''
if (!exists("flare")) flare = ''
if (!exists("traj")) traj = ''
if (!exists("c2f")) c2f = ''
if (!exists("sizes")) sizes = '4836 10080 19908'
set datafile separator ','
# The warm-start lines, appended to each plot when there is a warm CSV.
warm_error = warm eq '' ? '' : sprintf(", '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::0 with linespoints dashtype 2 title 'accurate, warm', '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::1 with linespoints dashtype 2 title 'fast, warm'", warm, warm)
warm_size = warm eq '' ? '' : sprintf(", '%s' using 1:3 skip 1 every 2::0 with linespoints dashtype 2 title 'accurate, warm', '%s' using 1:3 skip 1 every 2::1 with linespoints dashtype 2 title 'fast, warm'", warm, warm)
warm5_error = warm5 eq '' ? '' : sprintf(", '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::0 with linespoints dashtype 4 title 'accurate, warm 5 %%', '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::1 with linespoints dashtype 4 title 'fast, warm 5 %%'", warm5, warm5)
warm5_size = warm5 eq '' ? '' : sprintf(", '%s' using 1:3 skip 1 every 2::0 with linespoints dashtype 4 title 'accurate, warm 5 %%', '%s' using 1:3 skip 1 every 2::1 with linespoints dashtype 4 title 'fast, warm 5 %%'", warm5, warm5)
flare_error = flare eq '' ? '' : sprintf(", '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::0 with linespoints dashtype 5 title 'accurate, flare 20 %%', '%s' using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::1 with linespoints dashtype 5 title 'fast, flare 20 %%'", flare, flare)
flare_size = flare eq '' ? '' : sprintf(", '%s' using 1:3 skip 1 every 2::0 with linespoints dashtype 5 title 'accurate, flare 20 %%', '%s' using 1:3 skip 1 every 2::1 with linespoints dashtype 5 title 'fast, flare 20 %%'", flare, flare)
# The coarse-to-fine cold rows (drape_bench --c2f-csv), on the size panel only: they have no
# error column (each run is its own chaotic path).
c2f_size = c2f eq '' ? '' : sprintf(", '%s' using 1:3 skip 1 with linespoints dashtype 3 lw 2 lc rgb 'black' title 'coarse to fine, cold'", c2f)
set terminal pngcairo size (traj eq '' ? 1100 : 1650),450 font ',10'
set output out
set multiplot layout 1,(traj eq '' ? 2 : 3)
set logscale xy
set grid
# Keep points off the frame (log axes autoscale to the data).
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set key top left
set format x '10^{%L}'
set title 'Skirt drape: wall time against error (vs tight reference)'
set xlabel 'mean vertex error [mm]'
set ylabel 'median wall time [s]'
# drape_bench writes the presets in alternating rows (accurate, fast), so `every 2` picks one
# preset and the points of a preset join into one line (a 1/0 filter would break the line).
plot csv using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::0 with linespoints title 'accurate, cold', \
     csv using ($8 > 0 ? $8 : 1e-4):3 skip 1 every 2::1 with linespoints title 'fast, cold' @warm_error @warm5_error @flare_error
set format x '%g'
set title 'Skirt drape: wall time against size'
set xlabel 'triangles'
set ylabel 'median wall time [s]'
plot csv using 1:3 skip 1 every 2::0 with linespoints title 'accurate, cold', \
     csv using 1:3 skip 1 every 2::1 with linespoints title 'fast, cold' @warm_size @warm5_size @flare_size @c2f_size
if (traj ne '') {
  set title 'Skirt drape: error along the solve (accurate preset)'
  set xlabel 'wall time [s]'
  set ylabel 'mean vertex distance to the reference [mm]'
  unset logscale x
  set logscale y
  set format y '%g'
  set xrange [0:*]
  set offsets 0, 0, graph 0.05, graph 0.05
  set key top right
  # One line per start and size, accurate rows only (a run of both presets writes both); the
  # rows of one solve are contiguous, so filtering the others out (1/0) leaves each line whole.
  accurate(start, n) = strcol(1) eq start && strcol(3) eq 'accurate' && $2 == n + 0
  plot for [n in sizes] traj using (accurate('cold', n) ? $5 : 1/0):($7 > 1e-4 ? $7 : 1e-4) skip 1 \
         with lines title sprintf('cold, %s triangles', n), \
       for [n in sizes] traj using (accurate('warm', n) ? $5 : 1/0):($7 > 1e-4 ? $7 : 1e-4) skip 1 \
         with lines dashtype 2 title sprintf('warm, %s triangles', n), \
       2 with lines linecolor 'gray' dashtype 3 title '2 mm'
}
unset multiplot
