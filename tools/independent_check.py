"""Shared helpers for the independent checks of expected/ (see docs/verification.md).

Each expected/<scene>/independent.py recomputes the scene's values with a second
implementation (mpmath at 30+ digits, or plain Python floats for formula-by-formula
comparisons) and calls check() for each file: every named column of the expected CSV
must agree with the independent values within the tolerance given here, which is
stated with its reason in each script.  Exit status 1 on any disagreement.
Run with /usr/bin/python3 (Debian's, where python3-mpmath is installed).
"""
import csv
import math
import os
import random
import sys


def read_expected(directory, name):
    with open(os.path.join(directory, name), newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.reader(lines))
    return rows[0], rows[1:]


class Checker:
    def __init__(self, directory):
        self.directory = directory
        self.failures = 0

    def check(self, name, column, values, abs_tol=0.0, rel_tol=0.0, exact=False):
        """values: one independent value per row of expected/<scene>/<name>."""
        header, rows = read_expected(self.directory, name)
        if column not in header:
            self.fail(f"{name}: no column {column}")
            return
        c = header.index(column)
        if len(values) != len(rows):
            self.fail(f"{name} {column}: {len(rows)} rows expected, independent check has {len(values)}")
            return
        worst = 0.0
        for r, (row, v) in enumerate(zip(rows, values)):
            cell = row[c]
            if exact:
                ok = cell == str(v)
                dev = 0.0 if ok else math.inf
            else:
                e = float(cell)
                dev = abs(float(v) - e)
                ok = math.isfinite(e) and dev <= abs_tol + rel_tol * abs(float(v))
            worst = max(worst, dev)
            if not ok:
                self.fail(f"{name} {column} row {r + 1}: expected file has {cell}, independent value {v}")
                return
        print(f"  {name} {column}: {len(rows)} values agree (largest deviation {worst:.3g})")

    def fail(self, message):
        self.failures += 1
        print("  DISAGREES: " + message)

    def finish(self):
        if self.failures:
            print(f"independent check: {self.failures} disagreement(s) in {self.directory}")
            sys.exit(1)
        print(f"independent check: {self.directory} agrees")


def directory_from_argv():
    if len(sys.argv) != 2:
        print("usage: independent.py EXPECTED_SCENE_DIR", file=sys.stderr)
        sys.exit(2)
    return sys.argv[1]


class GslMt19937:
    """gsl_rng_mt19937 after gsl_rng_set(seed) (seed 0 is 4357, as GSL's), drawing through
    Python's MT19937: the bootstraps' resamples (studies/resampling.hpp) redrawn."""

    def __init__(self, seed):
        s = (seed & 0xFFFFFFFF) or 4357
        mt = [s]
        for i in range(1, 624):
            mt.append((1812433253 * (mt[-1] ^ (mt[-1] >> 30)) + i) & 0xFFFFFFFF)
        self.r = random.Random()
        self.r.setstate((3, tuple(mt) + (624,), None))

    def uniform_int(self, n):
        """gsl_rng_uniform_int: (draw - min) / (range / n), rejected while >= n."""
        scale = 0xFFFFFFFF // n
        while True:
            k = self.r.getrandbits(32) // scale
            if k < n:
                return k


def percentile(v, p):
    """The percentile of the bootstraps' intervals: linear between order statistics at
    p (n - 1), as studies/resampling.hpp's percentile_interval."""
    v = sorted(v)
    at = p * (len(v) - 1)
    k = int(math.floor(at))
    return v[k] + (at - k) * (v[k + 1] - v[k]) if k + 1 < len(v) else v[-1]
