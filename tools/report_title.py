"""The report's first page: what the report is and what it was built from (the date, the commit, the
outputs read), every scene against expected/, and the findings by kind: a reviewer who reads one
page has the verdicts of the run and of the paper.

A scene that out/summary.csv does not list (a partial run, or the report built from a copy of
expected/) is still a row, with the number of output files found for it and no comparison.
"""
import datetime
import os
import subprocess

import findings
import report_outputs as outputs
from report_findings import ENTRIES

TOOLS = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(TOOLS)

# The scenes in the order reproduce runs them (reproduce --list), each with what it reproduces,
# in the words of the README's table, shortened to a line.
SCENES = [
    ("fig04", "Figure 4: q1..q5 against x, their minimum, the q ≥ 2 limit of cases 3 and 5"),
    ("fig07", "Figure 7: q for cases 1, 2, 4 with N = 2..12 pulses; how q settles with N"),
    ("errata", "every printed formula evaluated as printed; the paper's claims measured"),
    ("fig05", "Figure 5: θ/α below the collapse PGA (Rd < 1); collapse under three criteria"),
    ("fig06", "Figure 6: θ(t_fin)/α of the full eq. 1 against the linearised eq. 3"),
    ("fig08", "Figure 8: eq. 27 against the one-sine overturning threshold and Coccia & Como"),
    ("table1", "Table 1: q = PGA/(α g); the collapse search on the records here"),
    ("table2", "Table 2: to_5 from PGA and PGV; the eleven half-periods of the records here"),
    ("fig11", "Figure 11: (p·to_k, q) against eq. 27; non-conservative points counted"),
    ("fig12", "Figure 12: to_5 only, the code's q = 2 and where eq. 27 falls below it"),
    ("spectrum", "the rocking spectrum of the Norcia records against Table 1's p"),
    ("fragility", "the first collapse q by IDA, lognormal fragility, eq. 27's share per to_k"),
    ("imperfection", "imperfect blocks: the closed forms per corner, eq. 27's share per to_k with them"),
]
REPRODUCES = dict(SCENES)


def git(*args):
    """A git command's output in the repository of this tool; None outside a checkout or without git."""
    try:
        r = subprocess.run(["git", "-C", REPO, *args], capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    return r.stdout.strip() if r.returncode == 0 else None


def commit_line():
    head = git("log", "-1", "--format=%h (%cs) %s")
    if head is None:
        return "not a git checkout (no commit to name)"
    dirty = git("status", "--porcelain", "--untracked-files=no")
    return head + ("; with uncommitted changes to tracked files" if dirty else "")


def outputs_line():
    out = os.path.realpath(outputs.OUT)
    if out == os.path.realpath(os.path.join(REPO, "expected")):
        return f"{outputs.OUT}/, the expected outputs themselves: no run, nothing compared"
    summary = os.path.join(outputs.OUT, "summary.csv")
    if not outputs.SUMMARY:
        return (f"{outputs.OUT}/, without summary.csv: no comparison with expected/ (make reproduce writes it after "
                "running every scene)")
    when = datetime.datetime.fromtimestamp(os.path.getmtime(summary)).strftime("%Y-%m-%d %H:%M")
    notes = outputs.read("", "summary.csv")[0]
    return f"{outputs.OUT}/ of make reproduce, {when}, compared with {notes.get('expected', 'expected/')}"


def files_of(scene):
    d = os.path.join(outputs.OUT, scene)
    return sorted(f for f in os.listdir(d) if f.endswith(".csv")) if os.path.isdir(d) else []


def scene_rows():
    """[scene, reproduces, status, time, largest deviation] for every scene, then any other the summary lists."""
    names = [s for s, _ in SCENES] + [s for s in outputs.SUMMARY if s not in REPRODUCES]
    rows = []
    for s in names:
        r = outputs.SUMMARY.get(s)
        if r:
            rows.append([s, REPRODUCES.get(s, ""), r[1], f"{float(r[2]):.2f}", r[3]])
        else:
            n = len(files_of(s))
            rows.append([s, REPRODUCES.get(s, ""), "not compared", "",
                         f"{n} CSV files in {outputs.OUT}/{s}" if n else "no outputs: the scene did not run"])
    return rows


def kind_rows():
    """[kind, findings] for every kind with entries: each id with its title, as README's summary groups them."""
    return [[f"{k.heading} ({len(es)})", "; ".join(f"{e.id} {e.title}" for e in es)]
            for k, es in findings.grouped(ENTRIES)]


def page(L):
    """The first page."""
    L.page("rocking-q: reproduction report",
           "Compares every output of every scene (make reproduce) with its expected copy under expected/, cell by "
           "cell, within the tolerances stated in expected/<scene>/TOLERANCES, and lists what the paper gets wrong.")
    L.text("S. Coccia, q-factor for slender masonry structures under out-of-plane seismic loading, Buildings 2025, "
           "15, 2622.  The paper gives closed-form behaviour factors q = PGA/(α g) for the overturning of a slender "
           "rigid block (Housner's rocking model, θ the block's rotation, α its slenderness angle) under step-pulse "
           "inputs, as functions of x = p·to.  rocking-q recomputes every figure and table the paper's text allows "
           "from its definitions and compares each with an expected output whose provenance and tolerance are "
           "stated beside it (expected/<scene>/PROVENANCE.md and TOLERANCES).", 8.5)
    L.text("This page: what the report was built from, every scene against expected/, and the findings by kind.  "
           "Then: the findings, each with its verdict, number and evidence (the entries of docs/findings.md); "
           "Figures 4-8; Tables 1-2 and Figures 11-12; the rocking spectrum and the fragility study on the records; "
           "the speed-accuracy trade (make bench).", 8.5, gap=0.12)

    L.text("Built from", 10, weight="bold", gap=0.04)
    bench = f"{outputs.OUT}/bench/summary.txt (make bench)" if outputs.BENCH_LINES else "not run (make bench)"
    for key, value in (("generated", datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")
                        + " by tools/report.py (make report)"),
                       ("code", "commit " + commit_line()),
                       ("outputs", outputs_line()),
                       ("benchmark", bench)):
        L.text(f"{key}: {value}", 8, indent=0.15, gap=0.025)
    L.y += 0.1

    L.text("The scenes against expected/", 10, weight="bold", gap=0.03)
    L.text("'match': every cell of every output within its tolerance; the largest deviation is the cell furthest "
           "from its expected value relative to its tolerance (file, column, line of the expected file).", 7.5,
           color="#333333", gap=0.04)
    L.table(["scene", "reproduces", "status", "time [s]", "largest deviation"], scene_rows(),
            [8, 38, 9, 6, 39], size=6.5)

    L.text("What the paper gets wrong, by kind", 10, weight="bold", gap=0.03)
    L.text("Only the first four kinds can be errors of the paper; the findings pages give each entry's scope, "
           "verdict and evidence.", 7.5, color="#333333", gap=0.04)
    L.table(["kind", "findings (id and title)"], kind_rows(), [18, 82], size=6.5)
