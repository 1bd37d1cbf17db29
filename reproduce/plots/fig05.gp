# Figure 5: theta/alpha against t/to below the collapse PGA.  gnuplot -e "dir='out/fig05'" fig05.gp
set datafile separator ","
set datafile missing "fallen"
set terminal pngcairo size 1500,1150 font "DejaVu Sans,10"
set output (exists("png") ? png : dir."/fig05.png")  # png: reproduce's temporary file
set multiplot layout 3,3 title "Figure 5: θ/α against t/t_o at PGA = q_i α g R_d (linearised eq. 3, impacts with restitution 1; the input ends at the dotted line)"
set xlabel "t / t_o  [-]"
set ylabel "θ / α  [-]"
set grid
set key bottom left font ",9"
set yrange [-2:2]
set xrange [0:4]
cases = "1 2 4"
xs = "0.2 0.5 0.8"
rds = "0.99 0.90 0.70"
do for [ci=1:3] {
  do for [xi=1:3] {
    c = word(cases, ci)
    tfin = (c eq "4") ? 3 : 2
    set title sprintf("case %s, x = p·t_o = %s", c, word(xs, xi))
    set arrow 1 from tfin,-2 to tfin,2 nohead dt 3 lc rgb "gray50"
    set arrow 2 from 0,1 to 4,1 nohead dt 2 lc rgb "red"
    set arrow 3 from 0,-1 to 4,-1 nohead dt 2 lc rgb "red"
    plot for [ri=1:3] dir."/fig05_histories.csv" using 1:(column(1 + 9*(ci-1) + 3*(xi-1) + ri)) with lines lw 2 title "R_d = ".word(rds, ri)
  }
}
unset multiplot
