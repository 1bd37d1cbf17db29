# Figure 4: q1..q5 against x = p*to.  Called as: gnuplot -e "dir='out/fig04'" fig04.gp
set datafile separator ","
set terminal pngcairo size 1000,700 font "DejaVu Sans,12"
set output (exists("png") ? png : dir."/fig04.png")  # png: reproduce's temporary file
set title "Figure 4: q-factor of the five step inputs (linearised eq. 3, collapse θ(t_{fin}) = α)"
set xlabel "x = p·t_o  [-]"
set ylabel "q = PGA / (α g)  [-]"
set logscale y
set yrange [1:100]
set xrange [0:2]
set grid
set key top right box opaque width 1
set style line 6 lc rgb "black" lw 4
# q >= 2 is needed by cases 3 and 5 to start rocking (first pulse PGA/2).
set arrow from 0,2 to 2,2 nohead dt 2 lc rgb "gray40"
set label "q = 2: cases 3 and 5 need q ≥ 2 to start rocking" at 0.03,1.87 tc rgb "gray30"
plot dir."/fig04.csv" using 1:7 skip 0 with lines ls 6 title "min(q_1..q_5)", \
     "" using 1:2 with lines lw 2 title "q_1 (eq. 12)", \
     "" using 1:3 with lines lw 2 title "q_2 (eq. 15)", \
     "" using 1:4 with lines lw 2 title "q_3 (eq. 19)", \
     "" using 1:5 with lines lw 2 title "q_4 (eq. 22)", \
     "" using 1:6 with lines lw 2 title "q_5 (eq. 24)", \
     dir."/fig04_points.csv" every ::1::1 using 2:3 with points pt 7 ps 2 lc rgb "red" title "q_2 = q_4 (min changes case)"
