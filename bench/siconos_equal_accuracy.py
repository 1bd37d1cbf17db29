#!/usr/bin/python3
"""The sliding-rocking engine against Siconos at equal accuracy (issue 41,
item 6; a benchmark, not a test): `make bench-siconos`.

On four cases (tests/sliding_siconos_test.sh's: a slide under a pulse, rocking
through an impact, slide-rock, a record's window that ends in a fall) it
measures, for each of a few well-defined quantities,
  - the engine's error against rtol (rocking simulate --friction --json),
  - Siconos' error against dt (tools/siconos_block.py, Moreau-Jean) and its
    order, fitted in log-log,
each against a reference: Newmark's closed form for the slide; the
rocking-only full model under gsl-rk8pd at rtol 1e-13 where the engine's run
never slips (the same model then); otherwise the engine at rtol 1e-13,
cross-checked by its own convergence and by Siconos' extrapolated to dt -> 0.

A Siconos value at dt is a single run's; where in its step an impact or an
input jump falls changes it by O(dt), so each dt runs on PHASES grids offset by
dt/PHASES and its error is the root mean square over them (the error a run
can be expected to have; the error of their mean is kept in the CSV).

Times are CPU seconds of one run inside its process: Siconos' time-stepping
loop as the tool reports it, on one BLAS thread (without Python's start, the
import of siconos and the plugin's compilation, whose wall time the CSV
keeps), the engine's through
the Python module rocking_q (the library the command runs; a command's process
start, about 5 ms, would hide runs of 0.03-1 ms), the fastest of 3 windows.
Without the module, the command's wall time is used and said so.

    bench/siconos_equal_accuracy.py --rocking build/rocking [--python build/python] [--out out/bench]
                     [--records DIR] [--phases K]
Writes OUT/siconos.txt and OUT/siconos.csv.  Exits 0 with "skip:" when
/usr/bin/python3 cannot import siconos; the record case is skipped without
the records (ROCKING_RECORDS, else ../shared/records).
"""
import argparse
import csv
import datetime
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TOOL = os.path.join(ROOT, "tools", "siconos_block.py")
PY = "/usr/bin/python3"
G = 9.81
RTOLS = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]
DEFAULT_RTOL = 1e-9
REFERENCE_RTOL = 1e-13
DTS = [1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6]
SICONOS_DT_COMPARED = 1e-4  # the dt tests/sliding_siconos_test.sh converges at
AQK = "esm/IT.AQK..HNE.D.20090406.013240.C.ACC.ASC"


class Case:
    def __init__(self, name, text, engine, siconos, quantities, reference, dts=DTS, closed=None):
        self.name, self.text, self.engine, self.siconos = name, text, engine, siconos
        self.quantities = quantities  # (JSON key, label, unit)
        self.reference = reference  # "closed", "full" or "engine"
        self.dts, self.closed = dts, closed or {}


def cases(window):
    a = "--train 1:1 --to 0.4 --pga 0.5"
    b = "--train 1:1,-1:0.8,1:0.5 --to 0.5 --pga 0.3"
    c = "--train 1:1,-1:1 --to 0.2 --pga 0.7"
    out = [
        Case("slide", "(a) slide: alpha 0.3, H 2 m, mu 0.2, 0.5 g for 0.4 s", a + " --alpha 0.3 --height 2 --friction 0.2",
             a + " --mu 0.2", [("slip_tfin_m", "slip(t_fin)", "m")], "closed",
             # Newmark: (a - mu) g T^2/2, the block sliding from rest for T.
             closed={"slip_tfin_m": (0.5 - 0.2) * G * 0.4 ** 2 / 2}),
        Case("rock", "(b) rock, one impact: alpha 0.2, H 3 m, mu 0.8, 1:1,-1:0.8,1:0.5, 0.3 g, t_o 0.5 s",
             b + " --alpha 0.2 --height 3 --friction 0.8", b + " --mu 0.8",
             [("max_theta_input_over_alpha", "max|theta|", "alpha"), ("theta_tfin_over_alpha", "theta(t_fin)", "alpha")],
             "full"),
        Case("slide-rock", "(c) slide-rock: alpha 0.2, H 3 m, mu 0.25, 1:1,-1:1, 0.7 g, t_o 0.2 s",
             c + " --alpha 0.2 --height 3 --friction 0.25", c + " --mu 0.25",
             [("max_theta_input_over_alpha", "max|theta|", "alpha"), ("theta_tfin_over_alpha", "theta(t_fin)", "alpha"),
              ("slip_tfin_m", "slip(t_fin)", "m")], "engine"),
    ]
    if window:
        w = f"--record {window} --record-dt 0.005"
        # Siconos' finest dt is 1e-5 here: at 5e-6 its 4.9 s of motion would take 14 s a run.
        out.append(Case("record", "(d) L'Aquila AQK E-W, 8 s around its PGA (0.33 g), 0.3 m x 2 m, mu 0.6: "
                        "6 impacts, the fall", w + " --unit g --thickness 0.3 --height 2 --friction 0.6",
                        w + " --mu 0.6 --overturn-angle 1.5707963267948966",
                        [("t_overturn", "the fall", "s"), ("slip_tfin_m", "slip at the fall", "m")], "engine",
                        dts=DTS[:-1]))
    return out


# Siconos' BLAS is OpenBLAS's pthread build, whose idle threads spin: on this
# 2-core machine under load half a run's CPU went to them as system time (10 s
# at dt 2e-5 on case (d), 3.4 s with one thread, the same numbers to the bit).
ONE_THREAD = dict(os.environ, OPENBLAS_NUM_THREADS="1")


def run_json(cmd, what, env=None):
    t0 = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    if done.returncode != 0:
        sys.exit(f"bench/siconos_equal_accuracy.py: {what} failed (exit {done.returncode}): {' '.join(cmd)}\n{done.stderr.strip()}")
    return json.loads(done.stdout), wall


def engine_json(rocking, args, rtol):
    return run_json([rocking, "simulate", *shlex.split(args), "--rtol", repr(rtol), "--json"], "rocking simulate")[0]


def module_kwargs(rq, args):
    """rocking simulate's options as rocking_q.simulate's keywords (docs/python.md)."""
    tokens = shlex.split(args)
    opts = {tokens[i][2:].replace("-", "_"): tokens[i + 1] for i in range(0, len(tokens), 2)}
    kw = {}
    if "record" in opts:
        kw["record"] = rq.read_record(opts.pop("record"), unit=opts.pop("unit"), dt=float(opts.pop("record_dt")))
    if "train" in opts:
        kw["train"] = opts.pop("train")
    kw.update({k: float(v) for k, v in opts.items()})
    return kw


class EngineClock:
    """CPU seconds of one engine run: in-process through rocking_q when it
    imports, else the command's wall time (process start included)."""

    def __init__(self, rocking, python_dir):
        self.rocking, self.rq = rocking, None
        if python_dir and os.path.isdir(python_dir):
            sys.path.insert(0, python_dir)
            try:
                import rocking_q
                self.rq = rocking_q
            except ImportError:
                pass
        self.how = ("CPU in-process (rocking_q), fastest of 3 windows of 0.05 s" if self.rq else
                    "WALL time of the rocking command, process start included (rocking_q not importable)")

    def time(self, args, rtol, expect):
        if self.rq is None:
            return min(run_json([self.rocking, "simulate", *shlex.split(args), "--rtol", repr(rtol), "--json"],
                                "rocking simulate")[1] for _ in range(5))
        kw = module_kwargs(self.rq, args)
        kw.update(rtol=rtol, dt=None)
        got = self.rq.simulate(**kw)
        # The timed run must be the command's: the same library, the same numbers.
        for key in ("max_theta_input_over_alpha", "slip_tfin_m", "t_overturn", "impacts"):
            if got[key] != expect[key]:
                sys.exit(f"bench/siconos_equal_accuracy.py: rocking_q.simulate gives {key} {got[key]!r}, the command "
                         f"{expect[key]!r} ({args} --rtol {rtol})")
        best = math.inf
        for _ in range(3):
            n, t0 = 0, time.process_time()
            while True:
                self.rq.simulate(**kw)
                n += 1
                spent = time.process_time() - t0
                if spent >= 0.05:
                    break
            best = min(best, spent / n)
        return best


def error(value, ref):
    if value is None or ref is None:
        return math.inf if (value is None) != (ref is None) else 0.0
    return abs(value - ref)


def fit_order(points):
    """Least squares of log(error) on log(dt): (order, C) with error ~ C dt^order."""
    xs = [math.log(dt) for dt, e in points if 0 < e < math.inf]
    ys = [math.log(e) for dt, e in points if 0 < e < math.inf]
    if len(xs) < 2:
        return math.nan, math.nan
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    p = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return p, math.exp(my - p * mx)


def g(v, digits=2):
    if v is None:
        return "none"
    if isinstance(v, float) and math.isinf(v):
        return "inf"
    return f"{v:.{digits}e}" if v != 0 else "0"


def human_time(s):
    if s < 1e-3:
        return f"{s * 1e6:.0f} us"
    if s < 1:
        return f"{s * 1e3:.3g} ms"
    if s < 3600 * 48:
        return f"{s:.3g} s"
    if s < 3.2e7 * 2:
        return f"{s / 86400:.3g} days"
    return f"{s / 3.156e7:.2g} years"


def record_window(rocking, records, tmp):
    """tests/sliding_siconos_test.sh's window: AQK E-W as one column in g
    (record floor with participation 0 is the ground), 3 s before its PGA to 5 s after."""
    esm = os.path.join(records, AQK)
    if not os.path.isfile(esm):
        return None
    floor = os.path.join(tmp, "floor.txt")
    done = subprocess.run([rocking, "record", "floor", esm, "--period", "1", "--participation", "0", "--output", floor],
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"bench/siconos_equal_accuracy.py: rocking record floor {esm}: {done.stderr.strip()}")
    with open(floor) as f:
        a = [float(line.split(",")[1]) for line in f if line.strip() and not line.startswith("#")]
    peak = max(range(len(a)), key=lambda k: abs(a[k]))
    path = os.path.join(tmp, "window.txt")
    with open(path, "w") as out:
        out.writelines("%.17g\n" % (v / G) for v in a[peak - 600:peak - 600 + 1601])
    return path


def machine():
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    ver = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "python3-siconos"], capture_output=True, text=True)
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    load = os.getloadavg()[0]
    return (f"{cpu}, {os.cpu_count()} cores, load {load:.1f} at the start; python3-siconos "
            f"{ver.stdout.strip() or '?'}; rocking-q {head.stdout.strip() or '?'}; "
            f"{datetime.datetime.now().strftime('%Y-%m-%d %H:%M')}")


def bench_case(case, rocking, clock, phases, say, rows):
    say("")
    say(case.text)
    keys = [q[0] for q in case.quantities]
    ref_e = engine_json(rocking, case.engine, REFERENCE_RTOL)
    stuck = ref_e["time_in"]["slide"] == 0 and ref_e["time_in"]["slide_rock"] == 0 and ref_e["slipping_impacts"] == 0
    # The reference, its name and its own spread u (how far a second reference lies).
    if case.reference == "closed":
        ref = dict(case.closed)
        ref_name = "the closed form (Newmark)"
        spread = {k: 0.0 for k in keys}
        check = ", ".join(f"{lab} {g(error(ref_e[k], ref[k]))} {u}" for k, lab, u in case.quantities)
        say(f"  reference: {ref_name}; the engine at rtol 1e-13 lies {check} from it")
    elif case.reference == "full" and stuck:
        full = engine_json(rocking, case.engine.split(" --friction")[0] + " --model full --solver gsl-rk8pd",
                           REFERENCE_RTOL)
        ref = {k: full[k] for k in keys}
        ref_name = "the rocking-only full model, gsl-rk8pd rtol 1e-13 (the engine's run never slips)"
        spread = {k: error(ref_e[k], ref[k]) for k in keys}
        say(f"  reference: {ref_name}; the engine at rtol 1e-13 lies " +
            ", ".join(f"{lab} {g(spread[k])} {u}" for k, lab, u in case.quantities) + " from it")
    else:
        ref = {k: ref_e[k] for k in keys}
        e12 = engine_json(rocking, case.engine, 1e-12)
        spread = {k: error(e12[k], ref[k]) for k in keys}
        ref_name = "the engine at rtol 1e-13" + ("" if stuck else " (its run slips: the rocking-only model is another model)")
        say(f"  reference: {ref_name}; at rtol 1e-12 it moves " +
            ", ".join(f"{lab} {g(spread[k])} {u}" for k, lab, u in case.quantities))
        if case.name == "record":
            full = engine_json(rocking, case.engine.split(" --friction")[0] + " --model full --solver gsl-rk8pd",
                               REFERENCE_RTOL)
            say(f"  (the rocking-only full model, rk8pd 1e-13, falls at {full['t_overturn']:.6f} s, "
                f"{error(full['t_overturn'], ref['t_overturn']):.2e} s from the engine: the slide-rock before the fall)")
    say("  " + ", ".join(f"{lab} {ref[k]:.12g} {u}" for k, lab, u in case.quantities) +
        f"; impacts {ref_e['impacts']}, overturned {ref_e['overturned']}")
    header = f"  {'method':8} {'setting':12}" + "".join(f" {lab + ' (' + u + ')':>22}" for _, lab, u in case.quantities)
    say(header + f" {'CPU per run':>12}  note")
    out = {"engine": [], "siconos": [], "ref": ref, "spread": spread, "case": case, "ref_name": ref_name}

    def row(method, setting, k, lab, u, value, err, err_mean, cpu, wall, extra):
        rows.append({"case": case.name, "quantity": lab, "unit": u, "method": method, "setting": setting,
                     "value": value, "reference": ref[k], "error": err, "error_of_offsets_mean": err_mean,
                     "cpu_s_per_run": cpu, "wall_s_process": wall, "impacts": extra.get("impacts"),
                     "overturned": extra.get("overturned"), "note": extra.get("note", "")})

    for rtol in RTOLS:
        e = engine_json(rocking, case.engine, rtol)
        cpu = clock.time(case.engine, rtol, e)
        same = e["impacts"] == ref_e["impacts"] and e["overturned"] == ref_e["overturned"]
        errs = {k: error(e[k], ref[k]) for k in keys}
        note = "" if same else f"impacts {e['impacts']}, overturned {e['overturned']}: not the reference's"
        out["engine"].append({"rtol": rtol, "errors": errs, "cpu": cpu, "same": same})
        for k, lab, u in case.quantities:
            row("engine", f"rtol {rtol:g}", k, lab, u, e[k], errs[k], "", cpu, "",
                {"impacts": e["impacts"], "overturned": e["overturned"], "note": note})
        say(f"  {'engine':8} {'rtol %g' % rtol:12}" + "".join(f" {g(errs[k]):>22}" for k in keys) +
            f" {human_time(cpu):>12}  {note}")
    for dt in case.dts:
        cmd = [PY, TOOL, *shlex.split(case.siconos), "--alpha", repr(ref_e["alpha"]), "--R", repr(ref_e["R_from_p"]),
               "--dt", repr(dt), "--phases", str(phases)]
        s, wall = run_json(cmd, "tools/siconos_block.py", ONE_THREAD)
        cpu = s["cpu_s"] / phases
        bp = s["by_phase"]
        impacts, overturned = sorted(set(bp["impacts"])), sorted(set(bp["overturned"]))
        same = impacts == [ref_e["impacts"]] and overturned == [ref_e["overturned"]]
        note = "" if same else f"impacts {impacts}, overturned {overturned} over the offsets: not the reference's"
        rms, mean_err = {}, {}
        for k, lab, u in case.quantities:
            errs = [error(v, ref[k]) for v in bp[k]]
            rms[k] = math.sqrt(sum(x * x for x in errs) / len(errs))
            mean = s[k] if s.get(k) is not None else None
            mean_err[k] = error(mean, ref[k])
            row("siconos", f"dt {dt:g}", k, lab, u, mean, rms[k], mean_err[k], cpu, wall,
                {"impacts": "/".join(map(str, impacts)), "overturned": "/".join(map(str, overturned)), "note": note})
        out["siconos"].append({"dt": dt, "rms": rms, "mean": {k: s.get(k) for k in keys}, "cpu": cpu, "same": same})
        say(f"  {'Siconos':8} {'dt %g' % dt:12}" + "".join(f" {g(rms[k]):>22}" for k in keys) +
            f" {human_time(cpu):>12}  {note}")
    # Siconos' order, and its extrapolation to dt -> 0 (first order, from the
    # means over the offsets at the two finest dt) as a check of the reference.
    out["fit"] = {k: fit_order([(r["dt"], r["rms"][k]) for r in out["siconos"]]) for k in keys}
    s1, s2 = out["siconos"][-2], out["siconos"][-1]
    for k, lab, u in case.quantities:
        p, C = out["fit"][k]
        line = f"  Siconos {lab}: order {p:.2f} (error ~ {C:.3g} dt^{p:.2f})"
        if s1["mean"][k] is not None and s2["mean"][k] is not None:
            extrap = s2["mean"][k] + (s2["mean"][k] - s1["mean"][k]) * s2["dt"] / (s1["dt"] - s2["dt"])
            out.setdefault("extrapolated", {})[k] = error(extrap, ref[k])
            line += (f"; extrapolated to dt -> 0 from dt {s1['dt']:g}, {s2['dt']:g}: {extrap:.9g}, "
                     f"{g(error(extrap, ref[k]))} {u} from the reference (the mean at {s2['dt']:g}: "
                     f"{g(error(s2['mean'][k], ref[k]))})")
        say(line)
    return out


def equal_accuracy(res, say, rows):
    """Per quantity: Siconos at the engine's accuracy at rtol 1e-9, and the
    engine at Siconos' accuracy at dt = 1e-4."""
    case = res["case"]
    default = next(r for r in res["engine"] if r["rtol"] == DEFAULT_RTOL)
    at_dt = next((r for r in res["siconos"] if r["dt"] == SICONOS_DT_COMPARED), None)
    # CPU x dt: a run's cost per step times its steps' span; the smallest over
    # the runs (fixed costs and the machine's other work only add to it).
    cost_dt = min(r["cpu"] * r["dt"] for r in res["siconos"])
    for k, lab, u in case.quantities:
        # Below the reference's spread, or below rounding (1e-15 of the value),
        # an error is not resolved: that is the target then.
        floor = max(res["spread"][k], 1e-15 * abs(res["ref"][k]))
        target = max(default["errors"][k], floor)
        below = "" if default["errors"][k] >= floor else " (not resolved: the reference's spread or rounding)"
        hit = next((r for r in res["siconos"] if r["rms"][k] <= target and r["same"]), None)
        if hit:
            s_dt, s_cpu, how = hit["dt"], hit["cpu"], "measured"
        else:
            p, C = res["fit"][k]
            s_dt = (target / C) ** (1 / p) if target > 0 and p > 0 else 0.0
            s_cpu = cost_dt / s_dt if s_dt > 0 else math.inf
            # No grid of doubles over a run of seconds has steps below about 1e-15 s.
            how = "extrapolated" + (", formal" if s_dt < 1e-12 else "")
        line = (f"  {case.name:10} {lab:16} engine rtol 1e-9: {g(target)} {u}{below} in {human_time(default['cpu'])}; "
                f"Siconos {how}: dt {g(s_dt, 1)} s, {human_time(s_cpu)} ({g(s_cpu / default['cpu'], 1)} times the engine's)")
        say(line)
        rows.append({"case": case.name, "quantity": lab, "unit": u, "method": "siconos at the engine's rtol 1e-9 accuracy",
                     "setting": f"dt {s_dt:.3g} ({how})", "value": "", "reference": res["ref"][k], "error": target,
                     "error_of_offsets_mean": "", "cpu_s_per_run": s_cpu, "wall_s_process": "", "impacts": "",
                     "overturned": "", "note": f"engine rtol 1e-9 CPU {default['cpu']:.3g} s"})
        if at_dt is None:
            continue
        s_err = at_dt["rms"][k]
        # The loosest rtol from which on every tighter one is within it: a
        # choice the errors alone make (the cheapest would follow the timings' noise).
        within = [r["errors"][k] <= s_err and r["same"] for r in res["engine"]]
        first = next((i for i in range(len(within)) if all(within[i:])), None)
        if first is not None:
            best = res["engine"][first]
            say(f"  {'':10} {'':16} Siconos dt 1e-4: {g(s_err)} {u} in {human_time(at_dt['cpu'])}; the engine's "
                f"loosest rtol within it: {best['rtol']:g} ({g(best['errors'][k])} {u}), {human_time(best['cpu'])} "
                f"({g(at_dt['cpu'] / best['cpu'], 1)} x faster)")
            rows.append({"case": case.name, "quantity": lab, "unit": u,
                         "method": "engine at Siconos' dt 1e-4 accuracy", "setting": f"rtol {best['rtol']:g}",
                         "value": "", "reference": res["ref"][k], "error": best["errors"][k],
                         "error_of_offsets_mean": "", "cpu_s_per_run": best["cpu"], "wall_s_process": "",
                         "impacts": "", "overturned": "", "note": f"Siconos dt 1e-4: error {s_err:.3g}, "
                         f"CPU {at_dt['cpu']:.3g} s"})


def main(argv):
    ap = argparse.ArgumentParser(prog="bench/siconos_equal_accuracy.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("--rocking", required=True, help="the rocking command (build/rocking)")
    ap.add_argument("--python", help="the folder of the module rocking_q (build/python), for the engine's times")
    ap.add_argument("--out", default="out/bench")
    ap.add_argument("--records", default=os.environ.get("ROCKING_RECORDS", os.path.join(ROOT, "..", "shared", "records")))
    ap.add_argument("--phases", type=int, default=4, help="grid offsets per Siconos dt (default 4)")
    a = ap.parse_args(argv)
    try:
        import siconos.kernel  # noqa: F401
    except ImportError:
        print("skip: /usr/bin/python3 cannot import siconos.kernel (make deps installs python3-siconos)")
        return 0
    if not os.access(a.rocking, os.X_OK):
        print(f"bench/siconos_equal_accuracy.py: --rocking {a.rocking}: not an executable (make build)", file=sys.stderr)
        return 2
    if not 1 <= a.phases <= 64:
        print(f"bench/siconos_equal_accuracy.py: --phases: must be in [1, 64] (got {a.phases})", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    lines, rows = [], []

    def say(text):
        print(text, flush=True)
        lines.append(text)

    clock = EngineClock(a.rocking, a.python)
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="bench_siconos.") as tmp:
        window = record_window(a.rocking, a.records, tmp)
        say("The sliding-rocking engine (rocking simulate --friction) against Siconos (tools/siconos_block.py)")
        say(f"machine: {machine()}")
        say(f"errors: |value - reference|; Siconos' the root mean square over {a.phases} runs on grids offset by "
            f"dt/{a.phases}; engine times: {clock.how}; Siconos': CPU of its time-stepping loop per run (OPENBLAS_NUM_THREADS=1)")
        if window is None:
            say(f"skip: case (d) needs {os.path.join(a.records, AQK)} (ROCKING_RECORDS or --records)")
        results = [bench_case(c, a.rocking, clock, a.phases, say, rows) for c in cases(window)]
    say("")
    say("Equal accuracy (Siconos' dt: the largest measured whose error is within the target, outcome and impacts "
        "the reference's; else extrapolated by its fitted order, its time by its fastest time per step)")
    for res in results:
        equal_accuracy(res, say, rows)
    say("")
    say(f"run time {time.perf_counter() - start:.0f} s; load {os.getloadavg()[0]:.1f} at the end")
    with open(os.path.join(a.out, "siconos.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(a.out, "siconos.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {os.path.join(a.out, 'siconos.txt')} and siconos.csv")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
