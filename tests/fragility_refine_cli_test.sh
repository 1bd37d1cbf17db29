#!/usr/bin/env bash
# rocking fragility --method refine (issue 39): on a synthetic record (rocking
# record synth, so that it runs without ../shared) the first overturning lies
# at or below the grid's first collapse, the JSON parses strictly and carries
# first_overturning, first_robust_collapse, bands, method, width, samples,
# with_margins and unguaranteed_from, the CSV has their columns, --jobs 1 and
# 2 and mpirun -np 2 give the same bytes, a rows file written by refine is
# read back to the same JSON and refused to a grid study, and --width
# without refine is refused (exit 2).  The MPI part is skipped, saying so,
# without MPI.
#
#   tests/fragility_refine_cli_test.sh ROCKING MPIEXEC   (MPIEXEC: "none" when built without MPI)
set -u
rocking=$(realpath "$1")
mpiexec="${2:-none}"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

"$rocking" record synth --stochastic 3 --dt 0.01 --duration 20 --output "$tmp/s3.txt" >/dev/null || exit 1
base=("$tmp/s3.txt" --unit m/s2 --alpha 0.1 --p 3 --q-max 2 --points 20 --quiet)
refine=("${base[@]}" --method refine --width 1e-3)
other=("${base[@]}" --method refine)  # for another --width

# ---- Refusals: exit 2, the option named.
check "--width without refine" "--width goes with --method refine" "$rocking" fragility "${base[@]}" --width 1e-3
status "--width without refine" 2 "$rocking" fragility "${base[@]}" --width 1e-3
status "--robust-width without refine" 2 "$rocking" fragility "${base[@]}" --robust-width 1e-2
check "--method unknown" "--method: grid or refine (got 'dense')" "$rocking" fragility "${base[@]}" --method dense
status "--method unknown" 2 "$rocking" fragility "${base[@]}" --method dense
check "--width too small" "--width: must be in [1e-7, 0.1]" "$rocking" fragility "${other[@]}" --width 1e-8
status "--width too large" 2 "$rocking" fragility "${other[@]}" --width 0.2

# ---- The JSON: strict, the fields there, the first overturning at or below the grid's first collapse.
"$rocking" fragility "${base[@]}" --json >"$tmp/grid.json" || { echo "FAIL: the grid run"; exit 1; }
"$rocking" fragility "${refine[@]}" --jobs 1 --json --output "$tmp/r.csv" >"$tmp/ref.json" || { echo "FAIL: the refine run"; exit 1; }
$py - "$tmp/grid.json" "$tmp/ref.json" <<'PY' && echo "ok: refine's JSON: strict, its fields, first overturning <= the grid's" || fail=1
import json, math, sys
def strict(path):
    def no_constant(name): raise ValueError("not JSON: " + name)
    return json.load(open(path), parse_constant=no_constant)
grid, ref = strict(sys.argv[1]), strict(sys.argv[2])
g, r = grid["blocks"][0]["records"][0], ref["blocks"][0]["records"][0]
assert "first_overturning" not in g and "method" not in grid["grid"], "the grid's JSON is unchanged"
assert ref["grid"]["method"] == "refine" and ref["grid"]["width"] == 1e-3 and ref["grid"]["robust_width"] == 5e-3
assert ref["grid"]["fit_capacity"] == "first_overturning"
assert "islands narrower than w may be missed" in ref["grid"]["refine_note"]
for key in ("first_overturning", "first_robust_collapse", "bands", "method", "samples", "with_margins", "unguaranteed_from"):
    assert key in r, key
f = r["first_overturning"]
assert f["collapsed"] and g["collapsed"]
assert f["q"] <= g["q"], (f["q"], g["q"])
assert f["q"] < 0.95 * g["q"], "the synthetic record's island below the grid's first collapse was not found"
assert f["q"] == r["q"] == r["intervals"][0]["from"], "the fit takes the first overturning"
assert f["bracket"]["q_safe"] < f["bracket"]["q_collapse"] == f["q"]
assert (f["bracket"]["q_collapse"] - f["bracket"]["q_safe"]) / f["q"] <= 1.01e-6
assert f["check"]["confirmation"] == "confirmed", f["check"]
rc = r["first_robust_collapse"]
assert rc["collapsed"] and f["q"] <= rc["q"] and math.isclose(rc["q"], g["q"], rel_tol=1e-5), (rc, g["q"])
assert len(r["bands"]) == 19 and all(0 <= b["share"] <= 1 and b["from"] < b["to"] for b in r["bands"])
assert any(b["share"] > 0 for b in r["bands"])
assert r["method"] == "refine" and r["samples"] > 0 and r["with_margins"] is True
assert r["unguaranteed_from"] is None  # q_max 2 below (pi/2 - 0.1)/0.1
PY
# The text: a line per record and the note with w and the guarantee.
check "the text's refine line" "first overturning q = 1.301275 in [" "$rocking" fragility "${refine[@]}"
check "the text's note" "every island and gap wider than w in ln q found, except above q = (pi/2 - alpha)/alpha where the margin's guarantee does not hold; islands narrower than w may be missed" \
    "$rocking" fragility "${refine[@]}"
check "the text says what the fits take" "three lognormal fits, each named by its capacity: the first overturning (conservative; the block's fit and empirical curve)" "$rocking" fragility "${refine[@]}"
# The CSV: the columns, and the grid's CSV without them.
check "the CSV's columns" "first_overturning,first_overturning_safe,first_overturning_collapse,first_overturning_check,first_robust_collapse,first_robust_collapsed,bands,samples,with_margins,unguaranteed_from" \
    grep -v '^#' "$tmp/r.csv"
"$rocking" fragility "${base[@]}" --output "$tmp/g.csv" >/dev/null
check_not "the grid's CSV has none of them" "first_overturning" cat "$tmp/g.csv"

# ---- The same bytes on 2 threads, from a rows file and its resume; a grid resume refused.
"$rocking" fragility "${refine[@]}" --jobs 2 --json >"$tmp/j2.json"
same "--jobs 2 = --jobs 1" "$tmp/j2.json" "$tmp/ref.json"
"$rocking" fragility "${refine[@]}" --jobs 2 --json --rows "$tmp/rows.csv" >"$tmp/rows.json"
same "with --rows = without" "$tmp/rows.json" "$tmp/ref.json"
"$rocking" fragility "${refine[@]}" --json --rows "$tmp/rows.csv" --resume >"$tmp/again.json"
same "the refine rows read back (--resume) = in memory" "$tmp/again.json" "$tmp/ref.json"
check "a grid resume of refine's rows is refused" "holds no results of this study" \
    "$rocking" fragility "${base[@]}" --json --rows "$tmp/rows.csv" --resume
check "a resume at another width is refused" "holds no results of this study" \
    "$rocking" fragility "${other[@]}" --width 2e-3 --json --rows "$tmp/rows.csv" --resume

# ---- Under mpirun: the bytes of the threaded run on 2 ranks.
if [[ $mpiexec == none || ! -x $mpiexec ]]; then
    echo "skipped: the MPI check (this rocking was built without MPI)"
    exit $fail
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
timeout 300 "$mpiexec" --oversubscribe -np 2 "$rocking" fragility "${refine[@]}" --json >"$tmp/np2.json" 2>"$tmp/np2.err"
code=$?
if [[ $code == 0 ]]; then echo "ok: -np 2 exits 0"; else echo "FAIL: -np 2 exits $code: $(head -3 "$tmp/np2.err")"; fail=1; fi
same "-np 2 = threads" "$tmp/np2.json" "$tmp/ref.json"
exit $fail
