# Fragility of the scene's four blocks: the fitted lognormal curve of each block
# (median and beta of fragility_fits.csv, well- or ill-conditioned columns) with
# the empirical points (fragility_empirical.csv).  gnuplot -e "dir='out/fragility'" fragility.gp
set datafile separator ","
fits = dir."/fragility_fits.csv"
emp  = dir."/fragility_empirical.csv"
set terminal pngcairo size 1200,900 font "DejaVu Sans,10"
set output (exists("png") ? png : dir."/fragility.png")  # png: reproduce's temporary file
set multiplot layout 2,2 title "Fragility over the shared records: lognormal fit (line) and empirical share (points)" noenhanced
set logscale x
set xrange [1:20]
set yrange [0:1]
set grid
set xlabel "q = PGA/(α g)"
set ylabel "P(overturn | q)"
set key bottom right
# Row i (0-based) of the fits, column c, without the notes and the header.
cell(i, c) = system(sprintf("grep -v '^#' %s | sed -n '%dp' | cut -d, -f%d", fits, 2 + i, c))
do for [i=0:3] {
  a = cell(i, 1)
  p = cell(i, 2)
  m = cell(i, 7); b = cell(i, 8)
  if (m eq "-") { m = cell(i, 14); b = cell(i, 15) }
  set title sprintf("α = %s, p = %s rad/s: median %.3g, β %.3g", a, p, real(m), real(b)) noenhanced
  plot norm(log(x/real(m))/real(b)) with lines lw 2 lc rgb "#c03030" title "lognormal fit", \
       emp using ((strcol(1) eq a && strcol(2) eq p) ? $3 : 1/0):4 with points pt 7 ps 1 lc rgb "black" title "empirical"
}
unset multiplot
