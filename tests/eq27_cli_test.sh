#!/usr/bin/env bash
# rocking eq27 on the command line: errors naming the option or file with
# their exit codes, strict JSON whose shares add up from its map and its
# records, the CSV's notes, each verdict recomputed through three other
# subcommands (fragility's collapse q, record info's to_k, q's eq. 27), and
# the bootstrap over records recomputed in Python from the JSON's per-record
# counts (GSL's mt19937 as expected/fragility/independent.py rebuilds it).
# The study's answers against known ones are the unit tests'
# (tests/test_eq27_at_scale.cpp).
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
check "alpha range"       "--alpha: each must be in (0, pi/4) (got 0.8)"  "$rocking" eq27 x --alpha 0.8
check "p-min range"       "--p-min: must be in (0.01, 1000] rad/s"       "$rocking" eq27 x --p-min 0
check "p-max below p-min" "--p-max: must not be below --p-min (2)"       "$rocking" eq27 x --p-min 2 --p-max 1
status "p-max below p-min" 2                                             "$rocking" eq27 x --p-min 2 --p-max 1
check "p-points range"    "--p-points: must be a whole number from 1 to 1000 (got 0)" "$rocking" eq27 x --p-points 0
check "q-max range"       "--q-max: must be in (1, 10000]"               "$rocking" eq27 x --q-max 1
check "unknown option"    "unknown option '--p'"                         "$rocking" eq27 x --p 1
check "seed alone"        "--seed goes with --bootstrap"                 "$rocking" eq27 x --seed 3
status "seed alone"       2                                              "$rocking" eq27 x --seed 3
check "bootstrap, no seed" "--bootstrap needs --seed"                    "$rocking" eq27 x --bootstrap 100
check "bootstrap of 1"    "--bootstrap: must be 0 (none) or from 2 to 100000 resamples (got 1)" "$rocking" eq27 x --bootstrap 1 --seed 3
check "seed range"        "--seed: the seed must be a whole number"      "$rocking" eq27 x --bootstrap 100 --seed 0
check "jobs range"        "--jobs: must be a whole number from 1 to 4096 (got 5000)" "$rocking" eq27 x --jobs 5000
# Bad files: exit 1, the file named.
check "missing file"      "no-such-file"                                 "$rocking" eq27 "$tmp/sine1.txt" no-such-file --unit g --dt 0.01
status "missing file"     1                                              "$rocking" eq27 "$tmp/sine1.txt" no-such-file --unit g --dt 0.01
status "output in no folder" 1                                           "${run[@]}" "${small[@]}" --output "$tmp/no/dir/m.csv"
# The plot's file refused before the study runs (the record is not read: it does not exist).
check "png in no folder"  "--png: $tmp/no/dir/m.png"                     "$rocking" eq27 no-such-file --png "$tmp/no/dir/m.png"
status "png in no folder" 1                                              "$rocking" eq27 no-such-file --png "$tmp/no/dir/m.png"
check "png without gnuplot" "--png $tmp/ng.png: gnuplot is not installed" env PATH=/nonexistent "$rocking" eq27 no-such-file --png "$tmp/ng.png"
status "png without gnuplot" 1                                           env PATH=/nonexistent "$rocking" eq27 no-such-file --png "$tmp/ng.png"

# Text: the shares, the censoring rule and the conservative list.
check "text share"        "to_5 "                                        "${run[@]}" "${small[@]}"
check "text censored"     "counted as conservative"                      "${run[@]}" "${small[@]}"
check "text conservative" "conservative on every block and record:"      "${run[@]}" "${small[@]}"
check "text no bootstrap" "bootstrap over records not run (--bootstrap K --seed S)" "${run[@]}" "${small[@]}"
check "text Wilson label" "95 % Wilson (independent cases)"              "${run[@]}" "${small[@]}"
check "text bootstrap"    "interval: 90 % bootstrap over records (200 resamples, seed 7)" \
                                                                         "${run[@]}" "${small[@]}" --bootstrap 200 --seed 7
check "text records"      "records with any"                             "${run[@]}" "${small[@]}" --bootstrap 200 --seed 7

# JSON: strict (no NaN or Infinity); each share is its map's sum over the
# blocks and its records' sum, the Wilson interval holds it; the bootstrap
# recomputed from the per-record counts, the same with the same seed, absent
# (null, and said so) without --bootstrap; then every verdict of the block
# (0.1, 2) recomputed from fragility --json, record info --json and q --json.
"${run[@]}" "${small[@]}" --json --bootstrap 300 --seed 11 >"$tmp/e.json"
"${run[@]}" "${small[@]}" --json --bootstrap 300 --seed 11 >"$tmp/e2.json"
"${run[@]}" "${small[@]}" --json >"$tmp/e0.json"
if cmp -s "$tmp/e.json" "$tmp/e2.json"; then echo "ok: same seed, same output"; else echo "FAIL: same seed, other output"; fail=1; fi
# The threads change the time, never a byte.
"${run[@]}" "${small[@]}" --json --bootstrap 300 --seed 11 --jobs 1 >"$tmp/e1.json"
"${run[@]}" "${small[@]}" --json --bootstrap 300 --seed 11 --jobs 3 >"$tmp/e3.json"
if cmp -s "$tmp/e1.json" "$tmp/e3.json"; then echo "ok: --jobs 1 and 3 identical"; else echo "FAIL: --jobs 1 and 3 differ"; fail=1; fi
"$rocking" fragility "${files[@]}" --unit g --dt 0.01 --alpha 0.1 --p 2 --json >"$tmp/f.json"
for f in "${files[@]}"; do "$rocking" record info "$f" --unit g --dt 0.01 --json; done >"$tmp/info.jsonl"
if $py - "$tmp/e.json" "$tmp/f.json" "$tmp/info.jsonl" "$rocking" "$tmp/e0.json" "$(dirname "$0")/../expected/fragility" <<'PY'
import json, subprocess, sys
sys.path.insert(0, sys.argv[6])
from independent import GslMt19937, percentile
def bad(c): raise ValueError(c)
e = json.load(open(sys.argv[1]), parse_constant=bad)
e0 = json.load(open(sys.argv[5]), parse_constant=bad)
assert e["cases"] == 18 and len(e["map"]) == 6 and e["records"] == 3, e
assert e["bootstrap_run"] and e["bootstrap"] == {"over": "records", "resamples": 300, "seed": 11, "level": 0.9}, e
assert e0["bootstrap_run"] is False and e0["bootstrap"] is None and "--bootstrap" in e0["bootstrap_note"], e0
assert e["wilson"]["level"] == 0.95 and "independent" in e["wilson"]["note"], e
counts = [r["non_conservative"] for r in e["by_record"]]
assert [r["file"] for r in e["by_record"]] == e["files"]
# The bootstrap: 300 resamples of the 3 records, each bringing its 6 blocks.
rng, boot = GslMt19937(11), [[] for _ in range(11)]
for _ in range(300):
    drawn = [counts[rng.uniform_int(3)] for _ in range(3)]
    for k in range(11):
        boot[k].append(sum(c[k] for c in drawn) / 18)
for k, s in enumerate(e["shares"]):
    assert s["k"] == k + 1 and s["cases"] == 18 and s["records"] == 3
    assert s["non_conservative"] == sum(m["non_conservative"][k] for m in e["map"]), s
    assert s["non_conservative"] == sum(c[k] for c in counts), s
    assert s["records_with_any"] == sum(c[k] > 0 for c in counts), s
    assert s["wilson"][0] <= s["share"] <= s["wilson"][1], s
    t = (1 - 0.9) / 2
    want = [percentile(boot[k], t), percentile(boot[k], 1 - t)]
    assert all(abs(a - b) <= 1e-15 for a, b in zip(s["bootstrap"], want)), (s, want)
    assert e0["shares"][k]["bootstrap"] is None and e0["shares"][k]["wilson"] == s["wilson"], e0["shares"][k]
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

# --method refine (issue 39): the shares under each capacity.  The options
# refused as fragility refuses them; --method grid is today's output, byte for
# byte; at --width 1e-3 every verdict of every block recomputed under both
# capacities from fragility --method refine's first overturning and first
# robust collapse, the first overturning's share never below the robust
# one's and above it for some k (the premise: the capacities differ here), and
# the robust bootstrap recomputed from its per-record counts with the same
# seed as the first overturning's (the same draws).
check "method unknown"    "--method: grid or refine (got 'dense')"       "${run[@]}" "${small[@]}" --method dense
status "method unknown"   2                                              "${run[@]}" "${small[@]}" --method dense
check "width with grid"   "--width goes with --method refine"            "${run[@]}" "${small[@]}" --width 1e-3
check "robust width with grid" "--robust-width goes with --method refine" "${run[@]}" "${small[@]}" --method grid --robust-width 1e-2
check "width range"       "--width: must be in [1e-7, 0.1] (in ln q)"    "${run[@]}" "${small[@]}" --method refine --width 0.2
check "robust width range" "--robust-width: must be in [1e-7, 1] (in ln q)" "${run[@]}" "${small[@]}" --method refine --robust-width 0
status "width range"      2                                              "${run[@]}" "${small[@]}" --method refine --width 0.2
"${run[@]}" "${small[@]}" --method grid --json --bootstrap 300 --seed 11 >"$tmp/eg.json"
if cmp -s "$tmp/e.json" "$tmp/eg.json"; then echo "ok: --method grid is the default's bytes"; else echo "FAIL: --method grid differs from the default"; fail=1; fi
refine=(--method refine --width 1e-3)
"${run[@]}" "${small[@]}" "${refine[@]}" --json --bootstrap 300 --seed 11 >"$tmp/r.json"
"${run[@]}" "${small[@]}" "${refine[@]}" --bootstrap 300 --seed 11 >"$tmp/r.txt"
"${run[@]}" "${small[@]}" "${refine[@]}" --bootstrap 300 --seed 11 --output "$tmp/r.csv" >/dev/null
"$rocking" fragility "${files[@]}" --unit g --dt 0.01 --alpha 0.1,0.2 --p 1,2,4 "${refine[@]}" --json >"$tmp/rf.json"
for text in "refine: w = 0.001 in ln q" "capacity: first overturning: the lowest q" "capacity: first robust collapse: the start" \
            "cases censored (no robust collapse up to q_max = 20)"; do
    if grep -qF "$text" "$tmp/r.txt"; then echo "ok: refine text: $text"; else echo "FAIL: refine text: $text"; fail=1; fi
done
for note in "# refine: w = 0.001" "# capacity: first overturning" "# robust capacity: first robust collapse" \
            "# robust censored: " "# robust share to_5: " "robust_censored,robust_nc_to1,"; do
    if grep -qF "$note" "$tmp/r.csv"; then echo "ok: refine csv: $note"; else echo "FAIL: refine csv: $note"; fail=1; fi
done
if $py - "$tmp/r.json" "$tmp/rf.json" "$tmp/info.jsonl" "$rocking" "$(dirname "$0")/../expected/fragility" <<'PY'
import json, subprocess, sys
sys.path.insert(0, sys.argv[5])
from independent import GslMt19937, percentile
def bad(c): raise ValueError(c)
e = json.load(open(sys.argv[1]), parse_constant=bad)
frag = json.load(open(sys.argv[2]), parse_constant=bad)["blocks"]
infos = [json.loads(line) for line in open(sys.argv[3])]
assert e["method"] == "refine" and e["width"] == 0.001 and e["robust_width"] == 0.005, e
assert e["capacity"] == "first_overturning" and "some q below" in e["capacity_note"], e
robust = e["first_robust_collapse"]
assert "robust width" in robust["capacity_note"], robust
q27 = {}
def eq27(x):
    if x not in q27:
        q27[x] = json.loads(subprocess.run([sys.argv[4], "q", "--case", "2", "--pulses", "6", "--x", repr(x), "--json"],
                                           capture_output=True, text=True, check=True).stdout)["q"]
    return q27[x]
differ = 0
for study, key in ((e, "first_overturning"), (robust, "first_robust_collapse")):
    assert len(study["map"]) == 6
    for cell in study["map"]:
        block = next(b for b in frag if b["alpha"] == cell["alpha"] and b["p"] == cell["p"])
        censored = sum(not r[key]["collapsed"] for r in block["records"])
        assert cell["censored"] == censored, (key, cell, censored)
        for k in range(11):
            count = sum(r[key]["collapsed"] and r[key]["q"] < eq27(cell["p"] * info["to"][k])
                        for r, info in zip(block["records"], infos))
            assert cell["non_conservative"][k] == count, (key, k + 1, cell, count)
    for k, s in enumerate(study["shares"]):
        assert s["non_conservative"] == sum(m["non_conservative"][k] for m in study["map"]), (key, s)
assert robust["censored"] == sum(m["censored"] for m in robust["map"])
for f, r in zip(e["shares"], robust["shares"]):
    assert f["non_conservative"] >= r["non_conservative"], (f, r)
    differ += f["non_conservative"] > r["non_conservative"]
assert differ > 0, "the premise: the two capacities give other verdicts on these records"
# Both bootstraps from one seed: the same draws of the 3 records.
for study in (e, robust):
    counts = [r["non_conservative"] for r in study["by_record"]]
    rng, boot = GslMt19937(11), [[] for _ in range(11)]
    for _ in range(300):
        drawn = [counts[rng.uniform_int(3)] for _ in range(3)]
        for k in range(11):
            boot[k].append(sum(c[k] for c in drawn) / 18)
    for k, s in enumerate(study["shares"]):
        want = [percentile(boot[k], 0.05), percentile(boot[k], 0.95)]
        assert all(abs(a - b) <= 1e-15 for a, b in zip(s["bootstrap"], want)), (s, want)
PY
then echo "ok: refine json"; else echo "FAIL: refine json"; fail=1; fi

# The PNG (issue 40), read by tests/plot_check.py against the same run's JSON: its size;
# the shares and both intervals drawn per to_k the JSON's (both capacities under refine);
# every case at to_5 drawn at x = p to_5 (record info's to_5, recomputed), its verdict
# flagged as its capacity q below eq. 27's, eq. 27's q that of rocking q at three cases,
# as many non-conservative and censored as the JSON counts.  The JSON unchanged by --png.
if command -v gnuplot >/dev/null; then
    ROCKING_PLOT_SCRIPT="$tmp/e.gp" "${run[@]}" "${small[@]}" --json --bootstrap 300 --seed 11 --png "$tmp/e.png" >"$tmp/ep.json"
    same "--png changes no byte of the JSON" "$tmp/ep.json" "$tmp/e.json"
    $py "$(dirname "$0")/plot_check.py" eq27 "$tmp/e.gp" "$tmp/e.png" "$tmp/ep.json" "$tmp/info.jsonl" "$rocking" || fail=1
    ROCKING_PLOT_SCRIPT="$tmp/r.gp" "${run[@]}" "${small[@]}" "${refine[@]}" --json --bootstrap 300 --seed 11 --png "$tmp/r.png" >"$tmp/rp.json"
    same "--png changes no byte of the refine JSON" "$tmp/rp.json" "$tmp/r.json"
    $py "$(dirname "$0")/plot_check.py" eq27 "$tmp/r.gp" "$tmp/r.png" "$tmp/rp.json" "$tmp/info.jsonl" "$rocking" || fail=1
else
    echo "FAIL: gnuplot is not installed (make deps): the PNG cannot be checked"; fail=1
fi

# CSV: one row per block, the notes naming model, solver, inputs, grids and the rule.
"${run[@]}" "${small[@]}" --output "$tmp/m.csv" --bootstrap 50 --seed 2 >/dev/null
for note in "# command: rocking eq27" "# model: linearised" "# solver: exact" "# inputs: $tmp/sine0.7.txt" \
            "# grid: alpha 0.1, 0.2; p: 3 log-spaced from 1 to 4 rad/s" "# ida: " "# verdict: " \
            "# intervals: 90 % bootstrap over records (50 resamples, seed 2); the Wilson interval takes every" \
            "# share to_5: " "95 % Wilson, cases taken as independent [" "records non-conservative on any block "; do
    if grep -qF "$note" "$tmp/m.csv"; then echo "ok: note $note"; else echo "FAIL: note $note"; fail=1; fi
done
rows=$(grep -vc '^#' "$tmp/m.csv")
if [[ $rows == 7 ]]; then echo "ok: csv rows"; else echo "FAIL: csv rows: $rows, wanted 7 (header and 6 blocks)"; fail=1; fi
# Repeats: an alpha or a record given twice would count its cases twice (0/4 read as 0/12,
# the Wilson interval narrowed): refused, exit 2, naming the repeat, whatever the spelling
# or the path (the same file, ./ or a link to it, a hard link, a copy: the same samples).
one=(--p-points 1 --p-min 2 --q-max 3)
check "alpha twice"       "--alpha: 0.1 is given twice (values 1 and 3)"  "${run[@]}" --alpha 0.1,0.2,0.1 "${one[@]}"
check "alpha twice, spelt otherwise" "--alpha: 0.1 is given twice"         "${run[@]}" --alpha 0.1,0.10 "${one[@]}"
status "alpha twice"      2                                               "${run[@]}" --alpha 0.1,0.1 "${one[@]}"
ln -s "$tmp/sine1.txt" "$tmp/link.txt"
ln "$tmp/sine1.txt" "$tmp/hard.txt"
cp "$tmp/sine1.txt" "$tmp/copy.txt"
for again in "$tmp/sine1.txt" "$tmp/./sine1.txt" "$tmp/link.txt" "$tmp/hard.txt" "$tmp/copy.txt"; do
    check "record twice: $(basename "$again")" "$again: the same record as $tmp/sine1.txt (records 2 and 4" \
        "$rocking" eq27 "$tmp/sine0.7.txt" "$tmp/sine1.txt" "$tmp/sine1.5.txt" "$again" --unit g --dt 0.01 --alpha 0.1 "${one[@]}"
    status "record twice: $(basename "$again")" 2 \
        "$rocking" eq27 "$tmp/sine0.7.txt" "$tmp/sine1.txt" "$again" --unit g --dt 0.01 --alpha 0.1 "${one[@]}"
done
# The same samples at another step are another record (two-column files: time, acceleration).
awk '{printf "%.2f %s\n", NR * 0.01, $1}' "$tmp/sine1.txt" >"$tmp/t1.txt"
awk '{printf "%.2f %s\n", NR * 0.02, $1}' "$tmp/sine1.txt" >"$tmp/t2.txt"
status "same samples, other step" 0 "$rocking" eq27 "$tmp/t1.txt" "$tmp/t2.txt" --unit g --alpha 0.1 "${one[@]}"
# --p-points 1 is one p: --p-min alone; a range with it was silently cut to its start.
check "one point, default range" "--p-points 1: one p, but the range runs from 0.5 to 10 rad/s" \
    "${run[@]}" --alpha 0.1 --p-points 1
check "one point, a range" "--p-points 1: one p, but the range runs from 1 to 4 rad/s" \
    "${run[@]}" --alpha 0.1 --p-points 1 --p-min 1 --p-max 4
status "one point, a range" 2 "${run[@]}" --alpha 0.1 --p-points 1 --p-min 1 --p-max 4
check "one point at --p-min" "p: 1 log-spaced from 2 to 2 rad/s" "${run[@]}" --alpha 0.1 --p-points 1 --p-min 2 --q-max 3
check "one point, --p-max the same" "p: 1 log-spaced from 2 to 2 rad/s" \
    "${run[@]}" --alpha 0.1 --p-points 1 --p-min 2 --p-max 2 --q-max 3
check "a range too narrow for its points" "--p-points: 1000 points from 1 to 1 rad/s repeat p = 1" \
    "${run[@]}" --alpha 0.1 --p-points 1000 --p-min 1 --p-max 1.0000000000001
status "a range too narrow for its points" 2 "${run[@]}" --alpha 0.1 --p-points 1000 --p-min 1 --p-max 1.0000000000001
# The engine's switches: --quiet taken, --resume refused (no rows file).
status "--quiet"          0 "${run[@]}" --alpha 0.1 "${one[@]}" --quiet
check "--resume"          "--resume: eq27 keeps no rows file to resume from" "${run[@]}" --resume
status "--resume"         2 "${run[@]}" --resume
exit $fail
