#!/usr/bin/python3
"""make report: one PDF a reviewer can read without running anything else.

Reads the scenes' CSV files under OUT (default out/) and writes OUT/report.pdf with, for
each figure and table of the paper, the reproduced version, the paper's claim, the
comparison with the expected output (status, largest deviation against its tolerance), and
the model and solver; the findings (every erratum and tested claim, the same entries as
docs/findings.md, from tools/findings.py); the real-record results and the
work-precision diagram.  Debian's matplotlib (/usr/bin/python3).

Layout: every page opens with its title and one sentence saying what it compares; text is
wrapped and placed by measuring it with the renderer, figures take the height they ask
for below it, and whatever does not fit goes on to a continuation page.  Before a page is
saved its text blocks and axes (with their labels and legends) are checked against each
other and the page's edges; an overlap is reported on stderr.

    /usr/bin/python3 tools/report.py [OUT]      (make report; OUT defaults to out/)

This file opens the PDF and builds the pages in order; the rest is a module per topic:

    report_layout.py     the page layout and its overlap check
    report_outputs.py    reading OUT's CSV files; this run against expected/
    report_findings.py   the findings pages; the verdicts the figure pages quote
    report_figures.py    Figures 4-8 (Sections 2-3)
    report_records.py    Tables 1-2 and Figures 11-12 (Section 4)
    report_spectrum.py   the rocking spectrum of the Norcia records
    report_fragility.py  the fragility study and eq. 27 at scale
    report_bench.py      the speed-accuracy trade (make bench)
"""
import datetime
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_layout import Layout  # noqa: E402  (first: it selects matplotlib's backend)
from matplotlib.backends.backend_pdf import PdfPages  # noqa: E402

import report_bench  # noqa: E402
import report_figures  # noqa: E402
import report_findings  # noqa: E402
import report_fragility  # noqa: E402
import report_outputs as outputs  # noqa: E402
import report_records  # noqa: E402
import report_spectrum  # noqa: E402


def title_page(L):
    """The title and the comparison of every scene with expected/."""
    L.page("rocking-q: reproduction report",
           "Compares every output of every scene (make reproduce) with its expected copy under expected/, cell by "
           "cell, within the tolerances stated in expected/<scene>/TOLERANCES.")
    L.text("S. Coccia, q-factor for slender masonry structures under out-of-plane seismic loading, Buildings 2025, "
           "15, 2622.  Every figure and table the paper's text allows is recomputed from its definitions and "
           "compared with an expected output whose provenance and tolerance are stated beside it (expected/<scene>/"
           "PROVENANCE.md and TOLERANCES).", 8.5)
    L.text(f"Generated {datetime.date.today().isoformat()} by make report from {outputs.OUT}/.  'match' means "
           "every cell of every output is within its tolerance; the largest deviation is given against that "
           "tolerance.  The pages after this one list what the paper gets wrong (the entries of docs/findings.md), then each figure "
           "and table, the real records and the speed-accuracy trade.", 8.5, gap=0.15)
    if outputs.SUMMARY:
        L.table(["scene", "status", "time [s]", "largest deviation"],
                [[r[0], r[1], f"{float(r[2]):.2f}", r[3]] for r in outputs.SUMMARY.values()], [8, 8, 8, 70], size=7.5)
    else:
        L.text("No comparison: make reproduce writes out/summary.csv.", 8.5)


def main(argv):
    outputs.load(argv[1] if len(argv) > 1 else "out")
    with PdfPages(os.path.join(outputs.OUT, "report.pdf")) as pdf:
        L = Layout(pdf)
        title_page(L)
        for topic in (report_findings, report_figures, report_records, report_spectrum, report_fragility,
                      report_bench):
            topic.pages(L)
        L.finish()
    for p in L.problems:
        print(f"report: layout: {p}", file=sys.stderr)
    print(f"wrote {os.path.join(outputs.OUT, 'report.pdf')} ({L.pages} pages)")


if __name__ == "__main__":
    main(sys.argv)
