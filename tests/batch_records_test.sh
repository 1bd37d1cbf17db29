#!/usr/bin/env bash
# rocking batch on the shared real records (ESM and PEER): relative record
# paths resolved against the manifest's folder wherever the batch is run
# from; the README's examples (simulate, collapse on the Norcia record) as
# rows; every row equal to its single command (batch_compare.py); the same
# bytes on 1 and 2 threads.  Without ../shared/records it exits 77 (a skip)
# and says so.
#
#   tests/batch_records_test.sh ROCKING
set -u
rocking=$(realpath "$1")
here=$(realpath "$(dirname "$0")")
py=/usr/bin/python3
records="${ROCKING_RECORDS:-$here/../../shared/records}"
nrc="$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC"
peer="$records/peer/RSN1158_KOCAELI_DZC180.AT2"
if [[ ! -f $nrc || ! -f $peer ]]; then
    echo "skipped: the shared records are absent (wanted $nrc and $peer; ../shared/records or \$ROCKING_RECORDS)"
    exit 77
fi
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/study"
# The records named relative to the manifest's folder, $tmp/study.
rel() { $py -c "import os, sys; print(os.path.relpath(sys.argv[1], sys.argv[2]))" "$1" "$tmp/study"; }
{
    echo "id,kind,record,alpha,p,scaling,restitution,criterion,points,q_max"
    echo "readme-simulate,simulate,$(rel "$nrc"),0.15,2,,housner,overturning,,"
    echo "scaled,simulate,$(rel "$peer"),0.12,1.5,pga=0.5,,,,"
    echo "readme-collapse,collapse,$(rel "$nrc"),0.15,,,,,,"
    echo "peer-collapse,collapse,$(rel "$peer"),0.2,,,,,,"
    echo "ida,ida,$(rel "$nrc"),0.15,2.5,,,,40,10"
    echo "spectrum,spectrum,$(rel "$peer"),0.15,,,,,40,"
} >"$tmp/study/m.csv"
cd /  # anywhere but the manifest's folder
"$rocking" batch "$tmp/study/m.csv" --jobs 1 --output "$tmp/r1.csv" 2>/dev/null
check "runs"  "# end: 6 jobs, 0 failed"  tail -1 "$tmp/r1.csv"
"$rocking" batch "$tmp/study/m.csv" --jobs 2 --output "$tmp/r2.csv" 2>/dev/null
if cmp -s "$tmp/r1.csv" "$tmp/r2.csv"; then echo "ok: --jobs 1 and 2 identical"; else echo "FAIL: --jobs 1 and 2 differ"; fail=1; fi
# The README's figures, as printed there.
if $py - "$tmp/r1.csv" <<'PY'
import csv, sys
rows = {r["id"]: r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#"))}
s, c = rows["readme-simulate"], rows["readme-collapse"]
assert s["collapse"] == "no" and s["impacts"] == "368" and abs(float(s["max_theta"]) - 0.600829152) < 1e-9, s
assert abs(float(s["theta_tfin"]) + 0.001083421548) < 1e-12 and s["solver_used"] == "exact", s
assert c["collapse"] == "yes" and abs(float(c["p_collapse"]) - 2.190222) < 1e-6 and abs(float(c["p_safe"]) - 2.190052) < 1e-6, c
PY
then echo "ok: the README's simulate and collapse figures"; else echo "FAIL: the README's figures"; fail=1; fi
if $py "$here/batch_compare.py" "$tmp/r1.csv" "$rocking" "$tmp/study"; then
    echo "ok: the rows agree with simulate, collapse, fragility and spectrum"
else echo "FAIL: a row differs from its single command"; fail=1; fi
exit $fail
