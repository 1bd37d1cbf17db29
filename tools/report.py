#!/usr/bin/python3
"""make report: one PDF a reviewer can read without running anything else.

Reads the scenes' CSV files under OUT (default out/) and writes OUT/report.pdf: a first page
saying what it was built from, with every scene's comparison with expected/ and the findings
by kind; the findings (every erratum and tested claim, the same entries as docs/findings.md,
from tools/findings.py); for each figure and table of the paper, the reproduced version, the
paper's claim, the comparison with the expected output (status, largest deviation against
its tolerance), and the model and solver; the real-record results and the work-precision
diagram.  Debian's matplotlib (/usr/bin/python3); the text is searchable (report_layout.py).

Layout: every page opens with its title and one sentence saying what it compares (a section
too short for a page of its own, such as a note that an output is missing, opens below the
previous one instead); text is wrapped and placed by measuring it with the renderer, figures
take the height they ask for below it, and whatever does not fit goes on to a continuation
page.  Before a page is saved its text blocks and axes (with their labels and legends) are
checked against each other and the page's edges; an overlap is reported on stderr.

    /usr/bin/python3 tools/report.py [OUT]      (make report; OUT defaults to out/)

This file opens the PDF and builds the pages in order; the rest is a module per topic:

    report_layout.py     the page layout, its overlap check and the report's font
    report_title.py      the first page: what was built from what, the scenes, the findings by kind
    report_outputs.py    reading OUT's CSV files; this run against expected/
    report_findings.py   the findings pages; the verdicts the figure pages quote
    report_figures.py    Figures 4-8 (Sections 2-3)
    report_records.py    Tables 1-2 and Figures 11-12 (Section 4)
    report_spectrum.py   the rocking spectrum of the Norcia records
    report_fragility.py  the fragility study and eq. 27 at scale
    report_imperfection.py  imperfect blocks: the closed forms per corner, eq. 27 on the records
    report_sliding.py    the paper's claims on a base with Coulomb friction (scene sliding)
    report_bench.py      the speed-accuracy trade (make bench)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_layout import Layout  # noqa: E402  (first: it selects matplotlib's backend)
from matplotlib.backends.backend_pdf import PdfPages  # noqa: E402

import report_bench  # noqa: E402
import report_figures  # noqa: E402
import report_findings  # noqa: E402
import report_fragility  # noqa: E402
import report_imperfection  # noqa: E402
import report_outputs as outputs  # noqa: E402
import report_records  # noqa: E402
import report_sliding  # noqa: E402
import report_spectrum  # noqa: E402
import report_title  # noqa: E402


def main(argv):
    outputs.load(argv[1] if len(argv) > 1 else "out")
    with PdfPages(os.path.join(outputs.OUT, "report.pdf")) as pdf:
        L = Layout(pdf)
        report_title.page(L)
        for topic in (report_findings, report_figures, report_records, report_spectrum, report_fragility,
                      report_imperfection, report_sliding, report_bench):
            topic.pages(L)
        L.finish()
    for p in L.problems:
        print(f"report: layout: {p}", file=sys.stderr)
    print(f"wrote {os.path.join(outputs.OUT, 'report.pdf')} ({L.pages} pages)")


if __name__ == "__main__":
    main(sys.argv)
