# Figure 7: q against x for cases 1, 2, 4 with N pulses.  gnuplot -e "dir='out/fig07'" fig07.gp
set datafile separator ","
set terminal pngcairo size 1500,560 font "DejaVu Sans,11"
set output (exists("png") ? png : dir."/fig07.png")  # png: reproduce's temporary file
set multiplot layout 1,3 title "Figure 7: q-factor with N pulses (collapse at the onset of pulse N+1; N = 6 is the paper's 6 + 1)"
set xlabel "x = p·t_o  [-]"
set ylabel "q = PGA / (α g)  [-]"
set logscale y
set yrange [1:100]
set xrange [0:2]
set grid
set key top right
do for [c in "1 2 4"] {
  base = (c eq "1") ? 1 : ((c eq "2") ? 7 : 13)
  name = (c eq "2") ? "case 2 (N = 6: eq. 27)" : ((c eq "4") ? "case 4 (N = 6: eq. 28)" : "case 1 (N = 6: Coccia \\& Como)")
  set title name
  plot for [k=0:5] dir."/fig07.csv" using 1:(column(base + 1 + k)) with lines lw (k == 2 ? 4 : 2) title sprintf("N = %d", 2 + 2*k)
}
unset multiplot
