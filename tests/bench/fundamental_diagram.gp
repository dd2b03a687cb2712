# Draws the fundamental diagrams written by entourage-bench-fd (gnuplot 5).
#   gnuplot -e "dir='bench-fd'; png='bench-fd/fundamental_diagram.png'" tests/bench/fundamental_diagram.gp
# Left: speed against flow; right: flow against density; per lane, one point per detector interval
# (small) and the mean of each demand level (joined). Four models, one colour each.
if (!exists("dir")) dir = "bench-fd"
if (!exists("png")) png = dir . "/fundamental_diagram.png"
points = dir . "/fd_points.csv"
summary = dir . "/fd_summary.csv"

set terminal pngcairo size 1400,600 font "sans,11"
set output png
set datafile separator ","
set key top right box opaque
set grid
colors = "#1f77b4 #d62728 #17becf #ff7f0e"
# The model labels contain spaces (word() would split them): one variable each, rows picked by
# comparing the first field.
label1 = "IDM"
label2 = "modified IDM"
label3 = "IDM + HDM"
label4 = "modified IDM + HDM"
pick(col, label) = (strcol(1) eq label) ? column(col) : NaN

set multiplot layout 1,2 title "Fundamental diagrams on a two-lane freeway (entourage-bench-fd)"
set title "Speed-flow"
set xlabel "flow per lane (veh/h)"
set ylabel "space-mean speed (km/h)"
plot \
  for [i=1:4] points skip 1 using (pick(4, value("label".i))):(pick(5, value("label".i))) \
      with points pt 7 ps 0.35 lc rgb word(colors, i) notitle, \
  for [i=1:4] summary skip 1 using (pick(3, value("label".i))):(pick(4, value("label".i))) \
      with linespoints pt 5 ps 0.9 lw 2 lc rgb word(colors, i) title value("label".i)
set title "Flow-density"
set xlabel "density per lane (veh/km)"
set ylabel "flow per lane (veh/h)"
plot \
  for [i=1:4] points skip 1 using (pick(6, value("label".i))):(pick(4, value("label".i))) \
      with points pt 7 ps 0.35 lc rgb word(colors, i) notitle, \
  for [i=1:4] summary skip 1 using (pick(5, value("label".i))):(pick(3, value("label".i))) \
      with linespoints pt 5 ps 0.9 lw 2 lc rgb word(colors, i) title value("label".i)
unset multiplot
