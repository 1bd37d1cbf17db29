# Work-precision diagram.  gnuplot -e "dir='out/bench'" work_precision.gp
set datafile separator ","
set terminal pngcairo size 1400,1000 font "DejaVu Sans,10"
set output dir."/work_precision.png"
set multiplot layout 2,2 title "Work-precision: error (in units of α) against CPU time and RHS evaluations"
set logscale xy
set grid
set format y "10^{%L}"
set format x "10^{%L}"
set key bottom left
solvers = "dopri5 rkf78 bulirsch-stoer gsl-rk8pd"
do for [scene in "pulse record"] {
  # On the record, rkf78, Bulirsch-Stoer and rk8pd end their steps on the samples; dopri5 steps across them (ode45).
  how = (scene eq "record") ? "\n(rkf78, bulirsch-stoer, gsl-rk8pd step from sample to sample; dopri5 across samples, as ode45)" : ""
  set title scene." scene: error against CPU time per run".how
  set xlabel "CPU time per run  [s]"
  set ylabel "error / α  [-]"
  plot for [s in solvers] dir."/work_precision.csv" using ((strcol(1) eq scene && strcol(2) eq s) ? $5 : 1/0):($4 > 0 ? $4 : 1e-17) with linespoints lw 2 title s, \
       dir."/work_precision.csv" using ((strcol(1) eq scene && strcol(2) eq "exact") ? $5 : 1/0):($4 > 0 ? $4 : 1e-17) with points pt 7 ps 2 lc rgb "black" title "exact (error 0 drawn at 1e-17)"
  set title scene." scene: error against right-hand-side evaluations".how
  set xlabel "RHS evaluations  [-]"
  plot for [s in solvers] dir."/work_precision.csv" using ((strcol(1) eq scene && strcol(2) eq s) ? $6 : 1/0):($4 > 0 ? $4 : 1e-17) with linespoints lw 2 title s
}
unset multiplot
