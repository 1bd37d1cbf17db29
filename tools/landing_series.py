"""The short bounce's landing as a series (closed_piece.hpp, short_bounce()).

A rebound leaving theta = 0 at omega on a record piece a0 + c1 u (eq. 3,
lin = a0 - sigma alpha, W = omega + c1) lands at the first root u > 0 of
    theta(u) = omega u + lin (cosh pu - 1) + W (sinh pu - pu) / p.
With x = pu = x0 (1 + e), x0 = -2 omega / (p lin), divided by lin x x0 / 2:
    F(e) = e + sum_{n>=2} 2 (12 delta)^(n-1) (1+e)^(2n-1) / (2n)!
             + 6 beta sum_{n>=1} (12 delta)^(n-1) (1+e)^(2n) / (2n+1)!  = 0,
    beta = W x0 / (3 p lin),  delta = x0^2 / 12,
and the velocity there, r = theta'(u) / omega,
    r = 1 - 2 (1+e) sum_{n>=0} (12 delta)^n (1+e)^(2n) / (2n+1)!
          - 6 beta sum_{n>=1} (12 delta)^(n-1) (1+e)^(2n) / (2n)!.
This script solves F(e) = 0 for e as a power series in (beta, delta) by
fixed-point iteration on exact fractions (one degree a pass), to degree DEG,
keeps the terms above CUT on the region |beta| <= TB, delta <= TD, and prints
them as the C++ lines of short_bounce() (e, and v = r + 1) with the bound on
what is left out.  --check FILE: exit 1 unless FILE holds those lines verbatim
and the bound is below eps/32 of double (the Newton iteration's own criterion).
Run with /usr/bin/python3; plain Python, no packages.
"""
import sys
from fractions import Fraction as Fr
from math import factorial

TB, TD, CUT, DEG = 1e-3, 1e-5, 2e-19, 13


def mul(a, b):
    c = {}
    for (i, j), x in a.items():
        for (k, l), y in b.items():
            if i + j + k + l <= DEG:
                c[(i + k, j + l)] = c.get((i + k, j + l), 0) + x * y
    return c


def add(*terms):
    c = {}
    for t in terms:
        for k, v in t.items():
            c[k] = c.get(k, 0) + v
    return c


def scale(a, s):
    return {k: v * s for k, v in a.items()}


def power(a, n):
    r = {(0, 0): Fr(1)}
    for _ in range(n):
        r = mul(r, a)
    return r


ONE, BETA = {(0, 0): Fr(1)}, {(1, 0): Fr(1)}


def delta12(n):
    return {(0, n): Fr(12) ** n}


def powers(v, top):
    out = [ONE]
    for _ in range(top):
        out.append(mul(out[-1], v))
    return out


def series():
    e = {}
    for _ in range(DEG + 1):
        vp = powers(add(ONE, e), 2 * DEG + 1)
        rest = add(*[scale(mul(delta12(n - 1), vp[2 * n - 1]), Fr(2, factorial(2 * n))) for n in range(2, DEG + 2)],
                   *[scale(mul(BETA, mul(delta12(n - 1), vp[2 * n])), Fr(6, factorial(2 * n + 1)))
                     for n in range(1, DEG + 1)])
        e = scale(rest, -1)
    vp = powers(add(ONE, e), 2 * DEG + 1)
    v = add(*[scale(mul(delta12(n), vp[2 * n + 1]), Fr(-2, factorial(2 * n + 1))) for n in range(0, DEG + 1)],
            *[scale(mul(BETA, mul(delta12(n - 1), vp[2 * n])), Fr(-6, factorial(2 * n))) for n in range(1, DEG + 1)])
    v = add(v, ONE, ONE)  # r + 1: r's constant term is -1
    return {k: x for k, x in e.items() if x}, {k: x for k, x in v.items() if x}


def size(k, x):
    return abs(float(x)) * TB ** k[0] * TD ** k[1]


def literal(x):
    return f"Real({x.numerator})" if x.denominator == 1 else f"Real({x.numerator}.0L / {x.denominator})"


def lines(name, s):
    keep = {k: x for k, x in s.items() if size(k, x) > CUT}
    left_out = sum(size(k, x) for k, x in s.items() if k not in keep)
    out = []
    for i in range(8):
        js = [j for (b, j) in keep if b == i]
        expr = "Real(0)"
        if js:
            expr = None
            for j in range(max(js), -1, -1):
                c = literal(keep[(i, j)]) if (i, j) in keep else None
                expr = (c or "Real(0)") if expr is None else (f"{c} + d * ({expr})" if c else f"d * ({expr})")
        out.append(f"const Real {name}{i} = {expr};")
    return out, len(keep), left_out


def main():
    e, v = series()
    text, bound_total = [], 0.0
    for name, s in (("e", e), ("v", v)):
        out, n, left_out = lines(name, s)
        # Degrees DEG - 1 and DEG show the tail's decay; beyond DEG it is
        # bounded by a geometric series with their ratio.
        top = [sum(size(k, x) for k, x in s.items() if sum(k) == d) for d in (DEG - 1, DEG)]
        ratio = top[1] / top[0]
        tail = top[1] * ratio / (1 - ratio)
        bound_total = max(bound_total, left_out + tail)
        print(f"// {name}: {n} terms kept; left out within degree {DEG}: {left_out:.2e}; beyond: {tail:.2e}")
        text += out
    for line in text:
        print(line)
    eps32 = 2.0 ** -52 / 32
    print(f"// truncation bound {bound_total:.2e} relative (eps/32 = {eps32:.2e})")
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        with open(sys.argv[2]) as f:
            source = [line.strip() for line in f]
        missing = [line for line in text if line not in source]
        for line in missing:
            print(f"{sys.argv[2]}: missing or different: {line}", file=sys.stderr)
        if bound_total >= eps32:
            print(f"truncation bound {bound_total:.2e} not below eps/32", file=sys.stderr)
        sys.exit(1 if missing or bound_total >= eps32 else 0)


main()
