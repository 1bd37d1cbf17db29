# Figure 12: to_5 only, with q = 2.  gnuplot -e "dir='out/fig12'" fig12.gp
set datafile separator ","
# eq. 27 (verified by the errata scene): case 2, 6 + 1 pulses
q27(x) = (2./3*sinh(3*x)**2 + 1./3) / (sinh(x)**2 - sinh(x/2)**2 + sinh(2*x)**2 - sinh(2.5*x)**2 - sinh(1.5*x)**2 + 2./3*sinh(3*x)**2)
set samples 400
stats dir."/fig12_summary.csv" every ::1::1 using 2 nooutput
x2 = STATS_min
set terminal pngcairo size 1000,700 font "DejaVu Sans,11"
set output (exists("png") ? png : dir."/fig12.png")  # png: reproduce's temporary file
set title "Figure 12: q against x = p·t_{o,5} (t_{o,5} = π PGV/PGA, eq. 31), eq. 27 and the code's q = 2"
set xlabel "x = p·t_o  [-]"
set ylabel "q  [-]"
set logscale y
set xrange [0:2]
set yrange [1:40]
set grid
set key top right
set arrow from 0,2 to 2,2 nohead lw 2 dt 2 lc rgb "black"
set arrow from x2,1 to x2,40 nohead dt 3 lc rgb "gray40"
set label sprintf("eq. 27 = 2 at x = %.3f", x2) at x2+0.02,30
plot dir."/fig12_points.csv" using (strcol(1) eq "paper" ? $5 : 1/0):4 with points pt 6 ps 1 lc rgb "blue" title "paper (Tables 1-2)", \
     dir."/fig12_records.csv" using 5:4 with points pt 8 ps 1 lc rgb "dark-orange" title "available records", \
     [0.05:2] q27(x) with lines lw 2 lc rgb "red" title "eq. 27"
