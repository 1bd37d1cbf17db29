#!/usr/bin/python3
"""Independent check of expected/spectrum: every confirmed boundary of
spectrum_intervals.csv re-simulated at both ends of its bracket by a second
implementation of the model, and spectrum_summary.csv's counts recounted.

The model (the scene's: table1_search() in reproduce/scenes/records_analysis.cpp,
records::collapses_at, dynamics::Model), written here from its statement, not from
the C++ code's method:

- Linearised eq. 3 in the paper's sign, on the corner sigma = sgn theta:
      theta'' = p^2 (theta + a(t)/g - sigma alpha),
  a(t) the record's samples (ESM ASCII, cm/s^2) times 0.01 / 9.81, linear between
  samples k dt.  (The equation is odd in (theta, a): the sign convention cannot
  change an outcome.)
- At rest the block lifts when |a|/g first exceeds alpha, on the corner sgn a.
- An impact at theta = 0 sends the block to the other corner with its angular
  velocity times Housner's e = 1 - 1.5 sin^2 alpha; the block rests when the
  rebound is slower than 1e-9 alpha p or comes within 1e-6/p of the previous impact
  (the model's rest rules, SimulationOptions).
- It overturns when |theta| reaches pi/2 during the record, or in the free rocking
  after it (ground at rest), followed to the end.

How, which is this script's own: on each sample interval the equation is linear with
a linear forcing, so theta(u) = theta0 + A (cosh pu - 1) + (omega0/p) sinh pu
+ (c1/p)(sinh pu - pu), A = theta0 + a0/g - sigma alpha.  All blocks on one record
are stepped together (numpy) through the intervals on which a bound on the chord's
error, (p dt)^2/8 max|theta''/p^2| at the ends, keeps sigma theta inside (0, pi/2):
nothing can happen there.  Any other interval is solved alone: the zeros of
theta'(u) in closed form (a quadratic in e^{pu}) split it into monotone parts, and
the first part where sigma theta reaches 0 or pi/2 holds the event, located by a
safeguarded Newton iteration.  The free rocking after the record is decided in
closed form, with no time limit: with the ground at rest the block goes over the
top iff sigma theta - alpha + sigma omega/p > 0, and otherwise returns to the
ground, where an impact either gives it that again or leaves it below the energy it
would need for ever after.  (The C++ code follows the free rocking with its solver
for 200/p and then decides by energy.)

Checked:
1. every interval end whose check is "confirmed": the block overturns at its
   *_collapse p and not at its *_safe p.  Ill-conditioned ends (the input times
   1 +- 1e-13 flips an outcome: rounding decides them, no solver can) are excluded
   and counted, as are the grid's own ends, which have no bracket;
2. the intervals' structure: each end's bracket ordered and 1e-6 relative wide at
   most (2e-6 allowed), from/to equal to the brackets' collapse ends, intervals
   ordered and disjoint per (record, alpha);
3. spectrum_summary.csv against spectrum_intervals.csv: one row per (record, alpha),
   the number of intervals, lowest_p, lowest_over_table1 (from its table1_p), the
   boundaries and their verdicts counted.  (table1_on_island_off_grid needs the grid,
   which expected/ does not hold: not checked.)

Usage: independent.py DIR (the folder holding spectrum_intervals.csv and
spectrum_summary.csv).  The records are read from $ROCKING_RECORDS or
<repository>/../shared/records; without them the check exits 77, which ctest
reports as skipped (SKIP_RETURN_CODE in CMakeLists.txt).  Exit 0 when all agree,
1 on any disagreement (each named), 2 on bad usage.
"""
import csv
import math
import os
import sys
import time

import numpy as np

SKIP = 77
HALF_PI = math.pi / 2
REST_VELOCITY = 1e-9  # a rebound slower than this times alpha p rests
MICRO_TIME = 1e-6  # an impact within this over p of the previous one: at rest
BRACKET_REL = 2e-6  # a bracket's relative width, at most (bisected to 1e-6)


# ---------------------------------------------------------------- the records

def records_dir():
    env = os.environ.get("ROCKING_RECORDS")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    return os.path.normpath(os.path.join(here, "..", "..", "..", "shared", "records"))


def read_esm(path):
    """dt (s) and the samples in g (cm/s^2 * 0.01 / 9.81), with the header's NDATA
    and PGA checked against the samples."""
    header, samples = {}, []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if ":" in s and not samples:
                key, _, value = s.partition(":")
                header[key.strip()] = value.strip()
            else:
                samples.append(float(s))
    if header.get("UNITS") != "cm/s^2":
        raise ValueError(f"{path}: UNITS {header.get('UNITS')!r}, expected cm/s^2")
    if int(header["NDATA"]) != len(samples):
        raise ValueError(f"{path}: NDATA {header['NDATA']} but {len(samples)} samples")
    pga = abs(float(header["PGA_CM/S^2"]))
    peak = max(abs(x) for x in samples)
    if abs(pga - peak) > 1e-6 * peak + 1e-6:
        raise ValueError(f"{path}: PGA_CM/S^2 {pga} but max |a| {peak}")
    dt = float(header["SAMPLING_INTERVAL_S"])
    return dt, [x * 0.01 / 9.81 for x in samples]


# ---------------------------------------------------------------- one interval, alone

def shx(x):
    """sinh x - x without cancellation."""
    if abs(x) > 0.5:
        return math.sinh(x) - x
    x2 = x * x
    term, total, n = x * x2 / 6.0, 0.0, 3
    while True:
        total += term
        if abs(term) <= 1e-18 * abs(total):
            return total
        term *= x2 / ((n + 1) * (n + 2))
        n += 2


def ch1(x):
    """cosh x - 1 without cancellation."""
    s = math.sinh(0.5 * x)
    return 2.0 * s * s


class Piece:
    """theta on one stretch of a sample interval from (theta0, omega0) on corner sg,
    the input a0 + c1 u (in g), u from 0."""

    __slots__ = ("p", "th0", "om0", "c1", "A", "W", "lin")

    def __init__(self, p, th0, om0, sg, alpha, a0, c1):
        self.p, self.th0, self.om0, self.c1 = p, th0, om0, c1
        self.lin = a0 - sg * alpha
        self.A = th0 + self.lin
        self.W = om0 + c1

    def theta(self, u):
        x = self.p * u
        return self.th0 + self.A * ch1(x) + self.om0 * math.sinh(x) / self.p + self.c1 * shx(x) / self.p

    def omega(self, u):
        x = self.p * u
        return self.om0 + self.p * self.A * math.sinh(x) + self.W * ch1(x)

    def accel(self, u):  # theta''
        x = self.p * u
        return self.p * (self.p * self.A * math.cosh(x) + self.W * math.sinh(x))

    def critical(self, h):
        """The zeros of theta' in (0, h), in order: with s = e^{pu},
        (W + pA) s^2 - 2 c1 s + (W - pA) = 0."""
        pa = self.p * self.A
        a2, b, c0 = self.W + pa, -2.0 * self.c1, self.W - pa
        roots = []
        if a2 == 0.0:
            if b != 0.0:
                roots = [-c0 / b]
        else:
            disc = b * b - 4.0 * a2 * c0
            if disc >= 0.0:
                q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
                roots = [q / a2] + ([c0 / q] if q != 0.0 else [])
        out = []
        for s in roots:
            if not s > 0.0:
                continue
            u = math.log(s) / self.p
            for _ in range(2):  # polish on theta' itself
                d = self.accel(u)
                if d == 0.0:
                    break
                u -= self.omega(u) / d
            if 0.0 < u < h:
                out.append(u)
        return sorted(out)


def find_level(f, df, lo, hi, flo, fhi):
    """The root of f in [lo, hi] (f(lo), f(hi) of opposite signs or f(hi) = 0):
    Newton's steps kept inside the bracket, bisection where they leave it."""
    if fhi == 0.0:
        return hi
    u = lo + (hi - lo) * flo / (flo - fhi)
    for _ in range(200):
        fu = f(u)
        if fu == 0.0:
            return u
        if (fu > 0) == (flo > 0):
            lo, flo = u, fu
        else:
            hi, fhi = u, fu
        d = df(u)
        nu = u - fu / d if d != 0.0 else 0.5 * (lo + hi)
        if not (lo < nu < hi):
            nu = 0.5 * (lo + hi)
        if abs(nu - u) <= 2e-16 * max(abs(u), 1e-300) or hi - lo <= 4e-16 * max(abs(hi), 1e-300):
            return nu
        u = nu
    return u


class Block:
    """One run: the state and the rules of the model."""

    __slots__ = ("p", "alpha", "e", "th", "om", "sg", "resting", "fallen", "t_last", "impacts", "rounding_rests")

    def __init__(self, p, alpha):
        self.p, self.alpha = p, alpha
        s = math.sin(alpha)
        self.e = 1.0 - 1.5 * s * s
        self.th = self.om = 0.0
        self.sg = 1.0
        self.resting, self.fallen = True, False
        self.t_last = None
        self.impacts = self.rounding_rests = 0

    def impact(self, t, om_i):
        self.impacts += 1
        micro = self.t_last is not None and t - self.t_last < MICRO_TIME / self.p
        self.t_last = t
        self.th = 0.0
        self.sg = -self.sg
        self.om = self.e * om_i
        if micro or abs(self.om) < REST_VELOCITY * self.alpha * self.p:
            self.om = 0.0
            self.resting = True

    def interval(self, k, dt, ak, ak1):
        """Sample interval k, [k dt, (k + 1) dt], from the state at its start, with
        all its events."""
        c1 = (ak1 - ak) / dt
        t0, te = k * dt, (k + 1) * dt
        t = t0
        for _ in range(10 ** 7):  # a guard: each pass ends at te, an impact, a rest or the fall
            if not (t < te and not self.fallen):
                return
            if self.resting:
                a_here = ak + c1 * (t - t0)
                if abs(a_here) > self.alpha:
                    a0 = a_here
                elif c1 > 0 and ak1 > self.alpha:
                    t, a0 = max(t, t0 + (self.alpha - ak) / c1), self.alpha
                elif c1 < 0 and ak1 < -self.alpha:
                    t, a0 = max(t, t0 + (-self.alpha - ak) / c1), -self.alpha
                else:
                    return
                if not t < te:
                    return
                self.resting = False
                self.sg = 1.0 if a0 > 0 else -1.0
                self.th = self.om = 0.0
            else:
                a0 = ak + c1 * (t - t0)
            t = self.stretch(t, te - t, a0, c1)
        raise RuntimeError(f"p = {self.p}, alpha = {self.alpha}: no end to interval {k}")

    def stretch(self, t, h, a0, c1):
        """Rocking from t for h at most: to the first impact (returns its time) or
        fall, or to t + h."""
        sg = self.sg
        pc = Piece(self.p, self.th, self.om, sg, self.alpha, a0, c1)
        cuts = [0.0] + pc.critical(h) + [h]
        va = sg * pc.th0  # sigma theta at the part's start
        for ua, ub in zip(cuts, cuts[1:]):
            vb = sg * pc.theta(ub)
            if vb >= HALF_PI:  # the fall
                self.fallen = True
                return t + ub
            if vb <= 0.0 and va > 0.0:  # an impact in this monotone part
                u = find_level(lambda s: sg * pc.theta(s), lambda s: sg * pc.omega(s), ua, ub, va, vb)
                self.impact(t + u, pc.omega(u))
                return t + u
            if vb < 0.0 and va <= 0.0:
                # sigma theta below the ground from the start: the block left it
                # only within rounding (theta0 = 0) and is pressed back: at rest.
                self.th = self.om = 0.0
                self.resting = True
                self.rounding_rests += 1
                return t
            va = vb
        self.th, self.om = pc.theta(h), pc.omega(h)
        return t + h

    def free_rocking_overturns(self):
        """After the record, the ground at rest: theta - sigma alpha =
        (u e^{pt} + v e^{-pt})/2 with sigma u = sigma theta - alpha + sigma omega/p."""
        if self.fallen:
            return True
        if self.resting:
            return False
        th, om, sg, p, al = self.th, self.om, self.sg, self.p, self.alpha
        while True:
            if sg * th - al + sg * om / p >= 0.0:
                return True  # over the top (or onto it, where the energy decides: >= 0)
            d = th - sg * al
            wi2 = om * om - p * p * d * d + p * p * al * al  # omega^2 at theta = 0
            wi = math.sqrt(max(wi2, 0.0))
            if self.e * wi < p * al:
                return False  # below the barrier on the near side, and for ever after
            th, om, sg = 0.0, -sg * self.e * wi, -sg  # the rebound, on the other corner


# ---------------------------------------------------------------- many blocks, one record

def series_shx(x):
    x2 = x * x
    term, total = x * x2 / 6.0, np.zeros_like(x)
    for n in range(3, 40, 2):
        total = total + term
        term = term * x2 / ((n + 1) * (n + 2))
    return total


def run_record(a, dt, blocks):
    """Every block on the record a (in g): overturned or not."""
    p = np.array([b.p for b in blocks])
    al = np.array([b.alpha for b in blocks])
    x = p * dt
    if np.any(x > 1.0):
        raise ValueError("p dt > 1: the series below are for short intervals")
    SH, CH1, SHX = np.sinh(x), 2 * np.sinh(0.5 * x) ** 2, series_shx(x)
    bound = x * x / 8.0
    th = np.zeros(len(blocks))
    om = np.zeros(len(blocks))
    sg = np.ones(len(blocks))
    rocking = np.zeros(len(blocks), dtype=bool)
    active = np.ones(len(blocks), dtype=bool)  # not fallen

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

    for k in range(len(a) - 1):
        ak, ak1 = a[k], a[k + 1]
        c1 = (ak1 - ak) / dt
        lin = ak - sg * al
        A = th + lin
        th1 = th + A * CH1 + om * SH / p + c1 * SHX / p
        om1 = om + p * A * SH + (om + c1) * CH1
        e1 = th1 + ak1 - sg * al
        b = bound * np.maximum(np.abs(A), np.abs(e1))
        s0, s1 = sg * th, sg * th1
        quiet = rocking & (np.minimum(s0, s1) - b > 0.0) & (np.maximum(s0, s1) + b < HALF_PI)
        th = np.where(quiet, th1, th)
        om = np.where(quiet, om1, om)
        lifts = max(abs(ak), abs(ak1)) > al
        event = active & ~quiet & (rocking | lifts)
        js = np.flatnonzero(event)
        if len(js):
            pull(js)
            for j in js:
                blocks[j].interval(k, dt, ak, ak1)
            push(js)
    pull(range(len(blocks)))
    return [blk.free_rocking_overturns() for blk in blocks]


# ---------------------------------------------------------------- the expected files

def read_csv(directory, name):
    with open(os.path.join(directory, name), newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return [dict(zip(rows[0], r)) for r in rows[1:]]


class Report:
    def __init__(self):
        self.failures = []

    def fail(self, message):
        self.failures.append(message)
        print("  DISAGREES: " + message)


def check_structure(intervals, rep):
    """Each end's bracket, from/to against it, the intervals' order per (record, alpha).
    Returns the confirmed ends: (record, alpha, p_collapse, p_safe, label)."""
    ends = []
    last = {}
    for r in intervals:
        key = (r["record"], r["alpha"])
        label = f"{r['record']} alpha {r['alpha']} interval {r['interval']}"
        lo, hi = float(r["from"]), float(r["to"])
        if not lo < hi:
            rep.fail(f"{label}: from {lo} not below to {hi}")
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
            if col:
                continue  # placed by rounding within its grid gap: no bracket to hold
            if at != coll:
                rep.fail(f"{label} {side}: {at} is not its bracket's collapse end {coll}")
            ordered = safe < coll if side == "from" else coll < safe
            if not ordered or abs(coll - safe) > BRACKET_REL * max(coll, safe):
                rep.fail(f"{label} {side}: bracket [{safe}, {coll}] not ordered or wider than {BRACKET_REL:g}")
            if check == "confirmed":
                ends.append((r["record"], float(r["alpha"]), coll, safe, f"{label} {side}"))
    return ends


def check_summary(intervals, summary, rep):
    """spectrum_summary.csv recounted from spectrum_intervals.csv."""
    per = {}
    for r in intervals:
        per.setdefault((r["record"], r["alpha"]), []).append(r)
    seen = set()
    checked = 0
    for s in summary:
        key = (s["record"], s["alpha"])
        seen.add(key)
        rows = per.get(key, [])
        label = f"summary {s['record']} alpha {s['alpha']}"
        counts = {"boundaries": 0, "ill_conditioned": 0, "confirmed": 0, "disagrees": 0}
        for r in rows:
            for side in ("from", "to"):
                c = r[f"{side}_check"]
                if c in ("grid start", "grid end"):
                    continue
                counts["boundaries"] += 1
                counts["ill_conditioned"] += c == "ill-conditioned"
                counts["confirmed"] += c == "confirmed"
                counts["disagrees"] += c == "second solver disagrees"
        want = {"intervals": str(len(rows))}
        want.update({k: str(v) for k, v in counts.items()})
        for col, v in want.items():
            if s[col] != v:
                rep.fail(f"{label}: {col} is {s[col]}, the intervals give {v}")
        if rows:
            lowest = float(rows[0]["from"])
            if float(s["lowest_p"]) != lowest:
                rep.fail(f"{label}: lowest_p {s['lowest_p']}, the first interval's from is {rows[0]['from']}")
            if s["table1_p"] not in ("none below 30",):
                ratio = lowest / float(s["table1_p"])
                if abs(float(s["lowest_over_table1"]) - ratio) > 1e-14 * ratio:
                    rep.fail(f"{label}: lowest_over_table1 {s['lowest_over_table1']}, lowest_p / table1_p is {ratio!r}")
        elif s["lowest_p"] != "none":
            rep.fail(f"{label}: lowest_p {s['lowest_p']} with no interval")
        checked += 1
    for key in per:
        if key not in seen:
            rep.fail(f"summary: no row for {key[0]} alpha {key[1]}, which has intervals")
    return checked


def main():
    if len(sys.argv) != 2:
        print("usage: independent.py DIR (holding spectrum_intervals.csv, spectrum_summary.csv)", file=sys.stderr)
        return 2
    directory = sys.argv[1]
    root = records_dir()
    intervals = read_csv(directory, "spectrum_intervals.csv")
    summary = read_csv(directory, "spectrum_summary.csv")
    rep = Report()
    start = time.time()

    ends = check_structure(intervals, rep)
    n_ends = sum(1 for r in intervals for s in ("from", "to") if r[f"{s}_check"] not in ("grid start", "grid end"))
    ill = [f"{r['record']} alpha {r['alpha']} interval {r['interval']} {s}"
           for r in intervals for s in ("from", "to") if r[f"{s}_check"] == "ill-conditioned"]
    other = n_ends - len(ends) - len(ill)
    n_summary = check_summary(intervals, summary, rep)
    print(f"  structure: {len(intervals)} intervals, {n_ends} boundaries ({len(ends)} confirmed, "
          f"{len(ill)} ill-conditioned, {other} other); summary: {n_summary} rows recounted")
    for x in ill:
        print(f"  excluded (ill-conditioned: rounding places it, no solver decides it): {x}")

    files = sorted({e[0] for e in ends})
    missing = [f for f in files if not os.path.isfile(os.path.join(root, f))]
    if missing:
        if rep.failures:  # what could be checked without the records disagrees: not a skip
            print(f"independent check: {len(rep.failures)} disagreement(s) in {directory} (records absent)")
            return 1
        where = "absent" if not os.path.isdir(root) else f"without {len(missing)} of the {len(files)} records"
        print(f"independent_spectrum: SKIPPED: the records folder {root} is {where} ($ROCKING_RECORDS or "
              f"../shared/records beside the repository); the structure and counts above agree, the brackets "
              f"need the records")
        return SKIP

    agree = 0
    for f in files:
        dt, a = read_esm(os.path.join(root, f))
        mine = [e for e in ends if e[0] == f]
        blocks = []
        for _, alpha, coll, safe, _ in mine:
            blocks += [Block(coll, alpha), Block(safe, alpha)]
        t0 = time.time()
        out = run_record(a, dt, blocks)
        n_ok = 0
        for i, (_, alpha, coll, safe, label) in enumerate(mine):
            at_coll, at_safe = out[2 * i], out[2 * i + 1]
            if at_coll and not at_safe:
                n_ok += 1
            else:
                rep.fail(f"{label}: bracket [{safe!r} safe, {coll!r} collapse] at alpha {alpha}: "
                         f"overturns at the collapse end: {'yes' if at_coll else 'NO'}, "
                         f"at the safe end: {'YES' if at_safe else 'no'}")
        agree += n_ok
        impacts = sum(b.impacts for b in blocks)
        print(f"  {f}: {n_ok} of {len(mine)} brackets agree ({len(blocks)} runs, {impacts} impacts, "
              f"{time.time() - t0:.1f} s)")

    print(f"independent check: {len(ends)} confirmed brackets re-simulated at both ends, {agree} agree, "
          f"{len(ends) - agree} disagree; {len(ill)} ill-conditioned excluded; {time.time() - start:.1f} s")
    if rep.failures:
        print(f"independent check: {len(rep.failures)} disagreement(s) in {directory}")
        return 1
    print(f"independent check: {directory} agrees")
    return 0


if __name__ == "__main__":
    sys.exit(main())
