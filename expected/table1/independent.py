#!/usr/bin/python3
"""Independent check of expected/table1/table1.csv: q = PGA / (alpha 981) recomputed
from the transcription (reproduce/data/paper_table1.csv), and the agreement with the
printed q within its rounding (0.005).  table1_records.csv is checked by
`reproduce --reference table1` (a second solver confirms every collapse bracket)."""
import csv, os, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
from independent_check import Checker, directory_from_argv  # noqa: E402

src = os.path.join(here, "..", "..", "reproduce", "data", "paper_table1.csv")
rows = [r for r in csv.reader(l for l in open(src) if not l.startswith("#"))][1:]
alphas = [0.05, 0.1, 0.15, 0.2, 0.25]
q, agrees, qp = [], [], []
for r in rows:
    for i, a in enumerate(alphas):
        v = float(r[1]) / (a * 981.0)
        q.append(v)
        qp.append(float(r[7 + 2 * i]))
        agrees.append("yes" if abs(v - float(r[7 + 2 * i])) <= 0.005 + 1e-9 else "no")
ck = Checker(directory_from_argv())
ck.check("table1.csv", "q_computed", q, rel_tol=1e-12)
ck.check("table1.csv", "q_paper", qp)
ck.check("table1.csv", "agrees", agrees, exact=True)
ck.finish()
