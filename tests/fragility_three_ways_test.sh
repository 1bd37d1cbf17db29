#!/usr/bin/env bash
# rocking fragility --method refine fits the capacity three ways (issue 39, item 3): on three
# synthetic records (rocking record synth, so that it runs without ../shared) the text names the
# three fits, the JSON carries them under "fits" with the stripes, the CSV's notes hold them, and
# each is checked apart: the first overturning's fit is the block's "fit"; the first robust
# collapse's fit and bootstrap are refitted by expected/fragility/independent.py's censored fit
# and its mt19937 bootstrap (pure Python, the records drawn in the order of their sha256); the
# stripes are recomputed from each record's intervals
# and fitted, with their bootstrap, by tools/stripe_mle.py (mpmath); the stripes' shares are the
# means of the records' bands.  One record: a rectangular pulse has no fit of any kind, each saying
# why.  The grid method's JSON has none of it.
#
#   tests/fragility_three_ways_test.sh ROCKING
set -u
rocking=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
py=/usr/bin/python3
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

for seed in 1 2 3; do
    "$rocking" record synth --stochastic $seed --dt 0.01 --duration 20 --output "$tmp/s$seed.txt" >/dev/null || exit 1
done
base=(--unit m/s2 --alpha 0.1 --p 3 --q-max 2.5 --points 20 --quiet)
refine=("$tmp/s1.txt" "$tmp/s2.txt" "$tmp/s3.txt" "${base[@]}" --method refine --width 1e-3 --bootstrap 20 --seed 5)

"$rocking" fragility "${refine[@]}" >"$tmp/text" || { echo "FAIL: the refine run"; exit 1; }
"$rocking" fragility "${refine[@]}" --json --output "$tmp/out.csv" >"$tmp/ref.json" || { echo "FAIL: the JSON run"; exit 1; }
check "the text: the first overturning's fit" "fit on the first overturning (conservative): lognormal median q = " cat "$tmp/text"
check "the text: the robust collapse's fit" "fit on the first robust collapse: lognormal median q = " cat "$tmp/text"
check "the text: the stripe fit" "multiple-stripe fit: lognormal median q = " cat "$tmp/text"
check "the text: the stripe fit's bootstrap" "(19 stripes x 3 records); 90 % bootstrap (20 resamples, seed 5)" cat "$tmp/text"
check "the text: the stripes in brief" "stripes: 19 (mean overturned share above 0 from q = " cat "$tmp/text"
check "the note: the three capacities" "three lognormal fits, each named by its capacity" cat "$tmp/text"
check "the CSV: the robust fit" "first robust collapse fit at alpha 0.1, p 3" cat "$tmp/out.csv"
check "the CSV: the stripe fit" "stripe fit at alpha 0.1, p 3" cat "$tmp/out.csv"
check "the CSV: the stripes" "stripes at alpha 0.1, p 3" cat "$tmp/out.csv"

$py "$here/../tools/stripe_mle.py" --fragility "$tmp/ref.json" >"$tmp/stripes.jsonl" || { echo "FAIL: stripe_mle.py"; fail=1; }
$py - "$tmp/ref.json" "$tmp/stripes.jsonl" "$here/../expected/fragility" "$here/../tools" <<'PY' \
    && echo "ok: the three fits against their independent refits" || fail=1
import json, math, sys
sys.path[:0] = [sys.argv[3], sys.argv[4]]
import independent  # expected/fragility/independent.py: the censored fit and its bootstrap
def strict(path):
    def no_constant(name): raise ValueError("not JSON: " + name)
    return json.load(open(path), parse_constant=no_constant)
doc = strict(sys.argv[1])
tool = json.loads(open(sys.argv[2]).readline())
g = doc["grid"]
assert math.isclose(g["stripe_half_width"], math.log(g["q_max"] / g["q_min"]) / (2 * (g["points"] - 1)), rel_tol=1e-15)
b = doc["blocks"][0]
fits = b["fits"]
assert sorted(fits) == ["first_overturning", "first_robust_collapse", "stripes"], sorted(fits)
# (a) the block's fit, on the first overturnings.
assert fits["first_overturning"] == {"fit": b["fit"], "no_fit": b["no_fit"]}
assert [r["q"] for r in b["records"]] == [r["first_overturning"]["q"] for r in b["records"]]
# (b) the first robust collapses: the censored fit and bootstrap of independent.py.
points = [(r["first_robust_collapse"]["q"], r["first_robust_collapse"]["collapsed"]) for r in b["records"]]
rob = fits["first_robust_collapse"]["fit"]
assert rob and fits["first_robust_collapse"]["no_fit"] is None, fits["first_robust_collapse"]
m, s = independent.fit(points)
assert math.isclose(rob["median"], m, rel_tol=1e-9) and math.isclose(rob["beta"], s, rel_tol=1e-9), (rob, m, s)
assert (rob["collapsed"], rob["censored"]) == (sum(c for _, c in points), sum(not c for _, c in points))
bt = rob["bootstrap"]
# drawn in the order of the records' sha256 (issue 40)
drawn = independent.in_draw_order(points, [r["sha256"] for r in b["records"]])
lo_m, hi_m, lo_b, hi_b = independent.bootstrap(drawn, bt["resamples"], bt["seed"], bt["level"])
for got, want in zip(bt["median"] + bt["beta"], (lo_m, hi_m, lo_b, hi_b)):
    assert math.isclose(got, want, rel_tol=1e-9), (bt, (lo_m, hi_m, lo_b, hi_b))
assert (bt["resamples"], bt["seed"], bt["level"]) == (20, 5, 0.9)
# (c) the stripes: tool's shares from the intervals, its fit and bootstrap.
st = fits["stripes"]["fit"]
assert st and fits["stripes"]["no_fit"] is None, fits["stripes"]
assert (st["stripes"], st["records"]) == (19, 3)
assert len(b["stripes"]) == len(tool["stripes"]) == 19
for mine, theirs in zip(b["stripes"], tool["stripes"]):
    assert mine["q"] == theirs["q"] and mine["from"] == theirs["from"] and mine["to"] == theirs["to"], (mine, theirs)
    assert abs(mine["share"] - theirs["share"]) <= 1e-14, (mine, theirs)
for j, stripe in enumerate(b["stripes"]):  # the mean of the records' bands
    bands = [r["bands"][j] for r in b["records"]]
    assert all(x["from"] == stripe["from"] and x["to"] == stripe["to"] for x in bands)
    assert abs(sum(x["share"] for x in bands) / 3 - stripe["share"]) <= 1e-15, (j, stripe, bands)
assert 0 < sum(s["share"] for s in b["stripes"]) < 19
t = tool["fit"]
assert math.isclose(st["median"], t["median"], rel_tol=1e-11) and math.isclose(st["beta"], t["beta"], rel_tol=1e-11), (st, t)
for k in ("median", "beta"):
    for got, want in zip(st["bootstrap"][k], t["bootstrap"][k]):
        assert math.isclose(got, want, rel_tol=1e-10), (k, st["bootstrap"], t["bootstrap"])
assert (st["bootstrap"]["resamples"], st["bootstrap"]["seed"]) == (20, 5)
PY

# One record.  A rectangular pulse (0.15 g for 0.8 s) overturns the block for every q above
# q* = 1/(1 - e^{-p d}) = 1.0998: its first overturning and robust collapse are one collapse with
# nothing censored above, its shares step from 0 to 1: no fit, and each says why.  A stochastic
# record's set is a dust of islands: no capacity fit, but its shares rise and fall, and the stripes
# have a fit.
$py -c "for k in range(81): print('%.2f 1.5' % (k * 0.01))" >"$tmp/rect.txt"
"$rocking" fragility "$tmp/rect.txt" "${base[@]}" --method refine --width 1e-3 --json >"$tmp/rect.json" || fail=1
"$rocking" fragility "$tmp/s3.txt" "${base[@]}" --method refine --width 1e-3 --json >"$tmp/one.json" || fail=1
$py - "$tmp/rect.json" "$tmp/one.json" <<'PY' && echo "ok: one record: each fit says why it has none" || fail=1
import json, math, sys
rect, one = (json.load(open(path))["blocks"][0] for path in sys.argv[1:3])
q = 1 / (1 - math.exp(-3 * 0.8))
assert abs(rect["records"][0]["first_overturning"]["q"] / q - 1) < 1.01e-6, rect["records"][0]["first_overturning"]
for name, entry in rect["fits"].items():
    assert entry["fit"] is None and entry["no_fit"], (name, entry)
assert "no censored record lies above it" in rect["fits"]["first_robust_collapse"]["no_fit"]
assert "perfect separation" in rect["fits"]["stripes"]["no_fit"], rect["fits"]["stripes"]
assert one["fits"]["first_overturning"]["fit"] is None and one["fits"]["first_robust_collapse"]["fit"] is None
assert one["fits"]["stripes"]["fit"]["records"] == 1, one["fits"]["stripes"]
PY
check "one record: the text says why the stripes have no fit" "multiple-stripe fit: no fit: the shares step from 0 to 1" \
    "$rocking" fragility "$tmp/rect.txt" "${base[@]}" --method refine --width 1e-3

# The grid method: none of it.
"$rocking" fragility "$tmp/s1.txt" "$tmp/s2.txt" "${base[@]}" --json >"$tmp/grid.json" || fail=1
check_not "the grid's JSON has no fits" '"fits"' cat "$tmp/grid.json"
check_not "the grid's JSON has no stripes" '"stripes"' cat "$tmp/grid.json"
check_not "the grid's text has no stripe fit" "multiple-stripe" "$rocking" fragility "$tmp/s1.txt" "$tmp/s2.txt" "${base[@]}"
exit $fail
