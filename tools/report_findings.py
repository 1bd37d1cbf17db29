"""The findings in the report: the pages "What the paper gets wrong" (every entry of
tools/findings.py, the same as docs/findings.md, by kind and then by section, each with this
run's comparison of its scenes), and what the figure pages say of them: verdicts(ids) in an
opening sentence, entry_verdicts(L, ids) under a figure.  The entries are built once, from
expected/, when this module is imported.
"""
import findings
import report_outputs as outputs
from report_layout import INK
from report_outputs import short_status


ENTRIES, PROBLEMS = findings.build()
BY_ID = {e.id: e for e in ENTRIES}


def plain(s):
    """Markdown to the page's plain text."""
    return s.replace("`", "").replace("**", "")


def verdicts(ids):
    return ", ".join(f"{i} {BY_ID[i].label}" for i in ids)


def entry_verdicts(L, ids):
    """The verdicts of these findings, as docs/findings.md gives them."""
    L.text("Findings (docs/findings.md; details on the findings pages):", 8, weight="bold", gap=0.04)
    for i in ids:
        e = BY_ID[i]
        L.text(f"{e.id} ({findings.verdict_of(e)}). {e.title}: {plain(e.verdict)}", 7.5, indent=0.15, gap=0.05)


BENCH_KEYS = {"T1b": ["table1 search on a grid 10 times finer"],
              "T1c": ["table1 search with the paper's setting", "table1 search, its"]}


# Red for the paper's errors, amber where it is right only in part or not yet known, blue for
# what the model shows beyond the paper, green where it holds.
KIND_COLOUR = {"erratum": "#b3261e", "fails": "#b3261e", "partial": "#9a6700", "unverified": "#9a6700",
               "beyond": INK, "caveat": INK, "holds": "#1a7f37"}


def render_entry(L, e):
    colour = KIND_COLOUR.get(e.kind, "#9a6700")
    L.need(1.2)
    L.text(f"{e.id}. {e.title}", 9.5, weight="bold", gap=0.03)
    if e.flag:
        L.text(f"REVIEW: {e.flag}", 7.5, color="#b3261e", indent=0.15, gap=0.03)
    L.text(f"Verdict: {findings.verdict_of(e)}   (this run: {short_status(e.scenes)})", 8, weight="bold",
           color=colour, indent=0.15, gap=0.02)
    L.text(plain(e.verdict), 7.5, indent=0.15, gap=0.04)
    if e.settle:
        L.text(f"What would settle it: {plain(e.settle)}", 7.5, indent=0.15, gap=0.04)
    L.text(f"Printed, {e.where}: {plain(e.printed)}", 7.5, indent=0.15, gap=0.03)
    L.text(f"Scope: {plain(e.scope)}.", 7.5, indent=0.15, gap=0.03)
    L.text(f"Measured: {plain(e.measured)}", 7.5, indent=0.15, gap=0.03)
    L.text("Evidence: " + plain("; ".join(e.evidence)), 7, color="#333333", indent=0.15, gap=0.03)
    L.text("Tests: " + (", ".join(e.tests) if e.tests else "none (see the notes)"), 7, color="#333333",
           indent=0.15, gap=0.03)
    L.text(f"Command: {e.command}", 7, color="#333333", indent=0.15, gap=0.03)
    for n in e.notes + e.extra_notes:
        L.text(f"Note: {plain(n)}", 7, color="#333333", indent=0.15, gap=0.03)
    for key in BENCH_KEYS.get(e.id, []):
        for line in outputs.BENCH_LINES:
            if line.startswith(key):
                L.text(f"This run's make bench (out/bench/summary.txt): {line}", 7, color=INK, indent=0.15, gap=0.03)
    L.y += 0.1


def pages(L):
    """The findings: the same entries as docs/findings.md, by kind, then section by section."""
    L.page("What the paper gets wrong, and how we know",
           "Lists every erratum and every tested claim of the paper, by kind, with its verdict and number, read from "
           "expected/ by tools/findings.py, the same entries as docs/findings.md; 'this run' compares the entry's "
           "scenes in this run with expected/.")
    for p in PROBLEMS:
        L.text(f"tools/findings.py: {p}", 7.5, color="#b3261e")
    L.text("Verdicts. Every finding has one of these kinds; only the first four can be errors of the paper.", 8,
           weight="bold", gap=0.04)
    for k in findings.KINDS:
        L.text("- " + plain(k.meaning), 7.5, indent=0.1, gap=0.03)
    L.y += 0.08
    for k, group in findings.grouped(ENTRIES):
        L.need(0.8)
        L.text(k.heading + (f" ({k.gloss})" if k.gloss else ""), 9, weight="bold", color=KIND_COLOUR[k.key],
               gap=0.03)
        L.table(["#", "finding", "scope tested", "verdict", "this run"],
                [[e.id, e.title, e.scope, findings.label_of(e), short_status(e.scenes)] for e in group],
                [5, 34, 40, 16, 12], size=6.5)
    for key, title, intro in findings.SECTIONS:
        group = [e for e in ENTRIES if e.section == key]
        if not group:
            continue
        L.need(2.1)             # the heading, its intro and the start of its first entry
        L.text(title, 11.5, weight="bold", color=INK, gap=0.04)
        if intro:
            L.text(plain(intro), 7.5, gap=0.08)
        for e in group:
            render_entry(L, e)
    L.need(1.0)
    L.text("Not in the findings: about the harness, not the paper", 11.5, weight="bold", color=INK, gap=0.04)
    for n in findings.NOT_HERE:
        L.text("- " + plain(n), 7.5, indent=0.1, gap=0.04)
