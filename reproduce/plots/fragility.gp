# Fragility of the scene's four blocks: the fitted lognormal curve of each block
# (median and beta of the fits files, well- or ill-conditioned columns) with the
# empirical points, over the shared records (fragility_fits.csv and
# fragility_empirical.csv, written only with the records folder) and over each
# synthetic set (fragility_synthetic_fits.csv, fragility_synthetic_empirical.csv:
# rows pulse, then stochastic).  gnuplot -e "dir='out/fragility'" fragility.gp
set datafile separator ","
fits = dir."/fragility_fits.csv"
emp  = dir."/fragility_empirical.csv"
sfits = dir."/fragility_synthetic_fits.csv"
semp  = dir."/fragility_synthetic_empirical.csv"
real_set = system(sprintf("test -f '%s' && echo 1 || echo 0", fits)) eq "1"
set terminal pngcairo size 1200,900 font "DejaVu Sans,10"
set output (exists("png") ? png : dir."/fragility.png")  # png: reproduce's temporary file
set multiplot layout 2,2 title "Fragility: lognormal fit (line) and empirical share (points) over the shared records (red), the MP2003 pulses (blue) and the RDK2008 stochastic records (green)" noenhanced
set logscale x
set xrange [1:20]
set yrange [0:1]
set grid
set xlabel "q = PGA/(α g)"
set ylabel "P(overturn | q)"
set key bottom right font ",8"
# Row i (0-based) of a fits file f, column c, without the notes and the header.
cell(f, i, c) = system(sprintf("grep -v '^#' %s | sed -n '%dp' | cut -d, -f%d", f, 2 + i, c))
# The fit of row i of file f whose alpha is in column c0 (median c0 + 6, beta c0 + 7; their *_ill twins
# c0 + 13, c0 + 14): "median,beta", or "-" where the block has no fit.
fit_of(f, i, c0) = (cell(f, i, c0 + 6) ne "-") ? cell(f, i, c0 + 6).",".cell(f, i, c0 + 7) : \
                   ((cell(f, i, c0 + 13) ne "-") ? cell(f, i, c0 + 13).",".cell(f, i, c0 + 14) : "-")
curve(mb, colour, name) = (mb eq "-") ? "" : sprintf("norm(log(x/%s)/%s) with lines lw 2 lc rgb '%s' title '%s fit', ", \
                          mb[1:strstrt(mb, ",") - 1], mb[strstrt(mb, ",") + 1:], colour, name)
do for [i=0:3] {
  a = cell(sfits, i, 2)
  p = cell(sfits, i, 3)
  cmd = ""
  if (real_set) {
    cmd = cmd.curve(fit_of(fits, i, 1), "#c03030", "records")
    cmd = cmd.sprintf("emp using ((strcol(1) eq '%s' && strcol(2) eq '%s') ? $3 : 1/0):4 with points pt 7 ps 1 lc rgb '#c03030' title 'records', ", a, p)
  }
  cmd = cmd.curve(fit_of(sfits, i, 2), "#1f5fbf", "pulses")
  cmd = cmd.sprintf("semp using ((strcol(1) eq 'pulse' && strcol(2) eq '%s' && strcol(3) eq '%s') ? $4 : 1/0):5 with points pt 5 ps 0.8 lc rgb '#1f5fbf' title 'pulses', ", a, p)
  cmd = cmd.curve(fit_of(sfits, 4 + i, 2), "#1a7f37", "stochastic")
  cmd = cmd.sprintf("semp using ((strcol(1) eq 'stochastic' && strcol(2) eq '%s' && strcol(3) eq '%s') ? $4 : 1/0):5 with points pt 9 ps 1 lc rgb '#1a7f37' title 'stochastic'", a, p)
  set title sprintf("α = %s, p = %s rad/s", a, p) noenhanced
  eval "plot ".cmd
}
unset multiplot
