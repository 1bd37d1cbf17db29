#!/usr/bin/env bash
# rocking eq27 on the command line: errors naming the option or file with
# their exit codes, strict JSON whose shares add up from its map, the CSV's
# notes, and each verdict recomputed through three other subcommands
# (fragility's collapse q, record info's to_k, q's eq. 27).  The study's
# answers against known ones are the unit tests' (tests/test_eq27_at_scale.cpp).
#
#   tests/eq27_cli_test.sh ROCKING
set -u
rocking="$1"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# Three synthetic records in g: decaying sines of 0.3 g at 0.7, 1 and 1.5 Hz.
for f in 0.7 1 1.5; do
    $py -c "
import math
for k in range(1000):
    t = k * 0.01
    print('%.10f' % (0.3 * math.sin(2 * math.pi * $f * t) * math.exp(-t / 3)))" >"$tmp/sine$f.txt"
done
files=("$tmp/sine0.7.txt" "$tmp/sine1.txt" "$tmp/sine1.5.txt")
run=("$rocking" eq27 "${files[@]}" --unit g --dt 0.01)
small=(--alpha 0.1,0.2 --p-min 1 --p-max 4 --p-points 3)

# Bad arguments: exit 2, the option named.
check "FILE first"        "FILE comes first, before '--alpha'"           "$rocking" eq27 --alpha 0.1
status "FILE first"       2                                              "$rocking" eq27 --alpha 0.1
check "alpha range"       "--alpha: each must be in (0, 0.7) (got 0.8)"  "$rocking" eq27 x --alpha 0.8
check "p-min range"       "--p-min: must be in (0.01, 1000] rad/s"       "$rocking" eq27 x --p-min 0
check "p-max below p-min" "--p-max: must not be below --p-min (2)"       "$rocking" eq27 x --p-min 2 --p-max 1
status "p-max below p-min" 2                                             "$rocking" eq27 x --p-min 2 --p-max 1
check "p-points range"    "--p-points: must be between 1 and 1000"       "$rocking" eq27 x --p-points 0
check "q-max range"       "--q-max: must be in (1, 10000]"               "$rocking" eq27 x --q-max 1
check "unknown option"    "unknown option '--p'"                         "$rocking" eq27 x --p 1
# Bad files: exit 1, the file named.
check "missing file"      "no-such-file"                                 "$rocking" eq27 "$tmp/sine1.txt" no-such-file --unit g --dt 0.01
status "missing file"     1                                              "$rocking" eq27 "$tmp/sine1.txt" no-such-file --unit g --dt 0.01
status "output in no folder" 1                                           "${run[@]}" "${small[@]}" --output "$tmp/no/dir/m.csv"

# Text: the shares, the censoring rule and the conservative list.
check "text share"        "to_5 "                                        "${run[@]}" "${small[@]}"
check "text censored"     "counted as conservative"                      "${run[@]}" "${small[@]}"
check "text conservative" "conservative on every block and record:"      "${run[@]}" "${small[@]}"

# JSON: strict (no NaN or Infinity); each share is its map's sum over the
# blocks, the interval holds it; then every verdict of the block (0.1, 2)
# recomputed from fragility --json, record info --json and q --json.
"${run[@]}" "${small[@]}" --json >"$tmp/e.json"
"$rocking" fragility "${files[@]}" --unit g --dt 0.01 --alpha 0.1 --p 2 --json >"$tmp/f.json"
for f in "${files[@]}"; do "$rocking" record info "$f" --unit g --dt 0.01 --json; done >"$tmp/info.jsonl"
if $py - "$tmp/e.json" "$tmp/f.json" "$tmp/info.jsonl" "$rocking" <<'PY'
import json, subprocess, sys
def bad(c): raise ValueError(c)
e = json.load(open(sys.argv[1]), parse_constant=bad)
assert e["cases"] == 18 and len(e["map"]) == 6, e
for k, s in enumerate(e["shares"]):
    assert s["k"] == k + 1 and s["cases"] == 18
    assert s["non_conservative"] == sum(m["non_conservative"][k] for m in e["map"]), s
    assert s["interval"][0] <= s["share"] <= s["interval"][1], s
frag = json.load(open(sys.argv[2]), parse_constant=bad)["blocks"][0]["records"]
infos = [json.loads(line) for line in open(sys.argv[3])]
cell = next(m for m in e["map"] if m["alpha"] == 0.1 and m["p"] == 2)
for k in range(11):
    count = 0
    for r, info in zip(frag, infos):
        x = 2 * info["to"][k]
        q27 = json.loads(subprocess.run([sys.argv[4], "q", "--case", "2", "--pulses", "6", "--x", repr(x), "--json"],
                                        capture_output=True, text=True, check=True).stdout)["q"]
        count += r["collapsed"] and r["q"] < q27
    assert cell["non_conservative"][k] == count, (k + 1, cell, count)
PY
then echo "ok: json"; else echo "FAIL: json"; fail=1; fi

# CSV: one row per block, the notes naming model, solver, inputs, grids and the rule.
"${run[@]}" "${small[@]}" --output "$tmp/m.csv" >/dev/null
for note in "# command: rocking eq27" "# model: linearised" "# solver: exact" "# inputs: $tmp/sine0.7.txt" \
            "# grid: alpha 0.1, 0.2; p: 3 log-spaced from 1 to 4 rad/s" "# ida: " "# verdict: " \
            "# share to_5 (95 % Wilson): "; do
    if grep -qF "$note" "$tmp/m.csv"; then echo "ok: note $note"; else echo "FAIL: note $note"; fail=1; fi
done
rows=$(grep -vc '^#' "$tmp/m.csv")
if [[ $rows == 7 ]]; then echo "ok: csv rows"; else echo "FAIL: csv rows: $rows, wanted 7 (header and 6 blocks)"; fail=1; fi
exit $fail
