#!/usr/bin/python3
"""The censored lognormal fit of studies::fit_lognormal, computed apart with mpmath at 40 digits.

    censored_mle.py --collapsed Q [Q ...] [--censored Q ...] [--json]

Maximises ln L = sum_collapsed ln[phi(z)/(beta q)] + sum_censored ln[1 - Phi(z)], z = ln(q/median)/beta,
by solving its two score equations (mpmath.findroot, from the best point of a grid over (ln median,
ln beta)), and, where every collapse is at one q = c and every censored point at one q = c e^D, D > 0,
also by the one-dimensional reduction of docs/fragility.md ("Equal and censored collapse values"):
n u + m h(u - 1/u) = 0 with u < 0, beta = D |u|, ln median = ln c + D u^2 (h the normal hazard).
The two must agree to 1e-25.  Prints median, beta and ln L to 20 digits (the values
tests/test_fragility.cpp holds), or says why ln L has no maximum (exit 3).
"""
import argparse
import json
import sys

import mpmath as mp

mp.mp.dps = 40


def log_sf(z):
    return mp.log(mp.erfc(z / mp.sqrt(2)) / 2)


def hazard(z):
    return mp.npdf(z) / (mp.erfc(z / mp.sqrt(2)) / 2)


def log_likelihood(mu, beta, col, cen):
    s = mp.mpf(0)
    for y in col:
        s += -mp.log(beta) - ((y - mu) / beta) ** 2 / 2 - mp.log(2 * mp.pi) / 2 - y
    for c in cen:
        s += log_sf((c - mu) / beta)
    return s


def score(mu, lb, col, cen):
    """d ln L / d mu and d ln L / d ln beta."""
    b = mp.exp(lb)
    gm = gb = mp.mpf(0)
    for y in col:
        z = (y - mu) / b
        gm += z / b
        gb += z * z - 1
    for c in cen:
        z = (c - mu) / b
        gm += hazard(z) / b
        gb += z * hazard(z)
    return gm, gb


def fit_by_score(col, cen):
    lo, hi = min(col + cen) - 1, max(col + cen) + 4
    grid = ((lo + (hi - lo) * i / 80, -4 + 7 * mp.mpf(j) / 80) for i in range(81) for j in range(81))
    start = max(grid, key=lambda x: log_likelihood(x[0], mp.exp(x[1]), col, cen))
    mu, lb = mp.findroot(lambda m, l: score(m, l, col, cen), start)
    return mu, mp.exp(lb)


def fit_by_reduction(n, y0, m, c):
    d = c - y0
    u = mp.findroot(lambda u: n * u + m * hazard(u - 1 / u), (mp.mpf(-20), mp.mpf("-0.05")), solver="anderson")
    return y0 + d * u * u, d * abs(u)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--collapsed", nargs="+", required=True)
    ap.add_argument("--censored", nargs="*", default=[])
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    col = [mp.log(mp.mpf(q)) for q in a.collapsed]
    cen = [mp.log(mp.mpf(q)) for q in a.censored]
    if len(set(col)) == 1 and not any(c > col[0] for c in cen):
        print("no maximum: every collapse at one q and no censored point above it", file=sys.stderr)
        return 3
    mu, beta = fit_by_score(col, cen)
    if len(set(col)) == 1 and len(set(cen)) == 1 and cen[0] > col[0]:
        mu1, beta1 = fit_by_reduction(len(col), col[0], len(cen), cen[0])
        if abs(mu1 - mu) > mp.mpf("1e-25") or abs(beta1 - beta) > mp.mpf("1e-25"):
            print("the two maximisations disagree: %s %s against %s %s" % (mu, beta, mu1, beta1), file=sys.stderr)
            return 1
    lnl = log_likelihood(mu, beta, col, cen)
    if a.json:
        print(json.dumps({"median": float(mp.exp(mu)), "beta": float(beta), "log_likelihood": float(lnl)}))
    else:
        print("median %s beta %s log_likelihood %s" % (mp.nstr(mp.exp(mu), 20), mp.nstr(beta, 20), mp.nstr(lnl, 20)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
