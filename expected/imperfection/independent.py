#!/usr/bin/python3
"""Independent check of expected/imperfection without the records: every value of the
closed-form files recomputed by a second implementation, and eq. 27's counts recounted.

1. imperfection_corners.csv: each corner's alpha, p, R and restitution, the setback and
   sigma0, from imperfect_block.py's Geometry (polygon integrals, vectors and the angular
   momentum about the pivot; no formula of dynamics/imperfect_block.cpp), to 1e-12.
2. imperfection_q.csv: each corner's collapse PGA from the printed closed forms (eqs. 12,
   15, 22 and 27, mpmath at 30 digits) at x_sigma = p_sigma x / p, times alpha_sigma /
   alpha; the printed forms themselves checked against the superposition (S2) of
   NOTES.md at each point (1e-20); min_phi from (S1) at 30 digits, each pulse's
   stationary point in closed form (phi = -F + a cosh + b sinh on a pulse); q_block,
   weaker, q_perfect and the overstatement.  q to 1e-12 relative, min_phi and the
   overstatement to 1e-12 absolute.
3. A simulation at x = 0.3 and 1.0 of every imperfection, block and case of
   imperfection_q.csv: the imperfect block of imperfect_block.py (closed form per pulse,
   expected/spectrum/independent.py's Piece) driven from rest at each corner's PGA must end
   at theta(t_fin) = alpha_sigma (1e-9) with its lowest theta / alpha_sigma after the first
   pulse equal to min_phi (1e-9): the closed form is the model's collapse, without impact.
4. imperfection_capacity.csv recomputed from 2 on every block (the range over cases 1, 2,
   4, eq. 27 and the 10 x; over x = 0.2..0.8; the weaker side and the excursions).
5. imperfection_eq27.csv recounted from imperfection_points.csv: each case's verdict from
   its first collapse q against eq. 27 as printed at x = p to_k (to_k from
   expected/table2/table2_records.csv, which expected/table2 checks) and toward each corner
   (Geometry and eq. 27 at 30 digits), counts exact, shares to 1e-15; the perfect block's
   rows against expected/fragility (its points within their 2e-6 bisection, the counts
   exactly): the same study in another scene.

Usage: independent.py DIR.  Exit 0 when all agree, 1 on any disagreement (each named), 2
on bad usage.  Without imperfection_points.csv (a run without the records) part 5 is
skipped with a message.
"""
import csv
import math
import os
import sys

from mpmath import mp, mpf, cosh, sinh, atanh

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import imperfect_block as ib  # noqa: E402
from independent_check import Checker, read_expected  # noqa: E402

mp.dps = 30
TRAINS = {"case 1": [(1, 1), (-1, 1)], "case 2": [(1, 1), (-0.5, 1)], "case 4": [(1, 1), (-0.5, 2)],
          "eq. 27": [(1, 1), (-0.5, 1)] * 3}
X = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.5, 2.0]
BLOCKS = [(0.05, 3.0), (0.1, 1.5), (0.1, 3.0), (0.2, 1.5), (0.2, 3.0)]


def printed(case, x):
    """The paper's printed closed forms (eqs. 12, 15, 22, 27)."""
    x = mpf(x)
    c = cosh(x)
    if case == "case 1":
        return (2 * c ** 2 - 1) / (2 * c * (c - 1))
    if case == "case 2":
        return (2 - 4 * c ** 2) / (3 * c - 4 * c ** 2 + 1)
    if case == "case 4":
        return 2 * cosh(3 * x) / (2 * cosh(3 * x) - 3 * cosh(2 * x) + 1)
    s2 = lambda v: sinh(v) ** 2
    return (mpf(2) / 3 * s2(3 * x) + mpf(1) / 3) / (s2(x) - s2(x / 2) + s2(2 * x) - s2(2.5 * x) - s2(1.5 * x)
                                                    + mpf(2) / 3 * s2(3 * x))


def jumps(train, q):
    """(tau_j, dF_j) of F = q A - 1: the superposition's jumps (NOTES.md)."""
    out, t, prev = [], mpf(0), mpf(0)
    for j, (amp, dur) in enumerate(train):
        out.append((t, q * mpf(amp) - 1 if j == 0 else q * (mpf(amp) - prev)))
        prev = mpf(amp)
        t += dur
    return out, t


def superposed(train, x):
    """(S2): q with phi(T) = 1."""
    x = mpf(x)
    js, T = jumps(train, mpf(1))
    den = sum((mpf(train[0][0]) if j == 0 else dF) * (cosh(x * (T - tj)) - 1) for j, (tj, dF) in enumerate(js))
    return cosh(x * T) / den


def lowest_phi(train, x, q):
    """The lowest phi on [end of pulse 1, T] by (S1): on each pulse phi = -F + a cosh(x u)
    + b sinh(x u), u from the pulse's start; its ends and its one stationary point."""
    x = mpf(x)
    js, T = jumps(train, q)

    def state(tau):
        phi = sum(dF * (cosh(x * (tau - tj)) - 1) for tj, dF in js if tj <= tau)
        dphi = sum(dF * x * sinh(x * (tau - tj)) for tj, dF in js if tj <= tau)
        return phi, dphi

    best = mpf("inf")
    t = mpf(train[0][1])
    for amp, dur in train[1:]:
        phi, dphi = state(t)
        F = q * mpf(amp) - 1
        a, b = phi + F, dphi / x
        best = min(best, phi, -F + a * cosh(x * dur) + b * sinh(x * dur))
        if a != 0 and abs(b / a) < 1:
            u = atanh(-b / a) / x
            if 0 < u < dur:
                best = min(best, -F + a * cosh(x * u) + b * sinh(x * u))
        t += dur
    return best


def read(d, name):
    header, rows = read_expected(d, name)
    return [dict(zip(header, r)) for r in rows]


def geometry_of(r, alpha=None, p=None):
    fc = float(r["fc_MPa"]) * 1e6
    density = float(r["density"]) if r["density"] != "-" else ib.DEFAULT_DENSITY
    return ib.Geometry(float(alpha or r["alpha"]), float(p or r["p"]), float(r["lean"]), float(r["out_of_plumb"]),
                       fc, density)


def closed_point(g, alpha, p, case, x):
    """Per side: (q over alpha, min_phi, x_sigma); and q_perfect."""
    out = []
    for k in (g.plus, g.minus):
        xs = mpf(k.p) * mpf(x) / mpf(p)
        q = printed(case, xs)
        out.append((q * mpf(k.alpha) / mpf(alpha), lowest_phi(TRAINS[case], xs, q), xs, q))
    return out, printed(case, x)


def main():
    if len(sys.argv) != 2:
        print("usage: independent.py DIR (the folder holding the imperfection scene's CSV files)", file=sys.stderr)
        return 2
    d = sys.argv[1]
    ck = Checker(d)

    # 1. corners
    corners = read(d, "imperfection_corners.csv")
    geo = {}
    cols = {k: [] for k in ("b", "h", "sigma0_kPa", "setback_mm", "setback_over_b", "alpha_plus", "p_plus", "R_plus",
                            "e_onto_plus", "alpha_minus", "p_minus", "R_minus", "e_onto_minus")}
    for r in corners:
        g = geometry_of(r)
        geo[(r["imperfection"], r["alpha"], r["p"])] = g
        for side, k in (("plus", g.plus), ("minus", g.minus)):
            for name, v in (("alpha", k.alpha), ("p", k.p), ("R", k.R), ("e_onto", k.e_onto)):
                cols[f"{name}_{side}"].append(v)
        for name, v in (("b", g.b), ("h", g.h), ("sigma0_kPa", g.sigma0 / 1e3), ("setback_mm", g.setback * 1e3),
                        ("setback_over_b", g.setback / g.b)):
            cols[name].append(v)
    for name, vals in cols.items():
        ck.check("imperfection_corners.csv", name, vals, abs_tol=1e-15, rel_tol=1e-12)

    # 2. q against x (alpha 0.10), and 3. the simulation at x = 0.3, 1.0
    qrows = read(d, "imperfection_q.csv")
    want = {k: [] for k in ("q_plus", "min_phi_plus", "q_minus", "min_phi_minus", "q_block", "weaker", "q_perfect",
                            "overstatement")}
    worst_s2 = worst_sim = 0.0
    sims = 0
    for r in qrows:
        g = geo[(r["imperfection"], r["alpha"], r["p"])]
        alpha, p, x = float(r["alpha"]), float(r["p"]), float(r["x"])
        sides, qp = closed_point(g, alpha, p, r["case"], x)
        for _, _, xs, q in sides:
            worst_s2 = max(worst_s2, float(abs(q / superposed(TRAINS[r["case"]], xs) - 1)))
        qb = min(sides[0][0], sides[1][0])
        want["q_plus"].append(float(sides[0][0]))
        want["min_phi_plus"].append(float(sides[0][1]))
        want["q_minus"].append(float(sides[1][0]))
        want["min_phi_minus"].append(float(sides[1][1]))
        want["q_block"].append(float(qb))
        want["weaker"].append("-1" if sides[1][0] < sides[0][0] else "1")
        want["q_perfect"].append(float(qp))
        want["overstatement"].append(float(qp / qb - 1))
        if r["x"] in ("0.3", "1.0"):
            for sigma, (qa, mphi, xs, q) in zip((1, -1), sides):
                pga = float(qa) * alpha
                end, low = ib.run_pulses(g, sigma, TRAINS[r["case"]], pga, x / p)
                worst_sim = max(worst_sim, abs(end - 1), abs(low - float(mphi)))
                sims += 1
    for name in ("q_plus", "q_minus", "q_block", "q_perfect"):
        ck.check("imperfection_q.csv", name, want[name], rel_tol=1e-12)
    for name in ("min_phi_plus", "min_phi_minus", "overstatement"):
        ck.check("imperfection_q.csv", name, want[name], abs_tol=1e-12)
    ck.check("imperfection_q.csv", "weaker", want["weaker"], exact=True)
    print(f"  printed eqs. 12, 15, 22, 27 against (S2) at every corner's x: largest relative difference {worst_s2:.2g}")
    if not worst_s2 < 1e-20:
        ck.fail(f"a printed closed form differs from (S2) by {worst_s2:.3g}")
    print(f"  {sims} runs of the imperfect block on the pulses: |theta(t_fin)/alpha_sigma - 1| and |lowest - "
          f"min_phi| at most {worst_sim:.2g}")
    if not worst_sim < 1e-9:
        ck.fail(f"the simulated block ends {worst_sim:.3g} away from the closed form")

    # 4. the capacity summary, every block
    srows = read(d, "imperfection_capacity.csv")
    want = {k: [] for k in ("points", "overstatement_min", "overstatement_max", "overstatement_min_0.2_0.8",
                            "overstatement_max_0.2_0.8", "weaker_minus", "off_corner")}
    for r in srows:
        g = geo[(r["imperfection"], r["alpha"], r["p"])]
        alpha, p = float(r["alpha"]), float(r["p"])
        over, paper, weaker, off = [], [], 0, 0
        for case in TRAINS:
            for x in X:
                sides, qp = closed_point(g, alpha, p, case, x)
                o = float(qp / min(sides[0][0], sides[1][0]) - 1)
                over.append(o)
                if 0.2 <= x <= 0.8:
                    paper.append(o)
                weaker += sides[1][0] < sides[0][0]
                off += not (sides[0][1] > 0 and sides[1][1] > 0)
        for k, v in (("points", str(len(over))), ("overstatement_min", min(over)), ("overstatement_max", max(over)),
                     ("overstatement_min_0.2_0.8", min(paper)), ("overstatement_max_0.2_0.8", max(paper)),
                     ("weaker_minus", str(weaker)), ("off_corner", str(off))):
            want[k].append(v)
    for k, v in want.items():
        if k in ("points", "weaker_minus", "off_corner"):
            ck.check("imperfection_capacity.csv", k, v, exact=True)
        else:
            ck.check("imperfection_capacity.csv", k, v, abs_tol=1e-12)

    # 5. eq. 27's counts
    if not os.path.exists(os.path.join(d, "imperfection_points.csv")):
        print("  imperfection_points.csv absent (a run without the records): eq. 27's counts not recounted")
    else:
        check_eq27(d, ck)
    ck.finish()
    return 0


def check_eq27(d, ck):
    points = read(d, "imperfection_points.csv")
    counts = read(d, "imperfection_eq27.csv")
    table2 = read(os.path.join(HERE, "..", "table2"), "table2_records.csv")
    to = {r["record"]: [float(r[f"to_{k}"]) for k in range(1, 12)] for r in table2}
    names = list(dict.fromkeys(r["imperfection"] for r in points))
    margin = math.inf
    tally = {}
    corner_geo = {}
    for r in points:
        i = r["imperfection"]
        t = tally.setdefault(i, {"cases": 0, "censored": 0, "ill": 0, "nom": [0] * 11, "cor": [0] * 11, "unom": [0] * 11, "ucor": [0] * 11,
                                 "rn": [set() for _ in range(11)], "rc": [set() for _ in range(11)], "records": set()})
        t["cases"] += 1
        t["records"].add(r["record"])
        if r["outcome"] == "censored":
            t["censored"] += 1
            continue
        ill = r["check"] == "ill-conditioned"
        t["ill"] += ill
        q = float(r["q_collapse"] if r["q_collapse"] != "-" else r["q_ill_collapse"])
        gap = (float(r["q_gap_safe"]), float(r["q_gap_collapse"])) if ill else None
        if ill and not gap[0] < float(r["q_ill_safe"]) < q <= gap[1]:
            ck.fail(f"{r['imperfection']} {r['record']} alpha {r['alpha']} p {r['p']}: the grid gap {gap} does not "
                    f"hold the ill-conditioned bracket")
        alpha, p = float(r["alpha"]), float(r["p"])
        key = (i, r["alpha"], r["p"])
        if key not in corner_geo:
            corner_geo[key] = geometry_of(r, alpha, p)
        g = corner_geo[key]
        for k in range(11):
            nominal = printed("eq. 27", mpf(p) * mpf(to[r["record"]][k]))
            toward = min(printed("eq. 27", mpf(c.p) * mpf(to[r["record"]][k])) * mpf(c.alpha) / mpf(alpha)
                         for c in (g.plus, g.minus))
            for q27, col, rec in ((nominal, "nom", "rn"), (toward, "cor", "rc")):
                if gap and gap[0] < q27 <= gap[1]:
                    t["u" + col][k] += 1  # rounding decides it: counted neither way
                    continue
                margin = min(margin, abs(math.log(q / float(q27))))
                if q < q27:
                    t[col][k] += 1
                    t[rec][k].add(r["record"])
    want = {c: [] for c in ("cases", "censored", "ill_conditioned", "non_conservative", "undecided", "share",
                            "records_with_any", "non_conservative_corners", "undecided_corners", "share_corners",
                            "records_with_any_corners", "records")}
    for r in counts:
        t, k = tally[r["imperfection"]], int(r["k"]) - 1
        for col, v in (("cases", t["cases"]), ("censored", t["censored"]), ("ill_conditioned", t["ill"]),
                       ("non_conservative", t["nom"][k]), ("undecided", t["unom"][k]),
                       ("share", t["nom"][k] / t["cases"]), ("undecided_corners", t["ucor"][k]),
                       ("records_with_any", len(t["rn"][k])), ("non_conservative_corners", t["cor"][k]),
                       ("share_corners", t["cor"][k] / t["cases"]), ("records_with_any_corners", len(t["rc"][k])),
                       ("records", len(t["records"]))):
            want[col].append(v)
    for col, v in want.items():
        if col.startswith("share"):
            ck.check("imperfection_eq27.csv", col, v, rel_tol=1e-15)
        else:
            ck.check("imperfection_eq27.csv", col, [str(x) for x in v], exact=True)
    print(f"  {len(names)} imperfections recounted; the smallest |ln(collapse q / eq. 27's q)| of a decided case: "
          f"{margin:.3g}")

    # The perfect block is the fragility scene's study: the same points and counts.
    frag = os.path.join(HERE, "..", "fragility")
    fp = {(r["record"], r["alpha"], r["p"]): r for r in read(frag, "fragility_points.csv")}
    worst = 0.0
    for r in points:
        if r["imperfection"] != "perfect":
            continue
        f = fp[(r["record"], r["alpha"], r["p"])]
        same = all(r[c] == f[c] for c in ("outcome", "intervals", "check") if c in f)
        for c in ("q_collapse", "q_safe", "q_ill_collapse", "q_ill_safe"):
            if (r[c] == "-") != (f[c] == "-"):
                same = False
            elif r[c] != "-":
                dev = abs(float(r[c]) / float(f[c]) - 1)
                worst = max(worst, dev)
                same = same and dev <= (2e-6 if "ill" not in c else 1.6e-2)
        if not same:
            ck.fail(f"perfect {r['record']} alpha {r['alpha']} p {r['p']}: not the fragility scene's point")
    fe = {r["k"]: r for r in read(frag, "fragility_eq27.csv")}
    for r in counts:
        if r["imperfection"] == "perfect":
            f = fe[r["k"]]
            if (r["non_conservative"], r["records_with_any"]) != (f["non_conservative"], f["records_with_any"]):
                ck.fail(f"perfect k {r['k']}: {r['non_conservative']} cases, {r['records_with_any']} records; the "
                        f"fragility scene has {f['non_conservative']}, {f['records_with_any']}")
    print(f"  the perfect block's points and counts against expected/fragility: brackets within {worst:.2g}")


if __name__ == "__main__":
    sys.exit(main())
