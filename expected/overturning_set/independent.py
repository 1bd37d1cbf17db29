#!/usr/bin/python3
"""Check of expected/overturning_set (ctest independent_overturning_set): the files'
structure, and both ends of every bracket re-simulated by the second implementation
(expected/spectrum/independent.py's model, through dense_scan.py), which must give
a safe run at every *_safe end and an overturning one at every *_collapse end.

Structure: islands numbered in order, disjoint and increasing; each bracket ordered
(safe below the start, above the end) and at most 1e-10 relative wide (1.5e-10
allowed for the rounding of its ends); from/to equal to the brackets' collapse
ends; width = (to - from) / from; each check one of the known words.

This re-runs the scan's own model at the brackets (about 100 runs, a few seconds);
the comparison with the library's kernel at all 10^5 points is check_scan.py's
(PROVENANCE.md).  Usage: independent.py DIR.  Exit 0 when all agree, 1 on any
disagreement (each named), 77 (a skip) without the records after checking the
structure, 2 on bad usage.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dense_scan  # noqa: E402

SKIP = 77
RECORD = "IT.NRC..HGE.D.20161030.064018.C.ACC.ASC"
FILES = {"ida_islands.csv": ("ida", 0.10, 2.5), "spectrum_islands.csv": ("spectrum", 0.10, None)}
CHECKS = {"agreed", "ill-conditioned", "disagrees", "scan start", "scan end"}
BRACKET = 1.5e-10


def read(directory, name):
    with open(os.path.join(directory, name), newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return [dict(zip(rows[0], r)) for r in rows[1:]]


def main():
    if len(sys.argv) != 2:
        print("usage: independent.py DIR", file=sys.stderr)
        return 2
    directory = sys.argv[1]
    failures = []

    def fail(msg):
        failures.append(msg)
        print("  DISAGREES: " + msg)

    todo = {}
    for name in FILES:
        rows = read(directory, name)
        last = None
        for i, r in enumerate(rows, 1):
            label = f"{name} island {r['island']}"
            if int(r["island"]) != i:
                fail(f"{label}: numbered out of order")
            lo, hi = float(r["from"]), float(r["to"])
            if not lo < hi or (last is not None and not last < lo):
                fail(f"{label}: [{lo!r}, {hi!r}] empty, or not after the island before it")
            last = hi
            if abs(float(r["width"]) - (hi - lo) / lo) > 1e-6 * (hi - lo) / lo:  # printed to 7 digits
                fail(f"{label}: width {r['width']} is not (to - from) / from")
            for side, at in (("from", lo), ("to", hi)):
                check = r[f"{side}_check"]
                if check not in CHECKS:
                    fail(f"{label} {side}: check {check!r}")
                if check in ("scan start", "scan end"):
                    continue
                safe, coll = float(r[f"{side}_safe"]), float(r[f"{side}_collapse"])
                if at != coll:
                    fail(f"{label} {side}: {at!r} is not its bracket's collapse end {coll!r}")
                ordered = safe < coll if side == "from" else coll < safe
                if not ordered or abs(coll - safe) > BRACKET * max(coll, safe):
                    fail(f"{label} {side}: bracket [{safe!r}, {coll!r}] not ordered or wider than {BRACKET:g}")
                if check != "ill-conditioned":
                    todo.setdefault(name, []).append((f"{label} {side}", safe, coll))
        print(f"  {name}: {len(rows)} islands, {len(todo.get(name, []))} brackets to re-run")

    root = dense_scan.ind.records_dir()
    if not os.path.isfile(os.path.join(root, "esm", RECORD)):
        if failures:
            return 1
        print(f"independent_overturning_set: SKIPPED: {RECORD} not in {root}/esm ($ROCKING_RECORDS or "
              f"../shared/records beside the repository); the structure above agrees, the brackets need the record")
        return SKIP
    for name, ends in todo.items():
        kind, alpha, p = FILES[name]
        case = dense_scan.Case(kind, RECORD, alpha, p)
        xs = [e[1] for e in ends] + [e[2] for e in ends]
        over, _ = case.outcomes(xs)
        n = len(ends)
        for j, (label, safe, coll) in enumerate(ends):
            if over[j] or not over[n + j]:
                fail(f"{label}: overturns at the safe end {safe!r}: {'YES' if over[j] else 'no'}, "
                     f"at the collapse end {coll!r}: {'yes' if over[n + j] else 'NO'}")
        print(f"  {name}: {n} brackets re-run at both ends")
    if failures:
        print(f"independent check: {len(failures)} disagreement(s) in {directory}")
        return 1
    print(f"independent check: {directory} agrees")
    return 0


if __name__ == "__main__":
    sys.exit(main())
