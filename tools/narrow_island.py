#!/usr/bin/python3
"""The two-pulse islands narrowed for issue 39 (tests/test_overturning_truth.cpp):
their boundaries from the closed forms at 40 digits, independently of the test's
long-double bisection and of the library.

The chain of closed forms is tests/two_pulses_truth.hpp's (+A0 g for d0, then -B g
for d1, restitution 0), re-typed here in mpmath.  Both islands come from its last
branch: the block, rescued by -B, lands at u_i < d1, rests, and is lifted on the
other corner for the rest r = d1 - u_i; it overturns iff (B - alpha) expm1(p r) >
alpha (the single pulse's criterion; the cosh branch is far: (B - alpha)(cosh pr - 1)
< pi/2 here).  The margin m = (B - alpha) expm1(p r) - alpha has a maximum in ln p
(ln q) whose height d1 sets: d1 a few 1e-8 above the tangency makes the island about
5e-5 wide.  Each boundary is m = 0, solved by mpmath's findroot on either side of
the maximum (found by golden section); the branch is checked at every point used.

The parameters are the doubles the library sees (PulseInput's amplitudes
pga * (-B / A0) and the like, computed here in Python floats, i.e. IEEE doubles, as
the C++ does), so that the boundaries printed are those of the input the library
simulates.

Prints, per island: the parameters, the maximum of m, the boundaries (30 digits),
the width in ln p (ln q), the slope of m at each boundary and m at (1 -+ 1e-9) times
each boundary (how well the library's double arithmetic can decide points there).
"""
from mpmath import mp, mpf, cosh, sinh, sqrt, atanh, log, expm1, exp, findroot, nstr

mp.dps = 40
HALF_PI = mp.pi / 2


def branch(A0, d0, B, d1, al, p):
    """(overturns, branch, margin): the chain of tests/two_pulses_truth.hpp."""
    c = A0 - al
    th1 = c * (cosh(p * d0) - 1)
    if th1 >= HALF_PI:
        return True, "first pulse", th1 - HALF_PI
    y0, v0 = th1 - al - B, c * sinh(p * d0)
    if y0 + v0 >= 0:
        return True, "beyond the manifold", y0 + v0
    u_peak = atanh(-v0 / y0) / p
    peak = al + B - sqrt(y0 * y0 - v0 * v0) if u_peak < d1 else al + B + y0 * cosh(p * d1) + v0 * sinh(p * d1)
    if peak >= HALF_PI:
        return True, "peak", peak - HALF_PI
    qa, qb, qc = y0 + v0, 2 * (al + B), y0 - v0
    u_i = log((-qb - sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)) / p
    if u_i >= d1:
        th = al + B + y0 * cosh(p * d1) + v0 * sinh(p * d1)
        om_p = y0 * sinh(p * d1) + v0 * cosh(p * d1)
        return (th - al) + om_p > 0, "no impact", (th - al) + om_p
    r, cb = d1 - u_i, B - al
    assert cb * (cosh(p * r) - 1) < HALF_PI
    m = cb * expm1(p * r) - al
    return m > 0, "impact, lifted again", m


def island(margin, a, b):
    """Golden section for the maximum of margin(x) on [a, b], then its two zeros."""
    g = (sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    for _ in range(160):
        if margin(c) > margin(d):
            b = d
        else:
            a = c
        c, d = b - g * (b - a), a + g * (b - a)
    xm = (a + b) / 2
    lo = findroot(margin, (xm - mpf("1e-3"), xm), solver="anderson")
    hi = findroot(margin, (xm, xm + mpf("1e-3")), solver="anderson")
    return xm, lo, hi


def report(name, margin, xm, lo, hi, unit):
    print(f"{name}:")
    print(f"  maximum of the margin: {nstr(margin(xm), 6)} rad at {unit} = {nstr(exp(xm), 12)}")
    for side, x in (("lower", lo), ("upper", hi)):
        slope = mp.diff(margin, x)
        print(f"  {side} boundary: {unit} = {nstr(exp(x), 30)}; margin slope {nstr(slope, 4)} rad per unit ln {unit}; "
              f"margin at x(1 - 1e-9): {nstr(margin(x + log(1 - mpf('1e-9'))), 4)}, "
              f"at x(1 + 1e-9): {nstr(margin(x + log(1 + mpf('1e-9'))), 4)}")
    print(f"  width in ln {unit}: {nstr(hi - lo, 6)}")


def main():
    al = mpf(0.1)
    # In p (tests/test_overturning_truth.cpp, NarrowInP): PulseInput(PulseTrain({{1, d0}, {-B/A0, d1}}), A0, 1).
    A0, d0, B, d1 = 0.2, 1.0, 0.11, 4.622764322
    Bd = -(A0 * (-B / A0))  # the library's amplitude of the second pulse, in double
    ends = (d0, d0 + d1)  # the pulse ends in double, as PulseInput accumulates them
    d1d = mpf(ends[1]) - mpf(ends[0])

    def m_p(x):
        over, which, m = branch(mpf(A0), mpf(d0), mpf(Bd), d1d, al, exp(x))
        assert which == "impact, lifted again", which
        return m

    xm, lo, hi = island(m_p, log(mpf("0.85")), log(mpf("0.97")))
    print(f"p: A0 {A0}, d0 {d0}, B {Bd!r} (as the library has it), d1 {nstr(d1d, 20)} (pulse end minus start, in double)")
    report("island in p", m_p, xm, lo, hi, "p")

    # In q (NarrowInQ): PulseInput(PulseTrain({{1, d0}, {-1, d1}}), 0.3, 1) scaled to q alpha, p = 3.
    d0, d1, p = 0.5, 0.850945071, 3.0
    ends = (d0, d0 + d1)
    d1d = mpf(ends[1]) - mpf(ends[0])

    def m_q(x):
        q = exp(x)
        over, which, m = branch(q * al, mpf(d0), q * al, d1d, al, mpf(p))
        assert which == "impact, lifted again", which
        return m

    xm, lo, hi = island(m_q, log(mpf("1.2")), log(mpf("1.33")))
    print(f"q: A0 = B = q alpha, d0 {d0}, d1 {nstr(d1d, 20)} (pulse end minus start, in double), p {p}")
    report("island in q", m_q, xm, lo, hi, "q")


if __name__ == "__main__":
    main()
