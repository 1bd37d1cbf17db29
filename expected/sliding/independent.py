#!/usr/bin/python3
"""Independent check of expected/sliding (the scene `sliding`, issue 41), with nothing taken from the
C++ code it checks:

  truth    the closed forms computed here: the regime a flat block at rest enters under a constant
           acceleration (docs/sliding.md's criteria, each grid point at least 1e-3 from an edge),
           Newmark's slip by its own piecewise integration, no rocking below tan(alpha);
  records  sliding_records.csv: every row with mu < tan(alpha) never lifts (Shenton's bound: the base
           cannot carry the force that tips the block); the rule (sliding_scene.hpp) implemented again
           here and applied to the runs' columns gives every effect; sliding_claim.csv,
           sliding_claim_verdict.csv and sliding_control.csv recounted from the rows;
  eq27     the ideal model's first collapse is the fragility scene's (expected/fragility/
           fragility_points.csv, within its 2e-6); eq. 27 (mpmath, 30 digits) at x = p to_k with
           table2's to_k (expected/table2/table2_records.csv) recounts sliding_eq27.csv from the points;
  fig05    PGA = q_i(x) alpha Rd with the closed forms of eqs. 12-24 (mpmath); the summary recounted;
  siconos  siconos.csv (expected/sliding/siconos_rows.py, Siconos's Moreau-Jean): no row that decides a
           verdict gives the other one, each verdict has a row that agrees, and every row names an effect
           the expected files hold.

    independent.py EXPECTED_DIR [--only truth,records,eq27,fig05,siconos]

Exit 1 naming the first disagreement of each part.  Standard library and mpmath.
"""
import argparse
import collections
import csv
import math
import os
import sys

from mpmath import cosh, mp, mpf, sinh

mp.dps = 30
G = 9.81
PEAK = 0.05           # the rule's 5 %
CLAIM = 0.35
FRICTIONS = ("0.8", "0.6", "0.4")
PARTS = ("truth", "records", "eq27", "fig05", "siconos")


class Fail(Exception):
    pass


def read(d, name):
    with open(os.path.join(d, name), newline="") as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def close(a, b, rel=0.0, abs_=0.0):
    return abs(a - b) <= abs_ + rel * abs(b)


def need(cond, what):
    if not cond:
        raise Fail(what)


# --- truth ----------------------------------------------------------------------------------

def regime(alpha, mu, a):
    """(regime, distance of a from the nearest criterion edge, per unit weight)."""
    t = math.tan(alpha)
    edges = [abs(a - mu), abs(a - t), abs(mu - t)]
    if a <= min(mu, t):
        return "rest", min(edges)
    if mu < t:
        return "slide", min(edges)
    turn = a * math.cos(alpha) - math.sin(alpha)
    f = 0.75 * math.cos(alpha) * turn - a
    n = 1 + 0.75 * math.sin(alpha) * turn
    edges.append(abs(abs(f) - mu * n))
    return ("rock" if abs(f) <= mu * n else "slide-rock"), min(edges)


def newmark(mu, pulses, dt=None):
    """The slip when it stops, pulses [(a/g, seconds)]: an event-by-event integration (velocity
    zero crossings found exactly), written apart from the scene's."""
    x = v = 0.0
    for a, T in pulses:
        t = 0.0
        while t < T:
            if v == 0.0:
                if abs(a) <= mu:
                    break
                s = math.copysign(1.0, a)
            else:
                s = math.copysign(1.0, v)
            acc = G * (a - mu * s)
            left = T - t
            if v != 0.0 and acc * v < 0.0 and -v / acc < left:
                tau = -v / acc
                x += v * tau / 2          # uniform deceleration to rest: mean speed v/2
                v, t = 0.0, t + tau
            else:
                x += v * left + acc * left * left / 2
                v, t = v + acc * left, T
    if v != 0.0:
        x += v * v / (2 * mu * G) * math.copysign(1.0, v)
    return x


def check_truth(d):
    rows = read(d, "sliding_truth.csv")
    n = collections.Counter()
    for r in rows:
        alpha, mu, a = float(r["alpha"]), float(r["mu"]), float(r["a_g"])
        if r["check"] == "regime":
            want, margin = regime(alpha, mu, a)
            need(margin >= 1e-3, f"sliding_truth.csv regime alpha {alpha} mu {mu} a {a}: {margin:.3g} from an edge")
            need(r["closed_form"] == want, f"regime alpha {alpha} mu {mu} a {a}: file's closed form "
                                           f"{r['closed_form']}, here {want}")
            need(r["engine"] == want, f"regime alpha {alpha} mu {mu} a {a}: engine {r['engine']}, closed form {want}")
        elif r["check"] == "newmark":
            need(mu < math.tan(alpha), f"newmark row alpha {alpha} mu {mu}: the block would rock")
            T = float(r["to_s"])
            pulses = [(float(p.split(":")[0]) * a, float(p.split(":")[1]) * T) for p in r["train"].split(",")]
            want = newmark(mu, pulses)
            need(close(float(r["closed_form"]), want, rel=1e-12), f"newmark {r['train']} mu {mu} a {a} T {T}: file's "
                                                                  f"closed form {r['closed_form']}, here {want!r}")
            # 50 atol (atol = 1e-9 alpha R): the slip-stop event inside a pulse is located on the
            # dense output; measured at most 1.2e-8 m.
            need(close(float(r["engine"]), want, abs_=5e-8), f"newmark {r['train']} mu {mu} a {a} T {T}: engine "
                                                              f"{r['engine']}, closed form {want!r}")
        elif r["check"] == "no-rock":
            need(mu < math.tan(alpha) and r["engine"] == "0" and r["closed_form"] == "0",
                 f"no-rock alpha {alpha} mu {mu}: engine {r['engine']}")
        n[r["check"]] += 1
    need(all(n[k] > 0 for k in ("regime", "newmark", "no-rock")), f"sliding_truth.csv: rows {dict(n)}")
    regimes = {r["engine"] for r in rows if r["check"] == "regime"}
    need(regimes == {"rest", "slide", "rock", "slide-rock"}, f"the regime grid meets {sorted(regimes)}, not all four")
    return f"{n['regime']} regimes (all four met), {n['newmark']} Newmark slips, {n['no-rock']} no-rock runs"


# --- records --------------------------------------------------------------------------------

ROCK = ("full_1e-9", "full_1e-11", "control_1e-9", "control_1e-11")


def effect(r, mu):
    """The rule of sliding_scene.hpp, from the row's columns."""
    outs = [r[c] for c in ROCK]
    f = [r[f"mu{mu}_1e-9"], r[f"mu{mu}_1e-11"]]
    if "outside" in outs[2:]:
        return "outside the model at mu 1e6"
    if "outside" in f:
        return "outside the model"
    if len(set(outs)) > 1:
        return "rocking near-tie"
    o = outs[0]
    if o == "no":
        peaks = [float(r["peak_" + c]) for c in ROCK]
        if max(peaks) > (1 + PEAK) * min(peaks):
            return "rocking near-tie"
    if f[0] != f[1]:
        return "sliding near-tie"
    if f[0] != o:
        return "outcome changed"
    if o == "yes":
        return "same"
    fp = [float(r[f"mu{mu}_peak_1e-9"]), float(r[f"mu{mu}_peak_1e-11"])]
    above = sum(x > (1 + PEAK) * y for x in fp for y in peaks)
    below = sum(x < (1 - PEAK) * y for x in fp for y in peaks)
    if above == 8 or below == 8:
        return "peak changed"
    return "peak near-tie" if above + below else "same"


def check_records(d):
    rows = read(d, "sliding_records.csv")
    tally = collections.defaultdict(lambda: collections.Counter())
    largest = collections.defaultdict(float)
    slip = collections.defaultdict(float)
    control = collections.defaultdict(lambda: [0] * 7 + [0.0])
    never = 0
    for r in rows:
        alpha = float(r["alpha"])
        for mu in FRICTIONS:
            if float(mu) < math.tan(alpha):
                never += 1
                need(all(r[f"mu{mu}_{c}"] == v for c, v in (("1e-9", "no"), ("1e-11", "no"), ("peak_1e-9", "0"),
                                                            ("peak_1e-11", "0"))),
                     f"{r['record']} alpha {alpha} q {r['q']} mu {mu} < tan(alpha): the block lifts or falls")
            e = effect(r, mu)
            need(e == r[f"mu{mu}_effect"], f"{r['record']} alpha {alpha} q {r['q']} mu {mu}: effect "
                                           f"'{r[f'mu{mu}_effect']}', the rule gives '{e}'")
            t = tally[(r["alpha"], mu)]
            t["cases"] += 1
            t[e] += 1
            t["slid"] += r[f"mu{mu}_slip_m"] not in ("-", "0")
            if e in ("same", "peak changed") and r["full_1e-11"] == "no" and float(r["peak_full_1e-11"]) > 0:
                ch = float(r[f"mu{mu}_peak_1e-11"]) / float(r["peak_full_1e-11"]) - 1
                if abs(ch) > abs(largest[(r["alpha"], mu)]):
                    largest[(r["alpha"], mu)] = ch
            if r[f"mu{mu}_1e-9"] == "no":
                slip[(r["alpha"], mu)] = max(slip[(r["alpha"], mu)], float(r[f"mu{mu}_slip_m"]))
        k = control[r["alpha"]]
        o = [r[c] for c in ROCK]
        k[0] += 1
        k[1] += o[0] != o[1]
        out = "outside" in o[2:]
        k[2] += not out and (o[2] != o[0] or o[3] != o[1])
        k[3] += out
        if not out and o == ["no"] * 4 and float(r["peak_full_1e-11"]) > 0:
            dev = max(abs(float(r["peak_" + c]) / float(r["peak_full_1e-11"]) - 1) for c in ROCK)
            k[4] += 1
            k[5] += dev <= 1e-6
            k[6] += dev <= 1e-3
            k[7] = max(k[7], dev)
    names = {"same": "same", "outcome_changed": "outcome changed", "peak_changed": "peak changed",
             "rocking_near_ties": "rocking near-tie", "sliding_near_ties": "sliding near-tie",
             "peak_near_ties": "peak near-tie"}
    claim = read(d, "sliding_claim.csv")
    need(len(claim) == len(tally), f"sliding_claim.csv: {len(claim)} rows, the records give {len(tally)}")
    for c in claim:
        t = tally[(c["alpha"], c["mu"])]
        for col, e in names.items():
            need(int(c[col]) == t[e], f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']} {col}: {c[col]}, "
                                      f"recounted {t[e]}")
        need(int(c["cases"]) == t["cases"] and int(c["slid"]) == t["slid"],
             f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']}: cases/slid {c['cases']}/{c['slid']}, recounted "
             f"{t['cases']}/{t['slid']}")
        need(int(c["outside_model"]) == t["outside the model"] + t["outside the model at mu 1e6"],
             f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']}: outside_model")
        need(close(float(c["largest_peak_change"]), largest[(c["alpha"], c["mu"])], abs_=1e-9),  # 10-digit peaks
             f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']}: largest_peak_change {c['largest_peak_change']}, "
             f"recomputed {largest[(c['alpha'], c['mu'])]}")
        need(close(float(c["largest_slip_standing_m"]), slip[(c["alpha"], c["mu"])], rel=1e-9),
             f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']}: largest_slip_standing_m")
        neg = t["outcome changed"] + t["peak changed"] == 0
        need(c["negligible"] == ("yes" if neg else "no"), f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']}: "
                                                          f"negligible")
        need(c["rocks_before_sliding"] == ("yes" if float(c["mu"]) >= math.tan(float(c["alpha"])) else "no"),
             f"sliding_claim.csv alpha {c['alpha']} mu {c['mu']}: rocks_before_sliding")
    for v in read(d, "sliding_claim_verdict.csv"):
        mu = v["mu"]
        below = [k for k in tally if k[1] == mu and float(k[0]) < CLAIM]
        eff = sum(tally[k]["outcome changed"] + tally[k]["peak changed"] for k in below)
        ties = sum(tally[k][e] for k in below for e in ("rocking near-tie", "sliding near-tie", "peak near-tie"))
        with_effect = sorted(float(k[0]) for k in tally if k[1] == mu and
                             tally[k]["outcome changed"] + tally[k]["peak changed"])
        need(int(v["effects_below_0.35"]) == eff and int(v["ties_below_0.35"]) == ties and
             int(v["cases_below_0.35"]) == sum(tally[k]["cases"] for k in below),
             f"sliding_claim_verdict.csv mu {mu}: counts")
        need(v["claim_below_0.35"] == ("holds" if eff == 0 else "fails"), f"sliding_claim_verdict.csv mu {mu}: claim")
        need(v["smallest_alpha_with_effect"] == ("%g" % with_effect[0] if with_effect else "none"),
             f"sliding_claim_verdict.csv mu {mu}: smallest_alpha_with_effect {v['smallest_alpha_with_effect']}")
    for c in read(d, "sliding_control.csv"):
        k = control[c["alpha"]]
        cols = ("cases", "full_tolerances_disagree", "control_disagrees", "control_outside", "safe_agreeing",
                "peak_within_1e-6", "peak_within_1e-3")
        need([int(c[x]) for x in cols] == k[:7], f"sliding_control.csv alpha {c['alpha']}: {[c[x] for x in cols]}, "
                                                 f"recounted {k[:7]}")
        # The rows' peaks are printed to 10 digits: their ratio recomputed from them to about 1e-9.
        need(close(float(c["largest_peak_deviation"]), k[7], abs_=1e-9 * (1 + k[7])),
             f"sliding_control.csv alpha {c['alpha']}: largest_peak_deviation")
    return (f"{len(rows)} cases x 3 mu: every effect by the rule, {never} runs with mu < tan(alpha) never lift; "
            "the claim, verdict and control tables recounted")


# --- eq27 -----------------------------------------------------------------------------------

def eq27(x):
    x = mpf(x)
    s2 = lambda v: sinh(v) ** 2
    return (mpf(2) / 3 * s2(3 * x) + mpf(1) / 3) / (s2(x) - s2(x / 2) + s2(2 * x) - s2(2.5 * x) - s2(1.5 * x)
                                                    + mpf(2) / 3 * s2(3 * x))


def check_eq27(d):
    pts = read(d, "sliding_eq27_points.csv")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the repository's expected/
    frag = {(r["record"], r["alpha"], r["p"]): r for r in read(os.path.join(root, "fragility"), "fragility_points.csv")}
    to = {r["record"]: [float(r[f"to_{k}"]) for k in range(1, 12)] for r in read(os.path.join(root, "table2"),
                                                                               "table2_records.csv")}
    models = ("ideal", "full", "0.8", "0.6", "0.4")
    cases = collections.defaultdict(dict)
    for r in pts:
        cases[(r["record"], r["alpha"], r["p"])][r["model"]] = r
        need(r["identity_failed"] == "0", f"sliding_eq27_points.csv {r['record']} {r['model']}: a taken outcome "
                                          "differs from its run")
    for key, m in cases.items():
        f = frag[key]
        want = "-" if f["outcome"] == "censored" else (f["q_collapse"] if f["q_collapse"] != "-" else f["q_ill_collapse"])
        got = m["ideal"]["q_collapse"]
        need((got == "-") == (want == "-") and (got == "-" or close(float(got), float(want), rel=2e-6)),
             f"{key}: the ideal first collapse {got}, the fragility scene's {want}")
    non = collections.Counter()
    more = collections.Counter()
    fewer = collections.Counter()
    anyr = collections.defaultdict(set)
    for key, m in cases.items():
        p = float(key[2])
        q27 = [float(eq27(p * t)) for t in to[key[0]]]
        nc = {}
        for name in models:
            r = m[name]
            for k in range(11):
                nc[(name, k)] = r["outcome"] == "collapsed" and float(r["q_collapse"]) < q27[k]
                if nc[(name, k)]:
                    non[(name, k)] += 1
                    anyr[(name, k)].add(key[0])
        for name in models:
            for k in range(11):
                more[(name, k)] += nc[(name, k)] and not nc[("full", k)]
                fewer[(name, k)] += not nc[(name, k)] and nc[("full", k)]
    for r in read(d, "sliding_eq27.csv"):
        k, name = int(r["k"]) - 1, r["model"]
        need(int(r["non_conservative"]) == non[(name, k)] and int(r["more_than_full"]) == more[(name, k)] and
             int(r["fewer_than_full"]) == fewer[(name, k)] and int(r["records_with_any"]) == len(anyr[(name, k)]) and
             int(r["cases"]) == len(cases) and close(float(r["share"]), non[(name, k)] / len(cases), rel=1e-15),
             f"sliding_eq27.csv k {k + 1} {name}: {r['non_conservative']} non-conservative, recounted "
             f"{non[(name, k)]} (more {more[(name, k)]}, fewer {fewer[(name, k)]})")
    # How near a verdict is to flipping: the smallest |ln(first collapse / eq. 27's q)| per model.
    margin = {}
    for key, m in cases.items():
        for name in models:
            if m[name]["outcome"] == "collapsed":
                q = float(m[name]["q_collapse"])
                margin[name] = min([margin.get(name, math.inf)] +
                                   [abs(math.log(q / float(eq27(float(key[2]) * t)))) for t in to[key[0]]])
    ideal = {int(r["k"]): int(r["non_conservative"]) for r in read(os.path.join(root, "fragility"), "fragility_eq27.csv")}
    need(all(non[("ideal", k - 1)] == v for k, v in ideal.items()), "the ideal shares differ from fragility_eq27.csv")
    return (f"{len(cases)} cases: the ideal first collapses are the fragility scene's; eq. 27's counts recounted; "
            "nearest |ln(q / eq. 27's q)|: " + ", ".join(f"{k} {v:.2g}" for k, v in margin.items()))


# --- fig05 ----------------------------------------------------------------------------------

def q_case(i, x):
    c = cosh(mpf(x))
    if i == 1:
        return (2 * c ** 2 - 1) / (2 * c * (c - 1))
    if i == 2:
        return (2 - 4 * c ** 2) / (3 * c - 4 * c ** 2 + 1)
    if i == 3:
        return (4 * c ** 2 - 2) / (2 * c ** 2 - 3 * c + 1)
    if i == 4:
        return 2 * cosh(3 * mpf(x)) / (2 * cosh(3 * mpf(x)) - 3 * cosh(2 * mpf(x)) + 1)
    return 2 * cosh(3 * mpf(x)) / (cosh(3 * mpf(x)) - 3 * c + 2)


def check_fig05(d):
    rows = read(d, "sliding_fig05.csv")
    crit = {"final-rotation": "final", "peak-rotation": "peak", "overturning": "overturning"}
    count = collections.defaultdict(collections.Counter)
    first = {1: 1, 2: 1, 3: 0.5, 4: 1, 5: 0.5}
    for r in rows:
        c, x, rd, alpha = int(r["case"]), float(r["x"]), float(r["Rd"]), float(r["alpha"])
        q = float(q_case(c, x))
        need(q * rd * first[c] > 1, f"sliding_fig05.csv case {c} x {x} Rd {rd}: no rocking (eq. 26)")
        need(close(float(r["pga_g"]), q * alpha * rd, rel=1e-9), f"sliding_fig05.csv case {c} x {x} Rd {rd}: pga")
        for name, col in crit.items():
            ref = r[f"rocking_{col}"]
            n = count[(r["alpha"], c, name, "full")]
            n["points"] += 1
            n["collapses"] += ref == "yes"
            n["ties"] += ref == "tie"
            n["outside"] += ref == "outside"
            for mu in FRICTIONS:
                mine = r[f"mu{mu}_{col}"]
                n = count[(r["alpha"], c, name, mu)]
                n["points"] += 1
                out = "outside" in (mine, ref)
                n["outside"] += out
                n["ties"] += not out and "tie" in (mine, ref)
                n["collapses"] += mine == "yes"
                n["caused"] += mine == "yes" and ref == "no"
                n["prevented"] += mine == "no" and ref == "yes"
                if mine == "yes" and ref == "no":
                    n["rd"] = min(n.get("rd", 9), rd)
    for s in read(d, "sliding_fig05_summary.csv"):
        n = count[(s["alpha"], int(s["case"]), s["criterion"], s["model"])]
        got = [int(s["points"]), int(s["collapses"]), int(s["near_ties"]), int(s["outside_model"])]
        want = [n["points"], n["collapses"], n["ties"], n["outside"]]
        if s["model"] != "full":
            got += [int(s["caused_by_sliding"]), int(s["prevented_by_sliding"])]
            want += [n["caused"], n["prevented"]]
            need((s["lowest_Rd_caused"] == "-") == (n["caused"] == 0) and
                 (n["caused"] == 0 or float(s["lowest_Rd_caused"]) == n["rd"]),
                 f"sliding_fig05_summary.csv alpha {s['alpha']} case {s['case']} {s['criterion']} {s['model']}: lowest Rd")
        need(got == want, f"sliding_fig05_summary.csv alpha {s['alpha']} case {s['case']} {s['criterion']} "
                          f"{s['model']}: {got}, recounted {want}")
    return f"{len(rows)} points: PGA from eqs. 12-24, the summary recounted"


# --- siconos --------------------------------------------------------------------------------

def check_siconos(d):
    """No row of siconos.csv disagrees with the engine; each verdict the rows decide has a row that agrees
    (an undecided row, one whose margin lies within Moreau-Jean's error at its finest steps, decides
    nothing either way); every row the rule of siconos_rows.py picks is there."""
    path = os.path.join(d, "siconos.csv")
    need(os.path.exists(path), "siconos.csv is missing: run expected/sliding/siconos_rows.py")
    rows = read(d, "siconos.csv")
    bad = [r for r in rows if r["verdict"] not in ("agree", "undecided")]
    need(not bad, f"siconos.csv: {len(bad)} rows where Siconos gives the other verdict, first: "
                  f"{bad[0]['key'] if bad else ''} mu {bad[0]['mu'] if bad else ''}")
    rec = {(r["record"], r["alpha"], r["q"]): r for r in read(d, "sliding_records.csv")}
    pts = {(r["alpha"], r["case"], r["x"], r["Rd"]): r for r in read(d, "sliding_fig05.csv")}
    agree = collections.Counter()
    for s in rows:
        w = s["key"].split()
        if s["part"] == "a":
            r = rec.get((w[0], w[2], w[4]))
            need(r is not None and r[f"mu{s['mu']}_effect"] in ("outcome changed", "peak changed"),
                 f"siconos.csv {s['key']} mu {s['mu']}: not an effect of sliding_records.csv")
            want = {"max_theta_over_alpha": "peak changed", "overturned": "outcome changed"}[s["quantity"]]
            need(r[f"mu{s['mu']}_effect"] == want, f"siconos.csv {s['key']} mu {s['mu']}: {s['quantity']}")
            below = float(w[2]) < CLAIM
            agree[("a", s["mu"], below)] += s["verdict"] == "agree"
        else:
            r = pts.get((w[1], w[3], w[5], w[7]))
            col = "final" if s["quantity"] == "theta_tfin_over_alpha" else "peak"
            need(r is not None and r[f"mu{s['mu']}_{col}"] == "yes" and r[f"rocking_{col}"] == "no",
                 f"siconos.csv {s['key']} mu {s['mu']}: not a collapse sliding caused in sliding_fig05.csv")
            agree[("fig05", s["mu"], col)] += s["verdict"] == "agree"
    # The verdicts the rows decide: each mu's effects below 0.35 (the claim fails) and its first effect;
    # each mu's collapses under the paper's criterion (Figure 5's claim with friction).
    for v in read(d, "sliding_claim_verdict.csv"):
        if v["claim_below_0.35"] == "fails":
            need(agree[("a", v["mu"], True)] > 0, f"siconos.csv: no row agrees with an effect below 0.35 at mu {v['mu']}")
        elif v["smallest_alpha_with_effect"] != "none":
            need(agree[("a", v["mu"], False)] > 0, f"siconos.csv: no row agrees with mu {v['mu']}'s first effect")
    caused = collections.Counter()
    for s in read(d, "sliding_fig05_summary.csv"):
        if s["criterion"] == "final-rotation" and s["model"] != "full":
            caused[s["model"]] += int(s["caused_by_sliding"])
    for mu, n in caused.items():
        need(n == 0 or agree[("fig05", mu, "final")] > 0, f"siconos.csv: no Figure 5 collapse agrees at mu {mu}")
    # Every row the rule of siconos_rows.py picks is there.
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import siconos_rows
    want_a = {(r["record"], r["alpha"], r["q"], mu) for _, r, mu, _ in siconos_rows.rows_a(d)}
    have_a = {(s["key"].split()[0], s["key"].split()[2], s["key"].split()[4], s["mu"]) for s in rows if s["part"] == "a"}
    want_f = {(r["alpha"], r["case"], r["x"], r["Rd"], mu) for _, r, mu, _ in siconos_rows.rows_fig05(d)}
    have_f = {tuple(s["key"].split()[1::2]) + (s["mu"],) for s in rows if s["part"] == "fig05"}
    need(want_a <= have_a, f"siconos.csv lacks {len(want_a - have_a)} record rows the rule picks: run "
                           "siconos_rows.py again")
    need(want_f <= have_f, f"siconos.csv lacks {len(want_f - have_f)} Figure 5 rows the rule picks")
    n = collections.Counter((s["part"], s["verdict"]) for s in rows)
    return ", ".join(f"{part}: {n[(part, 'agree')]} agree, {n[(part, 'undecided')]} undecided"
                     for part in ("a", "fig05")) + "; none disagrees; every verdict they decide has a row that agrees"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("expected")
    ap.add_argument("--only", default=",".join(PARTS))
    a = ap.parse_args()
    failed = 0
    for part in a.only.split(","):
        if part not in PARTS:
            print(f"independent.py: unknown part '{part}' (parts: {', '.join(PARTS)})", file=sys.stderr)
            return 2
        try:
            said = globals()["check_" + part](a.expected)
            print(f"  {part}: {said}")
        except Fail as x:
            failed += 1
            print(f"  {part}: DISAGREES: {x}")
    if failed:
        print(f"independent check: {failed} part(s) disagree in {a.expected}")
        return 1
    print(f"independent check: {a.expected} agrees")
    return 0


if __name__ == "__main__":
    sys.exit(main())
