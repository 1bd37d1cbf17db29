# Figure 8: eq. 27 against w/p with Makris' one-sine curve and Coccia & Como.  gnuplot -e "dir='out/fig08'" fig08.gp
set datafile separator ","
set terminal pngcairo size 1100,750 font "DejaVu Sans,11"
set output (exists("png") ? png : dir."/fig08.png")  # png: reproduce's temporary file
set title "Figure 8: q (eq. 27, case 2 with 6+1 pulses) against ω/p = π/(p·t_o), beside the one-sine overturning threshold a_p/(α g)"
set xlabel "ω_p / p = π / (p·t_o)  [-]"
set ylabel "q = PGA/(α g)  or  a_p/(α g)  [-]"
set grid
set key top left
set xrange [0:10]
set yrange [0.9:10]
set logscale y
plot dir."/fig08.csv" using 1:3 with lines lw 3 lc rgb "red" title "eq. 27 (this paper)", \
     "" using 1:4 with lines lw 2 lc rgb "blue" title "Coccia \\& Como (case 1, 6+1 pulses)", \
     "" using 1:6 with linespoints lw 2 pt 7 ps 0.6 lc rgb "black" title "one-sine threshold, linearised, e = 1", \
     "" using 1:7 with lines lw 1 dt 2 lc rgb "gray30" title "linearised, Housner e (α = 0.1)", \
     "" using 1:8 with lines lw 1 dt 3 lc rgb "dark-green" title "full eq. 1, e = 1 (α = 0.25; a_p/(g tan α))", \
     "" using 1:9 with lines lw 1 dt 4 lc rgb "purple" title "full eq. 1, Housner e (α = 0.25)", \
     "" using 1:5 with lines lw 1 dt 5 lc rgb "orange" title "fit 1 + ω_p/(6p) (Makris \\& Roussos)"
