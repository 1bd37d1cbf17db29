#!/usr/bin/python3
"""The dense scan (dense_scan.py, the second implementation) against the library's
record kernel, point by point, and the expected file made from the two.

For every scan point and both ends of every bisected bracket, the library's
outcome (kernel_outcomes, built from kernel_outcomes.cpp: records::collapses_at,
the exact solver, as the IDA and the spectrum run it).  Where the two disagree, the
point is probed in both implementations (the input times 1 -+ 1e-13, the probe of
docs/spectrum.md) and re-run by the library with GSL rk8pd at rtol 1e-13: a
disagreement that a probe flips is ill-conditioned (rounding decides it); one that
no probe flips is a real disagreement, reported.

Each boundary's check in the CSV:
  agreed            the library gives the scan's outcome at both ends of its bracket,
                    and the probe flips neither end in either implementation;
  ill-conditioned   the probe flips an end (in either implementation), or an end
                    where the two disagree and the probe flips an outcome;
  disagrees         an end where they disagree and no probe flips anything;
and the scan's own ends ("scan start", "scan end") have no bracket.

Usage: check_scan.py ida|spectrum RECORD ALPHA [P] PREFIX KERNEL_BINARY OUT_CSV
(PREFIX as given to dense_scan.py; RECORD under $ROCKING_RECORDS/esm).
"""
import csv
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dense_scan  # noqa: E402

PROBE = 1e-13


def kernel(binary, path, kind, alpha, p, xs, rk8pd=False, factor=1.0):
    """The library's outcome at each x, the input times factor."""
    if kind == "ida" and factor != 1.0:
        xs, factor = [x * factor for x in xs], 1.0
    args = [binary, path, kind, repr(alpha)] + ([repr(p)] if kind == "ida" else []) + (["--rk8pd"] if rk8pd else []) \
        + (["--factor", repr(factor)] if factor != 1.0 else [])
    text = "\n".join(repr(float(x)) for x in xs) + "\n"
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True).stdout.split()
    assert len(out) == len(xs)
    return np.array([o == "1" for o in out])


def main():
    a = sys.argv[1:]
    kind = a[0]
    if kind == "ida":
        record, alpha, p, prefix, binary, out_csv = a[1:]
        p = float(p)
    else:
        record, alpha, prefix, binary, out_csv = a[1:]
        p = None
    alpha = float(alpha)
    case = dense_scan.Case(kind, record, alpha, p)
    path = os.path.join(dense_scan.ind.records_dir(), "esm", record)
    scan = np.load(prefix + ".scan.npz")
    br = np.load(prefix + ".brackets.npz")
    xs, over = scan["x"], scan["over"]
    t0 = time.time()
    k_scan = kernel(binary, path, kind, alpha, p, xs)
    bad = np.flatnonzero(k_scan != over)
    print(f"scan: {len(xs)} points, the kernel disagrees at {len(bad)} ({time.time() - t0:.0f} s)")
    lo, hi, lo_o, hi_o = br["lo"], br["hi"], br["lo_over"], br["hi_over"]
    k_lo = kernel(binary, path, kind, alpha, p, lo)
    k_hi = kernel(binary, path, kind, alpha, p, hi)
    print(f"brackets: {len(lo)}; the kernel disagrees at {int((k_lo != lo_o).sum())} lower and "
          f"{int((k_hi != hi_o).sum())} upper ends")

    # Every disagreeing point: the probe in both implementations, rk8pd in the library.
    pts = sorted(set([float(xs[i]) for i in bad] + [float(x) for x in lo[k_lo != lo_o]] +
                     [float(x) for x in hi[k_hi != hi_o]]))
    verdict = {}
    if pts:
        ind_up, _ = case.outcomes(pts, factor=1 + PROBE)
        ind_dn, _ = case.outcomes(pts, factor=1 - PROBE)
        ind_0, _ = case.outcomes(pts)
        ker_0 = kernel(binary, path, kind, alpha, p, pts)
        ker_up = kernel(binary, path, kind, alpha, p, pts, factor=1 + PROBE)
        ker_dn = kernel(binary, path, kind, alpha, p, pts, factor=1 - PROBE)
        rk = kernel(binary, path, kind, alpha, p, pts, rk8pd=True)
        for j, x in enumerate(pts):
            flips = len({bool(ind_up[j]), bool(ind_dn[j]), bool(ind_0[j])}) > 1 or \
                len({bool(ker_up[j]), bool(ker_dn[j]), bool(ker_0[j])}) > 1
            verdict[x] = ("ill-conditioned" if flips else "disagrees", bool(ind_0[j]), bool(ker_0[j]), bool(rk[j]),
                          (bool(ind_dn[j]), bool(ind_up[j])), (bool(ker_dn[j]), bool(ker_up[j])))
            print(f"  {kind} x = {x!r}: independent {int(ind_0[j])} (probe -/+ {int(ind_dn[j])}{int(ind_up[j])}), "
                  f"kernel {int(ker_0[j])} (probe -/+ {int(ker_dn[j])}{int(ker_up[j])}), rk8pd 1e-13 {int(rk[j])}: "
                  f"{verdict[x][0]}")

    # The probe at every bracket end, in both implementations: an end whose
    # outcome the input times 1 -+ 1e-13 flips lies within rounding of its
    # boundary (or of another one), which no solver decides.
    ends = np.concatenate([lo, hi])
    end_o = np.concatenate([lo_o, hi_o])
    flipped = set()
    for fac in (1 + PROBE, 1 - PROBE):
        o_ind, _ = case.outcomes(ends, factor=fac)
        o_ker = kernel(binary, path, kind, alpha, p, ends, factor=fac)
        for j in np.flatnonzero((o_ind != end_o) | (o_ker != end_o)):
            flipped.add(float(ends[j]))
            print(f"  probe {fac!r} flips the end {float(ends[j])!r}: independent {int(o_ind[j])}, kernel {int(o_ker[j])}")
    print(f"probe: {len(flipped)} of {len(ends)} bracket ends flipped by the input times 1 -+ {PROBE:g}")

    def check(x_safe, x_coll):
        vs = [verdict[x][0] for x in (x_safe, x_coll) if x in verdict]
        if "disagrees" in vs:
            return "disagrees"
        if vs or x_safe in flipped or x_coll in flipped:
            return "ill-conditioned"
        return "agreed"

    rows = []
    start = ("scan start", float(xs[0]), None) if over[0] else None
    for j in range(len(lo)):
        if not lo_o[j] and hi_o[j]:
            start = (check(float(lo[j]), float(hi[j])), float(hi[j]), float(lo[j]))
        else:
            rows.append((start, (check(float(hi[j]), float(lo[j])), float(lo[j]), float(hi[j]))))
            start = None
    if start is not None:
        rows.append((start, ("scan end", float(xs[-1]), None)))
    unit = "q" if kind == "ida" else "p"
    with open(out_csv, "w", newline="") as f:
        f.write(f"# {os.path.basename(out_csv)}: the islands of overturning of {record}, alpha {alpha}"
                + (f", p {p} rad/s, in q = PGA/(alpha g)" if kind == "ida" else ", record unscaled, in p (rad/s)")
                + f", on [{xs[0]!r}, {xs[-1]!r}]: a scan of {len(xs)} log-spaced points by expected/spectrum/independent.py's"
                + " model (dense_scan.py), every change of outcome bisected to 1e-10 relative, each bracket end re-run"
                + " by the library's record kernel (check_scan.py); PROVENANCE.md\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["island", "from", "to", "from_safe", "from_collapse", "from_check", "to_collapse", "to_safe",
                    "to_check", "width"])
        for i, (s, e) in enumerate(rows, 1):
            w.writerow([i, repr(s[1]), repr(e[1]), "" if s[2] is None else repr(s[2]), repr(s[1]), s[0], repr(e[1]),
                        "" if e[2] is None else repr(e[2]), e[0], f"{(e[1] - s[1]) / s[1]:.6e}"])
    n_ill = sum(1 for s, e in rows for c in (s[0], e[0]) if c == "ill-conditioned")
    n_dis = sum(1 for s, e in rows for c in (s[0], e[0]) if c == "disagrees")
    print(f"{len(rows)} islands in {unit} written to {out_csv}; boundaries ill-conditioned {n_ill}, disagreeing {n_dis}; "
          f"{time.time() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
