#!/usr/bin/python3
"""Dense scans of the overturning set on a short range, by a second implementation
(issue 39's "dense scan of a real record"; provenance: PROVENANCE.md beside this).

The model and its solution are expected/spectrum/independent.py's (imported, not
copied): linearised eq. 3 solved in closed form on each sample interval, impacts and
falls located on the closed form, Housner's restitution and the model's rest rules,
the free rocking after the record decided in closed form.  It shares no code with
the C++ library.  Here it is stepped over many blocks at once, each with its own
scale of the record (an IDA: q, the record times q alpha / PGA) or its own p (a
spectrum).

Two stages, each resumable from its .npz:
  scan     N log-spaced points on [lo, hi] (both included), the outcome at each;
  bisect   every change of outcome between neighbours bisected (all brackets at
           once, one vectorised run per halving) until (hi - lo) <= tol * hi.

Usage:
  dense_scan.py ida      RECORD ALPHA P  LO HI N TOL OUT_PREFIX
  dense_scan.py spectrum RECORD ALPHA    LO HI N TOL OUT_PREFIX
RECORD is a file of $ROCKING_RECORDS (or ../shared/records beside the repository)
under esm/.  Writes OUT_PREFIX.scan.npz, OUT_PREFIX.brackets.npz and
OUT_PREFIX.islands.csv, with progress on stdout.
"""
import csv
import importlib.util
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("spectrum_independent", os.path.join(HERE, "..", "spectrum", "independent.py"))
ind = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ind)

HALF_PI = ind.HALF_PI


def run_many(a, dt, p, alpha, scale):
    """ind.run_record, each block with its own p and its own scale of the record a
    (in g).  Returns the outcomes (bool array) and the blocks' impact counts."""
    n = len(p)
    blocks = [ind.Block(float(p[j]), alpha) for j in range(n)]
    p = np.asarray(p, dtype=float)
    s = np.asarray(scale, dtype=float)
    al = np.full(n, alpha)
    x = p * dt
    if np.any(x > 1.0):
        raise ValueError("p dt > 1")
    SH, CH1, SHX = np.sinh(x), 2 * np.sinh(0.5 * x) ** 2, ind.series_shx(x)
    bound = x * x / 8.0
    th = np.zeros(n)
    om = np.zeros(n)
    sg = np.ones(n)
    rocking = np.zeros(n, dtype=bool)
    active = np.ones(n, dtype=bool)

    def pull(js):
        for j in js:
            b = blocks[j]
            b.th, b.om, b.sg = float(th[j]), float(om[j]), float(sg[j])

    def push(js):
        for j in js:
            b = blocks[j]
            th[j], om[j], sg[j] = b.th, b.om, b.sg
            rocking[j] = not b.resting and not b.fallen
            active[j] = not b.fallen

    amax = np.abs(np.asarray(a))
    for k in range(len(a) - 1):
        ak0, ak10 = a[k], a[k + 1]
        ak, ak1 = s * ak0, s * ak10
        c1 = (ak1 - ak) / dt
        A = th + ak - sg * al
        th1 = th + A * CH1 + om * SH / p + c1 * SHX / p
        om1 = om + p * A * SH + (om + c1) * CH1
        e1 = th1 + ak1 - sg * al
        b = bound * np.maximum(np.abs(A), np.abs(e1))
        s0, s1 = sg * th, sg * th1
        quiet = rocking & (np.minimum(s0, s1) - b > 0.0) & (np.maximum(s0, s1) + b < HALF_PI)
        th = np.where(quiet, th1, th)
        om = np.where(quiet, om1, om)
        lifts = s * max(amax[k], amax[k + 1]) > al
        event = active & ~quiet & (rocking | lifts)
        js = np.flatnonzero(event)
        if len(js):
            pull(js)
            for j in js:
                blocks[j].interval(k, dt, float(ak[j]), float(ak1[j]))
            push(js)
    pull(range(n))
    return np.array([blk.free_rocking_overturns() for blk in blocks]), np.array([blk.impacts for blk in blocks])


class Case:
    def __init__(self, kind, record, alpha, p=None):
        root = ind.records_dir()
        self.dt, a = ind.read_esm(os.path.join(root, "esm", record))
        self.a = np.array(a)
        self.kind, self.alpha, self.p = kind, alpha, p
        self.peak = float(np.max(np.abs(self.a)))

    def outcomes(self, xs, chunk=5000, log=None, factor=1.0):
        """The outcome at each x (q or p), in chunks, with the input times
        factor (the probe)."""
        xs = np.asarray(xs, dtype=float)
        out = np.zeros(len(xs), dtype=bool)
        imp = np.zeros(len(xs), dtype=np.int64)
        t0 = time.time()
        for i in range(0, len(xs), chunk):
            x = xs[i:i + chunk]
            if self.kind == "ida":
                p = np.full(len(x), self.p)
                scale = x * self.alpha / self.peak * factor
            else:
                p = x
                scale = np.full(len(x), factor)
            out[i:i + chunk], imp[i:i + chunk] = run_many(self.a, self.dt, p, self.alpha, scale)
            if log:
                log(f"  {min(i + chunk, len(xs))}/{len(xs)} runs, {time.time() - t0:.0f} s, "
                    f"{int(out[:i + chunk].sum())} overturn")
        return out, imp


def main():
    args = sys.argv[1:]
    if not args or args[0] not in ("ida", "spectrum"):
        print(__doc__, file=sys.stderr)
        return 2
    kind = args[0]
    if kind == "ida":
        record, alpha, p, lo, hi, n, tol, prefix = args[1:]
        case = Case(kind, record, float(alpha), float(p))
    else:
        record, alpha, lo, hi, n, tol, prefix = args[1:]
        case = Case(kind, record, float(alpha))
    lo, hi, n, tol = float(lo), float(hi), int(n), float(tol)

    def log(msg):
        print(msg, flush=True)

    scan_file = prefix + ".scan.npz"
    if os.path.exists(scan_file):
        z = np.load(scan_file)
        xs, over = z["x"], z["over"]
        log(f"scan: {len(xs)} points read from {scan_file}")
    else:
        xs = lo * (hi / lo) ** (np.arange(n) / (n - 1))
        xs[0], xs[-1] = lo, hi
        log(f"scan: {n} points on [{lo}, {hi}] ({kind})")
        over, imp = case.outcomes(xs, log=log)
        np.savez(scan_file, x=xs, over=over, impacts=imp)

    changes = np.flatnonzero(over[1:] != over[:-1])
    a_x, b_x = xs[changes].copy(), xs[changes + 1].copy()  # a: the lower end
    a_o, b_o = over[changes].copy(), over[changes + 1].copy()
    log(f"bisect: {len(changes)} changes of outcome")
    halvings = 0
    while True:
        wide = (b_x - a_x) > tol * b_x
        if not wide.any():
            break
        js = np.flatnonzero(wide)
        mid = 0.5 * (a_x[js] + b_x[js])
        o, _ = case.outcomes(mid)
        same_as_a = o == a_o[js]
        a_x[js[same_as_a]] = mid[same_as_a]
        b_x[js[~same_as_a]] = mid[~same_as_a]
        halvings += 1
        log(f"  halving {halvings}: {len(js)} brackets")
    np.savez(prefix + ".brackets.npz", lo=a_x, hi=b_x, lo_over=a_o, hi_over=b_o)

    # Islands: a run of overturning samples, from the bracket before it to the one after.
    rows = []
    k = 0
    nb = len(a_x)
    start = None
    if over[0]:
        start = ("scan start", xs[0], xs[0])
    for j in range(nb):
        if not a_o[j] and b_o[j]:  # safe below, overturns above: an island starts
            start = ("bracket", a_x[j], b_x[j])
        else:
            rows.append((start, ("bracket", a_x[j], b_x[j])))
            start = None
    if start is not None:
        rows.append((start, ("scan end", xs[-1], xs[-1])))
    with open(prefix + ".islands.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["island", "from", "from_safe", "from_collapse", "to", "to_collapse", "to_safe", "width_rel"])
        for i, (s, e) in enumerate(rows, 1):
            fs, fc = (s[1], s[2]) if s[0] == "bracket" else ("", s[1])
            tc, ts = (e[1], e[2]) if e[0] == "bracket" else (e[1], "")
            w.writerow([i, repr(float(fc)), "" if fs == "" else repr(float(fs)), repr(float(fc)), repr(float(tc)),
                        repr(float(tc)), "" if ts == "" else repr(float(ts)), f"{(tc - fc) / fc:.3e}"])
    log(f"islands: {len(rows)} written to {prefix}.islands.csv")
    return 0


if __name__ == "__main__":
    sys.exit(main())
