#!/usr/bin/env python3
"""Checks a rocking batch results file against the single commands.

Every row of RESULTS is rerun by the command that runs its study alone
(simulate --record, collapse, fragility for an ida row, spectrum), with the
options its manifest cells give, from the manifest's folder DIR, and each
figure of the row must equal the command's JSON as a double: both are %.17g
of the same computation, or the batch computes something else.  A row with
method refine (issue 39) is rerun with --method refine and its widths, and
its first robust collapse and bands checked against the command's.

    batch_compare.py RESULTS ROCKING DIR [--kinds simulate,collapse,ida,spectrum]
"""
import csv, json, subprocess, sys
path, rocking, tmp = sys.argv[1:4]
wanted = set(sys.argv[5].split(",")) if len(sys.argv) > 5 and sys.argv[4] == "--kinds" else {"simulate", "collapse", "ida", "spectrum"}
rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
for r in rows:  # the manifest's columns it does not have: empty, as the batch takes them
    for k in ("unit", "record_dt", "p", "height", "half_height", "scaling", "model", "restitution", "criterion",
              "points", "q_max", "method", "width", "robust_width"):
        r.setdefault(k, "")
def run(*args):
    return json.loads(subprocess.run([rocking, *args], capture_output=True, text=True, check=True, cwd=tmp).stdout)
def record_args(r, dt_flag):
    a = [] if not r["unit"] else ["--unit", r["unit"]]
    return a + ([dt_flag, r["record_dt"]] if r["record_dt"] else [])
def method_args(r):
    if r["method"] != "refine": return []
    return ["--method", "refine"] + (["--width", r["width"]] if r["width"] else []) + \
        (["--robust-width", r["robust_width"]] if r["robust_width"] else [])
def same_capacities(r, j, x, found):
    # The refine method's JSON holds the first robust collapse and every band; the row the bands that overturn.
    if r["method"] != "refine": return
    robust = j["first_robust_collapse"]
    assert (r["robust_collapse"] == "yes") == robust[found], (r, robust)
    same(x + "_robust", r[x + "_robust"], robust[x] if robust[found] else None)
    bands = [b for b in j["bands"] if b["share"] > 0]
    cells = [c.split("|") for c in r["bands"].split(";")] if r["bands"] else []
    assert len(cells) == len(bands), (r["bands"], bands)
    for c, b in zip(cells, bands):
        for v, key in zip(c, ("from", "to", "share")): same("band " + key, v, b[key])
def same(what, got, want):
    # Both are %.17g of a double: equal as doubles, or the batch differs from the command.
    if want is None: assert got == "", (what, got)
    else: assert float(got) == float(want), (what, got, want)
kinds = set()
for r in rows:
    assert r["status"] == "ok", r
    kinds.add(r["kind"])
    if r["kind"] == "simulate":
        args = ["simulate", "--record", r["record"], *record_args(r, "--record-dt"), "--alpha", r["alpha"]]
        args += ["--p", r["p"]] if r["p"] else ["--height", r["height"]] if r["height"] else ["--half-height", r["half_height"]]
        for col, flag in (("model", "--model"), ("restitution", "--restitution"), ("criterion", "--criterion")):
            if r[col]: args += [flag, r[col]]
        if r["scaling"]: args += ["--" + r["scaling"].split("=")[0], r["scaling"].split("=")[1]]
        j = run(*args, "--json")
        same("max_theta", r["max_theta"], j["max_theta_input_over_alpha"])
        same("theta_tfin", r["theta_tfin"], j["theta_tfin_over_alpha"])
        same("t_overturn", r["t_overturn"], j["t_overturn"])
        assert int(r["impacts"]) == j["impacts"], r
        assert (r["collapse"] == "yes") == j["collapse"], r
        assert r["criterion_used"] == j["criterion"] and r["solver_used"].split()[0] == j["solver"], (r, j)
        assert r["model_used"] == ("full" if "full" in j["model"] else "linearised"), (r, j)
    elif r["kind"] == "collapse":
        j = run("collapse", r["record"], *record_args(r, "--dt"), "--alpha", r["alpha"], "--json")
        same("p_collapse", r["p_collapse"], j["p"])
        same("p_safe", r["p_safe"], j["p_safe"])
        assert int(r["simulations"]) == j["simulations"] and (r["collapse"] == "yes") == j["found"], (r, j)
    elif r["kind"] == "ida":
        grid = (["--points", r["points"]] if r["points"] else []) + (["--q-max", r["q_max"]] if r["q_max"] else [])
        j = run("fragility", r["record"], *record_args(r, "--dt"), "--alpha", r["alpha"], "--p", r["p_used"], *grid,
                *method_args(r), "--json")["blocks"][0]["records"][0]
        assert (r["collapse"] == "yes") == j["collapsed"], (r, j)
        same("q_collapse", r["q_collapse"], j["q"] if j["collapsed"] else None)
        if j["collapsed"]:
            low = j["intervals"][0]["lower"]
            same("q_safe", r["q_safe"], low["q_safe"] if low else None)
        assert int(r["intervals"]) == len(j["intervals"]) and int(r["simulations"]) == j["simulations"], (r, j)
        same_capacities(r, j, "q", "collapsed")
    elif r["kind"] == "spectrum":
        grid = ["--points", r["points"]] if r["points"] else []
        grid += (["--p-min", r["p_min"]] if r.get("p_min") else []) + (["--p-max", r["p_max"]] if r.get("p_max") else [])
        j = run("spectrum", r["record"], *record_args(r, "--dt"), "--alpha", r["alpha"], *grid, *method_args(r),
                "--json")["spectra"][0]
        assert int(r["intervals"]) == len(j["intervals"]) and int(r["simulations"]) == j["simulations"], (r, j)
        if j["intervals"]:
            first = j["intervals"][0]
            same("p_collapse", r["p_collapse"], first["from"])
            same("p_safe", r["p_safe"], first["lower"]["p_safe"] if first["lower"] else None)
        same_capacities(r, j, "p", "found")
assert kinds == wanted, kinds
assert any(r["collapse"] == "yes" for r in rows) and any(r["collapse"] == "no" for r in rows)
print(len(rows), "rows agree")
