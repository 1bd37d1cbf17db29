#!/usr/bin/python3
"""Independent check of expected/fragility: the lognormal fits of fragility_fits.csv
refitted in Python from fragility_points.csv, without numpy or scipy and without the
C++ code's method.

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

Usage: independent.py DIR (the folder holding the scene's CSV files).  Exit 0 when all
agree to 1e-7 relative (the simplex stops at a simplex of 1e-12, Newton at a step
of 1e-13; a step is halved while ln L falls).
"""
import csv
import math
import random
import sys

TOL = 1e-7


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
    print("fragility independent: %d values, worst relative deviation %.2g" % (checked, worst))
    for x in failures:
        print("  FAIL " + x)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
