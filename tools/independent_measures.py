"""The eleven half-periods to_1..to_11 of a record (Section 4 of the paper), re-implemented
with numpy for the independent checks of expected/ (expected/table2 on the real records,
expected/fragility on the synthetic ones), apart from the C++ code (records/measures.cpp):
pulses between the zero crossings of the piecewise-linear record, trapezoidal velocity, FFT
peaks with 8x zero padding and a parabola, the Morse CWT (beta 27, gamma 3) on the grid of
cwt.hpp (16 voices from 25 Hz or 0.25/dt down to 0.1 Hz).  Run with /usr/bin/python3.
"""
import math

import numpy as np


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


def half_periods(a, dt):
    """(PGA, PGV, Amax, [to_1..to_11]) of the acceleration samples a (any unit; to_k in s)."""
    a = np.asarray(a, dtype=float)
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
    return pga, pgv, amax, to
