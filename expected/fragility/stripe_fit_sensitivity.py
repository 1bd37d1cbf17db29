#!/usr/bin/python3
"""How far the multiple-stripe fit of the fragility scene may move when the boundaries of the
records' overturning sets move: the basis of the stripe fits' TOLERANCES (PROVENANCE.md, "Under
each capacity").

A boundary computed on another machine is either the same double or, where rounding decides an
outcome at a bisection point, one whole bracket (2e-6 relative) away; an ill-conditioned one (the
probe flips it) may sit anywhere between the two samples around it, at most w apart in ln q.  A
boundary that moves by d in ln q moves its stripe's count z_j by d / (the stripe's width in ln q).
The fit's (ln median, ln beta) then move by at most sum_j |d theta / d z_j| dz_j, the derivatives
by central differences (dz = 1e-3) of the double-precision fit of independent_capacities.py
(BFGS on (S2)), and ln L at the maximum by sum_j |ln Phi(u_j) - ln Phi(-u_j)| dz_j (at the
maximum ln L's own dependence on median and beta drops out).  Printed per block:
  every boundary a bracket: dz_j = (boundaries in stripe j) x 2e-6 / width_j;
  one boundary by w (the ill-conditioned case): the worst stripe's |d theta / d z_j| w / width_j.

Input: the --json of `rocking fragility FILES --alpha 0.1,0.2 --p 1.5,3 --method refine --width
1e-3 --bootstrap 500 --seed 1` on the scene's records (the boundaries are the intervals' ends).
Usage: stripe_fit_sensitivity.py FILE.json [WIDTH]   (WIDTH: w, default 1e-3).
"""
import importlib.util
import json
import math
import os
import sys

import numpy as np
from scipy.special import log_ndtr

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("independent_capacities", os.path.join(HERE, "independent_capacities.py"))
ic = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ic)


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    w = float(sys.argv[2]) if len(sys.argv) == 3 else 1e-3
    doc = json.load(open(sys.argv[1]))
    g = ic.sm.grid(doc["grid"]["q_min"], doc["grid"]["q_max"], doc["grid"]["points"])
    x = np.log([math.sqrt(a * b) for a, b in zip(g, g[1:])])
    width = np.log(np.array(g[1:]) / np.array(g[:-1]))
    for block in doc["blocks"]:
        recs = block["records"]
        n = float(len(recs))
        z = np.array([sum(r["bands"][j]["share"] for r in recs) for j in range(len(x))])
        ends = np.zeros(len(x))
        for r in recs:
            for i in r["intervals"]:
                for q in (i["from"], i["to"]):
                    ends[min(max(int(np.searchsorted(g, q)) - 1, 0), len(x) - 1)] += 1
        fit = block["fits"]["stripes"]["fit"]
        start = [math.log(fit["median"]), math.log(fit["beta"])]
        m, b = ic.ranking_fit(x, n, z, start)
        theta = np.array([math.log(m), math.log(b)])
        jac = []
        for j in range(len(x)):
            h = 1e-3
            zp, zm = z.copy(), z.copy()
            zp[j], zm[j] = min(z[j] + h, n), max(z[j] - h, 0.0)
            fp, fm = ic.ranking_fit(x, n, zp, theta), ic.ranking_fit(x, n, zm, theta)
            jac.append((np.log(fp) - np.log(fm)) / (zp[j] - zm[j]))
        jac = np.abs(np.array(jac))
        u = (x - theta[0]) / b
        dlnl = np.abs(log_ndtr(u) - log_ndtr(-u))
        dz = ends * 2e-6 / width
        one = w / width
        print("alpha %g p %g: %d boundaries, at most %d in a stripe; every boundary a bracket: ln median %.2g, "
              "ln beta %.2g, ln L %.2g; one boundary by w = %g: ln median %.2g, ln beta %.2g, ln L %.2g"
              % (block["alpha"], block["p"], ends.sum(), ends.max(), (jac[:, 0] * dz).sum(), (jac[:, 1] * dz).sum(),
                 (dlnl * dz).sum(), w, (jac[:, 0] * one).max(), (jac[:, 1] * one).max(), (dlnl * one).max()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
