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
check "alpha out of range" "--alpha: each must be in (0, pi/4) (got 0.8)" "$rocking" fragility x --alpha 0.8 --p 1
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
# The plot's and the fits' files refused before the study runs (the record is not read:
# it does not exist), and gnuplot missing said first.
check "png in no folder"   "--png: $tmp/no/dir/f.png"       "$rocking" fragility no-such-file --alpha 0.1 --p 2 --png "$tmp/no/dir/f.png"
status "png in no folder"  1                                 "$rocking" fragility no-such-file --alpha 0.1 --p 2 --png "$tmp/no/dir/f.png"
check "fits in no folder"  "--fits: $tmp/no/dir/f.csv"      "$rocking" fragility no-such-file --alpha 0.1 --p 2 --fits "$tmp/no/dir/f.csv"
check "png without gnuplot" "--png $tmp/ng.png: gnuplot is not installed" env PATH=/nonexistent "$rocking" fragility no-such-file --alpha 0.1 --p 2 --png "$tmp/ng.png"
status "png without gnuplot" 1                               env PATH=/nonexistent "$rocking" fragility no-such-file --alpha 0.1 --p 2 --png "$tmp/ng.png"
check "png is a record"    "writing it would replace the input"                 "${run[@]}" --alpha 0.1 --p 2 --png "$tmp/sine1.txt"

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

# The PNG and the fits' CSV (issue 40), read by tests/plot_check.py against the same
# run's JSON: the PNG's size for its panels; each block's curve Phi(ln(q/median)/beta) at
# every 40th q, the bootstrap band the least and greatest of the curves at its interval's
# corners, the empirical and censored points, n and the censored in the title; --fits's
# median, beta and bootstrap ends the JSON's.  The grid (six blocks, two with a censored
# record) and the refine method's three fits; the other outputs unchanged by them.
if command -v gnuplot >/dev/null; then
    plotted=(--alpha 0.1,0.2 --p 0.5,2,4 --q-max 15 --bootstrap 50 --seed 3)
    ROCKING_PLOT_SCRIPT="$tmp/f.gp" "${run[@]}" "${plotted[@]}" --json --png "$tmp/f.png" --fits "$tmp/fits.csv" >"$tmp/fp.json"
    "${run[@]}" "${plotted[@]}" --json >"$tmp/fp0.json"
    same "--png and --fits change no byte of the JSON" "$tmp/fp.json" "$tmp/fp0.json"
    if grep -q '"collapsed": false' "$tmp/fp.json"; then echo "ok: a censored record plotted"; else echo "FAIL: no censored record in the plot's study"; fail=1; fi
    $py "$(dirname "$0")/plot_check.py" fragility "$tmp/f.gp" "$tmp/f.png" "$tmp/fp.json" "$tmp/fits.csv" || fail=1
    refined=(--alpha 0.1 --p 2 --method refine --width 1e-3 --bootstrap 20 --seed 3)
    ROCKING_PLOT_SCRIPT="$tmp/fr.gp" "${run[@]}" "${refined[@]}" --json --png "$tmp/fr.png" --fits "$tmp/fitsr.csv" >"$tmp/fr.json"
    "${run[@]}" "${refined[@]}" --output "$tmp/fr.csv" --png "$tmp/fr2.png" >"$tmp/fr.txt"
    "${run[@]}" "${refined[@]}" --output "$tmp/fr0.csv" >"$tmp/fr0.txt"
    same "--png changes no byte of the text" "$tmp/fr.txt" "$tmp/fr0.txt"
    same "--png changes no byte of the CSV" "$tmp/fr.csv" "$tmp/fr0.csv"
    $py "$(dirname "$0")/plot_check.py" fragility "$tmp/fr.gp" "$tmp/fr.png" "$tmp/fr.json" "$tmp/fitsr.csv" || fail=1
    check "the three fits named" "first robust collapse: median" cat "$tmp/fr.gp"
else
    echo "FAIL: gnuplot is not installed (make deps): the PNG cannot be checked"; fail=1
fi

# The first collapse q, by another subcommand: simulate --record at the bracket's
# ends (q and q (1 - 1e-5), below the safe end) must overturn and not.
q=$("${run[@]}" --alpha 0.1 --p 2 --json | $py -c "import json,sys; print(repr(json.load(sys.stdin)['blocks'][0]['records'][0]['intervals'][0]['lower']['q_safe']))")
qc=$("${run[@]}" --alpha 0.1 --p 2 --json | $py -c "import json,sys; print(repr(json.load(sys.stdin)['blocks'][0]['records'][0]['q']))")
sim=("$rocking" simulate --record "$tmp/sine1.txt" --unit g --record-dt 0.01 --alpha 0.1 --p 2 --restitution housner --criterion overturning --json)
over() { "${sim[@]}" --q "$1" | $py -c "import json,sys; print(json.load(sys.stdin)['collapse'])"; }
check "simulate overturns at the first q" "True"  over "$qc"
check "simulate spares the safe end"      "False" over "$q"
# --restitution on the study (issue 40): the model says so, and its first collapse q is
# simulate's under the same restitution at both ends of its bracket.
check "restitution stated" "restitution 0.7" "${run[@]}" --alpha 0.1 --p 2 --restitution 0.7
q7=$("${run[@]}" --alpha 0.1 --p 2 --restitution 0.7 --json | $py -c "import json,sys; r=json.load(sys.stdin)['blocks'][0]['records'][0]; print(repr(r['q']), repr(r['intervals'][0]['lower']['q_safe']))")
read -r qc7 qs7 <<<"$q7"
sim7=("$rocking" simulate --record "$tmp/sine1.txt" --unit g --record-dt 0.01 --alpha 0.1 --p 2 --restitution 0.7 --json)
over7() { "${sim7[@]}" --q "$1" | $py -c "import json,sys; print(json.load(sys.stdin)['collapse'])"; }
check "restitution 0.7: simulate overturns at the first q" "True" over7 "$qc7"
check "restitution 0.7: simulate spares the safe end" "False" over7 "$qs7"
check "restitution refused" "--restitution" "${run[@]}" --alpha 0.1 --p 2 --restitution 1.5
status "restitution refused" 2 "${run[@]}" --alpha 0.1 --p 2 --restitution 1.5

# Blocks as built (issue 40): --block BxH is alpha = atan(B/H), p = sqrt(3 g/(4 R)),
# R = sqrt(B^2 + H^2)/2 (eqs. 2, 4), here computed by Python, and the study the same
# as with those alpha and p given, but for the block's name.
check "block: its name in the text" "alpha = 0.14889, p = 1.90737 rad/s (block 0.6x4 m):" "${run[@]}" --block 0.6x4
check "block with alpha refused" "--block gives each block's alpha and p" "${run[@]}" --block 0.6x4 --alpha 0.1
status "block with alpha refused" 2 "${run[@]}" --block 0.6x4 --alpha 0.1
check "a block as wide as tall" "--block 4x4: alpha = atan(B/H) = 0.785398 rad is not below pi/4" "$rocking" fragility x --block 4x4
check "a squat block within pi/4 is searched" "x: cannot open the file" "$rocking" fragility x --block 3.5x4
check "block wider than tall" "alpha = atan(B/H) = 0.896055 rad is not below pi/4" "$rocking" fragility x --block 5x4
check "block grammar" "each block is THICKNESSxHEIGHT in m, e.g. 0.6x4 (got '0.6*4')" "$rocking" fragility x --block '0.6*4'
read -r alpha p < <($py -c "import math; B, H = 0.6, 4.0; R = math.hypot(B, H) / 2; print(repr(math.atan(B / H)), repr(math.sqrt(3 * 9.81 / (4 * R))))")
"${run[@]}" --block 0.6x4 --json >"$tmp/built.json"
"${run[@]}" --alpha "$alpha" --p "$p" --json >"$tmp/given.json"
if $py - "$tmp/built.json" "$tmp/given.json" <<'PY'
import json, sys
built, given = (json.load(open(f)) for f in sys.argv[1:3])
assert built["blocks"][0].pop("built") == "0.6x4"
assert built == given, "the blocks as built and as alpha, p differ"
PY
then echo "ok: --block 0.6x4 is alpha $alpha, p $p"; else echo "FAIL: --block 0.6x4 against alpha, p"; fail=1; fi
exit $fail
