#!/usr/bin/python3
"""Independent check of expected/table2: to_5 = pi |PGV| / PGA from the transcribed
Table 1 against Table 2; the consistency of Table 2's columns with eqs. 29-30; and the
eleven half-periods of the real records re-implemented with numpy (pulses between the
zero crossings of the piecewise-linear record, trapezoidal velocity, FFT peaks with 8x
zero padding and a parabola, Morse CWT beta 27 gamma 3 with the grid of cwt.hpp).
Tolerances: 1e-12 for arithmetic; 1e-6 relative for the records (FFT rounding)."""
import csv, math, os, sys
import numpy as np
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
from independent_check import Checker, directory_from_argv, read_expected  # noqa: E402

data = os.path.join(here, "..", "..", "reproduce", "data")
t1 = [r for r in csv.reader(l for l in open(os.path.join(data, "paper_table1.csv")) if not l.startswith("#"))][1:]
t2 = [r for r in csv.reader(l for l in open(os.path.join(data, "paper_table2.csv")) if not l.startswith("#"))][1:]
d = directory_from_argv()
ck = Checker(d)
to5 = [math.pi * abs(float(r[2])) / float(r[1]) for r in t1]
ck.check("table2.csv", "to5_computed", to5, rel_tol=1e-12)
ck.check("table2.csv", "agrees", ["yes" if abs(v - float(r[5])) <= 0.0005 + 1e-9 else "no" for v, r in zip(to5, t2)],
         exact=True)
tol = 0.0005 * (1 + math.pi / 2) + 1e-12
ck.check("table2_columns.csv", "eqs29_30_as_printed",
         ["yes" if abs(float(r[3]) - math.pi / 2 * float(r[4])) <= tol else "no" for r in t2], exact=True)
ck.check("table2_columns.csv", "eqs29_30_with_to1_to2",
         ["yes" if abs(float(r[1]) - math.pi / 2 * float(r[2])) <= tol else "no" for r in t2], exact=True)


def read_record(path):
    lines = open(path).read().splitlines()
    if ":" in lines[0]:
        head = dict(l.split(":", 1) for l in lines if ":" in l and not l.strip().lstrip("-").replace(".", "").isdigit())
        dt = float(head["SAMPLING_INTERVAL_S"])
        a = np.array([float(l) for l in lines if l.strip() and ":" not in l]) * 0.01
    else:
        n = lines[3].upper()
        dt = float(n.split("DT=")[1].split()[0].rstrip(","))
        a = np.array([float(t) for l in lines[4:] for t in l.split()]) * 9.81
    return a, dt


def pulses(a, dt):
    out, start, area, peak = [], 0.0, 0.0, abs(a[0])
    for k in range(len(a) - 1):
        a0, a1, t0 = a[k], a[k + 1], dt * k
        peak = max(peak, abs(a0))
        if (a0 > 0 and a1 < 0) or (a0 < 0 and a1 > 0):
            tau = dt * a0 / (a0 - a1)
            area += 0.5 * a0 * tau
            out.append((start, t0 + tau, area, peak)); start, area, peak = t0 + tau, 0.5 * a1 * (dt - tau), 0.0
        else:
            if a0 == 0 and a1 != 0:  # a stretch of exact zeros ends: a new pulse starts
                if area != 0 or peak != 0:
                    out.append((start, t0, area, peak))
                start, area, peak = t0, 0.0, 0.0
            area += 0.5 * (a0 + a1) * dt
            if a1 == 0 and a0 != 0:
                out.append((start, t0 + dt, area, max(peak, 0.0))); start, area, peak = t0 + dt, 0.0, 0.0
    out.append((start, dt * (len(a) - 1), area, max(peak, abs(a[-1]))))
    return [p for p in out if p[1] > p[0] and (p[2] != 0 or p[3] != 0)]


def fourier_peak(x, dt):
    n = 1
    while n < 8 * len(x):
        n *= 2
    amp = np.abs(np.fft.fft(x, n))[: n // 2 + 1]
    k = 1 + int(np.argmax(amp[1: n // 2]))
    s = 0.0
    if k > 1:
        ym, y0, yp = amp[k - 1], amp[k], amp[k + 1]
        den = ym - 2 * y0 + yp
        if den < 0:
            s = 0.5 * (ym - yp) / den
    return (k + s) / (n * dt)


def cwt_peaks(x, dt, fmin, fmax, voices=16, beta=27.0, gamma=3.0):
    n = 1
    while n < 2 * len(x):
        n *= 2
    X = np.fft.fft(x, n)
    wp = (beta / gamma) ** (1 / gamma)
    abg = 2 * math.exp((beta / gamma) * (1 + math.log(gamma / beta)))
    w = 2 * math.pi * np.arange(n) / (n * dt)
    w[n // 2 + 1:] = -1
    J = int(math.ceil(voices * math.log2(fmax / fmin)))
    fr, mx, mean, en = [], [], [], []
    for j in range(J + 1):
        f = fmax * 2 ** (-j / voices)
        s = wp / (2 * math.pi * f)
        psi = np.zeros(n)
        pos = w > 0
        sw = s * w[pos]
        psi[pos] = abg * np.exp(beta * np.log(sw) - sw ** gamma)
        W = np.abs(np.fft.ifft(X * psi))[: len(x)]
        fr.append(f); mx.append(W.max()); mean.append(W.mean()); en.append((W * W).sum() * dt)

    def peak(values):
        j = int(np.argmax(values))
        lf = math.log(fr[j])
        if 0 < j < len(values) - 1:
            ym, y0, yp = values[j - 1], values[j], values[j + 1]
            den = ym - 2 * y0 + yp
            if den < 0:
                lf -= (math.log(fr[j - 1]) - lf) * 0.5 * (ym - yp) / den
        return math.exp(lf)
    return peak, mx, mean, en


root = os.environ.get("ROCKING_RECORDS", os.path.join(here, "..", "..", "..", "shared", "records"))
header, rows = read_expected(d, "table2_records.csv")
if not os.path.isdir(root):
    print("  table2_records.csv: records folder absent, not checked")
else:
    cols = {c: [] for c in header}
    for r in rows:
        a, dt = read_record(os.path.join(root, r[0]))
        pga = np.abs(a).max()
        v = np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * dt)])
        pgv = np.abs(v).max()
        ps = pulses(a, dt)
        largest = max(ps, key=lambda p: abs(p[2]))
        withpga = max(ps, key=lambda p: p[3])
        amax = abs(largest[2])
        k = np.arange(len(v), dtype=float)
        slope, icpt = np.polyfit(k, v, 1)
        vd = v - (icpt + slope * k)
        fmax, fmin = min(25.0, 0.25 / dt), 0.1
        pa, mxa, mna, ena = cwt_peaks(a, dt, fmin, fmax)
        pv, mxv, mnv, env = cwt_peaks(vd, dt, fmin, fmax)
        to = [largest[1] - largest[0], withpga[1] - withpga[0], math.pi * amax / (2 * pga), amax / pga,
              math.pi * pgv / pga, 1 / (2 * fourier_peak(a, dt)), 1 / (2 * fourier_peak(vd, dt)),
              1 / (2 * pa(mxa)), 1 / (2 * pv(mnv)), 1 / (2 * pa(ena)), 1 / (2 * pv(env))]
        cols["PGA_cms2"].append(100 * pga); cols["PGV_cms"].append(100 * pgv); cols["Amax_cms"].append(100 * amax)
        for i in range(11):
            cols["to_%d" % (i + 1)].append(to[i])
    for c in ["PGA_cms2", "PGV_cms", "Amax_cms"] + ["to_%d" % i for i in range(1, 12)]:
        ck.check("table2_records.csv", c, cols[c], rel_tol=1e-6)
ck.finish()
