#!/usr/bin/env bash
# Issue 39's public example, by hand (not in ctest: about 70 s on 2 shared
# cores, over the 60 s a ctest test may take): IT.NRC HGE 2016-10-30,
# alpha 0.10, p 2.5 rad/s, --method refine --width 1e-5 reports the first
# overturning 1.31947 (to 1e-5 relative) and the first robust collapse 1.7349
# (the grid's first collapse).  Exit 77 (skipped) without /work/shared/records.
#
#   tests/fragility_refine_hge_test.sh ROCKING [RECORDS]
set -u
rocking="$1"
records="${2:-/work/shared/records}"
file="$records/esm/IT.NRC..HGE.D.20161030.064018.C.ACC.ASC"
[[ -f $file ]] || { echo "skipped: $file is not there"; exit 77; }
out=$(mktemp) || exit 1
trap 'rm -f "$out"' EXIT
"$rocking" fragility "$file" --alpha 0.1 --p 2.5 --method refine --width 1e-5 --json --quiet >"$out" || exit 1
/usr/bin/python3 - "$out" <<'PY'
import json, math, sys
r = json.load(open(sys.argv[1]))["blocks"][0]["records"][0]
f, rc = r["first_overturning"], r["first_robust_collapse"]
print("first overturning %.7g (%s), first robust collapse %.7g, %d runs with margins"
      % (f["q"], f["check"]["confirmation"], rc["q"], r["samples"]))
assert f["collapsed"] and math.isclose(f["q"], 1.31947, rel_tol=1e-5), f
assert f["check"]["confirmation"] == "confirmed", f["check"]
assert rc["collapsed"] and math.isclose(rc["q"], 1.7349, rel_tol=1e-4), rc
print("ok: issue 39's example")
PY
