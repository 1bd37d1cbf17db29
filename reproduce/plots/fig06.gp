# Figure 6: theta(t_fin)/alpha, full eq. 1 against linearised eq. 3.  gnuplot -e "dir='out/fig06'" fig06.gp
set datafile separator ","
set terminal pngcairo size 1500,520 font "DejaVu Sans,10"
set output (exists("png") ? png : dir."/fig06.png")  # png: reproduce's temporary file
set multiplot layout 1,3 title "Figure 6: θ(t_{fin})/α from the full eq. 1 (solid) and the linearised eq. 3 (= 1, dashed); case 2 at PGA = q_2 α g; H = half-height (eq. 2)"
set xlabel "H  [m]"
set ylabel "θ(t_{fin}) / α  [-]"
set grid
set key bottom right
set yrange [0.8:1.01]
set xrange [1:10]
tos = "0.1 0.25 0.5"
alphas = "0.05 0.1 0.15 0.2 0.25"
do for [ti=1:3] {
  to = real(word(tos, ti))
  set title sprintf("t_o = %s s", word(tos, ti))
  plot 1 with lines dt 2 lc rgb "black" title "linearised", \
       for [ai=1:5] dir."/fig06.csv" using 3:((abs($1 - real(word(alphas, ai))) < 1e-9 && abs($2 - to) < 1e-9) ? $7 : 1/0) with linespoints lw 2 pt 7 ps 0.6 title "α = ".word(alphas, ai)
}
unset multiplot
