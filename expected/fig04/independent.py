#!/usr/bin/python3
"""Independent check of expected/fig04: the printed eqs. 12, 15, 19, 22, 24 (each verified
by hand against the jump sum, see PROVENANCE.md) evaluated with mpmath at 40 digits, and
the marked points found by mpmath's findroot.  Tolerance: relative 1e-13 (the C++ values
are accurate to a few 1e-16; 1e-13 leaves room for libm differences between machines)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from independent_check import Checker, directory_from_argv, read_expected  # noqa: E402
from mpmath import mp, mpf, cosh, findroot  # noqa: E402

mp.dps = 40


def q(i, x):
    c = cosh(x)
    if i == 1:
        return (2 * c**2 - 1) / (2 * c * (c - 1))                      # eq. 12
    if i == 2:
        return (2 - 4 * c**2) / (3 * c - 4 * c**2 + 1)                 # eq. 15
    if i == 3:
        return (4 * c**2 - 2) / (2 * c**2 - 3 * c + 1)                 # eq. 19
    if i == 4:
        return 2 * cosh(3 * x) / (2 * cosh(3 * x) - 3 * cosh(2 * x) + 1)  # eq. 22
    return 2 * cosh(3 * x) / (cosh(3 * x) - 3 * c + 2)                 # eq. 24


d = directory_from_argv()
ck = Checker(d)
header, rows = read_expected(d, "fig04.csv")
xs = [mpf(k) / 100 for k in range(5, 201)]
ck.check("fig04.csv", "x", [float(x) for x in xs], rel_tol=0.0)
for i in range(1, 6):
    ck.check("fig04.csv", f"q{i}", [float(q(i, x)) for x in xs], rel_tol=1e-13)
mins = [min(range(1, 6), key=lambda i: q(i, x)) for x in xs]
ck.check("fig04.csv", "q_min", [float(q(i, x)) for i, x in zip(mins, xs)], rel_tol=1e-13)
ck.check("fig04.csv", "case_min", mins, exact=True)

x24 = findroot(lambda x: q(2, x) - q(4, x), mpf("0.5"))
roots = [findroot(lambda x, i=i: q(i, x) - 2, mpf(1)) for i in (1, 2, 4)]
ck.check("fig04_points.csv", "x", [float(x24)] + [float(r) for r in roots] + [50.0, 50.0], rel_tol=1e-13)
ck.check("fig04_points.csv", "q", [float(q(2, x24)), 2.0, 2.0, 2.0, float(q(3, mpf(50))), float(q(5, mpf(50)))],
         rel_tol=1e-13)
ck.finish()
