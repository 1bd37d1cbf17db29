#!/usr/bin/python3
"""Independent check of expected/table2: to_5 = pi |PGV| / PGA from the transcribed
Table 1 against Table 2; the consistency of Table 2's columns with eqs. 29-30; and the
eleven half-periods of the real records re-implemented with numpy (pulses between the
zero crossings of the piecewise-linear record, trapezoidal velocity, FFT peaks with 8x
zero padding and a parabola, Morse CWT beta 27 gamma 3 with the grid of cwt.hpp; the code
is tools/independent_measures.py, shared with expected/fragility's check of the synthetic records).
Tolerances: 1e-12 for arithmetic; 1e-6 relative for the records (FFT rounding)."""
import csv, math, os, sys
import numpy as np
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
from independent_check import Checker, directory_from_argv, read_expected  # noqa: E402
from independent_measures import half_periods  # noqa: E402

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


root = os.environ.get("ROCKING_RECORDS", os.path.join(here, "..", "..", "..", "shared", "records"))
header, rows = read_expected(d, "table2_records.csv")
if not os.path.isdir(root):
    print("  table2_records.csv: records folder absent, not checked")
else:
    cols = {c: [] for c in header}
    for r in rows:
        a, dt = read_record(os.path.join(root, r[0]))
        pga, pgv, amax, to = half_periods(a, dt)
        cols["PGA_cms2"].append(100 * pga); cols["PGV_cms"].append(100 * pgv); cols["Amax_cms"].append(100 * amax)
        for i in range(11):
            cols["to_%d" % (i + 1)].append(to[i])
    for c in ["PGA_cms2", "PGV_cms", "Amax_cms"] + ["to_%d" % i for i in range(1, 12)]:
        ck.check("table2_records.csv", c, cols[c], rel_tol=1e-6)
ck.finish()
