#!/usr/bin/env bash
# The same --seed gives the same bootstrap intervals, bit for bit, whatever the order of the files on the
# command line (issue 40, item 6): rocking fragility --method refine (its three fits: first overturning,
# first robust collapse, stripes) and rocking eq27 (its shares under each capacity), each on five synthetic
# records named so that the order they were made in, `sort`, `sort -r` and a shuffle all differ, against
# the first order's JSON.  Beside it: the per-record listing follows the command line; each record's
# sha256 is recomputed here from its file (hashlib, the samples read and divided by g = 9.81 as the reader
# does); the robust collapse's bootstrap and eq. 27's are expected/fragility/independent.py's drawing the
# records in the order of their sha256; and the premise, that drawn as listed (before issue 40) the orders
# give other intervals, so that this test fails on that behaviour.
#
#   tests/fragility_order_cli_test.sh ROCKING
set -u
rocking=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
py=/usr/bin/python3
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

names=(zeta Alpha mid beta Omega)
for k in 0 1 2 3 4; do
    "$rocking" record synth --stochastic $((k + 1)) --dt 0.01 --duration 20 --output "$tmp/${names[$k]}.txt" \
        >/dev/null || exit 1
done
cd "$tmp" || exit 1
made=(zeta.txt Alpha.txt mid.txt beta.txt Omega.txt)
mapfile -t sorted < <(printf '%s\n' "${made[@]}" | LC_ALL=C sort)
mapfile -t reversed < <(printf '%s\n' "${made[@]}" | LC_ALL=C sort -r)
shuffled=(mid.txt Omega.txt zeta.txt beta.txt Alpha.txt)
frag=(--unit m/s2 --alpha 0.1 --p 3 --q-max 2.5 --points 20 --method refine --width 1e-3 --bootstrap 40
      --seed 9 --json --quiet)
eq27=(--unit m/s2 --alpha 0.1,0.2 --p-min 2 --p-max 4 --p-points 2 --q-max 3 --method refine --width 1e-3
      --bootstrap 40 --seed 9 --json --quiet)
orders=(made sorted reversed shuffled)
for o in "${orders[@]}"; do
    declare -n files=$o
    "$rocking" fragility "${files[@]}" "${frag[@]}" >"frag_$o.json" || { echo "FAIL: fragility in the $o order"; fail=1; }
    "$rocking" eq27 "${files[@]}" "${eq27[@]}" >"eq27_$o.json" || { echo "FAIL: eq27 in the $o order"; fail=1; }
    printf '%s\n' "${files[@]}" >"order_$o"
    unset -n files
done

$py - "$here/../expected/fragility" "$here/../tools" "${orders[@]}" <<'PY' && echo "ok: the same intervals in every order" || fail=1
import hashlib, json, struct, sys
sys.path[:0] = [sys.argv[1], sys.argv[2]]
import independent  # expected/fragility/independent.py: the censored fit, its bootstrap, the draw order
orders = sys.argv[3:]
def strict(path):
    def no_constant(name): raise ValueError("not JSON: " + name)
    return json.load(open(path), parse_constant=no_constant)
def sha256_of(path):
    """rocking's reader on a two-column file in m/s^2: dt = t1 - t0, each sample times 1 then over g = 9.81."""
    rows = [line.replace(",", " ").split() for line in open(path) if line.strip() and not line.startswith("#")]
    t, a = [float(r[0]) for r in rows], [float(r[1]) * 1.0 / 9.81 for r in rows]
    return hashlib.sha256(("%.17g" % (t[1] - t[0])).encode() + b";" + struct.pack("<%dd" % len(a), *a)).hexdigest()
listing = {o: open("order_" + o).read().split() for o in orders}
frag = {o: strict("frag_%s.json" % o) for o in orders}
eq27 = {o: strict("eq27_%s.json" % o) for o in orders}
ref = frag[orders[0]]["blocks"][0]
assert all(ref["fits"][k]["fit"] for k in ("first_overturning", "first_robust_collapse", "stripes")), ref["fits"]
assert all(ref["fits"][k]["fit"]["bootstrap"] for k in ref["fits"]), ref["fits"]
by_file = {r["file"]: r for r in ref["records"]}
for o in orders:
    b = frag[o]["blocks"][0]
    # The listing: the command line's order, each record as in the first order's run.
    assert [r["file"] for r in b["records"]] == listing[o], (o, [r["file"] for r in b["records"]])
    for r in b["records"]:
        assert r == by_file[r["file"]], (o, r["file"])
        assert r["sha256"] == sha256_of(r["file"]), (o, r["file"])
    # Every fit and its bootstrap, and the stripes' shares: the same bits (the same %.17g text).
    assert b["fits"] == ref["fits"], (o, b["fits"], ref["fits"])
    assert b["fit"] == ref["fit"] and b["stripes"] == ref["stripes"], o
    e, e0 = eq27[o], eq27[orders[0]]
    assert e["files"] == listing[o], o
    for key in ("shares",):
        assert e[key] == e0[key], (o, key)
    assert e["first_robust_collapse"]["shares"] == e0["first_robust_collapse"]["shares"], o
    assert [r["file"] for r in e["by_record"]] == listing[o], o
    assert all(r["sha256"] == sha256_of(r["file"]) for r in e["by_record"]), o
assert any(s["bootstrap"][0] < s["bootstrap"][1] for s in eq27[orders[0]]["shares"])  # intervals, not points
# The robust collapse's bootstrap drawn in the order of the records' sha256 (independent.py's).
points = [(r["first_robust_collapse"]["q"], r["first_robust_collapse"]["collapsed"]) for r in ref["records"]]
shas = [r["sha256"] for r in ref["records"]]
bt = ref["fits"]["first_robust_collapse"]["fit"]["bootstrap"]
want = independent.bootstrap(independent.in_draw_order(points, shas), bt["resamples"], bt["seed"], bt["level"])
for got, w in zip(bt["median"] + bt["beta"], want):
    assert abs(got - w) <= 1e-9 * abs(w), (bt, want)
# Eq. 27's bootstrap over records: independent.py's, drawing the records' counts in the order of their sha256.
def eq27_bounds(e, records):
    counts = [r["non_conservative"] for r in records]
    blocks = len(e["map"])
    return [list(b) for b in independent.record_bootstrap(counts, blocks, e["bootstrap"]["resamples"],
                                                          e["bootstrap"]["seed"], e["bootstrap"]["level"])]
e0 = eq27[orders[0]]
drawn = independent.in_draw_order(e0["by_record"], [r["sha256"] for r in e0["by_record"]])
assert eq27_bounds(e0, drawn) == [s["bootstrap"] for s in e0["shares"]], (eq27_bounds(e0, drawn), e0["shares"])
# The premise: drawn as listed, the orders would give other intervals.
as_listed, eq27_as_listed = set(), set()
for o in orders:
    rs = frag[o]["blocks"][0]["records"]
    pts = [(r["first_robust_collapse"]["q"], r["first_robust_collapse"]["collapsed"]) for r in rs]
    as_listed.add(independent.bootstrap(pts, bt["resamples"], bt["seed"], bt["level"]))
    eq27_as_listed.add(str(eq27_bounds(eq27[o], eq27[o]["by_record"])))
assert len(as_listed) > 1 and len(eq27_as_listed) > 1, (as_listed, eq27_as_listed)
print("  %d orders, the listing as given; drawn as listed they would give %d and %d intervals"
      % (len(orders), len(as_listed), len(eq27_as_listed)))
PY
exit $fail
