#!/usr/bin/python3
"""Independent check of expected/fragility: the lognormal fits of fragility_fits.csv
refitted in Python from fragility_points.csv, without numpy or scipy and without the
C++ code's method, and fragility_eq27.csv recomputed from the same points.

- The fit: maximum likelihood of P(overturn | q) = Phi(ln(q / median) / beta) with the
  censored records kept (Baker 2015).  Without censoring, the closed form (mean and
  1/n deviation of ln q); with it, Newton's method on the score equations (analytic
  gradient, Hessian by central differences of it) from the closed form, and where that
  walks off (a resample of a few clustered collapses beside many censored points) from
  the best point of a coarse grid; the C++ code uses Newton's method in Olsen's
  parameters 1/beta and mu/beta, where ln L is concave (before that GSL's simplex).
- The bootstrap: GSL's mt19937 re-implemented through Python's own Mersenne Twister
  (the state GSL's gsl_rng_set builds, Knuth's 2002 initialisation, loaded into
  random.setstate), gsl_rng_uniform_int's rejection rule, each resample refitted as
  above, and the percentiles with linear interpolation between order statistics.
- The counts (collapsed, censored, ill-conditioned) and the empirical shares.
- Eq. 27 at scale: each case's verdict rebuilt from the point's collapse q, the record's
  to_1..to_11 read from expected/table2/table2_records.csv and eq. 27 as printed (the
  formula verified in expected/errata) evaluated with mpmath at 30 digits; then the
  counts per to_k, the share, the Wilson interval (z from Python's NormalDist), the
  blocks and records with any non-conservative case, and the bootstrap over records
  (the same mt19937 draws: records drawn with replacement, each bringing its cases on
  every block, the share per k a count over records x blocks, the same percentile
  interpolation).

The synthetic set (fragility_synthetic_*.csv), the same way, and its records first:
- The records regenerated from the set's definition here (not read from the CSV): each
  Mavroeidis & Papageorgiou (2003) pulse's acceleration from its closed form with numpy;
  each Rezaeian & Der Kiureghian (2008) record from the model's formulas with numpy (the
  modulating function with the alphas solved anew with mpmath at 30 digits from the
  documented Ia, D5-95 and t_mid; the filter's full sum, without the C++ code's cut; the
  critically damped post-filter integrated exactly for linear input), its white noise
  drawn from GSL itself through ctypes (gsl_rng_mt19937, gsl_ran_gaussian_ziggurat: the
  noise is GSL's by definition, pinned by SyntheticStochastic.SeedOneNoiseIsPinned).
  The labels, PGA, PGV and to_1..to_11 (tools/independent_measures.py, numpy, as
  expected/table2's check) against the CSV, each pulse's to_pulse = 1/(2 fp) and which
  to_k recover it; each point's q_input from the regenerated PGA.
- Eq. 27 at the pulse's own half-period: q at x = p/(2 fp) with mpmath, each verdict,
  and the count, Wilson and bootstrap of the note "pulse half-period".
- The fits per (set, block) and eq. 27 per set (pulse, stochastic, and their union) as
  for the shared records, with the to_k computed here.

Usage: independent.py DIR (the folder holding the scene's CSV files).  Exit 0 when the
fits agree to 1e-7 relative (the simplex stops at a simplex of 1e-12, Newton at a step
of 1e-13; a step is halved while ln L falls), eq. 27's counts and bootstrap bounds
exactly, its share and Wilson bounds to 1e-12 relative; the synthetic records' PGA and
PGV to 1e-10, their to_k to 1e-6 (as table2's: FFT rounding), q_input to 1e-10 and
eq. 27's q at the pulse's half-period to 1e-12.  Without fragility_points.csv (a run
without the shared records) the shared records' part is skipped.
"""
import csv
import ctypes
import ctypes.util
import hashlib
import importlib.util
import math
import os
import re
import struct
import sys
from statistics import NormalDist

import numpy as np
from mpmath import exp as mp_exp, findroot, gammainc, log as mp_log, loggamma, mp, mpf, sinh

TOL = 1e-7
TOL_EQ27 = 1e-12
mp.dps = 30
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from independent_measures import half_periods  # noqa: E402
from independent_check import GslMt19937, percentile  # noqa: E402

TOL_RECORD = 1e-10   # PGA, PGV, q_input: the same formulas, rounded apart (measured 6e-14)
TOL_TO = 1e-6        # to_k: as expected/table2 (FFT rounding between libraries)
G = 9.81


def read_notes(path):
    notes = {}
    with open(path) as f:
        for line in f:
            if line.startswith("# ") and ": " in line:
                key, value = line[2:].rstrip("\n").split(": ", 1)
                notes[key] = value
    return notes


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


def log_sf(z):  # ln(1 - Phi(z)); its asymptotic series far in the tail, where erfc underflows
    if z < 30:
        return math.log(0.5 * math.erfc(z / math.sqrt(2)))
    return -0.5 * z * z - math.log(z) - 0.5 * math.log(2 * math.pi) + math.log1p(-1 / z ** 2 + 3 / z ** 4)


def hazard(z):  # phi(z) / (1 - Phi(z)); z + 1/z far in the tail
    sf = 0.5 * math.erfc(z / math.sqrt(2))
    return phi(z) / sf if z < 30 else z + 1 / z


def log_likelihood(points, mu, beta):
    s = 0.0
    for q, c in points:
        z = (math.log(q) - mu) / beta
        s += (-0.5 * z * z - 0.5 * math.log(2 * math.pi) - math.log(beta) - math.log(q)) if c else log_sf(z)
    return s


def log_likelihood_at(points, mu, lb):
    """ln L at (mu, ln beta), -inf where beta overflows or underflows (a step far out, which the guard halves)."""
    try:
        return log_likelihood(points, mu, math.exp(lb))
    except (OverflowError, ZeroDivisionError, ValueError):
        return -math.inf


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


def newton(points, mu, lb):
    """Newton's method on the score equations in (mu, ln beta), the Hessian by central differences of the
    analytic gradient, up the gradient where ln L is not concave, each step halved while ln L falls."""
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
        while t > 1e-12 and not log_likelihood_at(points, mu + t * dm, lb + t * dl) >= here - 1e-12:
            t /= 2
        mu, lb = mu + t * dm, lb + t * dl
        if abs(t * dm) < 1e-13 and abs(t * dl) < 1e-13:
            break
    return mu, lb


def converged(points, mu, lb):
    try:
        g = gradient(points, mu, lb)
    except (OverflowError, ZeroDivisionError, ValueError):
        return False
    return all(math.isfinite(x) and abs(x) < 1e-6 for x in g)


def fit(points):
    mu, beta = closed_form(points)
    if all(c for _, c in points):
        return math.exp(mu), beta
    try:
        mu1, lb1 = newton(points, mu, math.log(beta))
    except (OverflowError, ZeroDivisionError, ValueError):
        mu1, lb1 = mu, -math.inf
    if not converged(points, mu1, lb1):
        # From the closed form of a few tightly clustered collapses beside many censored points (a resample
        # of the pulses: beta 0.06 where the maximum has 2.6), Newton can walk off: start again from the
        # best point of a coarse grid over (mu, ln beta), 61 x 61 points.
        ln = [math.log(q) for q, _ in points]
        lo, hi = min(ln) - 1, max(ln) + 4
        best = max(((lo + (hi - lo) * i / 60, -4 + 7 * j / 60) for i in range(61) for j in range(61)),
                   key=lambda x: log_likelihood_at(points, x[0], x[1]))
        mu1, lb1 = newton(points, *best)
        if not converged(points, mu1, lb1):
            raise RuntimeError("the refit did not converge on %r" % (points,))
    return math.exp(mu1), math.exp(lb1)




def has_maximum(points):
    """Whether ln L has a maximum: a collapse, and two distinct collapse q or a censored q above the one."""
    collapsed = {q for q, c in points if c}
    return len(collapsed) > 1 or (len(collapsed) == 1 and any(q > min(collapsed) for q, c in points if not c))


def in_draw_order(items, identities):
    """The items in the order every bootstrap draws the records in (issue 40; studies/record_order.hpp): by
    their identities (hex SHA-256) as strings, equal ones in the order listed.  Written apart from the C++
    code's std::stable_sort: Python's sort of the indices keyed by (identity, index)."""
    if len(items) != len(identities):
        raise ValueError("%d identities for %d records" % (len(identities), len(items)))
    return [items[i] for i in sorted(range(len(items)), key=lambda i: (identities[i], i))]


def bootstrap(points, resamples, seed, level):
    """The points drawn by their positions, in the order given (a study's draw order: in_draw_order)."""
    rng = GslMt19937(seed)
    med, bet = [], []
    while len(med) < resamples:
        draw = [points[rng.uniform_int(len(points))] for _ in points]
        if not has_maximum(draw):
            continue
        m, b = fit(draw)
        med.append(m)
        bet.append(b)
    t = (1 - level) / 2
    return (percentile(med, t), percentile(med, 1 - t), percentile(bet, t), percentile(bet, 1 - t))


def eq27(x):
    """Eq. 27 (the behaviour factor for six pulses) as printed, at 30 digits."""
    x = mpf(x)
    s2 = lambda v: sinh(v) ** 2
    return (mpf(2) / 3 * s2(3 * x) + mpf(1) / 3) / (s2(x) - s2(x / 2) + s2(2 * x) - s2(2.5 * x) - s2(1.5 * x)
                                                    + mpf(2) / 3 * s2(3 * x))


def wilson(k, n, level):
    z = NormalDist().inv_cdf(0.5 + level / 2)
    ph, z2n = k / n, z * z / n
    centre = (ph + z2n / 2) / (1 + z2n)
    half = z * math.sqrt(ph * (1 - ph) / n + z2n / (4 * n)) / (1 + z2n)
    return (0.0 if k == 0 else centre - half, 1.0 if k == n else centre + half)


def record_bootstrap(counts, blocks, resamples, seed, level):
    """counts[r][k]: record r's non-conservative cases for k, of `blocks`."""
    rng, n = GslMt19937(seed), len(counts)
    shares = [[] for _ in range(11)]
    for _ in range(resamples):
        drawn = [counts[rng.uniform_int(n)] for _ in range(n)]
        for k in range(11):
            shares[k].append(sum(c[k] for c in drawn) / (n * blocks))
    t = (1 - level) / 2
    return [(percentile(v, t), percentile(v, 1 - t)) for v in shares]


def identities_of(pts, failures):
    """{record: identity} from a points file's rows (one identity per record on every block, each distinct)."""
    ids = {}
    for p in pts:
        if ids.setdefault(p["record"], p["identity"]) != p["identity"]:
            failures.append("%s: two identities, %s and %s" % (p["record"], ids[p["record"]], p["identity"]))
    if len(set(ids.values())) != len(ids):
        failures.append("two records share an identity")
    return ids


def check_eq27(pts, rows, to_of, failures):
    """fragility_eq27.csv from fragility_points.csv and table2's to_k; returns the values compared.  The
    bootstrap draws the records in the order of their identities (in_draw_order)."""
    records = list(dict.fromkeys(p["record"] for p in pts))
    ids = identities_of(pts, failures)
    blocks = list(dict.fromkeys((p["alpha"], p["p"]) for p in pts))
    # nc[r][b][k]: the verdict of record r on block b for to_k.
    nc = {r: {} for r in records}
    for p in pts:
        if p["outcome"] == "censored":
            verdict = [False] * 11  # collapse q above q_max, unknown: counted as conservative
        else:
            q = float(p["q_collapse"] if p["q_collapse"] != "-" else p["q_ill_collapse"])
            verdict = [q < eq27(float(p["p"]) * to) for to in to_of[p["record"]]]
        nc[p["record"]][(p["alpha"], p["p"])] = verdict
    counts = [[sum(nc[r][b][k] for b in blocks) for k in range(11)] for r in records]
    n_cases = len(records) * len(blocks)
    checked = 0
    if len(rows) != 11:
        failures.append("eq27: %d rows, not 11" % len(rows))
        return checked
    boot = None
    for k, row in enumerate(rows):
        name = "eq27 to_%d" % (k + 1)
        got = {"k": k + 1, "non_conservative": sum(c[k] for c in counts), "cases": n_cases,
               "blocks_with_any": sum(any(nc[r][b][k] for r in records) for b in blocks),
               "records_with_any": sum(c[k] > 0 for c in counts), "records": len(records)}
        for key, v in got.items():
            checked += 1
            if int(row[key]) != v:
                failures.append("%s %s: Python %d, CSV %s" % (name, key, v, row[key]))
        share = got["non_conservative"] / n_cases
        close = {"share": share}
        close["wilson_lo"], close["wilson_hi"] = wilson(got["non_conservative"], n_cases, 0.95)
        for key, v in close.items():
            checked += 1
            want = float(row[key])
            if abs(v - want) > TOL_EQ27 * abs(want):
                failures.append("%s %s: Python %.17g, CSV %.17g" % (name, key, v, want))
        if boot is None:
            boot = record_bootstrap(in_draw_order(counts, [ids[r] for r in records]), len(blocks),
                                    int(row["resamples"]), int(row["seed"]), float(row["boot_level"]))
        for key, v in zip(("boot_lo", "boot_hi"), boot[k]):
            checked += 1
            if v != float(row[key]):  # exact: counts over 64, one interpolation, the same on both sides
                failures.append("%s %s: Python %.17g, CSV %s" % (name, key, v, row[key]))
    return checked


def sample_digest(dt, samples_g):
    """studies::sample_digest: SHA-256 of the step's %.17g text, ';' and the samples in g as little-endian doubles."""
    return hashlib.sha256(("%.17g" % dt).encode() + b";" + struct.pack("<%dd" % len(samples_g), *samples_g)).hexdigest()


def shared_samples_g(path):
    """A shared record as rocking reads it, in g (the scene's g = 9.81): ESM's cm/s^2 times 0.01 over 9.81, PEER's g
    times 9.81 over 9.81 (the reader keeps m/s^2), each operation as the C++ code orders it, so the doubles agree
    to the bit (the text parsed by correctly rounded conversions on both sides)."""
    spec = importlib.util.spec_from_file_location("t1", os.path.join(HERE, "..", "table1",
                                                                     "independent_first_overturning.py"))
    t1 = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(t1)
    if path.endswith(".AT2"):
        dt, g = t1.read_at2(path)
        return dt, [x * 9.81 / 9.81 for x in g]
    return t1.ind.read_esm(path)


def check_identities(pts, generated, failures):
    """Each record's identity recomputed here: a generated record's the SHA-256 of its label; a shared one's the
    digest of its samples as read from ../shared/records (skipped, and said, without the folder)."""
    ids = identities_of(pts, failures)
    if generated:
        for label, identity in ids.items():
            if hashlib.sha256(label.encode()).hexdigest() != identity:
                failures.append("%s: identity %s is not the SHA-256 of its label" % (label, identity))
        return "%d identities, each the SHA-256 of its label" % len(ids)
    root = os.environ.get("ROCKING_RECORDS") or os.path.join(HERE, "..", "..", "..", "shared", "records")
    missing = [r for r in ids if not os.path.isfile(os.path.join(root, r))]
    if missing:
        return "%d identities not recomputed: %d records absent from %s" % (len(ids), len(missing), root)
    for record, identity in ids.items():
        dt, a = shared_samples_g(os.path.join(root, record))
        if sample_digest(dt, a) != identity:
            failures.append("%s: identity %s, its samples' digest here %s" % (record, identity, sample_digest(dt, a)))
    return "%d identities, each the digest of the record's samples read here" % len(ids)


def point_of(p):
    """A fragility_*points.csv row as (q, collapsed)."""
    if p["outcome"] == "censored":
        return float(p["q_censored"]), False
    return float(p["q_collapse"] if p["q_collapse"] != "-" else p["q_ill_collapse"]), True


def check_fits(pts, fits, prefix, agree, failures):
    """fits: the rows of a fits file (of one set); pts: the points file's rows of that set."""
    for f in fits:
        block = [p for p in pts if p["alpha"] == f["alpha"] and p["p"] == f["p"]]
        points, ill = [], 0
        for p in block:
            points.append(point_of(p))
            ill += p["check"] == "ill-conditioned"
        # The fit and its bootstrap take the records in their draw order (the fit alone would not care).
        points = in_draw_order(points, [p["identity"] for p in block])
        name = prefix + "alpha %s p %s" % (f["alpha"], f["p"])
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
        # How far ln L may move when every collapse q moves by the points' 2e-6 (TOLERANCES):
        # sum over the points of |d ln L / d ln q_i| at the fit (the fit's own shift is second order).
        mu, bound = math.log(m), 0.0
        for q, c in points:
            z = (math.log(q) - mu) / b
            bound += (abs(-z / b - 1) if c else hazard(z) / b) * 2e-6
        print("  %s: ln L moves at most %.2g for a 2e-6 move of every q" % (name, bound))


# ---- The synthetic set, regenerated here ----

PULSE_FP = [2.0, 1.25, 0.8, 0.5, 0.32]             # Hz
PULSE_SHAPES = [(2.0, 0.0), (3.0, math.pi / 2)]    # (gamma, nu)
PULSE_A, PULSE_REST, PULSE_DT = 0.5, 2.0, 0.005
SEEDS, STOCH_DT, STOCH_DURATION = range(1, 11), 0.01, 40.0
# records::StochasticDefaults
IA_S_G, D5_95, T_MID, FMID, FPRIME, ZETA, FC = 0.0468, 17.3, 12.4, 5.87, -0.089, 0.213, 0.2
RECOVER = 0.05


def text_of(v):
    """The C++ generator's text of a parameter: the shortest %g of 15-17 digits that reads back."""
    for digits in (15, 16, 17):
        t = "%.*g" % (digits, v)
        if float(t) == v:
            return t
    return t


def samples(dt, duration):
    return int(math.floor(duration / dt + 1e-9)) + 1


def pulse_acceleration(A, fp, nu, gamma, t0, dt, duration):
    """a(t) = dv/dt of v(t) = (A/2)(1 + cos(2 pi fp s/gamma)) cos(2 pi fp s + nu), s = t - t0, on |s| <= gamma/(2 fp)."""
    t = dt * np.arange(samples(dt, duration))
    s = t - t0
    w = 2 * np.pi * fp
    a = -(A * np.pi * fp / gamma) * (np.sin(w * s / gamma) * np.cos(w * s + nu)
                                     + gamma * np.sin(w * s + nu) * (1 + np.cos(w * s / gamma)))
    a[np.abs(s) > gamma / (2 * fp)] = 0.0
    return a


def gamma_pinv(p, k):
    return findroot(lambda x: gammainc(k, 0, x, regularized=True) - mpf(p), mpf(k))


def default_modulation():
    """(alpha1, alpha2, alpha3, t_mid) of the defaults: q^2 is a gamma density of shape k = 2 alpha2 - 1,
    k from t_mid / D5-95 (a function of k alone), alpha3 from D5-95, alpha1 from Ia; mpmath at 30 digits."""
    ratio = mpf(T_MID) / mpf(D5_95)
    k = findroot(lambda k: gamma_pinv(0.45, k) / (gamma_pinv(0.95, k) - gamma_pinv(0.05, k)) - ratio, mpf(6.5))
    a3 = (gamma_pinv(0.95, k) - gamma_pinv(0.05, k)) / (2 * mpf(D5_95))
    a1 = mp_exp((mp_log(2 * mpf(G) * mpf(IA_S_G) * mpf(G) / mp.pi) + k * mp_log(2 * a3) - loggamma(k)) / 2)
    return float(a1), float((k + 1) / 2), float(a3), float(gamma_pinv(0.45, k) / (2 * a3))


def gsl_normals(seed, n):
    """n normals from GSL itself: gsl_rng_mt19937 seeded, gsl_ran_gaussian_ziggurat (sigma 1)."""
    ctypes.CDLL(ctypes.util.find_library("gslcblas") or "libgslcblas.so.0", mode=ctypes.RTLD_GLOBAL)
    g = ctypes.CDLL(ctypes.util.find_library("gsl") or "libgsl.so")
    g.gsl_rng_alloc.restype = ctypes.c_void_p
    g.gsl_rng_alloc.argtypes = [ctypes.c_void_p]
    g.gsl_rng_set.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
    g.gsl_rng_free.argtypes = [ctypes.c_void_p]
    g.gsl_ran_gaussian_ziggurat.restype = ctypes.c_double
    g.gsl_ran_gaussian_ziggurat.argtypes = [ctypes.c_void_p, ctypes.c_double]
    r = g.gsl_rng_alloc(ctypes.c_void_p.in_dll(g, "gsl_rng_mt19937").value)
    g.gsl_rng_set(r, seed)
    u = np.array([g.gsl_ran_gaussian_ziggurat(r, 1.0) for _ in range(n)])
    g.gsl_rng_free(r)
    return u


def stochastic_acceleration(seed, dt, duration, modulation):
    a1, a2, a3, t_mid = modulation
    n = samples(dt, duration)
    t = dt * np.arange(n)
    u = gsl_normals(seed, n)
    w_mid, w_prime, w_c = 2 * math.pi * FMID, 2 * math.pi * FPRIME, 2 * math.pi * FC
    root = math.sqrt(1 - ZETA * ZETA)
    # nu(t_k) = sum_{i<=k} h(t_k - t_i; t_i) u_i / sqrt(sum_{i<=k} h^2), every term kept
    num, den = np.zeros(n), np.zeros(n)
    for i in range(n):
        w = w_mid + w_prime * (t[i] - t_mid)
        s = t[: n - i]
        h = w / root * np.exp(-ZETA * w * s) * np.sin(w * root * s)
        num[i:] += h * u[i]
        den[i:] += h * h
    nu = np.zeros(n)
    nu[1:] = num[1:] / np.sqrt(den[1:])
    x = np.where(t > 0, a1 * np.power(np.maximum(t, 1e-300), a2 - 1) * np.exp(-a3 * t), 0.0) * nu
    # z'' + 2 w z' + w^2 z = x(t), x linear on each step: z = z_p + (A + B s) e^(-w s) with the
    # particular solution z_p = (x_k + c s)/w^2 - 2c/w^3; the record is z'' = x - 2 w z' - w^2 z.
    w, e = w_c, math.exp(-w_c * dt)
    out, z, v = np.empty(n), 0.0, 0.0
    for k in range(n):
        out[k] = x[k] - 2 * w * v - w * w * z
        if k + 1 == n:
            break
        c = (x[k + 1] - x[k]) / dt
        A = z - (x[k] / w ** 2 - 2 * c / w ** 3)
        B = (v - c / w ** 2) + w * A
        z = (A + B * dt) * e + (x[k + 1] / w ** 2 - 2 * c / w ** 3)
        v = (B - w * (A + B * dt)) * e + c / w ** 2
    return out


def synthetic_set():
    """[(set, label, a, dt, duration, to_pulse or None)] in the scene's order."""
    out = []
    for fp in PULSE_FP:
        for gamma, nu in PULSE_SHAPES:
            half = gamma / (2 * fp)
            t0 = PULSE_REST + half
            duration = t0 + half + PULSE_REST
            label = "MP2003 pulse A=%s fp=%s nu=%s gamma=%s t0=%s" % tuple(text_of(v) for v in (PULSE_A, fp, nu, gamma, t0))
            out.append(("pulse", label, pulse_acceleration(PULSE_A, fp, nu, gamma, t0, PULSE_DT, duration), PULSE_DT,
                        duration, 1 / (2 * fp)))
    modulation = default_modulation()
    for seed in SEEDS:
        out.append(("stochastic", "RDK2008 stochastic seed=%d" % seed,
                    stochastic_acceleration(seed, STOCH_DT, STOCH_DURATION, modulation), STOCH_DT, STOCH_DURATION,
                    None))
    return out, modulation


def check_synthetic(d, failures, agree):
    recs = read(d + "/fragility_synthetic_records.csv")
    pts = read(d + "/fragility_synthetic_points.csv")
    fits = read(d + "/fragility_synthetic_fits.csv")
    e27 = read(d + "/fragility_synthetic_eq27.csv")
    notes = read_notes(d + "/fragility_synthetic_eq27.csv")
    made, modulation = synthetic_set()
    print("fragility independent, synthetic: alphas %.17g %.17g %.17g (mpmath), t_mid %.17g s" % modulation[:4])
    if [(r["set"], r["record"]) for r in recs] != [(m[0], m[1]) for m in made]:
        failures.append("synthetic records: the labels differ from the set defined here")
        return
    to_of, pga_of, half_of, worst, margin = {}, {}, {}, {"pga": 0.0, "pgv": 0.0, "to": 0.0}, 1.0
    for r, (set_, label, a, dt, duration, half) in zip(recs, made):
        pga, pgv, _, to = half_periods(a, dt)
        to_of[label], pga_of[label], half_of[label] = to, pga, half
        for key, v in (("dt", dt), ("duration", duration)):
            if float(r[key]) != v:
                failures.append("%s %s: CSV %s, here %r" % (label, key, r[key], v))
        if int(r["samples"]) != len(a):
            failures.append("%s samples: CSV %s, here %d" % (label, r["samples"], len(a)))
        for key, v, tol in (("pga_ms2", pga, TOL_RECORD), ("pgv_ms", pgv, TOL_RECORD)):
            dev = abs(v - float(r[key])) / abs(v)
            worst[key[:3]] = max(worst[key[:3]], dev)
            if dev > tol:
                failures.append("%s %s: here %.17g, CSV %s" % (label, key, v, r[key]))
        for k in range(11):
            dev = abs(to[k] - float(r["to_%d" % (k + 1)])) / to[k]
            worst["to"] = max(worst["to"], dev)
            if dev > TOL_TO:
                failures.append("%s to_%d: here %.17g, CSV %s" % (label, k + 1, to[k], r["to_%d" % (k + 1)]))
        if half is None:
            if any(r[c] != "-" for c in ("to_pulse", "recovers", "closest", "closest_ratio")):
                failures.append("%s: a stochastic record with pulse columns" % label)
            continue
        ratios = [t / half for t in to]
        recovers = " ".join(str(k + 1) for k in range(11) if abs(ratios[k] - 1) <= RECOVER) or "none"
        closest = min(range(11), key=lambda k: abs(ratios[k] - 1))
        margin = min(margin, min(abs(abs(x - 1) - RECOVER) for x in ratios))
        if float(r["to_pulse"]) != half:
            failures.append("%s to_pulse: CSV %s, here %r" % (label, r["to_pulse"], half))
        if r["recovers"] != recovers or int(r["closest"]) != closest + 1:
            failures.append("%s recovers/closest: CSV %s / %s, here %s / %d" % (label, r["recovers"], r["closest"],
                                                                                recovers, closest + 1))
        if abs(ratios[closest] - float(r["closest_ratio"])) > TOL_TO * ratios[closest]:
            failures.append("%s closest_ratio: CSV %s, here %.17g" % (label, r["closest_ratio"], ratios[closest]))
    print("fragility independent, synthetic: %d records regenerated; worst relative deviation PGA %.2g, PGV %.2g, "
          "to_k %.2g; the nearest ratio to_k/to_pulse is %.2g from the 5 %% line of 'recovers'"
          % (len(made), worst["pga"], worst["pgv"], worst["to"], margin))

    # The points: q_input from the regenerated PGA; eq. 27 at the pulse's own half-period.
    worst_q, worst_27, pulse_margin = 0.0, 0.0, 1e300
    for p in pts:
        label, alpha, pp = p["record"], float(p["alpha"]), float(p["p"])
        qi = pga_of[label] / (alpha * G)
        worst_q = max(worst_q, abs(qi - float(p["q_input"])) / qi)
        if abs(qi - float(p["q_input"])) > TOL_RECORD * qi:
            failures.append("%s alpha %s p %s q_input: here %.17g, CSV %s" % (label, p["alpha"], p["p"], qi, p["q_input"]))
        half = half_of[label]
        if half is None:
            if p["q_eq27_pulse"] != "-" or p["non_conservative_pulse"] != "-":
                failures.append("%s: a stochastic point with eq. 27 at a pulse's half-period" % label)
            continue
        q27 = eq27(pp * half)
        worst_27 = max(worst_27, float(abs(q27 - mpf(p["q_eq27_pulse"])) / q27))
        if abs(q27 - mpf(p["q_eq27_pulse"])) > TOL_EQ27 * q27:
            failures.append("%s alpha %s p %s q_eq27_pulse: here %s, CSV %s" % (label, p["alpha"], p["p"],
                                                                               mp.nstr(q27, 17), p["q_eq27_pulse"]))
        q, collapsed = point_of(p)
        verdict = "yes" if collapsed and q < q27 else "no"
        if collapsed:
            pulse_margin = min(pulse_margin, abs(math.log(q / float(q27))))
        if p["non_conservative_pulse"] != verdict:
            failures.append("%s alpha %s p %s non_conservative_pulse: here %s, CSV %s"
                            % (label, p["alpha"], p["p"], verdict, p["non_conservative_pulse"]))
    print("fragility independent, synthetic: %d points: q_input within %.2g, eq. 27 at the pulse's half-period "
          "within %.2g; its verdicts flip only if a collapse q moves by %.3g in ln q" % (len(pts), worst_q, worst_27,
                                                                                      pulse_margin))

    print("fragility independent, synthetic: " + check_identities(pts, True, failures))

    # The fits per (set, block).
    for set_ in ("pulse", "stochastic"):
        check_fits([p for p in pts if p["set"] == set_], [f for f in fits if f["set"] == set_], set_ + " ", agree,
                   failures)

    # Eq. 27 per set, with the to_k computed here.
    checked = 0
    for set_, members in (("pulse", ("pulse",)), ("stochastic", ("stochastic",)),
                          ("synthetic", ("pulse", "stochastic"))):
        rows = [r for r in e27 if r["set"] == set_]
        n_fail = len(failures)
        checked += check_eq27([p for p in pts if p["set"] in members], rows, to_of, failures)
        failures[n_fail:] = [set_ + " " + f for f in failures[n_fail:]]
    print("fragility independent, synthetic: %d eq. 27 values (counts, bootstrap bounds exact; share, Wilson 1e-12)"
          % checked)

    # The note "pulse half-period": eq. 27 at x = p/(2 fp), its counts, Wilson and bootstrap.
    pp = [p for p in pts if p["set"] == "pulse"]
    records = list(dict.fromkeys(p["record"] for p in pp))
    blocks = list(dict.fromkeys((p["alpha"], p["p"]) for p in pp))
    nc = {(p["record"], p["alpha"], p["p"]): p["non_conservative_pulse"] == "yes" for p in pp}
    counts = [[sum(nc[(r, a, b)] for a, b in blocks)] * 11 for r in records]
    k = sum(c[0] for c in counts)
    n = len(records) * len(blocks)
    wl, wh = wilson(k, n, 0.95)
    first = e27[0]
    ids = identities_of(pp, failures)
    bl, bh = record_bootstrap(in_draw_order(counts, [ids[r] for r in records]), len(blocks), int(first["resamples"]),
                              int(first["seed"]), float(first["boot_level"]))[0]
    with_any = sum(c[0] > 0 for c in counts)
    want = ("%d of %d cases non-conservative, share %.4g, Wilson 95 %% [%.3g, %.3g], bootstrap over the pulses 90 %% "
            "[%.3g, %.3g]; %d of %d pulses non-conservative on at least one block" % (k, n, k / n, wl, wh, bl, bh,
                                                                                     with_any, len(records)))
    if not notes.get("pulse half-period", "").endswith(want):
        failures.append("note 'pulse half-period': CSV '%s', here '...%s'" % (notes.get("pulse half-period"), want))
    print("fragility independent, synthetic: eq. 27 at the pulse's own half-period: " + want)


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "."
    failures, checked, worst = [], 0, 0.0

    def agree(what, got, want):
        nonlocal checked, worst
        checked += 1
        dev = abs(got - want) / abs(want)
        worst = max(worst, dev)
        if dev > TOL:
            failures.append("%s: Python %.17g, CSV %.17g (rel %.2g)" % (what, got, want, dev))

    if not os.path.exists(d + "/fragility_points.csv"):
        print("fragility independent: no fragility_points.csv (a run without the shared records): their part skipped")
    else:
        pts = read(d + "/fragility_points.csv")
        print("fragility independent: " + check_identities(pts, False, failures))
        check_fits(pts, read(d + "/fragility_fits.csv"), "", agree, failures)
        print("fragility independent: %d fit values, worst relative deviation %.2g" % (checked, worst))
        t2 = read(os.path.join(HERE, "..", "table2", "table2_records.csv"))
        to_of = {r["record"]: [float(r["to_%d" % k]) for k in range(1, 12)] for r in t2}
        missing = sorted({p["record"] for p in pts} - set(to_of))
        if missing:
            failures.append("eq27: no to_k in expected/table2 for " + ", ".join(missing))
        else:
            n = check_eq27(pts, read(d + "/fragility_eq27.csv"), to_of, failures)
            print("fragility independent: %d eq. 27 values (counts, bootstrap bounds exact; share, Wilson 1e-12)" % n)
    checked, worst = 0, 0.0
    check_synthetic(d, failures, agree)
    print("fragility independent, synthetic: %d fit values, worst relative deviation %.2g" % (checked, worst))
    for x in failures:
        print("  FAIL " + x)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
