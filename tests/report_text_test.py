#!/usr/bin/python3
"""The report's text can be searched and copied, and its first page is filled (issue 40, item 7).

Builds the report (SOURCE_DIR/tools/report.py) from a copy of expected/, the outputs a run of
make reproduce compares (not the plots' own data, spectrum_grid.csv and the fragility's empirical
shares, nor make bench's output: the report leaves out what it draws from them), and
reads it back with poppler's pdftotext and pdffonts, as a reader's search and copy see it.
It fails when:

- a font is Type 3: matplotlib's default, which draws θ, α and every other glyph beyond
  Latin-1 as a picture that pdftotext does not see (pdffonts lists the fonts);
- θ or α is missing from the text;
- a scene (README's table of scenes) or a finding id (the headings of docs/findings.md) is
  missing from the first page's text: the first page is the index of both;
- the first page holds fewer than MIN_WORDS words.

MIN_WORDS = 600: about half of what one page of the findings pages holds (1066 and 1150
words of 7.5-pt prose and tables on the second and third pages), more than twice what the
first page held before issue 40 (130 words built from a copy of expected/, 256 after a full
make reproduce, its summary table filled), and well below the filled page's 1037 (a copy of
expected/) and 1039 (a full run), so that the margin is for wording, not for layout luck.

    tests/report_text_test.py SOURCE_DIR

SOURCE_DIR may be any checkout (git archive of an older commit shows what the test says of its
report).  Exit 0: passed; 1: failed, each failure on stderr; 77: skipped, since pdftotext or
pdffonts is missing (poppler-utils; make deps installs it).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

MIN_WORDS = 600


def ids_in(path, pattern):
    with open(path, encoding="utf-8") as f:
        return [m.group(1) for m in re.finditer(pattern, f.read(), re.M)]


def pdf_text(pdf, *pages):
    return subprocess.run(["pdftotext", "-enc", "UTF-8", *pages, pdf, "-"], check=True, capture_output=True,
                          text=True).stdout


def has_word(text, word):
    """word as a whole token: C1 is not found inside C10, T1 not inside T1a."""
    return re.search(r"(?<![A-Za-z0-9_])" + re.escape(word) + r"(?![A-Za-z0-9_])", text) is not None


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    source = argv[1]
    report = os.path.join(source, "tools", "report.py")
    missing = [t for t in ("pdftotext", "pdffonts") if shutil.which(t) is None]
    if missing:
        print(f"report_text: SKIP: {' and '.join(missing)} not found (Debian's poppler-utils; make deps installs it)")
        return 77

    scenes = ids_in(os.path.join(source, "README.md"), r"^\| `([a-z0-9_]+)` \|")
    finding_ids = ids_in(os.path.join(source, "docs", "findings.md"), r"^### ([A-Z][0-9]+[a-z]?)\. ")
    if len(scenes) < 10 or len(finding_ids) < 20:
        print(f"report_text: README.md gives {len(scenes)} scenes and docs/findings.md {len(finding_ids)} finding "
              "ids: their tables or headings are not where this test reads them", file=sys.stderr)
        return 1

    with tempfile.TemporaryDirectory(prefix="report_text.") as tmp:
        out = os.path.join(tmp, "out")
        shutil.copytree(os.path.join(source, "expected"), out)
        run = subprocess.run([sys.executable, report, out], capture_output=True, text=True)
        if run.returncode != 0:
            print(f"report_text: {report} {out} exited {run.returncode}:\n{run.stderr}", file=sys.stderr)
            return 1
        pdf = os.path.join(out, "report.pdf")
        fonts = subprocess.run(["pdffonts", pdf], check=True, capture_output=True, text=True).stdout
        whole = pdf_text(pdf)
        first = pdf_text(pdf, "-f", "1", "-l", "1")

    failures = []
    type3 = [line.split()[0] for line in fonts.splitlines()[2:] if "Type 3" in line]
    if type3:
        failures.append(f"Type 3 fonts, whose glyphs beyond Latin-1 are pictures, not text: {', '.join(type3)}")
    for greek in ("θ", "α"):
        if greek not in whole:
            failures.append(f"'{greek}' is not in the report's text")
    for s in scenes:
        if not has_word(first, s):
            failures.append(f"scene '{s}' is not on the first page")
    for i in finding_ids:
        if not has_word(first, i):
            failures.append(f"finding '{i}' is not on the first page")
    words = len(first.split())
    if words < MIN_WORDS:
        failures.append(f"the first page holds {words} words, fewer than {MIN_WORDS}")

    for f in failures:
        print(f"report_text: FAIL: {f}", file=sys.stderr)
    print(f"report_text: {len(scenes)} scenes, {len(finding_ids)} finding ids, {words} words on the first page, "
          f"{whole.count('θ')} θ and {whole.count('α')} α in the text: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
