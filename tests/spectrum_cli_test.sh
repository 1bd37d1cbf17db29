#!/usr/bin/env bash
# rocking spectrum on the command line: clear errors with their exit codes,
# strict JSON, the CSV and the PNG whole, and every boundary it prints seen
# as a bracket by two other subcommands (simulate at both of its ends,
# collapse for Table 1's p).  On the batch engine, the same JSON bytes on any
# threads, from a rows file, from a resume of a finished or a killed one,
# and under mpirun on 2 and 3 ranks; a resume of another study refused.  The
# boundaries' places against known answers are the unit tests'
# (tests/test_spectrum.cpp), the rows' round trip too (tests/test_study_rows.cpp).
#
#   tests/spectrum_cli_test.sh ROCKING [MPI]   (MPI: "1" when built with MPI; the last check
#                                              needs ../shared/records or $ROCKING_RECORDS)
set -u
rocking=$(realpath "$1")
built_with_mpi="${2:-0}"
records="${ROCKING_RECORDS:-$(dirname "$0")/../../shared/records}"
py=/usr/bin/python3
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail=0

expect() {  # description, wanted exit status, wanted substring, command...
    local what="$1" want_status="$2" want="$3"; shift 3
    local out status
    out=$(timeout 120 "$@" 2>&1); status=$?
    if [[ $status != "$want_status" || "$out" != *"$want"* ]]; then
        echo "FAIL: $what: exit $status (wanted $want_status), wanted '$want' in: ${out:0:600}"; fail=1
    else echo "ok: $what"; fi
}

# A synthetic record, plain text in g: a decaying sine of 0.3 g at 1 Hz, 10 s.
# At alpha = 0.1 and 0.2 its spectrum has three and two intervals.
rec="$tmp/sine.txt"
$py -c "
import math
for k in range(1000):
    t = k * 0.01
    print('%.10f' % (0.3 * math.sin(2 * math.pi * t) * math.exp(-t / 3)))" >"$rec"
run=("$rocking" spectrum "$rec" --unit g --dt 0.01)

# Bad arguments: exit 2, the option named, before the file is read.
expect "alpha required"        2 "--alpha is required"                       "$rocking" spectrum no-such-file
expect "a mark off the p range"  2 "--mark 0.6x400: its p, 0.191801 rad/s (H 400 m), lies outside the spectrum's p range [0.3, 30] rad/s (--p-min, --p-max)" "$rocking" spectrum no-such-file --mark 0.6x400
expect "alpha list ends"       2 "--alpha: a list of numbers"                "$rocking" spectrum no-such-file --alpha 0.1,
expect "alpha not a number"    2 "--alpha: 'x' is not a number"              "$rocking" spectrum no-such-file --alpha 0.1,x
expect "alpha out of range"    2 "--alpha: each must be in (0, pi/4) (got 0.8)" "$rocking" spectrum no-such-file --alpha 0.8
expect "points too few"        2 "--points: must be a whole number from 2 to 100000 (got 1)" "$rocking" spectrum no-such-file --alpha 0.1 --points 1
expect "points not whole"      2 "--points: must be a whole number from 2 to 100000 (got 2.5)" "$rocking" spectrum no-such-file --alpha 0.1 --points 2.5
expect "p-min at 0"            2 "--p-min: must be in [0.01, 1000] rad/s"    "$rocking" spectrum no-such-file --alpha 0.1 --p-min 0
expect "p-max infinite"        2 "--p-max: 'inf' is not a finite number"     "$rocking" spectrum no-such-file --alpha 0.1 --p-max inf
expect "p-max below p-min"     2 "--p-max: must be above --p-min (3 rad/s)"  "$rocking" spectrum no-such-file --alpha 0.1 --p-min 3 --p-max 2
expect "unknown option"        2 "unknown option '--criterion'"              "$rocking" spectrum no-such-file --alpha 0.1 --criterion overturning
expect "empty output name"     2 "--output: an empty file name"              "$rocking" spectrum no-such-file --alpha 0.1 --output ""
expect "FILE first"            2 "FILE comes first, before '--alpha'"        "$rocking" spectrum --alpha 0.1 "$rec"
expect "unit for plain text"   2 "--unit is required for a plain-text record" "$rocking" spectrum "$rec" --alpha 0.1 --dt 0.01
# Bad files: exit 1, the file named.
expect "missing file"          1 "no-such-file"                              "$rocking" spectrum no-such-file --alpha 0.1
printf 'not a record\n' >"$tmp/bad.txt"
expect "unreadable record"     1 "$tmp/bad.txt"                              "$rocking" spectrum "$tmp/bad.txt" --alpha 0.1
expect "output in no folder"   1 "--output: $tmp/no/such/dir/s.csv"          "${run[@]}" --alpha 0.1 --points 5 --output "$tmp/no/such/dir/s.csv"
expect "png in no folder"      1 "--png: $tmp/no/such/dir/s.png"             "${run[@]}" --alpha 0.1 --points 5 --png "$tmp/no/such/dir/s.png"
expect "png without gnuplot"   1 "--png $tmp/nognuplot.png: gnuplot is not installed" env PATH=/nonexistent "${run[@]}" --alpha 0.1 --points 5 --png "$tmp/nognuplot.png"
if [[ -e "$tmp/nognuplot.png" ]]; then echo "FAIL: a PNG left behind without gnuplot"; fail=1; fi
# Before any work: the missing gnuplot is said before the record is read.
expect "no gnuplot said before the record" 1 "--png $tmp/nognuplot.png: gnuplot is not installed" env PATH=/nonexistent "$rocking" spectrum no-such-file --alpha 0.1 --png "$tmp/nognuplot.png"

# The text: intervals with their checks, the grid's limit, Table 1's p.
expect "text intervals"        0 $'alpha = 0.2: overturns for p (rad/s) in (H: the heights of the blocks of this alpha at its ends)\n  [' "${run[@]}" --alpha 0.1,0.2
expect "text states the limit" 0 "islands narrower than half a step (x1.01164) may be missed" "${run[@]}" --alpha 0.1
expect "text names Table 1"    0 "Table 1's search (p from 0.3 by x1.01, the first collapse): p = 2.022946 rad/s" "${run[@]}" --alpha 0.1
expect "text: confirmed"       0 "from: confirmed; to: confirmed" "${run[@]}" --alpha 0.1
expect "no lift said"          0 "alpha = 0.5: the record never lifts the block (PGA 0.2764 g <= the uplift threshold alpha g)" "${run[@]}" --alpha 0.5 --points 10
out=$("${run[@]}" --alpha 0.1,0.2,0.5 --points 30 2>&1)
if [[ "$out" == *nan* || "$out" == *inf* ]]; then echo "FAIL: nan or inf in the text: $out"; fail=1; else echo "ok: no nan or inf in the text"; fi
# The threads change the time, never a byte (one alpha a job, in the given order).
"${run[@]}" --alpha 0.2,0.1,0.15 --points 40 --json --jobs 1 >"$tmp/j1.json" 2>&1
"${run[@]}" --alpha 0.2,0.1,0.15 --points 40 --json --jobs 3 >"$tmp/j3.json" 2>&1
if cmp -s "$tmp/j1.json" "$tmp/j3.json"; then echo "ok: --jobs 1 and 3 identical"; else echo "FAIL: --jobs 1 and 3 differ"; fail=1; fi
expect "jobs refused"          2 "--jobs: must be a whole number from 1 to 4096 (got 'x')" "${run[@]}" --alpha 0.1 --jobs x

# ---- On the batch engine: each alpha a job, the same bytes however its rows came.
same() {  # description, file, reference
    if cmp -s "$2" "$3"; then echo "ok: $1"; else echo "FAIL: $1: differs from $3"; fail=1; fi
}
study=("${run[@]}" --alpha 0.2,0.1,0.15 --points 40 --json)
"${study[@]}" --jobs 2 >"$tmp/j2.json" 2>&1
same "--jobs 2 = --jobs 1" "$tmp/j2.json" "$tmp/j1.json"
"${study[@]}" --rows "$tmp/r.rows" >"$tmp/rows.json" 2>"$tmp/rows.err"
same "--rows = in memory" "$tmp/rows.json" "$tmp/j1.json"
expect "the rows file is finished" 0 "# end: 3 jobs, 0 failed" tail -n 1 "$tmp/r.rows"
if [[ -s "$tmp/rows.err" ]]; then echo "FAIL: --rows said on stderr: $(head -3 "$tmp/rows.err")"; fail=1; fi
"${study[@]}" --rows "$tmp/r.rows" --resume >"$tmp/resumed.json" 2>&1
same "--resume of the finished rows = in memory" "$tmp/resumed.json" "$tmp/j1.json"
expect "resume needs rows"     2 "--resume needs --rows FILE" "${study[@]}" --resume
expect "resume of other alphas" 1 "holds no results of this study" "${study[@]/0.2,0.1,0.15/0.2,0.1}" --rows "$tmp/r.rows" --resume
# An edited record: the resume names it (its samples' digest is in the rows' header).
cp "$rec" "$tmp/sine.orig"
$py -c "
import sys
v = [float(l) for l in open(sys.argv[1])]
open(sys.argv[1], 'w').write(''.join('%.10f\n' % (x * 1.1) for x in v))" "$rec"
expect "resume over an edited record names it" 1 "$rec, a record the study names, has changed since $tmp/r.rows was written" \
    "${study[@]}" --rows "$tmp/r.rows" --resume
cp "$tmp/sine.orig" "$rec"
expect "empty rows name"       2 "--rows: an empty file name" "${study[@]}" --rows ""
expect "rows in no folder"     1 "$tmp/no/such/dir/r.rows" "${study[@]}" --rows "$tmp/no/such/dir/r.rows"

# A study killed (SIGKILL) once some rows are on disk, then resumed: the JSON
# of the uninterrupted run.  A longer record (60 s, decaying slowly) and 20
# alphas, so that it runs for seconds; ROCKING_BATCH_FLUSH_SECONDS=0 commits
# each row as it comes.
long="$tmp/long.txt"
$py -c "
import math
for k in range(6000):
    t = k * 0.01
    print('%.10f' % (0.3 * math.sin(2 * math.pi * t) * math.exp(-t / 30)))" >"$long"
many=$(seq -s, 0.02 0.02 0.40)
big=("$rocking" spectrum "$long" --unit g --dt 0.01 --alpha "$many" --points 2000 --json)
"${big[@]}" >"$tmp/big.json" 2>&1
ROCKING_BATCH_FLUSH_SECONDS=0 "${big[@]}" --rows "$tmp/k.rows" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1200); do
    grep -qs 'jobs [1-9]' "$tmp/k.rows.partial.state" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
done
kill -KILL "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
kept=$(sed -n 's/.* jobs \([0-9]*\) failed.*/\1/p' "$tmp/k.rows.partial.state" 2>/dev/null)
if [[ -e "$tmp/k.rows" || -z "$kept" || $kept -ge 20 || $kept -lt 1 ]]; then
    echo "FAIL: the kill did not leave a partial rows file (rows kept: '${kept}'; finished: $([[ -e "$tmp/k.rows" ]] && echo yes || echo no))"; fail=1
else
    echo "ok: killed with $kept of 20 rows on disk"
    expect "resume of a partial with other alphas" 1 "has changed since $tmp/k.rows.partial was begun" \
        "${big[@]/$many/0.02,0.04}" --rows "$tmp/k.rows" --resume
    cp "$long" "$tmp/long.orig"
    awk 'NR == 3000 { $1 = 2 * $1 } 1' "$tmp/long.orig" >"$long"   # one sample doubled
    expect "resume of a partial over an edited record names it" 1 \
        "$long, a record the study names, has changed since $tmp/k.rows.partial was begun" \
        "${big[@]}" --rows "$tmp/k.rows" --resume
    cp "$tmp/long.orig" "$long"
    "${big[@]}" --rows "$tmp/k.rows" --resume >"$tmp/killed.json" 2>"$tmp/killed.err"
    same "a killed study resumed = uninterrupted" "$tmp/killed.json" "$tmp/big.json"
    expect "the resumed rows file is finished" 0 "# end: 20 jobs, 0 failed" tail -n 1 "$tmp/k.rows"
fi

# Under mpirun (2 and 3 ranks on 2 cores): the bytes of the threads.
if [[ $built_with_mpi == 1 ]] && command -v mpirun >/dev/null; then
    # Tests run as root in containers: OpenMPI refuses root unless told.
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    for np in 2 3; do
        timeout 300 mpirun --oversubscribe -np $np "${study[@]}" >"$tmp/np$np.json" 2>"$tmp/np$np.err"
        code=$?
        if [[ $code != 0 ]]; then echo "FAIL: -np $np exits $code: $(head -3 "$tmp/np$np.err")"; fail=1; fi
        same "-np $np = threads" "$tmp/np$np.json" "$tmp/j1.json"
    done
    timeout 300 mpirun --oversubscribe -np 2 "${study[@]}" --rows "$tmp/np2.rows" >"$tmp/np2rows.json" 2>/dev/null
    same "-np 2 with --rows = threads" "$tmp/np2rows.json" "$tmp/j1.json"
    same "-np 2's rows file = the threads'" "$tmp/np2.rows" "$tmp/r.rows"
else
    echo "skipped: mpirun checks (built with MPI: $built_with_mpi; mpirun: $(command -v mpirun || echo none))"
fi

# JSON, strict (no NaN or Infinity, nothing after the object), with the CSV
# and the PNG from the same run.
"${run[@]}" --alpha 0.1,0.2,0.5 --json --output "$tmp/s.csv" --png "$tmp/s.png" >"$tmp/s.json" 2>"$tmp/s.err"
status=$?
if [[ $status != 0 ]]; then echo "FAIL: json run exit $status: $(cat "$tmp/s.err")"; fail=1; fi
cat >"$tmp/check.py" <<'EOF'
import csv, json, math, subprocess, sys

json_path, csv_path, png_path, rocking, rec = sys.argv[1:6]
problems = []
def refuse(name):
    raise ValueError("non-finite JSON number: " + name)
d = json.loads(open(json_path, "rb").read().decode("utf-8"), parse_constant=refuse)
grid = d["grid"]
if grid["points"] != 200 or grid["p_min"] != 0.3 or grid["p_max"] != 30:
    problems.append("grid: %r" % grid)
if "islands narrower than half a step" not in grid["note"]:
    problems.append("the grid's note does not state its limit")
spectra = {s["alpha"]: s for s in d["spectra"]}
if sorted(spectra) != [0.1, 0.2, 0.5]:
    problems.append("alphas: %r" % sorted(spectra))
if spectra[0.5]["lifts"] or spectra[0.5]["intervals"]:
    problems.append("alpha 0.5 cannot lift the block at 0.276 g")
if len(spectra[0.1]["intervals"]) != 3 or len(spectra[0.2]["intervals"]) != 2:
    problems.append("interval counts %d, %d (wanted 3, 2)" % (len(spectra[0.1]["intervals"]), len(spectra[0.2]["intervals"])))

def simulate(alpha, p):
    out = subprocess.run([rocking, "simulate", "--record", rec, "--unit", "g", "--record-dt", "0.01", "--alpha", repr(alpha),
                          "--p", repr(p), "--restitution", "housner", "--criterion", "overturning", "--json"],
                         capture_output=True, check=True).stdout
    return json.loads(out, parse_constant=refuse)

for alpha, s in spectra.items():
    for pt in s["points"]:
        if pt["t_overturn"] is not None and not pt["overturning"]:
            problems.append("alpha %g, p %g: a fall time without overturning" % (alpha, pt["p"]))
    for k, iv in enumerate(s["intervals"]):
        if not iv["from"] < iv["to"]:
            problems.append("alpha %g: interval %d empty" % (alpha, k))
        for side in ("lower", "upper"):
            b = iv[side]
            if b is None:
                continue
            if abs(b["p_collapse"] - b["p_safe"]) > 1e-6 * max(b["p_collapse"], b["p_safe"]):
                problems.append("alpha %g: bracket wider than 1e-6: %r" % (alpha, b))
            if b["confirmation"] != "confirmed":
                problems.append("alpha %g: %r" % (alpha, b))
            # Another subcommand must see the same bracket.
            if not simulate(alpha, b["p_collapse"])["collapse"] or simulate(alpha, b["p_safe"])["collapse"]:
                problems.append("alpha %g: simulate does not see the bracket %r" % (alpha, b))
    # Every grid point's max |theta|/alpha as simulate gives it, at a few points.
    for pt in s["points"][::97]:
        r = simulate(alpha, pt["p"])
        if r["max_theta_input_over_alpha"] != pt["max_theta"] or r["collapse"] != pt["overturning"]:
            problems.append("alpha %g, p %r: simulate gives %r, %r" % (alpha, pt["p"], r["max_theta_input_over_alpha"], r["collapse"]))
    # Table 1's p as the collapse subcommand finds it.
    c = json.loads(subprocess.run([rocking, "collapse", rec, "--unit", "g", "--dt", "0.01", "--alpha", repr(alpha), "--json"],
                                  capture_output=True, check=True).stdout, parse_constant=refuse)
    if c["p"] != s["table1"]["p"] or c["p_safe"] != s["table1"]["p_safe"]:
        problems.append("alpha %g: Table 1's p %r against collapse's %r" % (alpha, s["table1"], c))

# The CSV: notes, one row per grid point and alpha, no nan or inf.
lines = open(csv_path).read().splitlines()
notes = [l for l in lines if l.startswith("#")]
for key in ("# model:", "# input:", "# grid:", "# refinement:", "# intervals at alpha 0.1:", "# Table 1's p at alpha 0.2:"):
    if not any(l.startswith(key) for l in notes):
        problems.append("CSV note missing: " + key)
rows = list(csv.DictReader(l for l in lines if not l.startswith("#")))
if len(rows) != sum(len(s["points"]) for s in d["spectra"]):
    problems.append("CSV rows %d against JSON points" % len(rows))
if any(c in ("nan", "inf", "-inf") for r in rows for c in r.values()):
    problems.append("nan or inf in the CSV")
# The PNG whole.
if open(png_path, "rb").read(8) != b"\x89PNG\r\n\x1a\n":
    problems.append("not a PNG: " + png_path)
for p in problems:
    print("FAIL: " + p)
print("ok: JSON, CSV and PNG checked (%d spectra)" % len(spectra) if not problems else "")
sys.exit(1 if problems else 0)
EOF
if [[ $status == 0 ]]; then
    if command -v gnuplot >/dev/null; then
        $py "$tmp/check.py" "$tmp/s.json" "$tmp/s.csv" "$tmp/s.png" "$rocking" "$rec" ||
            { echo "FAIL: the JSON, CSV and PNG check (above)"; fail=1; }
    else
        echo "FAIL: gnuplot is not installed (make deps): the PNG cannot be checked"; fail=1
    fi
fi

# The PNG drawn (issue 40), read from its gnuplot script (ROCKING_PLOT_SCRIPT) by
# tests/plot_check.py against the same run's JSON: the PNG's size for its panels, one
# y range for all, the data drawn the JSON's points with the overturned runs apart, the
# top axis's heights H = 2 R cos(alpha), R = 3 g/(4 p^2) at their p (recomputed there),
# and each marked block a line at its p labelled with its outcome.  Two blocks of one
# alpha (0.3x3 overturns, 0.4x4 does not: the premise, checked) and another alpha.
if command -v gnuplot >/dev/null; then
    ROCKING_PLOT_SCRIPT="$tmp/mark.gp" "${run[@]}" --alpha 0.2 --mark 0.3x3,0.4x4 --png "$tmp/mark.png" --json \
        >"$tmp/mark.json" 2>"$tmp/mark.err" || { echo "FAIL: --mark --png: $(head -3 "$tmp/mark.err")"; fail=1; }
    "${run[@]}" --alpha 0.2 --mark 0.3x3,0.4x4 --json >"$tmp/mark0.json" 2>&1
    same "--png changes no byte of the JSON" "$tmp/mark.json" "$tmp/mark0.json"
    if $py -c "import json, sys; m = json.load(open(sys.argv[1]))['marks']; sys.exit(sorted(x['overturns'] for x in m) != [False, True])" "$tmp/mark.json"
    then echo "ok: one marked block overturns, one does not"; else echo "FAIL: the marks' premise"; fail=1; fi
    $py "$(dirname "$0")/plot_check.py" spectrum "$tmp/mark.gp" "$tmp/mark.png" "$tmp/mark.json" || fail=1
fi

# A real record where Table 1's search met an island the grids step over:
# the output says so (docs/spectrum.md).
norcia="$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC"
if [[ -f "$norcia" ]]; then
    expect "Table 1's island named" 0 "p = 1.908956 rad/s (safe at 1.908809); it lies on an island narrower than the grids' step, found through its bracket" \
        "$rocking" spectrum "$norcia" --alpha 0.1
    # Marked blocks (issue 40): each one's outcome is simulate's at its own size
    # (the same default model), and the nearest overturning p above a safe one
    # is the start of a spectrum interval that simulate sees overturn, with the
    # height of eqs. 2 and 4 at it.
    "$rocking" spectrum "$norcia" --mark 1x4,0.6x4,0.25x3 --json >"$tmp/marks.json"
    for block in 1x4 0.6x4 0.25x3; do
        B=${block%x*} H=${block#*x}
        sim=$("$rocking" simulate --record "$norcia" --thickness "$B" --height "$H" --json |
              $py -c "import json,sys; print(json.load(sys.stdin)['collapse_overturning'])")
        mark=$($py -c "import json,sys; print([m for m in json.load(open(sys.argv[1]))['marks'] if m['built'] == sys.argv[2]][0]['overturns'])" "$tmp/marks.json" "$block")
        if [[ "$sim" == "$mark" ]]; then echo "ok: mark $block: overturns $mark, as simulate"; else echo "FAIL: mark $block: $mark, simulate $sim"; fail=1; fi
    done
    if $py - "$tmp/marks.json" "$rocking" "$norcia" <<'PY'
import json, math, subprocess, sys
d = json.load(open(sys.argv[1]))
checked, checked_inside = 0, False
for s in d["spectra"]:  # each interval's ends as heights, eqs. 2 and 4 inverted here
    for i in s["intervals"]:
        for end in ("from", "to"):
            H = 2 * 3 * 9.81 / (4 * i[end] ** 2) * math.cos(s["alpha"])
            assert abs(i["height_" + end] - H) < 1e-12 * H, (i, H)
for m in d["marks"]:
    sp = [s for s in d["spectra"] if s["alpha"] == m["alpha"]][0]
    B, H = (float(v) for v in m["built"].split("x"))
    assert abs(m["alpha"] - math.atan(B / H)) < 1e-15 and abs(m["height"] - H) < 1e-12 * H, m
    run = lambda p: json.loads(subprocess.run([sys.argv[2], "simulate", "--record", sys.argv[3], "--alpha", repr(m["alpha"]),
                                               "--p", repr(p), "--json"], capture_output=True, check=True).stdout)["collapse"]
    if m["in_set"]:
        # Inside an interval: the changes are its own ends, and just beyond them the blocks survive.
        inside = [i for i in sp["intervals"] if i["from"] <= m["p"] <= i["to"]][0]
        lo, hi = m["change_below"], m["change_above"]
        assert lo["found"] and lo["p"] == inside["from"] and not run(inside["lower"]["p_safe"]), (m, inside)
        if hi["found"]:
            assert hi["p"] == inside["to"] and not run(inside["upper"]["p_safe"]), (m, inside)
        checked_inside = True
        continue
    if not m["change_above"]["found"]:
        continue
    up = m["change_above"]
    assert up["p"] > m["p"] and any(i["from"] == up["p"] for i in sp["intervals"]), (m, sp["intervals"][:3])
    assert not any(i["from"] <= m["p"] <= i["to"] for i in sp["intervals"])
    R = 3 * 9.81 / (4 * up["p"] ** 2)
    assert abs(up["height"] - 2 * R * math.cos(m["alpha"])) < 1e-12 * up["height"], up
    assert run(up["p"] * (1 + 1e-9)) and not run(m["p"]), m
    checked += 1
assert checked >= 1, "no safe mark with an overturning p above it"
assert checked_inside, "no mark inside an interval"
PY
    then echo "ok: marks' nearest overturning p"; else echo "FAIL: marks' nearest overturning p"; fail=1; fi
    expect "mark grammar" 2 "--mark: each block is THICKNESSxHEIGHT in m" "$rocking" spectrum "$norcia" --mark 0.6
else
    echo "skipped: shared records folder absent ($norcia)"
fi

# --restitution (issue 40): stated in the model, and each boundary seen by simulate under it.
"$rocking" spectrum "$rec" --unit g --dt 0.01 --alpha 0.1 --points 40 --restitution 0.5 --json >"$tmp/e05.json"
if $py - "$tmp/e05.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert "restitution 0.5" in d["model"], d["model"]
PY
then echo "ok: spectrum --restitution stated"; else echo "FAIL: spectrum --restitution"; fail=1; fi

if [[ $fail != 0 ]]; then echo "spectrum_cli_test: FAILED"; exit 1; fi
echo "spectrum_cli_test: all passed"
