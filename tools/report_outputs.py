"""The run's outputs as the report reads them: load(out) points it at a run (default out/, as
make reproduce writes it); read() gives a scene's CSV file with its "# key: value" notes,
col/dict_rows/num/short its columns and numbers; the comparison with expected/ (OUT/
summary.csv) in a line (status_line), a sentence (run_status) or a word (short_status); and
scene_status, the comparison and the CSV's model, solver and inputs under a page's opening
sentence.  BENCH_LINES holds make bench's summary when it ran.
"""
import csv
import os


# The run the report reads: set once by load(), before any page is built.  load() rebinds
# them, so other modules read them as report_outputs.OUT, never through `from ... import OUT`.
OUT = "out"
SUMMARY = {}        # scene -> its row of OUT/summary.csv (the comparison with expected/)
BENCH_LINES = []    # the lines of OUT/bench/summary.txt (make bench), if it ran


def load(out):
    """Points the report at the run in `out`: its summary.csv and bench/summary.txt, both optional."""
    global OUT, SUMMARY, BENCH_LINES
    OUT = out
    SUMMARY = {}
    s = read("", "summary.csv")
    if s:
        for r in s[2]:
            SUMMARY[r[0]] = r
    bench = os.path.join(OUT, "bench", "summary.txt")
    BENCH_LINES = open(bench).read().splitlines() if os.path.exists(bench) else []


def read(scene, name):
    """(notes, header, rows) of OUT/scene/name; None when absent."""
    path = os.path.join(OUT, scene, name)
    if not os.path.exists(path):
        return None
    notes, lines = {}, []
    for line in open(path, newline=""):
        if line.startswith("# "):
            k, _, v = line[2:].partition(": ")
            notes[k] = v.strip()
        else:
            lines.append(line)
    rows = list(csv.reader(lines))
    return notes, rows[0], rows[1:]


def col(table, name, cast=float):
    _, header, rows = table
    i = header.index(name)
    out = []
    for r in rows:
        try:
            out.append(cast(r[i]))
        except ValueError:
            out.append(float("nan"))
    return out


def short(v, n=4):
    try:
        return f"{float(v):.{n}g}"
    except ValueError:
        return v


def dict_rows(table):
    """The rows of a read() table as dicts by column name: columns are read by name, extra ones ignored."""
    _, header, rows = table
    return [dict(zip(header, r)) for r in rows]


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def status_line(scene):
    r = SUMMARY.get(scene)
    if not r:
        return "comparison: not run (make reproduce writes out/summary.csv)"
    return f"comparison with expected/{scene}: {r[1].upper()} ({float(r[2]):.2f} s); largest deviation: {r[3]}"


def differing(scenes):
    """The scenes of this run that differ from expected/; None when a scene was not compared."""
    got = [SUMMARY.get(sc) for sc in scenes]
    if not all(got):
        return None
    return [r[0] for r in got if r[1] != "match"]


def run_status(scenes):
    """This run's outputs against expected/, in words, for a sentence."""
    bad = differing(scenes)
    if bad is None:
        return "this run has no comparison with expected/ (out/summary.csv missing)"
    where = " and ".join(f"expected/{sc}" for sc in scenes)
    if not bad:
        return f"this run's outputs match {where}"
    return f"this run's outputs DIFFER from expected/ in {', '.join(bad)} (first page)"


def short_status(scenes):
    """This run against expected/ in a word or two."""
    bad = differing(scenes)
    if bad is None:
        return "not compared"
    return "match" if not bad else "differs in " + ", ".join(bad)


def notes_block(L, notes):
    for key in ("model", "solver", "inputs", "variants", "criteria"):
        if notes and key in notes:
            L.text(f"{key}: {notes[key]}", 7, color="#333333", gap=0.03)
    L.y += 0.06


def scene_status(L, scene, notes):
    """Under a figure page's opening sentence: the comparison with expected/, then the CSV's model, solver, inputs."""
    L.text("Reproduction: " + status_line(scene), 8)
    notes_block(L, notes)
