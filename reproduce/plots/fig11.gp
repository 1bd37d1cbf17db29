# Figure 11: (p to_k, q) for the eleven definitions against eq. 27.  gnuplot -e "dir='out/fig11'" fig11.gp
set datafile separator ","
# eq. 27 (verified by the errata scene): case 2, 6 + 1 pulses
q27(x) = (2./3*sinh(3*x)**2 + 1./3) / (sinh(x)**2 - sinh(x/2)**2 + sinh(2*x)**2 - sinh(2.5*x)**2 - sinh(1.5*x)**2 + 2./3*sinh(3*x)**2)
set samples 400
set terminal pngcairo size 1600,1200 font "DejaVu Sans,9"
set output (exists("png") ? png : dir."/fig11.png")  # png: reproduce's temporary file
set multiplot layout 3,4 title "Figure 11: points (p·t_{o,k}, q) of Tables 1-2 (paper, circles) and of the available records (triangles) against eq. 27 (line); below the line = non-conservative"
set xlabel "x = p·t_o  [-]"
set ylabel "q  [-]"
set logscale y
set xrange [0:3]
set yrange [1:40]
set grid
set key top right font ",8"
do for [k=1:11] {
  set title sprintf("t_{o,%d}", k)
  plot dir."/fig11_points.csv" using (strcol(1) eq "paper" && $3 == k ? $8 : 1/0):5 with points pt 6 ps 0.7 lc rgb "blue" title "paper", \
       dir."/fig11_records.csv" using ($3 == k ? $8 : 1/0):5 with points pt 8 ps 0.7 lc rgb "dark-orange" title "records", \
       [0.05:3] q27(x) with lines lw 2 lc rgb "red" notitle
}
unset multiplot
