#!/usr/bin/python3
"""Independent check of expected/spectrum/spectrum_refined.csv and
spectrum_refined_intervals.csv (issue 39): the refine method's overturning set of each
Norcia record and alpha beside the grid method's.

The model and its solution are independent.py's, beside this file (imported, not copied:
linearised eq. 3 solved in closed form on each sample interval, Housner's restitution,
the model's rest rules, the free rocking after the record decided in closed form; no code
shared with the C++ library).  Checked:

1. every boundary of spectrum_refined_intervals.csv whose check is "confirmed": the block
   overturns at its *_collapse p and not at its *_safe p (both ends re-simulated); the
   brackets ordered, at most 2e-6 relative wide, the intervals ordered and disjoint
   (independent.py's structure check, an island seen at one point allowed: from = to);
   ill-conditioned ends (rounding places them) are named and not re-simulated;
2. every number of spectrum_refined.csv recomputed: grid_lowest_p and grid_intervals
   against spectrum_summary.csv (the grid method's); first_overturning_p, its safe end and
   check against the first listed interval; first_robust_p and its bracket as the first
   listed interval wider than the robust width in ln p (read from the notes); the two
   percentages 100 (1 - p / grid_lowest_p) to 1e-9; intervals_listed counted, every
   listed interval within the listing rule; share_first_to_robust, share_5pc_below_grid
   and band_share_at_first as the listed intervals' cover, in ln p, of
   [first_overturning_p, first_robust_p], [grid_lowest_p / 1.05, grid_lowest_p] and the
   main-grid step (200 p log-spaced on [0.3, 30]) holding first_overturning_p, to 1e-9;
   guarantee from the record's PGA: yes iff PGA/(alpha g) <= (pi/2 - alpha)/alpha;
3. one row against a dense scan by this model (expected/overturning_set/
   spectrum_islands.csv: IT.NRC HGE 2016-10-30 06:40, alpha 0.1, 10^5 points on
   [1.183, 1.186] rad/s, every change of outcome bisected to 1e-10): the row's first
   overturning lies on an island of the scan (within its 1e-6 bisection), every scan
   island below it is narrower than the width w (in ln p, read from the notes), every scan
   island wider than w meets a listed interval, and every listed boundary inside the
   scan's range has its collapse end on a scan island -- the search's guarantee, seen by
   a second implementation.

The records are read from $ROCKING_RECORDS or <repository>/../shared/records; without them
the checks that need no record (2 but the guarantee, 3, and 1's structure) run and the
check exits 77 (ctest: skipped).  Usage: independent_refined.py DIR.  Exit 0 when all
agree, 1 on any disagreement (each named), 2 on bad usage.
"""
import importlib.util
import math
import os
import re
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("spectrum_independent", os.path.join(HERE, "independent.py"))
ind = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ind)

SKIP = 77
ROWS, LISTED, SUMMARY = "spectrum_refined.csv", "spectrum_refined_intervals.csv", "spectrum_summary.csv"
SCAN_RECORD, SCAN_ALPHA, SCAN_RANGE = "esm/IT.NRC..HGE.D.20161030.064018.C.ACC.ASC", "0.10", (1.183, 1.186)
P_MIN, P_MAX, POINTS = 0.3, 30.0, 200  # the main grid the file's bands are steps of (its notes say so)
BELOW_GRID = 1.05
BISECTION = 1e-6
DERIVED = 1e-9  # a recomputed share or percentage: the same arithmetic, in another order


def widths_of(directory):
    """w and the robust width, both in ln p, from the file's '# width' note; and the main
    grid's statement from its '# solver' note, which must be the one assumed here."""
    w = robust = grid = None
    with open(os.path.join(directory, ROWS)) as f:
        for line in f:
            if not line.startswith("#"):
                break
            m = re.match(r"# width: w = ([0-9.e+-]+) in ln p .*robust width ([0-9.e+-]+) in ln p", line)
            if m:
                w, robust = float(m.group(1)), float(m.group(2))
            if line.startswith("# solver:"):
                grid = f"from {POINTS} p log-spaced from {P_MIN:g} to {P_MAX:g} rad/s" in line
    if w is None or grid is None:
        raise ValueError(f"{ROWS}: no '# width: w = W in ln p ... robust width R in ln p' or no '# solver' note")
    if not grid:
        raise ValueError(f"{ROWS}: the solver note does not state the main grid {POINTS} p on [{P_MIN}, {P_MAX}]")
    return w, robust


def cover(intervals, a, b):
    """The share of [a, b], in ln p, that the intervals cover."""
    c = 0.0
    for lo, hi in intervals:
        x, y = max(a, lo), min(b, hi)
        if y > x:
            c += math.log(y / x)
    return c / math.log(b / a)


def main_step(p):
    """The step [g_k, g_k+1] of the main grid (log-spaced, both ends included) holding p."""
    ratio = (P_MAX / P_MIN) ** (1 / (POINTS - 1))
    k = min(max(int(math.floor(math.log(p / P_MIN) / math.log(ratio))), 0), POINTS - 2)
    lo = P_MIN * ratio ** k
    hi = P_MAX if k == POINTS - 2 else P_MIN * ratio ** (k + 1)
    if p < lo:  # rounding at a grid point
        k -= 1
        lo, hi = P_MIN * ratio ** k, lo
    elif p >= hi and k < POINTS - 2:
        lo, hi = hi, P_MIN * ratio ** (k + 2)
    return lo, hi


def check_structure(intervals, rep):
    """independent.py's structure check, but for an island seen at one point: a sample
    that overturned between two safe neighbours 1e-6 apart bisects to two brackets sharing
    their collapse end, an interval with from = to (narrower than the bisection).  Each
    end's bracket ordered and at most 2e-6 wide, from/to its collapse end, the intervals
    of a pair numbered from 1, ordered and disjoint.  Returns the confirmed ends
    (record, alpha, p_collapse, p_safe, label) and the ill-conditioned ones' labels."""
    ends, ill, last = [], [], {}
    for r in intervals:
        key = (r["record"], r["alpha"])
        label = f"{r['record']} alpha {r['alpha']} interval {r['interval']}"
        lo, hi = float(r["from"]), float(r["to"])
        point = lo == hi and r["from_collapse"] == r["to_collapse"] and r["from_collapse"] != "-"
        if not (lo < hi or point):
            rep.fail(f"{label}: from {lo!r} not below to {hi!r}")
        n = int(r["interval"])
        prev = last.get(key)
        if (prev is None and n != 1) or (prev is not None and (n != prev[0] + 1 or not prev[1] < lo)):
            rep.fail(f"{label}: out of order or overlapping the interval before it")
        last[key] = (n, hi)
        for side, at in (("from", lo), ("to", hi)):
            check = r[f"{side}_check"]
            if check in ("grid start", "grid end"):
                continue
            col = "_ill" if check == "ill-conditioned" else ""
            safe, coll = float(r[f"{side}{col}_safe"]), float(r[f"{side}{col}_collapse"])
            if at != coll:
                rep.fail(f"{label} {side}: {at!r} is not its bracket's collapse end {coll!r}")
            ordered = safe < coll if side == "from" else coll < safe
            if not ordered or abs(coll - safe) > ind.BRACKET_REL * max(coll, safe):
                rep.fail(f"{label} {side}: bracket [{safe!r}, {coll!r}] not ordered or wider than {ind.BRACKET_REL:g}")
            if check == "confirmed":
                ends.append((r["record"], float(r["alpha"]), coll, safe, f"{label} {side}"))
            elif check == "ill-conditioned":
                ill.append(f"{label} {side}")
    return ends, ill


def close(got, want, tol=DERIVED):
    return abs(float(got) - want) <= tol


def check_row(r, listed, summary, w, robust_w, rep):
    """spectrum_refined.csv's row r recomputed from its listed intervals and the grid's summary."""
    label = f"{r['record']} alpha {r['alpha']}"
    s = summary.get((r["record"], r["alpha"]))
    if s is None:
        rep.fail(f"{label}: no row in {SUMMARY}")
        return
    if r["grid_lowest_p"] != s["lowest_p"] or r["grid_intervals"] != s["intervals"]:
        rep.fail(f"{label}: grid_lowest_p/grid_intervals {r['grid_lowest_p']}/{r['grid_intervals']}, "
                 f"{SUMMARY} has {s['lowest_p']}/{s['intervals']}")
    has_grid = r["grid_lowest_p"] != "none"
    grid = float(r["grid_lowest_p"]) if has_grid else None
    spans = [(float(x["from"]), float(x["to"])) for x in listed]
    if r["intervals_listed"] != str(len(listed)) or int(r["intervals"]) < len(listed):
        rep.fail(f"{label}: intervals {r['intervals']}, intervals_listed {r['intervals_listed']}, "
                 f"{len(listed)} listed")
    if not listed:
        if r["intervals"] != "0" or r["first_overturning_p"] != "none up to 30" or r["first_robust_p"] != "none up to 30":
            rep.fail(f"{label}: no interval listed, yet the row reports one")
        return

    def bracket(x):
        """p, safe end and check of the interval x's start, as the row states them."""
        if x["from_check"] == "grid start":
            return x["from"], "none: overturns at 0.3", "-"
        safe = x["from_safe"] if x["from_check"] != "ill-conditioned" else x["from_ill_safe"]
        return x["from"], safe, x["from_check"]

    def percent(col, p):
        if not has_grid:
            if r[col] != "-":
                rep.fail(f"{label}: {col} {r[col]} without a grid p")
        elif not close(r[col], 100 * (1 - p / grid)):
            rep.fail(f"{label}: {col} {r[col]}, recomputed {100 * (1 - p / grid)!r}")

    first = listed[0]
    want = bracket(first)
    got = (r["first_overturning_p"], r["first_overturning_safe"], r["first_overturning_check"])
    if float(got[0]) != float(want[0]) or got[1:] != want[1:]:
        rep.fail(f"{label}: first overturning {got}, the first listed interval gives {want}")
    p_first = float(first["from"])
    percent("first_below_grid_percent", p_first)

    robust = next((x for x in listed if math.log(float(x["to"]) / float(x["from"])) > robust_w), None)
    if robust is None:
        if r["first_robust_p"] != "none up to 30" or r["intervals"] != r["intervals_listed"]:
            rep.fail(f"{label}: no listed interval wider than {robust_w:g} in ln p, yet the row has "
                     f"first_robust_p {r['first_robust_p']} with {r['intervals_listed']} of {r['intervals']} listed")
        p_robust = None
    else:
        want = bracket(robust)
        got = (r["first_robust_p"], r["first_robust_safe"], r["first_robust_check"])
        if got[0] == "none up to 30" or float(got[0]) != float(want[0]) or got[1:] != want[1:]:
            rep.fail(f"{label}: first robust collapse {got}, the first listed interval wider than "
                     f"{robust_w:g} in ln p gives {want}")
        p_robust = float(robust["from"])
        percent("robust_below_grid_percent", p_robust)

    # The listing rule: every listed interval starts at or below the cut.
    step = main_step(p_first)
    if p_robust is not None:
        cut = max(p_robust, grid if has_grid else 0, step[1])
        beyond = [x["interval"] for x in listed if float(x["from"]) > cut * (1 + 1e-15)]
        if beyond:
            rep.fail(f"{label}: intervals {beyond} listed beyond the cut {cut!r}")

    if p_robust is not None and p_robust > p_first:
        if not close(r["share_first_to_robust"], cover(spans, p_first, p_robust)):
            rep.fail(f"{label}: share_first_to_robust {r['share_first_to_robust']}, "
                     f"recomputed {cover(spans, p_first, p_robust)!r}")
    elif r["share_first_to_robust"] != "-":
        rep.fail(f"{label}: share_first_to_robust {r['share_first_to_robust']} with no range between the two")
    if has_grid and grid / BELOW_GRID >= P_MIN:
        want = cover(spans, grid / BELOW_GRID, grid)
        if not close(r["share_5pc_below_grid"], want):
            rep.fail(f"{label}: share_5pc_below_grid {r['share_5pc_below_grid']}, recomputed {want!r}")
    elif r["share_5pc_below_grid"] != "-":
        rep.fail(f"{label}: share_5pc_below_grid {r['share_5pc_below_grid']} without a band below the grid's p")
    want = cover(spans, *step)
    if not close(r["band_share_at_first"], want):
        rep.fail(f"{label}: band_share_at_first {r['band_share_at_first']} (step {step}), recomputed {want!r}")


def check_scan(rows, per, w, rep):
    """The dense scan's row: the first overturning on a scan island, the islands below it
    narrower than w, the islands wider than w met by a listed interval."""
    scan = ind.read_csv(os.path.join(HERE, "..", "overturning_set"), "spectrum_islands.csv")
    row = next((r for r in rows if (r["record"], r["alpha"]) == (SCAN_RECORD, SCAN_ALPHA)), None)
    if row is None or row["first_overturning_p"] == "none up to 30":
        rep.fail(f"dense scan: no first overturning for {SCAN_RECORD} alpha {SCAN_ALPHA} to compare with")
        return
    islands = [(int(s["island"]), float(s["from"]), float(s["to"])) for s in scan]
    lo, hi = SCAN_RANGE
    p = float(row["first_overturning_p"])
    if not lo <= p <= hi:
        rep.fail(f"dense scan: the first overturning {p!r} is outside the scan's range [{lo}, {hi}]")

    def on_island(x):
        return [n for n, a, b in islands if a * (1 - BISECTION) <= x <= b * (1 + BISECTION)]

    on = on_island(p)
    if not on:
        rep.fail(f"dense scan: the first overturning {p!r} lies on no island of the scan")
    below = [(n, a, b) for n, a, b in islands if b < p * (1 - BISECTION)]
    for n, a, b in below:
        if math.log(b / a) > w:
            rep.fail(f"dense scan: island {n} [{a!r}, {b!r}] below the first overturning is wider than w = {w:g}")
    listed = [(float(x["from"]), float(x["to"])) for x in per.get((SCAN_RECORD, SCAN_ALPHA), [])]
    wide = [(n, a, b) for n, a, b in islands if math.log(b / a) > w]
    met = 0
    for n, a, b in wide:
        if any(x <= b * (1 + BISECTION) and y >= a * (1 - BISECTION) for x, y in listed):
            met += 1
        else:
            rep.fail(f"dense scan: island {n} [{a!r}, {b!r}], wider than w = {w:g}, meets no listed interval")
    ends = [(v, side) for a, b in listed for side, v in (("from", a), ("to", b)) if lo <= v <= hi]
    seen = 0
    for x, side in ends:
        if on_island(x):
            seen += 1
        else:
            rep.fail(f"dense scan: the listed interval's {side} {x!r} lies on no island of the scan")
    print(f"  dense scan: the first overturning {p:.9g} on island {on[0] if on else '-'}; {len(below)} islands "
          f"below it, the widest {max((math.log(b / a) for _, a, b in below), default=0):.3g} in ln p (w = {w:g}); "
          f"{met} of {len(wide)} scan islands wider than w met by a listed interval; {seen} of {len(ends)} listed "
          f"ends in its range on a scan island")


def main():
    if len(sys.argv) != 2:
        print("usage: independent_refined.py DIR (holding spectrum_refined.csv, spectrum_refined_intervals.csv, "
              "spectrum_summary.csv)", file=sys.stderr)
        return 2
    directory = sys.argv[1]
    rows = ind.read_csv(directory, ROWS)
    intervals = ind.read_csv(directory, LISTED)
    summary = {(s["record"], s["alpha"]): s for s in ind.read_csv(directory, SUMMARY)}
    w, robust_w = widths_of(directory)
    rep = ind.Report()
    start = time.time()

    # 1 (structure) and 2.
    ends, ill = check_structure(intervals, rep)
    per = {}
    for x in intervals:
        per.setdefault((x["record"], x["alpha"]), []).append(x)
    keys = {(r["record"], r["alpha"]) for r in rows}
    for k in per:
        if k not in keys:
            rep.fail(f"{k[0]} alpha {k[1]}: intervals listed for a pair without a row")
    for r in rows:
        check_row(r, per.get((r["record"], r["alpha"]), []), summary, w, robust_w, rep)
    print(f"  {len(rows)} rows recomputed from {len(intervals)} listed intervals ({len(ends)} confirmed boundaries, "
          f"{len(ill)} ill-conditioned) and {SUMMARY}; w = {w:g}, robust width {robust_w:g}")
    for x in ill:
        print(f"  excluded (ill-conditioned: rounding places it, no solver decides it): {x}")
    moved = [float(r["first_below_grid_percent"]) for r in rows if r["first_below_grid_percent"] != "-"]
    robust_moved = [float(r["robust_below_grid_percent"]) for r in rows if r["robust_below_grid_percent"] != "-"]
    if moved:
        print(f"  first overturning below the grids' lowest p: median {statistics.median(moved):.3g} %, "
              f"max {max(moved):.3g} %, min {min(moved):.3g} % ({len(moved)} rows); first robust collapse: "
              f"median {statistics.median(robust_moved):.3g} %, max {max(robust_moved):.3g} %, "
              f"min {min(robust_moved):.3g} %")

    # 3.
    check_scan(rows, per, w, rep)

    # 1 (the boundaries) and 2's guarantee, on the records.
    root = ind.records_dir()
    files = sorted({r["record"] for r in rows})
    missing = [f for f in files if not os.path.isfile(os.path.join(root, f))]
    if missing:
        if rep.failures:
            print(f"independent check: {len(rep.failures)} disagreement(s) in {directory} (records absent)")
            return 1
        print(f"independent_spectrum_refined: SKIPPED: the records folder {root} is absent or lacks {len(missing)} "
              f"of {len(files)} records ($ROCKING_RECORDS or ../shared/records beside the repository); the rows, "
              f"structure and dense scan above agree, the boundaries need the records")
        return SKIP
    agree = 0
    for f in files:
        dt, a = ind.read_esm(os.path.join(root, f))
        pga = max(abs(x) for x in a)  # in g
        for r in (r for r in rows if r["record"] == f):
            alpha = float(r["alpha"])
            want = "yes" if pga / alpha <= (math.pi / 2 - alpha) / alpha else "no"
            if r["guarantee"] != want:
                rep.fail(f"{f} alpha {r['alpha']}: guarantee {r['guarantee']}, PGA {pga:.6g} g gives {want}")
        mine = [e for e in ends if e[0] == f]
        blocks = []
        for _, alpha, coll, safe, _ in mine:
            blocks += [ind.Block(coll, alpha), ind.Block(safe, alpha)]
        t0 = time.time()
        out = ind.run_record(a, dt, blocks)
        n_ok = 0
        for i, (_, alpha, coll, safe, label) in enumerate(mine):
            if out[2 * i] and not out[2 * i + 1]:
                n_ok += 1
            else:
                rep.fail(f"{label}: bracket [{safe!r} safe, {coll!r} collapse]: overturns at the collapse end: "
                         f"{'yes' if out[2 * i] else 'NO'}, at the safe end: {'YES' if out[2 * i + 1] else 'no'}")
        agree += n_ok
        print(f"  {f}: {n_ok} of {len(mine)} brackets agree ({len(blocks)} runs, {time.time() - t0:.1f} s)")
    print(f"independent check: {len(ends)} confirmed boundaries re-simulated at both ends, {agree} agree; "
          f"{time.time() - start:.1f} s")
    if rep.failures:
        print(f"independent check: {len(rep.failures)} disagreement(s) in {directory}")
        return 1
    print(f"independent check: {directory} agrees")
    return 0


if __name__ == "__main__":
    sys.exit(main())
