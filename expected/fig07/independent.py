#!/usr/bin/python3
"""Independent check of expected/fig07: the jump sum (S2)
    q = cosh(x T) / sum_j dA_j (cosh(x s_j) - 1)
written afresh from the pulse patterns of NOTES.md and evaluated with mpmath at 40 digits
(no cancellation or overflow concerns at that precision).  Tolerances: relative 1e-12
for q (the C++ engine's error is below condition * 1e-16 < 2e-14 here); relative 1e-9
for the diagnostic condition number; absolute 1e-12 for the relative change of q."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from independent_check import Checker, directory_from_argv  # noqa: E402
from mpmath import mp, mpf, cosh  # noqa: E402

mp.dps = 40
PATTERNS = {1: [(1, 1), (-1, 1)], 2: [(1, 1), (mpf(-1) / 2, 1)], 4: [(1, 1), (mpf(-1) / 2, 2)]}


def q_and_condition(case, n, x):
    pulses = [PATTERNS[case][k % 2] for k in range(n)]
    T = sum(d for _, d in pulses)
    tau, prev, terms = mpf(0), mpf(0), []
    for a, d in pulses:
        if a != prev:
            terms.append((a - prev) * (cosh(x * (T - tau)) - 1))
        prev = a
        tau += d
    den = sum(terms)
    return cosh(x * T) / den, sum(abs(t) for t in terms) / den


d = directory_from_argv()
ck = Checker(d)
xs = [mpf(k) / 100 for k in range(5, 201)]
ck.check("fig07.csv", "x", [float(x) for x in xs])
worst = [0.0] * len(xs)
for c in (1, 2, 4):
    for n in (2, 4, 6, 8, 10, 12):
        values = []
        for k, x in enumerate(xs):
            qv, cond = q_and_condition(c, n, x)
            values.append(float(qv))
            worst[k] = max(worst[k], float(cond))
        ck.check("fig07.csv", f"case{c}_N{n}", values, rel_tol=1e-12)
ck.check("fig07.csv", "worst_condition", worst, rel_tol=1e-9)

qs, changes = [], []
for c in (1, 2, 4):
    for x in (mpf("0.25"), mpf("0.5"), mpf(1), mpf("1.5")):
        for n in range(2, 13, 2):
            qn = q_and_condition(c, n, x)[0]
            qs.append(float(qn))
            changes.append(0.0 if n == 2 else float(qn / q_and_condition(c, n - 2, x)[0] - 1))
ck.check("fig07_settling.csv", "q", qs, rel_tol=1e-12)
ck.check("fig07_settling.csv", "change_from_N_minus_2", changes, abs_tol=1e-12)
ck.finish()
