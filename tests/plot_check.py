#!/usr/bin/env python3
"""The PNGs of rocking spectrum, fragility, eq27 and assess (issue 40) against what
they must draw, from the gnuplot script the command kept (ROCKING_PLOT_SCRIPT)
and the same run's --json: every number recomputed here, with the standard
library only.

    plot_check.py spectrum SCRIPT PNG JSON
    plot_check.py fragility SCRIPT PNG JSON [FITS_CSV]
    plot_check.py eq27 SCRIPT PNG JSON INFO_JSONL ROCKING
    plot_check.py assess SCRIPT PNG JSON ROCKING RECORD

Each PNG: its signature, its IHDR's width and height (the size its layout
gives for the panels it has), and its IEND last.  Exit 1 with the failures
listed, 0 when all hold.
"""
import csv
import json
import math
import re
import struct
import subprocess
import sys

G = 9.81  # m/s^2, as the library's kGravity
problems = []


def want(cond, what):
    if not cond:
        problems.append(what)
    return cond


def png_size(path):
    data = open(path, "rb").read()
    if not want(data[:8] == b"\x89PNG\r\n\x1a\n", "%s: no PNG signature" % path):
        return None
    length, kind = struct.unpack(">I4s", data[8:16])
    if not want(kind == b"IHDR" and length == 13, "%s: the first chunk is not IHDR" % path):
        return None
    want(data.endswith(b"IEND\xaeB`\x82"), "%s: does not end with IEND" % path)
    return struct.unpack(">II", data[16:24])


def datablocks(script):
    blocks, name = {}, None
    for line in script.splitlines():
        m = re.match(r"^\$(\w+) << EOD$", line)
        if m:
            name = m.group(1)
            blocks[name] = []
        elif line == "EOD":
            name = None
        elif name is not None:
            blocks[name].append([float(v) for v in line.split()])
    return blocks


def sections(script):
    """The script's lines cut after each plot command: the settings of one panel, its plot last."""
    out, current = [], []
    for line in script.splitlines():
        current.append(line)
        if line.startswith("plot "):
            out.append(current)
            current = []
    return out


def caption_lines(script):
    return len(re.findall(r"^set label 1\d\d '", script, re.M))


def phi(z):
    return 0.5 * math.erfc(-z / math.sqrt(2))


def lognormal(q, median, beta):
    return phi(math.log(q / median) / beta)


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


# ---- rocking spectrum --png ----

def check_spectrum(script_path, png, json_path):
    script = open(script_path).read()
    d = json.load(open(json_path))
    spectra = d["spectra"]
    size = png_size(png)
    want(size == (1000, 36 + 350 * len(spectra) + 110), "spectrum PNG size %r, wanted 1000 x %d" %
         (size, 36 + 350 * len(spectra) + 110))
    # One y range, set once before the panels, none inside them.
    want(len(re.findall(r"^set yrange", script, re.M)) == 1, "spectrum: not exactly one 'set yrange'")
    want(script.index("set yrange") < script.index("\nplot "), "spectrum: the y range is set after a panel")
    want("outside" not in script, "spectrum: a key outside the panels")
    blocks = datablocks(script)
    panels = sections(script)
    want(len(panels) == len(spectra), "spectrum: %d plots for %d alphas" % (len(panels), len(spectra)))
    p_min, p_max = d["grid"]["p_min"], d["grid"]["p_max"]
    tics_checked = 0
    for k, (s, panel) in enumerate(zip(spectra, panels)):
        alpha = s["alpha"]
        text = "\n".join(panel)
        # The data drawn are the JSON's points: p, max |theta|/alpha, overturned.
        rows = blocks.get("spectrum%d" % k, [])
        want([[pt["p"], pt["max_theta"], 1.0 if pt["overturning"] else 0.0] for pt in s["points"]] == rows,
             "spectrum alpha %g: the datablock is not the JSON's points" % alpha)
        # Overturned runs: off the line, points in the strip, named in the key.
        plot = panel[-1]
        want("$3 != 0 ? 1/0 :" in plot and "'overturned run (θ reaches the fall angle)'" in plot,
             "spectrum alpha %g: the overturned runs are not drawn apart: %s" % (alpha, plot[:300]))
        # The top axis: each tic's height label is H = 2 R cos(alpha), R = 3 g / (4 p^2), at its p.
        m = re.search(r"^set x2tics \((.*)\)$", text, re.M)
        if not want(m, "spectrum alpha %g: no x2tics" % alpha):
            continue
        tics = re.findall(r"'([^']*)' ([-+0-9.eE]+)", m.group(1))
        want(len(tics) >= 2, "spectrum alpha %g: fewer than two height tics" % alpha)
        for label, at in tics:
            p = float(at)
            R = 3 * G / (4 * p * p)
            H = 2 * R * math.cos(alpha)
            want(p_min <= p <= p_max, "spectrum alpha %g: tic %s at p %r off the axis" % (alpha, label, p))
            want(close(H, float(label), 1e-12), "spectrum alpha %g: tic '%s' at p %r, where H = %r" % (alpha, label, p, H))
            tics_checked += 1
        want(re.search(r"^set x2label 'H \[m\]", text, re.M), "spectrum alpha %g: the top axis is not labelled H [m]" % alpha)
        # Each block marked on this alpha: a line at its p, its name and outcome beside it.
        for mark in d["marks"]:
            if mark["alpha"] != alpha:
                continue
            lines = [float(a) for a, b in re.findall(r"^set arrow \d+ from ([-+0-9.eE]+), graph 0 to ([-+0-9.eE]+), graph 1 .*#008000", text, re.M)]
            want(mark["p"] in lines, "spectrum: no line at the marked block %s's p %r (lines at %r)" % (mark["built"], mark["p"], lines))
            outcome = "overturns" if mark["overturns"] else "safe"
            label = re.search(r"^set label \d+ '%s: (\w+)' at ([-+0-9.eE]+), graph" % re.escape(mark["built"]), text, re.M)
            want(label and label.group(1) == outcome and float(label.group(2)) == mark["p"],
                 "spectrum: the mark %s is not labelled '%s' at its p" % (mark["built"], outcome))
    want(tics_checked >= 2 * len(spectra), "spectrum: %d height tics checked" % tics_checked)
    # One key, below the panels, in the last plot.
    want(script.count("set key at screen") == 1 and script.count("unset key") == len(spectra) - 1,
         "spectrum: not one key for the figure")


# ---- rocking fragility --png ----

def check_fragility(script_path, png, json_path, fits_path=None):
    script = open(script_path).read()
    d = json.load(open(json_path))
    blocks_json = d["blocks"]
    n = len(blocks_json)
    columns = 1 if n == 1 else 2
    rows = (n + columns - 1) // columns
    size = png_size(png)
    height = 36 + rows * 470 + 24 + 16 * caption_lines(script)
    want(size == (760 * columns, height), "fragility PNG size %r, wanted %d x %d" % (size, 760 * columns, height))
    blocks = datablocks(script)
    refine = d["grid"].get("method") == "refine"
    q_min, q_max = d["grid"]["q_min"], d["grid"]["q_max"]
    for k, b in enumerate(blocks_json):
        fit = b["fit"]
        curve = blocks.get("curve%d" % k, [])
        if not want(len(curve) == 241, "fragility block %d: %d curve points" % (k, len(curve))):
            continue
        want(curve[0][0] == q_min and close(curve[-1][0], q_max, 1e-14), "fragility block %d: the curve's q range" % k)
        records = b["records"]
        censored = sum(not r["collapsed"] for r in records)
        want(("n = %d records, %d censored" % (len(records), censored)) in script,
             "fragility block %d: its title lacks 'n = %d records, %d censored'" % (k, len(records), censored))
        for row in curve[::40]:
            q = row[0]
            if fit:
                want(close(row[1], lognormal(q, fit["median"], fit["beta"]), 1e-12),
                     "fragility block %d: P(%r) = %r, Phi gives %r" % (k, q, row[1], lognormal(q, fit["median"], fit["beta"])))
            if fit and fit["bootstrap"]:
                m, bb = fit["bootstrap"]["median"], fit["bootstrap"]["beta"]
                corners = [lognormal(q, mm, be) for mm in m for be in bb]
                want(close(row[2], min(corners), 1e-12) and close(row[3], max(corners), 1e-12),
                     "fragility block %d: the band at q %r is [%r, %r], the corners give [%r, %r]" %
                     (k, q, row[2], row[3], min(corners), max(corners)))
            if refine:
                for col, key in ((4, "first_robust_collapse"), (5, "stripes")):
                    f = b["fits"][key]["fit"]
                    if f:
                        want(close(row[col], lognormal(q, f["median"], f["beta"]), 1e-12),
                             "fragility block %d: the %s curve at q %r" % (k, key, q))
        # The empirical points: each overturning record's q and the share at or below it.
        qs = sorted(r["q"] for r in records if r["collapsed"])
        want(blocks.get("empirical%d" % k) == [[q, (i + 1) / len(records)] for i, q in enumerate(qs)],
             "fragility block %d: the empirical points" % k)
        want(len(blocks.get("censored%d" % k, [])) == censored and
             all(row[0] == q_max for row in blocks.get("censored%d" % k, [])),
             "fragility block %d: the censored points" % k)
        if fit:
            want(("median %s, β" % ("%.4g" % fit["median"])) in script, "fragility block %d: the key lacks its median" % k)
    if fits_path:
        lines = [l for l in open(fits_path) if not l.startswith("#")]
        table = list(csv.DictReader(lines))
        capacities = ["first_overturning", "first_robust_collapse", "stripes"] if refine else ["first_collapse"]
        want(len(table) == n * len(capacities), "--fits: %d rows for %d blocks" % (len(table), n))
        for k, b in enumerate(blocks_json):
            for j, capacity in enumerate(capacities):
                row = table[k * len(capacities) + j]
                f = b["fit"] if j == 0 else b["fits"][capacity]["fit"]
                want(row["capacity"] == capacity and float(row["alpha"]) == b["alpha"] and float(row["p"]) == b["p"],
                     "--fits row %d: %r" % (k, row))
                if not f:
                    want(row["median"] == "-" and row["no_fit"] != "-", "--fits row %d: a fit where none" % k)
                    continue
                want(float(row["median"]) == f["median"] and float(row["beta"]) == f["beta"],
                     "--fits row %d (%s): median, beta %s, %s against %r, %r" %
                     (k, capacity, row["median"], row["beta"], f["median"], f["beta"]))
                boot = f["bootstrap"]
                if boot:
                    want([float(row[c]) for c in ("median_lo", "median_hi", "beta_lo", "beta_hi")] ==
                         boot["median"] + boot["beta"] and int(row["resamples"]) == boot["resamples"] and
                         int(row["seed"]) == boot["seed"], "--fits row %d (%s): the bootstrap's ends" % (k, capacity))
                else:
                    want(row["median_lo"] == "-", "--fits row %d: bootstrap ends without a bootstrap" % k)


# ---- rocking eq27 --png ----

def check_eq27(script_path, png, json_path, info_path, rocking):
    script = open(script_path).read()
    e = json.load(open(json_path))
    infos = [json.loads(line) for line in open(info_path)]
    size = png_size(png)
    height = 36 + 40 + 360 + 55 + 64 + 24 + 16 * caption_lines(script)
    want(size == (1200, height), "eq27 PNG size %r, wanted 1200 x %d" % (size, height))
    blocks = datablocks(script)
    studies = [e] + ([e["first_robust_collapse"]] if e.get("method") == "refine" else [])
    for i, study in enumerate(studies):
        shares = blocks.get("shares%d" % i, [])
        wanted = [[s["k"], s["share"]] + (s["bootstrap"] or [0, 0]) + s["wilson"] + [s["non_conservative"], s["cases"]]
                  for s in study["shares"]]
        want(shares == wanted, "eq27: the shares drawn (%d) are not the JSON's" % i)
    want(("shares%d" % len(studies)) not in blocks, "eq27: more capacities drawn than run")
    # The cases at to_5, record-major: x = p to_5, eq. 27's q there, the capacity, its verdict.
    cases = blocks.get("cases", [])
    nb = len(e["map"])
    want(len(cases) == e["cases"] == len(infos) * nb, "eq27: %d cases drawn of %d" % (len(cases), e["cases"]))
    flags = [int(c[3]) for c in cases]
    want(flags.count(1) == e["shares"][4]["non_conservative"], "eq27: %d non-conservative drawn, the JSON's to_5 %d" %
         (flags.count(1), e["shares"][4]["non_conservative"]))
    want(flags.count(2) == e["censored"], "eq27: %d censored drawn of %d" % (flags.count(2), e["censored"]))
    for j, (x, q27, q, flag) in enumerate(cases):
        r, b = divmod(j, nb)
        want(x == e["map"][b]["p"] * infos[r]["to"][4], "eq27 case %d: x %r is not p to_5" % (j, x))
        want((flag == 1) == (q < q27 and flag != 2), "eq27 case %d: flag %d for q %r against %r" % (j, flag, q, q27))
    for j in (0, len(cases) // 2, len(cases) - 1):
        x, q27 = cases[j][0], cases[j][1]
        out = subprocess.run([rocking, "q", "--case", "2", "--pulses", "6", "--x", repr(x), "--json"],
                             capture_output=True, text=True, check=True).stdout
        want(close(json.loads(out)["q"], q27, 1e-13), "eq27 case %d: eq. 27's q %r, rocking q gives %s" % (j, q27, out[:80]))
    want("plot x with lines" in script, "eq27: no 1:1 line")


# ---- rocking assess --png ----

def check_assess(script_path, png, json_path, rocking, record):
    script = open(script_path).read()
    d = json.load(open(json_path))
    r = d["records"][0]
    size = png_size(png)
    want(size == (1000, 36 + 2 * 350 + 110), "assess PNG size %r, wanted 1000 x 846" % (size,))
    panels = sections(script)
    if not want(len(panels) == 2, "assess: %d plots, wanted the response and the spectrum" % len(panels)):
        return
    upper = "\n".join(panels[0])
    # The runs: 300 q log-spaced from 1 to the IDA's end (20, or twice the record's q).
    rows = datablocks(script).get("response", [])
    q_hi = min(1e4, max(20.0, 2 * r["q_record"]))
    want(len(rows) == 300 and rows[0][0] == 1.0 and rows[-1][0] == q_hi,
         "assess: the runs are not 300 q from 1 to %r: %d rows from %r to %r" % (q_hi, len(rows), rows[0][0], rows[-1][0]))
    for k in range(1, len(rows)):
        want(close(rows[k][0] / rows[k - 1][0], (q_hi / 1.0) ** (1 / 299), 1e-12), "assess: run %d not log-spaced" % k)
    # Below the first overturning the IDA found, no run overturns (the search against the runs).
    fo = r["first_overturning"]
    early = [row for row in rows if row[0] < fo["q"] and row[2] != 0]
    want(not early, "assess: runs overturn below the IDA's first overturning %r: %r" % (fo["q"], early[:3]))
    # Five runs again, by simulate at their q: the same peak and outcome.
    for row in (rows[0], rows[75], rows[150], rows[225], rows[-1]):
        out = subprocess.run([rocking, "simulate", "--record", record, "--alpha", repr(d["alpha"]), "--p", repr(d["p"]),
                              "--q", repr(row[0]), "--json"], capture_output=True, check=True).stdout
        s = json.loads(out)
        want(bool(row[2]) == s["collapse_overturning"], "assess: the run at q %r: overturns %r, simulate %r" %
             (row[0], row[2], s["collapse_overturning"]))
        if not s["overturned_during_input"]:
            want(close(row[1], s["max_theta_input_over_alpha"], 1e-12), "assess: the run at q %r: peak %r, simulate %r" %
                 (row[0], row[1], s["max_theta_input_over_alpha"]))
    # A line at each q of the check and of the model, where on the axis.
    drawn = [float(x) for x in re.findall(r"^set arrow \d+ from ([-+0-9.eE]+), graph 0 to ", upper, re.M)]
    for name, q in (("the record", r["q_record"]), ("eq. 27", r["q_eq27"]), ("first overturning", fo["q"]),
                    ("first robust collapse", r["first_robust_collapse"]["q"])):
        if 1 <= q <= q_hi:
            want(q in drawn, "assess: no line at %s's q %r (lines at %r)" % (name, q, drawn))
    # The top axis: the record's scale factor, q / q_record.
    m = re.search(r"^set x2range \[([-+0-9.eE]+):([-+0-9.eE]+)\]$", upper, re.M)
    want(m and close(float(m.group(1)), 1 / r["q_record"], 1e-15) and close(float(m.group(2)), q_hi / r["q_record"], 1e-15),
         "assess: the top axis is not q / the record's q")
    verdict = "eq. 27 check %s" % ("PASSES" if r["passes"] else "FAILS")
    want(re.search(r"^set title '%s \(margin" % verdict, upper, re.M), "assess: the title does not say '%s'" % verdict)
    # Below, the spectrum with the block marked at its p.
    lower = "\n".join(panels[1])
    want(re.search(r"^set arrow \d+ from %s, graph 0 .*#008000" % re.escape(repr(d["p"])), lower, re.M),
         "assess: the spectrum has no line at the block's p %r" % d["p"])


if __name__ == "__main__":
    kind, args = sys.argv[1], sys.argv[2:]
    try:
        {"spectrum": check_spectrum, "fragility": check_fragility, "eq27": check_eq27, "assess": check_assess}[kind](*args)
    except FileNotFoundError as e:
        problems.append("%s: not written (the command kept no script, drew no PNG or wrote no JSON)" % e.filename)
    for p in problems:
        print("FAIL: " + p)
    if not problems:
        print("ok: the %s plot: %s" % (kind, ", ".join(args[:2])))
    sys.exit(1 if problems else 0)
