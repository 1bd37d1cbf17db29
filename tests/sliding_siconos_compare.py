#!/usr/bin/python3
"""One case of tests/sliding_siconos_test.sh: rocking simulate --friction
against tools/siconos_block.py at dt = h, h/2, h/4 (the rule is stated in the
test's header).  Prints every number compared; exit 1 on a failure.

    sliding_siconos_compare.py ROCKING TOOL NAME --h H --phases K --quantities Q,... \
        --engine "ARGS" --siconos "ARGS" [--decoy "ARGS"] [--closed-form KEY=VALUE]

ENGINE ARGS are rocking simulate's (with --friction, without --json); SICONOS
ARGS the tool's input and --mu, its --alpha and --R taken from the engine's
JSON so that both simulate one block.  DECOY ARGS replace ENGINE ARGS for a
second engine run that the same rule must reject (the test can fail).
"""
import argparse
import json
import shlex
import subprocess
import sys

# The absolute floors: the engine's own error (rtol 1e-11, atol 1e-11 alpha on
# theta and on the slip over R, its events located to rounding) is below 1e-9
# of each; these are a hundred times that, and far below any difference the
# rule has to see (1e-5 and up).
FLOOR = {"max_theta_input_over_alpha": 1e-7, "theta_tfin_over_alpha": 1e-7, "slip_tfin_m": 1e-7,
         "t_overturn": 1e-7}


def engine(rocking, args):
    cmd = [rocking, "simulate", *shlex.split(args), "--rtol", "1e-11", "--json"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}: exit {done.returncode}: {done.stderr.strip()}")
    return json.loads(done.stdout)


def siconos(tool, args, e, dt, phases):
    cmd = ["/usr/bin/python3", tool, *shlex.split(args), "--alpha", repr(e["alpha"]), "--R", repr(e["R_from_p"]),
           "--dt", repr(dt), "--phases", str(phases)]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}: exit {done.returncode}: {done.stderr.strip()}")
    return json.loads(done.stdout)


def variation(values):
    """The total variation of a quantity over the K grid offsets, around the
    cycle (offset K dt/K is offset 0 on the next step's grid)."""
    return sum(abs(values[(j + 1) % len(values)] - values[j]) for j in range(len(values)))


def judge(key, s, e_value):
    """The rule for one quantity: (converging, accepted, the numbers)."""
    S = [r[key] for r in s]
    K = s[0]["phases"]
    resid = [variation(r["by_phase"][key]) / K for r in s]
    d1, d2 = S[0] - S[1], S[1] - S[2]
    bound = 2 * abs(d2) + resid[1] + 2 * resid[2] + FLOOR[key]
    return abs(d2) < abs(d1), abs(S[2] - e_value) <= bound, S, resid, bound


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("rocking")
    ap.add_argument("tool")
    ap.add_argument("name")
    ap.add_argument("--h", type=float, required=True)
    ap.add_argument("--phases", type=int, required=True)
    ap.add_argument("--quantities", required=True)
    ap.add_argument("--engine", required=True)
    ap.add_argument("--siconos", required=True)
    ap.add_argument("--decoy")
    ap.add_argument("--closed-form", action="append", default=[])
    a = ap.parse_args()
    keys = a.quantities.split(",")
    e = engine(a.rocking, a.engine)
    runs = [siconos(a.tool, a.siconos, e, a.h / n, a.phases) for n in (1, 2, 4)]
    ok = True
    print(f"{a.name}: rocking simulate {a.engine}")
    print(f"  Siconos at dt = {a.h:g}, {a.h / 2:g}, {a.h / 4:g} s, each the mean of {a.phases} grid offsets; "
          f"CPU {sum(r['cpu_s'] for r in runs):.1f} s")
    for key in keys:
        converging, accepted, S, resid, bound = judge(key, runs, e[key])
        ok = ok and converging and accepted
        print(f"  {key}: engine {e[key]:.9g}; Siconos {S[0]:.9g}, {S[1]:.9g}, {S[2]:.9g} "
              f"(offset residuals {resid[0]:.2g}, {resid[1]:.2g}, {resid[2]:.2g})")
        print(f"    |S(h/2) - S(h/4)| = {abs(S[1] - S[2]):.3g} {'<' if converging else 'NOT <'} "
              f"|S(h) - S(h/2)| = {abs(S[0] - S[1]):.3g}; |S(h/4) - E| = {abs(S[2] - e[key]):.3g} "
              f"{'<=' if accepted else '>'} {bound:.3g}: {'ok' if converging and accepted else 'FAIL'}")
    for item in a.closed_form:
        key, value = item.split("=")
        converging, accepted, S, resid, bound = judge(key, runs, float(value))
        ok = ok and converging and accepted
        print(f"  {key} against the closed form {float(value):.9g}: |S(h/4) - C| = {abs(S[2] - float(value)):.3g} "
              f"{'<=' if accepted else '>'} {bound:.3g}: {'ok' if converging and accepted else 'FAIL'}")
    # The outcome and the impacts: the same in every run at every dt.
    outcomes = {o for r in runs for o in r["by_phase"]["overturned"]}
    same = outcomes == {e["overturned"]}
    ok = ok and same
    print(f"  overturned: engine {e['overturned']}, Siconos runs {sorted(outcomes)}: {'ok' if same else 'FAIL'}")
    counts = {c for r in runs for c in r["by_phase"]["impacts"]}
    same = counts == {e["impacts"]}
    ok = ok and same
    print(f"  impacts: engine {e['impacts']}, Siconos runs {sorted(counts)}: {'ok' if same else 'FAIL'}")
    if a.decoy:
        d = engine(a.rocking, a.decoy)
        caught = [key for key in keys if not judge(key, runs, d[key])[1]]
        caught += ["overturned"] if d["overturned"] != e["overturned"] else []
        caught += ["impacts"] if d["impacts"] != e["impacts"] else []
        print(f"  decoy rocking simulate {a.decoy}: " +
              ", ".join(f"{key} {d[key]:.9g}" for key in keys) +
              (f"; rejected on {', '.join(caught)}: ok" if caught else "; NOT rejected: FAIL (the rule cannot fail)"))
        ok = ok and bool(caught)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
