#!/usr/bin/python3
"""The multiprecision reference for the response at the extremes.

Writes tests/reference/response_extremes.csv (samples of theta/alpha and
theta'/(alpha p)) and tests/reference/excursion_extremes.csv (the validity
flags' extrema), which tests/test_response_extremes.cpp reads.

Independent of the engine it checks: it sums (S1) as printed,
    phi(tau) = sum_{tau_j <= tau} dF_j (cosh(x (tau - tau_j)) - 1),
    dF_0 = q A_0 - 1, dF_j = q (A_j - A_{j-1}), the input's end a jump too,
with q the exact collapse q of (S2), q = cosh(xT) / sum_j dA_j (cosh(x s_j) - 1),
or a given double q, in mpmath at x tau / ln 10 + 40 digits and more, so
that the cancellation of (S1)'s terms (e^{x tau} against O(1)) costs
nothing.  The extrema come from propagating (psi, w) = (phi + F, phi')
pulse by pulse in the same precision, with the stationary points inside a
pulse at tanh u = -w/psi (phi) and tanh u = -psi/w (phi').  The engine
uses neither form.

The grid: cases 1-5 repeated to N = 1, 2, 6, 50, 1000 pulses and three
trains with durations that are not integers, at x from 1e-6 to 1e3, kept
where x t_fin <= 3000 (at most ~1500 digits; beyond, the terms of (S1)
exceed any precision mpmath reaches in minutes).  Times: t_fin k/16 for
k = 1..18 (two past t_fin, in free rocking) and the middle of every pulse
of the short trains.  Given q: 0.8 and 1.25 times the collapse q, rounded to
double, for N <= 6.

Run: /usr/bin/python3 tools/response_reference.py   (about 20 s)
     /usr/bin/python3 tools/response_reference.py --check   (ctest response_reference:
     regenerates into a temporary folder and fails if tests/reference differs)
"""
import math
import os
import sys

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "tests", "reference")

PATTERNS = {
    1: [(1.0, 1.0), (-1.0, 1.0)],
    2: [(1.0, 1.0), (-0.5, 1.0)],
    3: [(0.5, 1.0), (-1.0, 1.0)],
    4: [(1.0, 1.0), (-0.5, 2.0)],
    5: [(0.5, 2.0), (-1.0, 1.0)],
}
# Trains given as --train would give them: durations not exact in binary.
TRAINS = {
    "1:0.3,-0.7:1.1,0.2:0.45": [(1.0, 0.3), (-0.7, 1.1), (0.2, 0.45)],
    "0.6:1.7,-1:0.1,0.9:0.3,-0.2:2.2": [(0.6, 1.7), (-1.0, 0.1), (0.9, 0.3), (-0.2, 2.2)],
    "1:2.5": [(1.0, 2.5)],
}
XS = [1e-6, 1e-3, 0.1, 1.0, 5.0, 12.0, 20.0, 50.0, 200.0, 700.0, 1000.0]
NS = [1, 2, 6, 50, 1000]
MAX_XT = 3000.0


def repeated(case, n):
    pattern = PATTERNS[case]
    return [pattern[k % len(pattern)] for k in range(n)]


def jumps(pulses):
    """(tau_j, dA_j) with tau_j summed in double, as the engine places them."""
    out, tau, previous = [], 0.0, 0.0
    for amplitude, duration in pulses:
        if amplitude != previous:
            out.append((tau, amplitude - previous))
        previous = amplitude
        tau += duration
    return out, tau


def collapse_q(js, T, x):
    den = sum(mpf(dA) * (mpmath.cosh(x * (T - mpf(t))) - 1) for t, dA in js)
    return mpmath.cosh(x * T) / den, den


def s1(js, T, last_amplitude, x, q, tau):
    """(S1) and its derivative over x, the input's end included after t_fin."""
    phi = dphi = mpf(0)
    all_jumps = js + [(T, -last_amplitude)]
    for k, (t, dA) in enumerate(all_jumps):
        if t > tau:
            break
        dF = q * mpf(dA) - (1 if k == 0 else 0)
        u = x * (mpf(tau) - mpf(t))
        e = mpmath.exp(u)
        phi += dF * ((e + 1 / e) / 2 - 1)
        dphi += dF * (e - 1 / e) / 2
    return phi, dphi


def extrema(pulses, x, q):
    """onset, min phi on [end of pulse 1, t_fin], min phi' on (0, t_fin], max phi on (0, t_fin)."""
    phi = w = mpf(0)
    min_phi, min_dphi, max_phi = mpf("inf"), mpf("inf"), mpf("-inf")
    # The pulses' ends as the engine places them, summed in double: at large
    # x the collapse q tunes phi to an exponentially sensitive balance, and
    # the decimal durations' own sums (1.4 against 1.4000000000000001) would
    # describe a slightly different train than the one q was found for.
    ends, t = [], 0.0
    for _, duration in pulses:
        start, t = t, t + duration
        ends.append((start, t))
    # The amplitudes as the sums of the jumps the engine holds, each rounded
    # to double (0.2 - (-0.7) = 0.8999999999999999): that ulp moves the
    # collapse response by 7e-9 at x = 200 for the first of TRAINS, a property
    # of the train, not of the arithmetic checked here.
    levels, level, previous = [], mpf(0), 0.0
    for amplitude, _ in pulses:
        if amplitude != previous:
            level += mpf(amplitude - previous)
        previous = amplitude
        levels.append(level)
    for k, (amplitude, duration) in enumerate(pulses):
        F = q * levels[k] - 1
        psi0 = phi + F
        U = x * (mpf(ends[k][1]) - mpf(ends[k][0]))
        last = k + 1 == len(pulses)
        if psi0 != 0:
            r = -w / psi0
            if 0 < r < 1:
                u = mpmath.atanh(r)
                if u < U:
                    value = psi0 * mpmath.cosh(u) + w * mpmath.sinh(u) - F
                    if k > 0:
                        min_phi = min(min_phi, value)
                    max_phi = max(max_phi, value)
        if w != 0:
            r = -psi0 / w
            if 0 < r < 1:
                u = mpmath.atanh(r)
                if u < U:
                    min_dphi = min(min_dphi, psi0 * mpmath.sinh(u) + w * mpmath.cosh(u))
        c, s = mpmath.cosh(U), mpmath.sinh(U)
        phi, w = psi0 * c + w * s - F, psi0 * s + w * c
        min_phi = min(min_phi, phi)
        if not last:
            max_phi = max(max_phi, phi)
        min_dphi = min(min_dphi, w)
    return q * levels[0] > 1, min_phi, min_dphi, max_phi


def g17(v):
    return mpmath.nstr(v, 17, min_fixed=-4, max_fixed=6) if mpmath.isfinite(v) else ("inf" if v > 0 else "-inf")


def trains():
    for case in PATTERNS:
        for n in NS:
            yield "case %d N %d" % (case, n), repeated(case, n), n
    for name, pulses in TRAINS.items():
        yield "train " + name, pulses, len(pulses)


def write(out):
    os.makedirs(out, exist_ok=True)
    samples = open(os.path.join(out, "response_extremes.csv"), "w")
    flags = open(os.path.join(out, "excursion_extremes.csv"), "w")
    for f in (samples, flags):
        f.write("# generated by tools/response_reference.py (mpmath %s): (S1) summed as printed at\n"
                "# x tau / ln 10 + 40 digits or more; do not edit by hand, rerun the tool\n" % mpmath.__version__)
    samples.write("train,x,q,tau,phi,dphi\n")
    flags.write("train,x,onset,min_phi,min_dphi,max_phi\n")
    for name, pulses, n in trains():
        js, T = jumps(pulses)
        for x_double in XS:
            if x_double * T > MAX_XT:
                continue
            taus = [T * k / 16 for k in range(1, 19)]
            if n <= 6:
                start = 0.0
                for _, d in pulses:
                    taus.append(start + d / 2)
                    start += d
            mp.dps = int(1.125 * x_double * T / math.log(10)) + 60
            x = mpf(x_double)
            qc, den = collapse_q(js, mpf(T), x)
            if den <= 0:
                continue
            onset, min_phi, min_dphi, max_phi = extrema(pulses, x, qc)
            flags.write("%s,%r,%d,%s,%s,%s\n" % (name, x_double, onset, g17(min_phi), g17(min_dphi), g17(max_phi)))
            qs = [("collapse", qc)]
            if n <= 6:
                qs += [(repr(float(qc * f)), mpf(float(qc * f))) for f in (mpf("0.8"), mpf("1.25"))]
            for label, q in qs:
                for tau in sorted(set(taus)):
                    phi, dphi = s1(js, T, pulses[-1][0], x, q, tau)
                    samples.write("%s,%r,%s,%r,%s,%s\n" % (name, x_double, label, tau, g17(phi), g17(dphi)))
            print(name, x_double, "digits", mp.dps, file=sys.stderr, flush=True)
    samples.close()
    flags.close()


def main():
    if "--check" not in sys.argv:
        write(OUT)
        return 0
    import filecmp
    import tempfile
    with tempfile.TemporaryDirectory() as fresh:
        sys.stderr = open(os.devnull, "w")
        write(fresh)
        for name in ("response_extremes.csv", "excursion_extremes.csv"):
            if not filecmp.cmp(os.path.join(fresh, name), os.path.join(OUT, name), shallow=False):
                print("tests/reference/%s differs from what tools/response_reference.py computes" % name)
                return 1
    print("tests/reference matches tools/response_reference.py")
    return 0


if __name__ == "__main__":
    sys.exit(main())
