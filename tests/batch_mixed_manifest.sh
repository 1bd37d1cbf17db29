#!/usr/bin/env bash
# The mixed manifest the batch tests share (batch_cli_test.sh, batch_mpi_test.sh):
# synthetic records in DIR/records and DIR/m.csv, every kind, costs from one
# simulation to a spectrum's hundreds, relative paths, a comment, a blank line.
#
#   tests/batch_mixed_manifest.sh ROCKING DIR
set -eu
rocking="$1"
tmp="$2"
py=/usr/bin/python3
mkdir -p "$tmp/records"
# Records: decaying sines of 0.3 g at 1 and 1.5 Hz (one column in g, dt 0.01 s)
# and a Mavroeidis-Papageorgiou pulse (two columns in m/s^2, from record synth).
for f in 1 1.5; do
    $py -c "
import math
for k in range(1500):
    t = k * 0.01
    print('%.10f' % (0.3 * math.sin(2 * math.pi * $f * t) * math.exp(-t / 4)))" >"$tmp/records/sine$f.txt"
done
"$rocking" record synth --pulse 0.5,1.2,0.3,2.5 --dt 0.005 --duration 12 --output "$tmp/records/pulse.txt" >/dev/null

# The mixed manifest: relative paths, resolved against the manifest's folder;
# costs from one simulation to a spectrum's hundreds; a comment and a blank line.
$py - "$tmp/m.csv" <<'PY'
import sys
rows = ["# a mixed manifest: every kind, costs from 1 run to hundreds", "",
        "id,kind,record,unit,record_dt,alpha,p,height,scaling,model,solver,restitution,criterion,points,q_max"]
k = 0
for rec, unit, dt in (("records/sine1.txt", "g", "0.01"), ("records/sine1.5.txt", "g", "0.01"),
                      ("records/pulse.txt", "m/s2", "")):
    for alpha in ("0.08", "0.12"):
        for p in ("1", "2.5"):
            k += 1
            # Every other one with the default restitution (1) and criterion (final-rotation).
            e, c = ("housner", "overturning") if k % 2 else ("", "")
            rows.append(f"s{k},simulate,{rec},{unit},{dt},{alpha},{p},,q={1 + k % 4},,,{e},{c},,")
            rows.append(f"f{k},simulate,{rec},{unit},{dt},{alpha},,3,,full,,0.9,,,")
            rows.append(f"i{k},ida,{rec},{unit},{dt},{alpha},{p},,,,,,,60,12")
        rows.append(f"c{k},collapse,{rec},{unit},{dt},{alpha},,,,,,,,,")
    rows.append(f"p{k},spectrum,{rec},{unit},{dt},0.1,,,,,,,,80,")
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
