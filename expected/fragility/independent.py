#!/usr/bin/python3
"""Independent check of expected/fragility: the lognormal fits of fragility_fits.csv
refitted in Python from fragility_points.csv, without numpy or scipy and without the
C++ code's method, and fragility_eq27.csv recomputed from the same points.

- The fit: maximum likelihood of P(overturn | q) = Phi(ln(q / median) / beta) with the
  censored records kept (Baker 2015).  Without censoring, the closed form (mean and
  1/n deviation of ln q); with it, Newton's method on the score equations (analytic
  gradient, Hessian by central differences of it) from the closed form, where the C++
  code uses GSL's Nelder-Mead simplex.
- The bootstrap: GSL's mt19937 re-implemented through Python's own Mersenne Twister
  (the state GSL's gsl_rng_set builds, Knuth's 2002 initialisation, loaded into
  random.setstate), gsl_rng_uniform_int's rejection rule, each resample refitted as
  above, and the percentiles with linear interpolation between order statistics.
- The counts (collapsed, censored, ill-conditioned) and the empirical shares.
- Eq. 27 at scale: each case's verdict rebuilt from the point's collapse q, the record's
  to_1..to_11 read from expected/table2/table2_records.csv and eq. 27 as printed (the
  formula verified in expected/errata) evaluated with mpmath at 30 digits; then the
  counts per to_k, the share, the Wilson interval (z from Python's NormalDist), the
  blocks and records with any non-conservative case, and the bootstrap over records
  (the same mt19937 draws: records drawn with replacement, each bringing its cases on
  every block, the share per k a count over records x blocks, the same percentile
  interpolation).

Usage: independent.py DIR (the folder holding the scene's CSV files).  Exit 0 when the
fits agree to 1e-7 relative (the simplex stops at a simplex of 1e-12, Newton at a step
of 1e-13; a step is halved while ln L falls), eq. 27's counts and bootstrap bounds
exactly, its share and Wilson bounds to 1e-12 relative.
"""
import csv
import math
import os
import random
import sys
from statistics import NormalDist

from mpmath import mp, mpf, sinh

TOL = 1e-7
TOL_EQ27 = 1e-12
mp.dps = 30
HERE = os.path.dirname(os.path.abspath(__file__))


def read(path):
    notes, rows = [], []
    with open(path) as f:
        lines = [l for l in f if l.strip()]
    body = [l for l in lines if not l.startswith("#")]
    r = csv.reader(body)
    header = next(r)
    for row in r:
        rows.append(dict(zip(header, row)))
    return rows


def phi(z):
    return math.exp(-0.5 * z * z) / math.sqrt(2 * math.pi)


def log_sf(z):  # ln(1 - Phi(z))
    sf = 0.5 * math.erfc(z / math.sqrt(2))
    return math.log(sf) if sf > 0 else -1e300


def hazard(z):  # phi(z) / (1 - Phi(z)); z + 1/z far in the tail
    sf = 0.5 * math.erfc(z / math.sqrt(2))
    return phi(z) / sf if z < 30 else z + 1 / z


def log_likelihood(points, mu, beta):
    s = 0.0
    for q, c in points:
        z = (math.log(q) - mu) / beta
        s += (-0.5 * z * z - 0.5 * math.log(2 * math.pi) - math.log(beta) - math.log(q)) if c else log_sf(z)
    return s


def gradient(points, mu, lb):
    beta = math.exp(lb)
    gm = gb = 0.0
    for q, c in points:
        z = (math.log(q) - mu) / beta
        if c:
            gm += z / beta
            gb += (z * z - 1) / beta
        else:
            h = hazard(z)
            gm += h / beta
            gb += h * z / beta
    return gm, gb * beta  # d/d ln beta


def closed_form(points):
    ln = [math.log(q) for q, c in points if c]
    mu = sum(ln) / len(ln)
    return mu, math.sqrt(sum((x - mu) ** 2 for x in ln) / len(ln))


def fit(points):
    mu, beta = closed_form(points)
    if all(c for _, c in points):
        return math.exp(mu), beta
    lb = math.log(beta)
    for _ in range(200):
        g = gradient(points, mu, lb)
        h = 1e-6
        gp, gq = gradient(points, mu + h, lb), gradient(points, mu - h, lb)
        hp, hq = gradient(points, mu, lb + h), gradient(points, mu, lb - h)
        a, b = (gp[0] - gq[0]) / (2 * h), (hp[0] - hq[0]) / (2 * h)
        c, d = (gp[1] - gq[1]) / (2 * h), (hp[1] - hq[1]) / (2 * h)
        det = a * d - b * c
        if det > 0 and a < 0:  # concave here: Newton's step
            dm = -(d * g[0] - b * g[1]) / det
            dl = -(a * g[1] - c * g[0]) / det
        else:  # otherwise up the gradient
            dm, dl = g[0], g[1]
        # Halve the step until ln L does not fall (a guard far from the maximum).
        here, t = log_likelihood(points, mu, math.exp(lb)), 1.0
        while t > 1e-12 and log_likelihood(points, mu + t * dm, math.exp(lb + t * dl)) < here - 1e-12:
            t /= 2
        mu, lb = mu + t * dm, lb + t * dl
        if abs(t * dm) < 1e-13 and abs(t * dl) < 1e-13:
            break
    return math.exp(mu), math.exp(lb)


class GslMt19937:
    """gsl_rng_mt19937 after gsl_rng_set(seed), through Python's MT19937."""

    def __init__(self, seed):
        s = seed & 0xFFFFFFFF or 4357
        mt = [s]
        for i in range(1, 624):
            mt.append((1812433253 * (mt[-1] ^ (mt[-1] >> 30)) + i) & 0xFFFFFFFF)
        self.r = random.Random()
        self.r.setstate((3, tuple(mt) + (624,), None))

    def uniform_int(self, n):
        scale = 0xFFFFFFFF // n
        while True:
            k = self.r.getrandbits(32) // scale
            if k < n:
                return k


def percentile(v, p):
    v = sorted(v)
    at = p * (len(v) - 1)
    k = int(math.floor(at))
    return v[k] + (at - k) * (v[k + 1] - v[k]) if k + 1 < len(v) else v[-1]


def bootstrap(points, resamples, seed, level):
    rng = GslMt19937(seed)
    med, bet = [], []
    while len(med) < resamples:
        draw = [points[rng.uniform_int(len(points))] for _ in points]
        if sum(c for _, c in draw) < 2:
            continue
        if closed_form(draw)[1] <= 0:
            continue
        m, b = fit(draw)
        med.append(m)
        bet.append(b)
    t = (1 - level) / 2
    return (percentile(med, t), percentile(med, 1 - t), percentile(bet, t), percentile(bet, 1 - t))


def eq27(x):
    """Eq. 27 (the behaviour factor for six pulses) as printed, at 30 digits."""
    x = mpf(x)
    s2 = lambda v: sinh(v) ** 2
    return (mpf(2) / 3 * s2(3 * x) + mpf(1) / 3) / (s2(x) - s2(x / 2) + s2(2 * x) - s2(2.5 * x) - s2(1.5 * x)
                                                    + mpf(2) / 3 * s2(3 * x))


def wilson(k, n, level):
    z = NormalDist().inv_cdf(0.5 + level / 2)
    ph, z2n = k / n, z * z / n
    centre = (ph + z2n / 2) / (1 + z2n)
    half = z * math.sqrt(ph * (1 - ph) / n + z2n / (4 * n)) / (1 + z2n)
    return (0.0 if k == 0 else centre - half, 1.0 if k == n else centre + half)


def record_bootstrap(counts, blocks, resamples, seed, level):
    """counts[r][k]: record r's non-conservative cases for k, of `blocks`."""
    rng, n = GslMt19937(seed), len(counts)
    shares = [[] for _ in range(11)]
    for _ in range(resamples):
        drawn = [counts[rng.uniform_int(n)] for _ in range(n)]
        for k in range(11):
            shares[k].append(sum(c[k] for c in drawn) / (n * blocks))
    t = (1 - level) / 2
    return [(percentile(v, t), percentile(v, 1 - t)) for v in shares]


def check_eq27(pts, rows, to_of, failures):
    """fragility_eq27.csv from fragility_points.csv and table2's to_k; returns the values compared."""
    records = list(dict.fromkeys(p["record"] for p in pts))
    blocks = list(dict.fromkeys((p["alpha"], p["p"]) for p in pts))
    # nc[r][b][k]: the verdict of record r on block b for to_k.
    nc = {r: {} for r in records}
    for p in pts:
        if p["outcome"] == "censored":
            verdict = [False] * 11  # collapse q above q_max, unknown: counted as conservative
        else:
            q = float(p["q_collapse"] if p["q_collapse"] != "-" else p["q_ill_collapse"])
            verdict = [q < eq27(float(p["p"]) * to) for to in to_of[p["record"]]]
        nc[p["record"]][(p["alpha"], p["p"])] = verdict
    counts = [[sum(nc[r][b][k] for b in blocks) for k in range(11)] for r in records]
    n_cases = len(records) * len(blocks)
    checked = 0
    if len(rows) != 11:
        failures.append("eq27: %d rows, not 11" % len(rows))
        return checked
    boot = None
    for k, row in enumerate(rows):
        name = "eq27 to_%d" % (k + 1)
        got = {"k": k + 1, "non_conservative": sum(c[k] for c in counts), "cases": n_cases,
               "blocks_with_any": sum(any(nc[r][b][k] for r in records) for b in blocks),
               "records_with_any": sum(c[k] > 0 for c in counts), "records": len(records)}
        for key, v in got.items():
            checked += 1
            if int(row[key]) != v:
                failures.append("%s %s: Python %d, CSV %s" % (name, key, v, row[key]))
        share = got["non_conservative"] / n_cases
        close = {"share": share}
        close["wilson_lo"], close["wilson_hi"] = wilson(got["non_conservative"], n_cases, 0.95)
        for key, v in close.items():
            checked += 1
            want = float(row[key])
            if abs(v - want) > TOL_EQ27 * abs(want):
                failures.append("%s %s: Python %.17g, CSV %.17g" % (name, key, v, want))
        if boot is None:
            boot = record_bootstrap(counts, len(blocks), int(row["resamples"]), int(row["seed"]),
                                    float(row["boot_level"]))
        for key, v in zip(("boot_lo", "boot_hi"), boot[k]):
            checked += 1
            if v != float(row[key]):  # exact: counts over 64, one interpolation, the same on both sides
                failures.append("%s %s: Python %.17g, CSV %s" % (name, key, v, row[key]))
    return checked


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "."
    pts = read(d + "/fragility_points.csv")
    fits = read(d + "/fragility_fits.csv")
    failures, checked, worst = [], 0, 0.0

    def agree(what, got, want):
        nonlocal checked, worst
        checked += 1
        dev = abs(got - want) / abs(want)
        worst = max(worst, dev)
        if dev > TOL:
            failures.append("%s: Python %.17g, CSV %.17g (rel %.2g)" % (what, got, want, dev))

    for f in fits:
        block = [p for p in pts if p["alpha"] == f["alpha"] and p["p"] == f["p"]]
        points, ill = [], 0
        for p in block:
            if p["outcome"] == "censored":
                points.append((float(p["q_censored"]), False))
            else:
                q = p["q_collapse"] if p["q_collapse"] != "-" else p["q_ill_collapse"]
                points.append((float(q), True))
                ill += p["check"] == "ill-conditioned"
        name = "alpha %s p %s" % (f["alpha"], f["p"])
        counts = (len(points), sum(c for _, c in points), sum(not c for _, c in points), ill)
        want = tuple(int(f[k]) for k in ("records", "collapsed", "censored", "ill_conditioned"))
        if counts != want:
            failures.append("%s: counts %s, CSV %s" % (name, counts, want))
        sfx = "_ill" if ill else ""
        if f["median" + sfx] == "-":
            failures.append("%s: no fit in the CSV" % name)
            continue
        m, b = fit(points)
        agree(name + " median", m, float(f["median" + sfx]))
        agree(name + " beta", b, float(f["beta" + sfx]))
        agree(name + " log_likelihood", log_likelihood(points, math.log(m), b), float(f["log_likelihood" + sfx]))
        if f["resamples"] != "-":
            got = bootstrap(points, int(f["resamples"]), int(f["seed"]), float(f["level"]))
            for v, k in zip(got, ("median_lo", "median_hi", "beta_lo", "beta_hi")):
                agree(name + " " + k, v, float(f[k + sfx]))
    print("fragility independent: %d fit values, worst relative deviation %.2g" % (checked, worst))
    t2 = read(os.path.join(HERE, "..", "table2", "table2_records.csv"))
    to_of = {r["record"]: [float(r["to_%d" % k]) for k in range(1, 12)] for r in t2}
    missing = sorted({p["record"] for p in pts} - set(to_of))
    if missing:
        failures.append("eq27: no to_k in expected/table2 for " + ", ".join(missing))
    else:
        n = check_eq27(pts, read(d + "/fragility_eq27.csv"), to_of, failures)
        print("fragility independent: %d eq. 27 values (counts, bootstrap bounds exact; share, Wilson 1e-12)" % n)
    for x in failures:
        print("  FAIL " + x)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
