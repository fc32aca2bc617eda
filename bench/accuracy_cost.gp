# Plots of the accuracy-versus-time report, from the CSV that accuracy_cost_bench writes:
#   gnuplot -e "dir='OUTDIR'" bench/accuracy_cost.gp
# reads OUTDIR/accuracy_cost.csv and writes, into OUTDIR,
#   accuracy_cost.png                    every problem, one panel each
#   accuracy_cost_<problem>.png          one problem, larger
#   accuracy_cost_release_per_step.png   the release transient against the time of one step
# The panels are log-log: the relative error against the CPU time a 1 kHz haptic tick costs (one
# solve, or the steps that cover 1 ms), every setting a point coloured by its series (the first
# of its settings: a theory, a series order, an integrator), the Pareto front a black line, the
# tick budget a dashed line.

if (!exists("dir")) dir = "."
csv = dir . "/accuracy_cost.csv"
budget = 100.0  # us per tick, as accuracy_cost_bench's kTickBudgetUs

# The CSV's columns.
c_problem = 1; c_series = 4; c_label = 5; c_error = 6; c_cpu = 7; c_tick = 11; c_front = 13
c_status = 14

problems = "frequencies tip_small tip_moderate elastica bridge pullin_cantilever pullin_bridge release"
array titles[8] = [ \
  "frequencies: modes 1-4 of the cantilever", \
  "tip\\_small: tip force PL^2/EI = 0.03 (tip 1 % of L down)", \
  "tip\\_moderate: tip force PL^2/EI = 0.3 (10 % of L)", \
  "elastica: tip force PL^2/EI = 5 (71 % of L)", \
  "bridge: 100 N/m, five thicknesses deep", \
  "pullin\\_cantilever: pull-in voltage", \
  "pullin\\_bridge: pull-in voltage, stretching", \
  "release: 1 ms of free vibration after a release" ]

set datafile separator comma
# Series colours, distinct on white.
array colours[8] = ["#7b3294", "#008837", "#2b83ba", "#d7191c", "#b8860b", "#404040", "#e66101", "#5e3c99"]
do for [k = 1:8] { set linetype k lc rgb colours[k] }
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid xtics ytics lc rgb "#dddddd"
set key top right font ",8" opaque box samplen 1 spacing 0.9 maxrows 4
set ylabel "relative error"
set arrow 1 from budget, graph 0 to budget, graph 1 nohead dt 2 lc rgb "#aa0000"

# y for the rows of problem p that ran, NaN for the others.
on(p, y) = (strcol(c_problem) eq p && strcol(c_status) eq "ok") ? y : NaN

# For problem p: $rows, the rows that ran; $front, its Pareto front by increasing tick cost; and
# series_name[k], the name of its series number k (the CSV names each on one line).
array series_name[16]
select = "undefine $rows $front $series; \
  set table $rows separator comma; \
  plot csv using c_tick:c_error with table if (strcol(c_problem) eq p && strcol(c_status) eq 'ok'); \
  set table $front separator comma; \
  plot csv using c_tick:c_error:c_front with table if (strcol(c_problem) eq p && column(c_front) == 1); \
  set table $series separator comma; \
  plot csv using c_series:(strcol(c_label)) with table if (strcol(c_problem) eq p && strcol(c_label) ne ''); \
  unset table; \
  do for [r = 1:|$series|] { \
    comma = strstrt($series[r], ','); \
    series_name[int($series[r][1:comma - 1] + 0)] = $series[r][comma + 1:] \
  }"

# Problem p's settings against the cost in column `cost`, a colour and a key entry a series;
# `front` is appended to the plot command.
in_series(k) = column(c_series) == k ? column(c_error) : NaN
settings = "for [k = 1:|$series|] csv using (on(p, column(cost))):(on(p, in_series(k))) \
  with points pt 7 ps 1 lc k title series_name[k] noenhanced"
front = ", $front using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'"

# The errors' decades, and two more above them for the key.
panel = "if (|$rows| == 0) { \
    set label 10 'no results' at graph 0.5, 0.5 center; \
    plot [1:10] [1:10] 1/0 notitle; \
    unset label 10 \
  } else { \
    set autoscale y; stats $rows using 2 nooutput; \
    set yrange [10**floor(log10(STATS_min)) : 10**(ceil(log10(STATS_max)) + 2)]; \
    plot @settings @front \
  }"

tick_axis = "CPU time per 1 kHz tick [us] (one solve, or the steps of 1 ms)"
cost = c_tick
set xlabel tick_axis

# Every problem on one page, on the cost axis of all of them.
set table $all separator comma
plot csv using c_tick:c_error with table if (strcol(c_status) eq 'ok')
unset table
stats $all using 1 nooutput
set xrange [10**floor(log10(STATS_min)) : 10**ceil(log10(STATS_max))]
set terminal pngcairo size 1400, 1900 font ",10"
set output dir . "/accuracy_cost.png"
set multiplot layout 4, 2 title \
  sprintf("cosmems: accuracy against cost (Pareto front black, the %g us tick budget dashed)", budget)
do for [i = 1:words(problems)] {
  p = word(problems, i)
  set title titles[i]
  eval select
  eval panel
}
unset multiplot

# One problem a file, each on its own cost axis.
set autoscale x
set terminal pngcairo size 900, 650 font ",11"
do for [i = 1:words(problems)] {
  p = word(problems, i)
  set title titles[i]
  set output dir . "/accuracy_cost_" . p . ".png"
  eval select
  eval panel
}

# The release against the time of one step: what a step costs, whatever its size. The front of
# the tick cost does not apply on this axis and is left out.
p = "release"
set title "release: 1 ms of free vibration, against the time of one step"
set output dir . "/accuracy_cost_release_per_step.png"
set xlabel "CPU time per step [us]"
unset arrow 1
cost = c_cpu
front = ""
eval select
eval panel
set output
