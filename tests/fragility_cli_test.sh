#!/usr/bin/env bash
# rocking fragility on the command line: errors naming the option or file
# with their exit codes, strict JSON, the CSV's notes, and the first collapse
# q it prints seen by simulate --record --q at both ends of its bracket.  The
# IDA's answers against known ones are the unit tests' (tests/test_ida.cpp).
#
#   tests/fragility_cli_test.sh ROCKING
set -u
rocking="$1"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# Two synthetic records in g: decaying sines of 0.3 g at 1 and 1.5 Hz.
for f in 1 1.5; do
    $py -c "
import math
for k in range(1000):
    t = k * 0.01
    print('%.10f' % (0.3 * math.sin(2 * math.pi * $f * t) * math.exp(-t / 3)))" >"$tmp/sine$f.txt"
done
run=("$rocking" fragility "$tmp/sine1.txt" "$tmp/sine1.5.txt" --unit g --dt 0.01)

# Bad arguments: exit 2, the option named.
check "alpha required"     "--alpha is required"            "$rocking" fragility no-such-file --p 1
status "alpha required"    2                                 "$rocking" fragility no-such-file --p 1
check "p required"         "--p is required"                "$rocking" fragility no-such-file --alpha 0.1
check "alpha out of range" "--alpha: each must be in (0, 0.7) (got 0.8)" "$rocking" fragility x --alpha 0.8 --p 1
check "q-max too low"      "--q-max: must be in (1, 10000]" "$rocking" fragility x --alpha 0.1 --p 1 --q-max 1
status "q-max too low"     2                                 "$rocking" fragility x --alpha 0.1 --p 1 --q-max 1
check "seed needed"        "--bootstrap needs --seed"       "$rocking" fragility x --alpha 0.1 --p 1 --bootstrap 10
check "FILE first"         "FILE comes first, before '--alpha'" "$rocking" fragility --alpha 0.1 --p 1
check "jobs zero"          "--jobs: must be a whole number from 1 to 4096 (got 0)" "$rocking" fragility x --alpha 0.1 --p 1 --jobs 0
status "jobs zero"         2                                 "$rocking" fragility x --alpha 0.1 --p 1 --jobs 0
check "jobs not a number"  "(got 2.5)"                    "$rocking" fragility x --alpha 0.1 --p 1 --jobs 2.5
check "unknown option"     "unknown option '--criterion'"   "$rocking" fragility x --alpha 0.1 --p 1 --criterion overturning
# Bad files: exit 1, the file named.
check "missing file"       "no-such-file"                   "$rocking" fragility "$tmp/sine1.txt" no-such-file --unit g --dt 0.01 --alpha 0.1 --p 1
status "missing file"      1                                 "$rocking" fragility "$tmp/sine1.txt" no-such-file --unit g --dt 0.01 --alpha 0.1 --p 1
status "output in no folder" 1                               "${run[@]}" --alpha 0.1 --p 2 --output "$tmp/no/dir/f.csv"

# Text: each record's first q and its intervals, the fit and the empirical curve.
check "text fit"           "lognormal median q = "          "${run[@]}" --alpha 0.1 --p 2,4 --bootstrap 50 --seed 3
check "text intervals"     "overturns for q in ["           "${run[@]}" --alpha 0.1 --p 2
check "censored"           "censored at q_max = 1.5"        "${run[@]}" --alpha 0.1 --p 0.5 --q-max 1.5

# JSON: strict (no NaN or Infinity), every record and block present.
"${run[@]}" --alpha 0.1,0.2 --p 2,4 --bootstrap 50 --seed 3 --json >"$tmp/f.json"
# The threads change the time, never a byte.
"${run[@]}" --alpha 0.1,0.2 --p 2,4 --bootstrap 50 --seed 3 --json --jobs 1 >"$tmp/f1.json"
"${run[@]}" --alpha 0.1,0.2 --p 2,4 --bootstrap 50 --seed 3 --json --jobs 3 >"$tmp/f3.json"
if cmp -s "$tmp/f1.json" "$tmp/f3.json"; then echo "ok: --jobs 1 and 3 identical"; else echo "FAIL: --jobs 1 and 3 differ"; fail=1; fi
if $py - "$tmp/f.json" <<'PY'
import json, sys
def bad(c): raise ValueError(c)
d = json.load(open(sys.argv[1]), parse_constant=bad)
assert len(d["blocks"]) == 4, d
for b in d["blocks"]:
    assert len(b["records"]) == 2
    for r in b["records"]:
        assert r["collapsed"] == bool(r["intervals"])
        if r["collapsed"]: assert r["q"] == r["intervals"][0]["from"]
PY
then echo "ok: json"; else echo "FAIL: json"; fail=1; fi

# CSV: one row per block and record, the notes naming model, solver, inputs and grid.
"${run[@]}" --alpha 0.1 --p 2,4 --output "$tmp/f.csv" >/dev/null
check "csv notes"          "solver"                          cat "$tmp/f.csv"
check "csv grid note"      "log-spaced from 1 to 20"         cat "$tmp/f.csv"
rows=$(grep -vc '^#' "$tmp/f.csv")
if [[ $rows == 5 ]]; then echo "ok: csv rows"; else echo "FAIL: csv rows: $rows, wanted a header and 4"; fail=1; fi

# The first collapse q, by another subcommand: simulate --record at the bracket's
# ends (q and q (1 - 1e-5), below the safe end) must overturn and not.
q=$("${run[@]}" --alpha 0.1 --p 2 --json | $py -c "import json,sys; print(repr(json.load(sys.stdin)['blocks'][0]['records'][0]['intervals'][0]['lower']['q_safe']))")
qc=$("${run[@]}" --alpha 0.1 --p 2 --json | $py -c "import json,sys; print(repr(json.load(sys.stdin)['blocks'][0]['records'][0]['q']))")
sim=("$rocking" simulate --record "$tmp/sine1.txt" --unit g --record-dt 0.01 --alpha 0.1 --p 2 --restitution housner --criterion overturning --json)
over() { "${sim[@]}" --q "$1" | $py -c "import json,sys; print(json.load(sys.stdin)['collapse'])"; }
check "simulate overturns at the first q" "True"  over "$qc"
check "simulate spares the safe end"      "False" over "$q"
exit $fail
