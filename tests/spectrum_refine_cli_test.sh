#!/usr/bin/env bash
# rocking spectrum --method refine (issue 39): on a synthetic record (rocking
# record synth, so that it runs without ../shared), whose Table 1 p lies on
# an island that the grids step over and whose set has islands below it:
# the JSON parses strictly and carries the first overturning, the first
# robust collapse, the bands, the method and its counts; every grid point's
# outcome (from the grid method's own run) agrees with the refined set; each
# band's share is the intervals' cover of it; the first boundaries are seen
# by `rocking simulate`; the text and CSV say the same; --jobs 1 and 2, a
# rows file read back and mpirun -np 2 give the same bytes; --width without
# refine, a bad width and a grid resume of refine's rows are refused.
#
#   tests/spectrum_refine_cli_test.sh ROCKING MPIEXEC   (MPIEXEC: "none" when built without MPI)
set -u
rocking=$(realpath "$1")
mpiexec="${2:-none}"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
same_whole() {  # as check_lib's same, and the reference not empty (two failed runs agree on nothing)
    if [[ ! -s $3 ]]; then echo "FAIL: $1: $3 is empty"; fail=1; else same "$@"; fi
}

"$rocking" record synth --stochastic 3 --dt 0.01 --duration 20 --output "$tmp/s3.txt" >/dev/null || exit 1
common=("$tmp/s3.txt" --unit m/s2 --p-min 1 --p-max 6 --points 20 --quiet --method)
base=("${common[@]}" grid --alpha 0.1)
refine=("${common[@]}" refine --width 1e-3 --alpha 0.1)
other=("${common[@]}" refine --alpha 0.1)  # for another --width
two=("${common[@]}" refine --width 1e-3 --alpha 0.1,0.15)

# ---- Refusals: exit 2, the option named.
check "--width without refine" "--width goes with --method refine" "$rocking" spectrum "${base[@]}" --width 1e-3
status "--width without refine" 2 "$rocking" spectrum "${base[@]}" --width 1e-3
status "--robust-width without refine" 2 "$rocking" spectrum "${base[@]}" --robust-width 1e-2
check "--method unknown" "--method: grid or refine (got 'dense')" "$rocking" spectrum "${common[@]}" dense --alpha 0.1
check "--width too large" "--width: must be in [1e-7, 0.1] (in ln p)" "$rocking" spectrum "${other[@]}" --width 0.2
status "--width too large" 2 "$rocking" spectrum "${other[@]}" --width 0.2
check "--robust-width 0" "--robust-width: must be in [1e-7, 1] (in ln p)" "$rocking" spectrum "${refine[@]}" --robust-width 0

# ---- The JSON against the grid's own run and simulate.
"$rocking" spectrum "${base[@]}" --json >"$tmp/grid.json" || { echo "FAIL: the grid run"; exit 1; }
"$rocking" spectrum "${refine[@]}" --jobs 1 --json --output "$tmp/r.csv" >"$tmp/ref.json" || { echo "FAIL: the refine run"; exit 1; }
$py - "$rocking" "$tmp/s3.txt" "$tmp/grid.json" "$tmp/ref.json" <<'PY' && echo "ok: refine's JSON: strict, its fields, the grid's outcomes, the bands, simulate" || fail=1
import json, math, subprocess, sys
rocking, rec = sys.argv[1], sys.argv[2]
def strict(path):
    def no_constant(name): raise ValueError("not JSON: " + name)
    return json.load(open(path), parse_constant=no_constant)
grid, ref = strict(sys.argv[3]), strict(sys.argv[4])
g, r = grid["spectra"][0], ref["spectra"][0]
assert "first_overturning" not in g and "method" not in grid, "the grid's JSON is unchanged"
assert ref["method"] == "refine" and ref["width"] == 1e-3 and ref["robust_width"] == 5e-3
assert ref["grid"]["offset_grid"] is False and math.isclose(ref["grid"]["islands_missed_below_ratio"], math.exp(1e-3))
assert "islands narrower than w may be missed" in ref["refine_note"]
for key in ("first_overturning", "first_robust_collapse", "bands", "samples", "accepted", "at_width", "with_margins", "unguaranteed_from"):
    assert key in r, key
ivs = r["intervals"]
assert len(ivs) > 50, len(ivs)
for a, b in zip(ivs, ivs[1:]):
    assert a["from"] < a["to"] < b["from"] < b["to"], (a, b)
# Every point of the grid method's two grids and Table 1's bracket: its outcome is the refined set's.
def inside(p):
    return any(iv["from"] <= p <= iv["to"] for iv in ivs)
def near_boundary(p):
    return any(abs(p - e) <= 2e-6 * p for iv in ivs for e in (iv["from"], iv["to"]))
wrong = [pt["p"] for pt in g["points"] if pt["overturning"] != inside(pt["p"]) and not near_boundary(pt["p"])]
assert not wrong, "grid points whose outcome the refined set contradicts: %r" % wrong[:5]
# The grid's first collapse is Table 1's p, on an island the grids stepped over; refine starts below it.
t1 = r["table1"]
assert t1["found"] and g["intervals"][0]["from"] <= t1["p"] <= g["intervals"][0]["to"]
f = r["first_overturning"]
assert f["found"] and f["p"] == ivs[0]["from"] and f["p"] < 0.85 * g["intervals"][0]["from"], (f, g["intervals"][0])
assert f["boundary"]["confirmation"] == "confirmed" and f["boundary"]["p_safe"] < f["boundary"]["p_collapse"] == f["p"]
rc = r["first_robust_collapse"]
first_wide = next(iv["from"] for iv in ivs if math.log(iv["to"] / iv["from"]) > 5e-3)
assert rc["found"] and rc["p"] == first_wide, (rc, first_wide)
# The bands: the main grid's 19 steps, each share the intervals' cover of it in ln p.
assert len(r["bands"]) == 19 and r["bands"][0]["from"] == 1 and r["bands"][-1]["to"] == 6
for b in r["bands"]:
    cover = sum(max(0.0, math.log(min(b["to"], iv["to"]) / max(b["from"], iv["from"]))) for iv in ivs)
    assert math.isclose(b["share"], cover / math.log(b["to"] / b["from"]), rel_tol=1e-9, abs_tol=1e-12), (b, cover)
assert r["with_margins"] is True and r["samples"] > 0 and r["accepted"] > 0
assert r["unguaranteed_from"] is None  # PGA 0.14 g: q 1.4 below (pi/2 - 0.1)/0.1
# The first five intervals' boundaries as `rocking simulate` sees them.
def overturns(p):
    out = subprocess.run([rocking, "simulate", "--record", rec, "--unit", "m/s2", "--alpha", "0.1", "--p", repr(p),
                          "--restitution", "housner", "--criterion", "overturning", "--json"], capture_output=True, check=True).stdout
    return json.loads(out)["collapse"]
for iv in ivs[:5]:
    for side in ("lower", "upper"):
        b = iv[side]
        assert overturns(b["p_collapse"]) and not overturns(b["p_safe"]), (side, b)
PY
# The text: the first intervals, the rest counted, the three numbers.
check "the text's cut" "more intervals (--json or --output lists every one)" "$rocking" spectrum "${refine[@]}"
check "the text's first overturning" "first overturning: p = " "$rocking" spectrum "${refine[@]}"
check "the text's Table 1 remark" "the spectrum overturns the block from p = " "$rocking" spectrum "${refine[@]}"
check "the CSV's first overturning" "# first overturning at alpha 0.1: " cat "$tmp/r.csv"
check "the CSV's shares" "# overturned share at alpha 0.1: [" cat "$tmp/r.csv"
"$rocking" spectrum "${base[@]}" --output "$tmp/g.csv" >/dev/null
check_not "the grid's CSV has none of them" "first overturning" cat "$tmp/g.csv"

# ---- The same bytes on 2 threads, from a rows file and its resume; a grid resume refused.
"$rocking" spectrum "${two[@]}" --jobs 1 --json >"$tmp/two1.json"
"$rocking" spectrum "${two[@]}" --jobs 2 --json >"$tmp/two2.json"
same_whole "--jobs 2 = --jobs 1" "$tmp/two2.json" "$tmp/two1.json"
"$rocking" spectrum "${refine[@]}" --json --rows "$tmp/rows.csv" >"$tmp/rows.json"
same_whole "with --rows = without" "$tmp/rows.json" "$tmp/ref.json"
"$rocking" spectrum "${refine[@]}" --json --rows "$tmp/rows.csv" --resume >"$tmp/again.json"
same_whole "the refine rows read back (--resume) = in memory" "$tmp/again.json" "$tmp/ref.json"
check "a grid resume of refine's rows is refused" "holds no results of this study" \
    "$rocking" spectrum "${base[@]}" --json --rows "$tmp/rows.csv" --resume
check "a resume at another width is refused" "holds no results of this study" \
    "$rocking" spectrum "${other[@]}" --width 2e-3 --json --rows "$tmp/rows.csv" --resume

# ---- Under mpirun: the bytes of the threaded run on 2 ranks.
if [[ $mpiexec == none || ! -x $mpiexec ]]; then
    echo "skipped: the MPI check (this rocking was built without MPI)"
    exit $fail
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
timeout 300 "$mpiexec" --oversubscribe -np 2 "$rocking" spectrum "${two[@]}" --json >"$tmp/np2.json" 2>"$tmp/np2.err"
code=$?
if [[ $code == 0 ]]; then echo "ok: -np 2 exits 0"; else echo "FAIL: -np 2 exits $code: $(head -3 "$tmp/np2.err")"; fail=1; fi
same_whole "-np 2 = threads" "$tmp/np2.json" "$tmp/two1.json"
exit $fail
