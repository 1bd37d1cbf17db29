#!/usr/bin/python3
"""The multiple-stripe fragility fit of studies::fit_stripes, computed apart with mpmath at 40 digits.

    stripe_mle.py --stripe Q N Z [--stripe Q N Z ...] [--json]
    stripe_mle.py --intervals FILE.json [--json]
    stripe_mle.py --fragility FILE.json

Maximises the binomial likelihood of Baker (2015) with a real count z_j (the sum of the records'
overturned shares at stripe j, of n_j records),

    ln L = sum_j [z_j ln Phi(u_j) + (n_j - z_j) ln Phi(-u_j)],   u_j = (ln q_j - ln median) / beta,

by solving its two score equations in (ln median, ln beta) (mpmath.findroot, from the best point of a
grid), where studies::fit_stripes runs Newton's method in (1/beta, ln median/beta) in doubles.  Before
fitting it decides, by its own reading of the conditions of docs/fragility.md ("Three capacities"),
whether ln L has a maximum with beta > 0, and otherwise prints why (exit 3): every share 0, every share
1, one stripe, a step from 0 to 1 (perfect separation), or a share that does not rise with q (the
records-weighted covariance of ln q and the share, with the shares' differences taken as exact
fractions, not > 0).

--intervals reads {"q_min", "q_max", "points", "sets": [[[from, to], ...] per record]} and, with
"bootstrap": {"resamples", "seed", "level"}, also prints the bootstrap interval (as below): the stripes are
the main grid's steps (q_k = q_min e^{k ln(q_max/q_min)/(points-1)}, the last q_max), each at its
geometric midpoint, and a record's share the length in ln q of its set within the step over the step's
(at 40 digits).  --fragility reads `rocking fragility --method refine --json` and for every block
recomputes the stripes from each record's intervals, fits them and, where the block's stripe fit has a
bootstrap, re-runs it: GSL's mt19937 (gsl_rng_set, gsl_rng_uniform_int) rebuilt on Python's Mersenne
Twister, one draw per record, the records in the order of their "sha256" (the order listed between equal
ones: rocking's draw order since issue 40), resamples without a maximum redrawn, percentiles by linear
interpolation.
It prints one JSON object per block.  Prints median, beta and ln L to 20 digits (the values
tests/test_stripe_fit.cpp holds).
"""
import argparse
import json
import math
import os
import sys
from fractions import Fraction

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from independent_check import GslMt19937, percentile  # noqa: E402

mp.mp.dps = 40


def log_phi(u):
    return mp.log(mp.ncdf(u))


def mills(u):
    return mp.npdf(u) / mp.ncdf(u)


def log_likelihood(mu, beta, stripes):
    s = mp.mpf(0)
    for x, n, z in stripes:
        u = (x - mu) / beta
        if z > 0:
            s += z * log_phi(u)
        if n - z > 0:
            s += (n - z) * log_phi(-u)
    return s


def scores(mu, lb, stripes):
    """d ln L / d mu and d ln L / d ln beta, each times -beta or -1: sum w_j and sum w_j u_j."""
    beta = mp.exp(lb)
    s0 = s1 = mp.mpf(0)
    for x, n, z in stripes:
        u = (x - mu) / beta
        w = (z * mills(u) if z > 0 else 0) - ((n - z) * mills(-u) if n - z > 0 else 0)
        s0 += w
        s1 += w * u
    return s0, s1


def why_no_maximum(raw):
    """raw: (q, n, z) as given (floats).  The reason, or None."""
    shares = [Fraction(z) / Fraction(n) for _, n, z in raw]
    if all(s == 0 for s in shares):
        return "every share 0"
    if all(s == 1 for s in shares):
        return "every share 1"
    if len(raw) == 1:
        return "one stripe"
    overturned_at_all = [q for (q, _, _), s in zip(raw, shares) if s > 0]
    not_wholly = [q for (q, _, _), s in zip(raw, shares) if s < 1]
    if max(not_wholly) <= min(overturned_at_all):
        return "perfect separation"
    total = sum(Fraction(n) for _, n, _ in raw)
    mean_share = sum(Fraction(z) for _, _, z in raw) / total
    mean_x = sum(n * mp.log(q) for q, n, _ in raw) / mp.mpf(total.numerator) * total.denominator
    cov = mp.mpf(0)
    for (q, n, _), s in zip(raw, shares):
        d = s - mean_share
        if d != 0:
            cov += n * (mp.log(q) - mean_x) * mp.mpf(d.numerator) / d.denominator
    if not cov > 0:
        return "share does not rise"
    return None


def fit(raw, start=None):
    """(median, beta, ln L) at 40 digits; start: (mu, ln beta) near the maximum, else a grid's best."""
    stripes = [(mp.log(q), mp.mpf(n), mp.mpf(z)) for q, n, z in raw]
    if start is None:
        xs = [x for x, _, _ in stripes]
        lo, hi = min(xs) - 2, max(xs) + 2
        start = max(((lo + (hi - lo) * i / 40, -6 + 8 * mp.mpf(j) / 40) for i in range(41) for j in range(41)),
                    key=lambda p: log_likelihood(p[0], mp.exp(p[1]), stripes))
    mu, lb = mp.findroot(lambda m, l: scores(m, l, stripes), start)
    s0, s1 = scores(mu, lb, stripes)
    scale = sum(n for _, n, _ in stripes)
    if abs(s0) > mp.mpf("1e-30") * scale or abs(s1) > mp.mpf("1e-30") * scale:
        raise RuntimeError("the scores did not vanish: %s %s" % (s0, s1))
    beta = mp.exp(lb)
    lnl = log_likelihood(mu, beta, stripes)
    # A maximum, not a saddle: ln L lower a little away from it in four directions.
    for dm, dl in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        h = mp.mpf("1e-6")
        if not log_likelihood(mu + h * dm, mp.exp(lb + h * dl), stripes) < lnl:
            raise RuntimeError("not a maximum")
    return mp.exp(mu), beta, lnl


def grid(q_min, q_max, points):
    """log_grid's main points in doubles, as studies::log_grid makes them (the last is q_max itself)."""
    span = math.log(q_max / q_min)
    return [q_max if k == points - 1 else q_min * math.exp(span * k / (points - 1)) for k in range(points)]


def stripes_from_sets(q_min, q_max, points, sets):
    """(q_j, from_j, to_j) and shares[r][j] (mpf), the share of step j that record r's set covers in ln q."""
    g = grid(q_min, q_max, points)
    steps = [(g[k - 1], g[k]) for k in range(1, len(g))]
    shares = []
    for spans in sets:
        row = []
        for a, b in steps:
            covered = mp.mpf(0)
            for lo, hi in spans:
                lo, hi = max(mp.mpf(a), mp.mpf(lo)), min(mp.mpf(b), mp.mpf(hi))
                if hi > lo:
                    covered += mp.log(hi) - mp.log(lo)
            row.append(covered / (mp.log(mp.mpf(b)) - mp.log(mp.mpf(a))))
        shares.append(row)
    return [(math.sqrt(a * b), a, b) for a, b in steps], shares


def raw_stripes(centres, shares):
    """(q, n, z) with z the sum of the shares rounded to a double (the Fraction test needs a rational)."""
    n = len(shares)
    return [(q, n, float(mp.fsum(row[j] for row in shares))) for j, (q, _, _) in enumerate(centres)]




def bootstrap(centres, shares, resamples, seed, level, start):
    rng, n = GslMt19937(seed), len(shares)
    medians, betas = [], []
    while len(medians) < resamples:
        draw = [shares[rng.uniform_int(n)] for _ in range(n)]
        raw = raw_stripes(centres, draw)
        if why_no_maximum(raw) is not None:
            continue
        try:
            m, b, _ = fit(raw, start)
        except (ZeroDivisionError, ValueError, RuntimeError):
            m, b, _ = fit(raw)
        medians.append(float(m))
        betas.append(float(b))
    t = (1 - level) / 2
    return {"median": [percentile(medians, t), percentile(medians, 1 - t)],
            "beta": [percentile(betas, t), percentile(betas, 1 - t)]}


def result(raw):
    why = why_no_maximum(raw)
    if why is not None:
        return {"no_fit": why}
    m, b, lnl = fit(raw)
    return {"median": m, "beta": b, "log_likelihood": lnl}


def show(r, as_json):
    if "no_fit" in r:
        print("no maximum: " + r["no_fit"], file=sys.stderr)
        return 3
    if as_json:
        print(json.dumps({k: float(v) for k, v in r.items()}))
    else:
        print("median %s beta %s log_likelihood %s" % tuple(mp.nstr(r[k], 20) for k in
                                                           ("median", "beta", "log_likelihood")))
    return 0


def fragility(path):
    doc = json.load(open(path))
    g = doc["grid"]
    for block in doc["blocks"]:
        # The records in the order the bootstrap draws them (issue 40): by their sha256, the order listed
        # between equal ones; the shares' sums at 40 digits do not see the order.
        records = [r for _, r in sorted(enumerate(block["records"]), key=lambda kr: (kr[1]["sha256"], kr[0]))]
        sets = [[(i["from"], i["to"]) for i in r["intervals"]] for r in records]
        centres, shares = stripes_from_sets(g["q_min"], g["q_max"], g["points"], sets)
        raw = raw_stripes(centres, shares)
        out = {"alpha": block["alpha"], "p": block["p"], "stripes": [
            {"q": q, "from": a, "to": b, "share": float(z / len(shares))} for (q, a, b), (_, _, z) in
            zip(centres, raw)]}
        r = result(raw)
        out["no_fit"] = r.get("no_fit")
        out["fit"] = None if "no_fit" in r else {"median": float(r["median"]), "beta": float(r["beta"])}
        given = (block.get("fits") or {}).get("stripes") or {}
        boot = (given.get("fit") or {}).get("bootstrap")
        if out["fit"] and boot:
            start = (mp.log(r["median"]), mp.log(r["beta"]))
            out["fit"]["bootstrap"] = bootstrap(centres, shares, boot["resamples"], boot["seed"], boot["level"],
                                                start)
        print(json.dumps(out))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--stripe", nargs=3, action="append", metavar=("Q", "N", "Z"))
    ap.add_argument("--intervals")
    ap.add_argument("--fragility")
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    if a.fragility:
        return fragility(a.fragility)
    if a.intervals:
        d = json.load(open(a.intervals))
        centres, shares = stripes_from_sets(d["q_min"], d["q_max"], d["points"], d["sets"])
        r = result(raw_stripes(centres, shares))
        status = show(r, a.json)
        if status == 0 and "bootstrap" in d:
            b = d["bootstrap"]
            interval = bootstrap(centres, shares, b["resamples"], b["seed"], b["level"],
                                 (mp.log(r["median"]), mp.log(r["beta"])))
            print(json.dumps(interval) if a.json else "bootstrap median [%r, %r] beta [%r, %r]" % tuple(
                interval["median"] + interval["beta"]))
        return status
    if not a.stripe:
        ap.error("--stripe, --intervals or --fragility")
    raw = [(float(q), float(n), float(z)) for q, n, z in a.stripe]
    return show(result(raw), a.json)


if __name__ == "__main__":
    sys.exit(main())
