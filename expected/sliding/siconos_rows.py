#!/usr/bin/python3
"""The rows of the sliding scene that decide its verdicts, computed again by a second method:
Siconos's Moreau-Jean time-stepping (tools/siconos_block.py: the block as a free rigid body with two
frictional unilateral corners, nothing taken from src/dynamics/sliding/).

    expected/sliding/siconos_rows.py EXPECTED_DIR [--jobs N] [--only a|fig05]

writes EXPECTED_DIR/siconos.csv (minutes to an hour of CPU: run by hand when the rows change, not
in the tests; expected/sliding/independent.py reads the file).  The rows, chosen from the expected
files by rule, not by hand:

  a      sliding_records.csv: every row where sliding changes the outcome or the peak (the 'effect'
         columns) at alpha < 0.35 (the paper's claim); every outcome changed where mu >= tan(alpha)
         (a block that rocks first) below alpha = 0.5; and, for mu 0.6 and 0.8, the largest peak
         change at the smallest alpha with an effect (where the claim's 'holds' ends for them);
  fig05  sliding_fig05.csv: every point where sliding causes a collapse under the paper's criterion
         (final) or the peak one that the rocking-only model does not have.

Each row runs on a ladder of steps h, h/2, h/4 (and h/8 on a record, h/8 and h/16 on a pulse, while
undecided: a record's run costs ~30 s of CPU per 100 s of motion at h/8), each the mean of K
runs on grids offset by h/K (K = 2 on a record, 4 on a pulse train), as tests/sliding_siconos_test.sh.
The verdict is the engine's ('agree') when every offset at the two finest steps gives it: for a peak changed,
every Siconos peak beyond 5 % of every rocking-only run's peak on the engine's side; for an outcome,
the same outcome; for Figure 5, |theta(t_fin)| (or max |theta| during the input) at or above alpha.
'disagree' where every one gives the other verdict, 'undecided' otherwise (Siconos's own error at
its finest steps is then larger than the margin to the verdict's line).  Standard library, numpy and siconos (Debian python3-siconos) only.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SICONOS = os.path.join(ROOT, "tools", "siconos_block.py")
PY = "/usr/bin/python3"
H = 2.0          # m, the scene's block height
CLAIM = 0.35
TRAINS = {1: "1:1,-1:1", 2: "1:1,-0.5:1", 3: "0.5:1,-1:1", 4: "1:1,-0.5:2", 5: "0.5:2,-1:1"}
G = 9.81


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def read_record(path):
    """The record in g, as the engine reads it (ESM in cm/s^2, PEER AT2 in g)."""
    lines = open(path).read().splitlines()
    if ":" in lines[0]:
        head = dict(l.split(":", 1) for l in lines if ":" in l and not l.strip().lstrip("-").replace(".", "").isdigit())
        dt = float(head["SAMPLING_INTERVAL_S"])
        a = [float(l) * 0.01 / G for l in lines if l.strip() and ":" not in l]
    else:
        dt = float(lines[3].upper().split("DT=")[1].split()[0].rstrip(","))
        a = [float(t) for l in lines[4:] for t in l.split()]
    return a, dt


def records_root():
    return os.environ.get("ROCKING_RECORDS", os.path.join(ROOT, "..", "shared", "records"))


def rows_a(d):
    """(part, row, mu, effect) of sliding_records.csv by the rule of the docstring."""
    rows = read(os.path.join(d, "sliding_records.csv"))
    effects = [(r, mu, r[f"mu{mu}_effect"]) for r in rows for mu in ("0.8", "0.6", "0.4")
               if r[f"mu{mu}_effect"] in ("outcome changed", "peak changed")]
    out = []
    for r, mu, e in effects:
        a = float(r["alpha"])
        if a < CLAIM or (e == "outcome changed" and float(mu) >= math.tan(a) and a < 0.5):
            out.append(("a", r, mu, e))
    # The first effect of mu 0.6 and 0.8: at their smallest alpha with one, the largest peak change.
    for mu in ("0.8", "0.6"):
        mine = [(float(r["alpha"]), r, e) for r, m, e in effects if m == mu]
        if not mine:
            continue
        first = min(a for a, _, _ in mine)
        peaks = [r for a, r, e in mine if a == first and e == "peak changed"]
        if peaks:
            change = lambda r: abs(float(r[f"mu{mu}_peak_1e-11"]) / float(r["peak_full_1e-11"]) - 1)
            r = max(peaks, key=change)
            if not any(x[1] is r and x[2] == mu for x in out):
                out.append(("a", r, mu, "peak changed"))
    return out


def rows_fig05(d):
    out = []
    for r in read(os.path.join(d, "sliding_fig05.csv")):
        for mu in ("0.8", "0.6", "0.4"):
            for crit in ("final", "peak"):
                if r[f"mu{mu}_{crit}"] == "yes" and r[f"rocking_{crit}"] == "no":
                    out.append(("fig05", r, mu, crit))
    # One Siconos ladder a point and mu: both criteria from the same runs.
    seen, unique = set(), []
    for part, r, mu, crit in out:
        key = (r["alpha"], r["case"], r["x"], r["Rd"], mu)
        if key not in seen:
            seen.add(key)
            unique.append((part, r, mu, [c for p, rr, m, c in out if (rr["alpha"], rr["case"], rr["x"], rr["Rd"], m) == key]))
    return unique


def siconos(args):
    out = subprocess.run([PY, SICONOS] + args, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"siconos_block.py {' '.join(args)}: {out.stderr.strip()}")
    return json.loads(out.stdout)


def judge(values, test):
    """'agree' when every offset at the two finest steps passes test, 'disagree' when every one fails it,
    else 'undecided': Moreau-Jean's error at those steps is larger than the verdict's margin."""
    fine = [v for step in values[-2:] for v in step]
    if all(test(v) for v in fine):
        return "agree"
    if not any(test(v) for v in fine):
        return "disagree"
    return "undecided"


def run_a(item, tmp):
    _, r, mu, effect = item
    alpha, q = float(r["alpha"]), float(r["q"])
    a, dt = read_record(os.path.join(records_root(), r["record"]))
    peak = max(abs(v) for v in a)
    path = os.path.join(tmp, f"rec_{abs(hash((r['record'], alpha, q, mu)))}.txt")
    with open(path, "w") as f:
        f.write("\n".join(repr(v * q * alpha / peak) for v in a) + "\n")
    R = 0.5 * H / math.cos(alpha)
    engine_over = r[f"mu{mu}_1e-11"] == "yes"
    ref = [float(r[c]) for c in ("peak_full_1e-9", "peak_full_1e-11", "peak_control_1e-9", "peak_control_1e-11")
           if r[c] != "-"]
    if effect == "peak changed":
        engine = float(r[f"mu{mu}_peak_1e-11"])
        above = engine > max(ref)
        test = (lambda v: v["peak"] > 1.05 * max(ref)) if above else (lambda v: v["peak"] < 0.95 * min(ref))
        quantity, engine_text = "max_theta_over_alpha", repr(engine)
    else:
        test = lambda v: v["overturned"] == engine_over
        quantity, engine_text = "overturned", "yes" if engine_over else "no"
    steps, values, means = [4e-4, 2e-4, 1e-4], [], []
    verdict = None
    while True:
        for h in steps[len(values):]:
            d = siconos(["--alpha", repr(alpha), "--R", repr(R), "--mu", mu, "--dt", repr(h), "--record", path,
                         "--record-dt", repr(dt), "--phases", "2"])
            bp = d["by_phase"]
            values.append([{"peak": p, "overturned": o} for p, o in zip(bp["max_theta_input_over_alpha"], bp["overturned"])])
            means.append(d["max_theta_input_over_alpha"] if effect == "peak changed" else
                         ("yes" if d["overturned"] else "no" if d["overturned"] is False else "mixed"))
        verdict = judge(values, test)
        if verdict != "undecided" or len(steps) >= 4:
            break
        steps.append(steps[-1] / 2)
    os.remove(path)
    return dict(part="a", key=f"{r['record']} alpha {r['alpha']} q {r['q']}", mu=mu, quantity=quantity,
                engine=engine_text, rocking=("%.10g..%.10g" % (min(ref), max(ref))) if ref else "overturned",
                steps=" ".join("%g" % h for h in steps[:len(values)]), siconos=" ".join(
                    ("%.10g" % m) if isinstance(m, float) else m for m in means),
                offsets_finest=" / ".join(" ".join(("%.10g" % v["peak"]) if effect == "peak changed" else
                                                   ("yes" if v["overturned"] else "no") for v in step)
                                          for step in values[-2:]),
                verdict=verdict)


def run_fig05(item, tmp):
    _, r, mu, crits = item
    alpha, c, x, rd, pga = float(r["alpha"]), int(r["case"]), float(r["x"]), float(r["Rd"]), float(r["pga_g"])
    R = 0.5 * H / math.cos(alpha)
    p = math.sqrt(3 * G / (4 * R))
    to = x / p
    steps, values = [4e-4, 2e-4, 1e-4], []
    tests = {"final": lambda v: v["over"] or abs(v["tfin"]) >= 1, "peak": lambda v: v["over"] or v["peak"] >= 1}
    while True:
        for h in steps[len(values):]:
            d = siconos(["--alpha", repr(alpha), "--R", repr(R), "--mu", mu, "--dt", repr(h), "--train", TRAINS[c],
                         "--to", repr(to), "--pga", repr(pga), "--phases", "4"])
            bp = d["by_phase"]
            values.append([{"tfin": t, "peak": m, "over": o} for t, m, o in
                           zip(bp["theta_tfin_over_alpha"], bp["max_theta_input_over_alpha"], bp["overturned"])])
        verdicts = {k: judge(values, tests[k]) for k in crits}
        if all(v != "undecided" for v in verdicts.values()) or len(steps) >= 6:
            break
        steps.append(steps[-1] / 2)
    out = []
    for k in crits:
        cell = r[f"mu{mu}_theta_tfin_1e-11"] if k == "final" else r[f"mu{mu}_max_theta"]
        q = "theta_tfin_over_alpha" if k == "final" else "max_theta_over_alpha"
        field = "tfin" if k == "final" else "peak"
        out.append(dict(part="fig05", key=f"alpha {r['alpha']} case {c} x {r['x']} Rd {r['Rd']}", mu=mu, quantity=q,
                        engine="fell" if cell == "-" else cell,
                        rocking="%s (%s)" % (r[f"rocking_{k}"], r["rocking_theta_tfin"] if k == "final" else
                                             r["rocking_max_theta"]),
                        steps=" ".join("%g" % h for h in steps[:len(values)]),
                        siconos=" ".join("%.10g" % (sum(v[field] for v in step) / len(step)) for step in values),
                        offsets_finest=" / ".join(" ".join("%.10g" % v[field] for v in step) for step in values[-2:]),
                        verdict=verdicts[k]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("expected")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", choices=("a", "fig05"))
    a = ap.parse_args()
    items = []
    if a.only in (None, "a"):
        if not os.path.isdir(records_root()):
            print("siconos_rows: the records folder is absent: part a not run", file=sys.stderr)
        else:
            items += rows_a(a.expected)
    if a.only in (None, "fig05"):
        items += rows_fig05(a.expected)
    print(f"siconos_rows: {len(items)} rows", file=sys.stderr, flush=True)
    cols = ["part", "key", "mu", "quantity", "engine", "rocking", "steps", "siconos", "offsets_finest", "verdict"]
    path = os.path.join(a.expected, "siconos.csv")
    partial = path + ".partial"
    results = []
    # Each row appended as it ends (a run of an hour keeps what it has done); the file is renamed
    # into place, the rows in the rule's order, once all are done.
    with open(partial, "w") as f:
        pass
    with tempfile.TemporaryDirectory(prefix="siconos_rows.") as tmp, \
            concurrent.futures.ProcessPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_a if it[0] == "a" else run_fig05, it, tmp): i for i, it in enumerate(items)}
        done = {}
        for f in concurrent.futures.as_completed(futures):
            got = f.result()
            got = got if isinstance(got, list) else [got]
            done[futures[f]] = got
            with open(partial, "a", newline="") as out:
                csv.DictWriter(out, fieldnames=cols).writerows(got)
            print(f"  {len(done)}/{len(items)}: {got[0]['key']} mu {got[0]['mu']}: "
                  + ", ".join(g["verdict"] for g in got), file=sys.stderr, flush=True)
        for i in range(len(items)):
            results += done[i]
    with open(path, "w", newline="") as f:
        f.write("# scene: sliding: the rows that decide its verdicts, by a second method (expected/sliding/siconos_rows.py)\n")
        f.write("# method: Siconos 4.4 Moreau-Jean (theta 1/2), NewtonImpactFrictionNSL(0, 0, mu, 2), 2D Lemke "
                "(tools/siconos_block.py); each step the mean over K grids offset by h/K (K 2 records, 4 pulses)\n")
        f.write("# columns: engine: the sliding engine's value at 1e-11 (sliding_records.csv, sliding_fig05.csv); "
                "rocking: the rocking-only runs' range (a) or verdict and value (fig05); siconos: the means at each "
                "step; offsets_finest: each offset's value at the two finest steps (/ between them); verdict: agree when "
                "every offset there gives the engine's verdict, disagree when none does, undecided otherwise\n")
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in results:
            w.writerow(r)
    os.remove(partial)
    print(f"siconos_rows: wrote {path}: " + ", ".join(
        f"{v} {sum(r['verdict'] == v for r in results)}" for v in ("agree", "disagree", "undecided")), file=sys.stderr)


if __name__ == "__main__":
    main()
