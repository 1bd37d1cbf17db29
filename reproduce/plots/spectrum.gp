# The rocking spectrum of the Norcia records: max |theta|/alpha against p, one
# panel per record (rows) and alpha (columns), the overturning intervals shaded
# and Table 1's p marked.  gnuplot -e "dir='out/spectrum'" spectrum.gp
set datafile separator ","
grid = dir."/spectrum_grid.csv"
iv   = dir."/spectrum_intervals.csv"
sm   = dir."/spectrum_summary.csv"
# The records and alphas, in the order of the summary (one row per pair).
stats sm using 0 nooutput
n = STATS_records
nalpha = 5
nrec = int(n / nalpha)
set terminal pngcairo size 2000,(260*nrec + 80) font "DejaVu Sans,9"
set output (exists("png") ? png : dir."/spectrum.png")  # png: reproduce's temporary file
set multiplot layout nrec,nalpha margins 0.03,0.99,0.02,0.975 spacing 0.025,0.02 title "Rocking spectra of the Norcia records: max |θ|/α against p; overturning intervals shaded; Table 1's p dashed blue" noenhanced
set logscale xy
set xrange [0.3:30]
set yrange [1e-3:1e2]
set grid
set key off
rec(i) = system(sprintf("grep -v '^#' %s | sed -n '%dp' | cut -d, -f1", sm, 2 + i*nalpha))
do for [i=0:nrec-1] {
  r = rec(i)
  do for [k=0:nalpha-1] {
    a = sprintf("%.2f", 0.05*(k+1))
    set title sprintf("%s  α = %s", system("basename ".r." .C.ACC.ASC"), a) noenhanced
    plot iv using ((strcol(1) eq r && strcol(2) eq a) ? sqrt($4*$5) : 1/0):(1):4:5:(1e-3):(1e2) \
           with boxxyerror fs transparent solid 0.35 noborder lc rgb "#e06060", \
         grid using ((strcol(1) eq r && strcol(2) eq a) ? $3 : 1/0):($5 > 1e-3 ? $5 : 1e-3) with lines lw 1 lc rgb "black", \
         sm using ((strcol(1) eq r && strcol(2) eq a && strcol(5) ne "none below 30") ? $5 : 1/0):(1e-3):(0):(1e5) \
           with vectors nohead dt 2 lw 2 lc rgb "blue"
  }
}
unset multiplot
