#!/usr/bin/python3
"""What is wrong in the paper, and how do we know: one source for docs/findings.md and
the report's findings pages.

Every printed formula and every tested claim of the paper is one entry, in the module of
its section (MODULES below): the claim as printed and where, its kind and the scope it was
tested on, what the harness measures, the test that pins it, the command that shows it, and
which CSV file, row and column hold the verdict.  The verdicts and numbers are not written
in the entries: they are read from the expected outputs (expected/<scene>/*.csv) each
time, so the document cannot drift from them.  The two findings that only `make bench`
measures (its output is not kept in expected/) are stated with the date and file they come
from (docs/performance.md).

    tools/findings.py --markdown > docs/findings.md     write the document
    tools/findings.py --check docs/findings.md          exit 1 when it is out of date
    tools/findings.py --kinds README.md                 exit 1 when an entry's kind or scope does not
                                                        fit, or README's summary groups it otherwise
    tools/findings.py --rounding OUT                    exit 1 when a fresh run's rounding noise
                                                        (OUT/errata/errata.csv) breaks a stated bound

--check also fails when an entry's curated wording no longer fits the data (a verdict
flipped in an expected CSV), when a row of a claims/summary CSV is in no entry, when an
entry names a test that does not exist, and on every --kinds fault of an entry.
--expected DIR reads another copy of expected/ (to show that the check fails on an altered
verdict).  tools/report.py imports this module and renders the same entries.  Standard
library only.

The modules, in the document's order (tools/findings_base.py holds what they share: the
expected files' reader, the number formats, ev() and @entry):

    tools/findings_errata.py     errata            E1-E4, the printed formulas of Sections 2-3
    tools/findings_fig47.py      fig47             C1-C8, claims about Figures 4 and 7
    tools/findings_fig05_08.py   fig05 fig06 fig08 F5a-F8, Figures 5, 6 and 8
    tools/findings_tables.py     table1 table2     T1a-T2b, Tables 1 and 2
    tools/findings_fig11_12.py   fig11 fig12       F11-F12, Figures 11 and 12 and the fragility
    tools/findings_imperfection.py imperfection    I1-I2, imperfect blocks (issue 41)
    tools/findings_sliding.py    sliding           S1-S3, the claims on a base with Coulomb friction

Adding a finding (issue 39's first overturning, the sliding work): write one function
of the data under @entry(...) in the module of its section, next to the entries of the
same figure or table (a new section: a row of SECTIONS and a module in MODULES), with

    id, section       "F13", a key of SECTIONS (where it sits in the document's body)
    title, where      the finding in a line; the equation, figure or section it is about
    printed           the paper's words, quoted from ../shared/paper/ (the claim as printed)
    kind              one of tools/findings_kinds.py's KINDS: "erratum", "fails" (in the
                      paper's scope), "partial", "unverified", "beyond" (the paper's range,
                      criterion or records), "caveat" (not claimed by the paper), "holds"
    scope             what it was tested on; for fails, partial, beyond and caveat also what
                      the paper states or claims ("x = 0.05..3.00, beyond the paper's stated
                      range x = 0.2..0.8"), since that is what the kind is judged against
    stands            the verdict label the wording assumes, one of the kind's labels
                      ("fails beyond the paper's range", "caveat: not a bound", "holds")
    settle            (unverified only) what would settle it
    measured, tests, command, scenes, notes

The function returns dict(label=..., verdict=..., evidence=[...]): the label computed from
the data in the kind's vocabulary (so that a flipped verdict flags the entry), the
sentence with its numbers, and ev(...) pointers to the CSV cells; a new claims or summary
CSV file goes under the module's COVERED, so that a row no entry reads fails the check.
State rounding noise with bound(), never in digits.  In a beyond or caveat entry the word
"fail" needs the kind's qualifier in the same clause ("... fails beyond the paper's range");
prefer "is non-conservative", "collapses".  Then add the id under its kind's heading in README.md's
"What the paper gets wrong", regenerate docs/findings.md, and run ctest -R findings.
"""
import argparse
import difflib
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from findings_base import Data, FindingsError, entries_of  # noqa: E402
from findings_kinds import (KINDS, bound_problems, entry_problems, grouped, noise_in_digits,  # noqa: E402
                            readme_problems)
import findings_errata  # noqa: E402
import findings_fig47  # noqa: E402
import findings_fig05_08  # noqa: E402
import findings_tables  # noqa: E402
import findings_fig11_12  # noqa: E402
import findings_imperfection  # noqa: E402
import findings_sliding  # noqa: E402
from findings_errata import E  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = "docs/findings.md"

# The entry modules in the document's order: the entries follow it, and within a module the
# order in which it defines them.
MODULES = [findings_errata, findings_fig47, findings_fig05_08, findings_tables, findings_fig11_12,
           findings_imperfection, findings_sliding]
ENTRIES = [e for m in MODULES for e in entries_of(m)]

# The document's body: a section per key (an entry's `section`), in this order, with its title
# and the sentence that opens it.
SECTIONS = [
    ("errata", "The printed formulas of Sections 2-3",
     "Every printed formula of Sections 2-3, evaluated as printed against the superposition engine "
     "(the exact solution of the linearised equation for piecewise-constant pulses) on x = p·to = "
     "0.05..2.00; a formula matches when the largest difference is below 1e-9."),
    ("fig47", "Claims about Figures 4 and 7 and the closed forms",
     "Measured on the closed forms and the engine (`expected/errata/claims.csv`)."),
    ("fig05", "Figure 5: is the closed form conservative below its PGA?",
     "Step inputs scaled to PGA = q_i α g Rd with Rd < 1, integrated with impacts (restitution 1) by the "
     "exact event-driven solver; collapse under three criteria."),
    ("fig06", "Figure 6: the full equation against the linearised one", ""),
    ("fig08", "Figure 8: eq. 27 against the one-sine overturning threshold", ""),
    ("table1", "Table 1", ""),
    ("table2", "Table 2", ""),
    ("fig11", "Figure 11", ""),
    ("fig12", "Figure 12", ""),
    ("imperfection", "Imperfect blocks (issue 41)",
     "The model's limit the paper names (\"neglects [...] geometric or material imperfections\"), tested: blocks "
     "that lean, stand out of plumb or pivot on corners set back by the masonry's finite strength "
     "(`dynamics/imperfect_block.hpp`, scene `imperfection`)."),
    ("sliding", "Sliding: the paper's claims on a base with Coulomb friction",
     "The paper's block rocks on a corner that never slips (its conclusion: it \"neglects base sliding\"). Scene "
     "`sliding` (issue 41, docs/sliding.md) puts the block on Coulomb friction μ = 0.8, 0.6, 0.4, with the full "
     "equations and impacts that may slip, and retests the one claim the paper makes about sliding and two claims "
     "it makes for its model."),
]

# Findings of docs/ and the PROVENANCE files that are about the harness, not the paper.
NOT_HERE = [
    "The solvers and the speed-accuracy trade (docs/solvers.md, docs/performance.md, "
    "`make bench`, `out/bench/summary.txt`): the exact solver against Dormand-Prince, the record kernel, why three "
    "ODE solvers step from sample to sample, and that the truth on a record can be out of reach of any "
    "double-precision solver.",
    "Hidden excursions and absurd inputs (docs/solvers.md, \"Hidden excursions\", \"Absurd and extreme inputs\", 2026-11-21): faults "
    "of the harness, found and fixed; no expected output changed.",
    "The history of Table 1's search on the records here (`expected/table1/PROVENANCE.md`): the record kernel's "
    "uplift fix, and the one value the move to the kernel changed (IT.AQK HNE, α = 0.05, p 1.0606 → 1.0464 "
    "rad/s); `expected/fig11/PROVENANCE.md` and `expected/fig12/PROVENANCE.md` record that no verdict moved with it.",
    "Eight values of Figure 8's full-equation threshold with Housner's restitution corrected on 2026-11-21 "
    "(`expected/fig08/PROVENANCE.md`, `Dynamics.ABlockPastTheTopWhenTheInputEndsFalls`): an engine bug, not a "
    "finding about the paper; F8's verdict holds in every variant.",
]


# ---------------------------------------------------------------------------------------
# Tests named by the entries must exist.

def known_tests():
    names = set()
    tests_dir = os.path.join(ROOT, "tests")
    for fn in sorted(os.listdir(tests_dir)):
        if fn.endswith(".cpp"):
            with open(os.path.join(tests_dir, fn)) as f:
                for m in re.finditer(r"^TEST(?:_F|_P)?\((\w+),\s*(\w+)\)", f.read(), re.M):
                    names.add(f"{m.group(1)}.{m.group(2)}")
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        cm = f.read()
    for m in re.finditer(r"foreach\(scene ([^)]*)\)(.*?)endforeach\(\)", cm, re.S):
        scenes = m.group(1).split()
        for t in re.finditer(r"add_test\(NAME (\w+)\$\{scene\}", m.group(2)):
            names.update(t.group(1) + s for s in scenes)
    names.update(re.findall(r"add_test\(NAME (\w+)\s", cm))
    return names


# ---------------------------------------------------------------------------------------

def build(expected=None):
    """The entries with their live verdicts; raises FindingsError on a structural problem."""
    data = Data(expected or os.path.join(ROOT, "expected"))
    problems = []
    entries = []
    for e in ENTRIES:
        try:
            entries.append(e.build(data))
        except (FindingsError, KeyError, ValueError, StopIteration, AttributeError) as x:
            problems.append(f"{e.id} ({e.title}): cannot read its evidence: {x!r}")
    # Every row of the files a module lists in COVERED must be in some entry: a new claim in a
    # scene's output with no entry fails the check.
    for m in MODULES:
        for name in m.COVERED:
            try:
                header, rows = data.table(name)
            except FindingsError as x:
                problems.append(str(x))
                continue
            exempt = getattr(m, "COVERED_EXEMPT", {}).get(name, set())
            for i, r in enumerate(rows):
                if i not in data.used[name] and r[header[0]] not in exempt:
                    problems.append(f"expected/{name}: row '{', '.join(list(r.values())[:2])}' is in no entry of "
                                    f"tools/{m.__name__}.py: add it to an entry")
    tests = known_tests()
    for e in ENTRIES:
        for t in e.tests:
            if t not in tests:
                problems.append(f"{e.id}: names the test '{t}', which is neither a GoogleTest in tests/*.cpp nor a "
                                f"ctest in CMakeLists.txt")
    for e in ENTRIES:
        problems += entry_problems(e)
    ids = [e.id for e in ENTRIES]
    problems += [f"{i}: two entries have this id" for i in sorted({i for i in ids if ids.count(i) > 1})]
    return entries, problems


def label_of(e):
    return e.label if not e.flag else f"{e.label} (REVIEW)"


def gloss_of(e):
    """What the entry's kind says beside its verdict ("a finding about the model, not an error of the paper")."""
    kind = next((k for k in KINDS if k.key == e.kind), None)
    return kind.gloss if kind else ""


def verdict_of(e):
    """The verdict with its gloss: "fails beyond the paper's range (a finding about the model, not an error of
    the paper)"."""
    return label_of(e) + (f" ({gloss_of(e)})" if gloss_of(e) else "")


def text_problems(text):
    """What the generated text must not say: rounding noise in digits."""
    return [f"the document quotes rounding noise in digits, '{x}': state it as a bound (findings_kinds.bound)"
            for x in noise_in_digits(text)]


def markdown(entries):
    out = []
    w = out.append
    w("# What the paper gets wrong, and how we know")
    w("")
    w("This file answers one question about S. Coccia, *q-factor for slender masonry structures under "
      "out-of-plane seismic loading*, Buildings 2025, 15, 2622: what is wrong in the paper, and how do you know? "
      "Each printed formula and each claim of the paper that the harness tests is one entry: the claim as printed "
      "(quoted from the text extracted from the PDF, with the equation, figure or section), its kind and the scope "
      "it was tested on, what the harness measures, the verdict with the measured number, and the evidence: the "
      "output file, row and column that hold it (`make reproduce` writes `out/`; the expected copy is under "
      "`expected/`), the test that pins it and the command that shows it. The verdicts and numbers are read from "
      "`expected/` by `tools/findings.py`, which writes this file (`/usr/bin/python3 tools/findings.py --markdown > "
      "docs/findings.md`) and the findings pages of `make report`'s `out/report.pdf` from the same entries; "
      "ctest `findings_doc` fails when this file no longer matches them, and `findings_kinds` when an entry lacks "
      "a kind or a scope, or the README's summary groups the findings otherwise. Do not edit it by hand.")
    w("")
    w("## Verdicts")
    w("")
    w("Every finding has one of these kinds; its verdict is one of the kind's labels. Only the first four can be "
      "errors of the paper; the others are not, and say so beside their verdict.")
    w("")
    for k in KINDS:
        w(f"- {k.meaning}")
    w("")
    w("Where a printed formula matches the engine (a difference below 1e-9), the difference left is rounding noise, "
      "which varies from build to build (one that is 0 in `expected/` exceeds 1e-14 on another build): it is "
      "given as a bound, the power of ten at least √10 times the value in `expected/` and at least 1e-13 "
      "(\"below 1e-13\"), not as digits. ctest `findings_rounding` checks each bound against a fresh run.")
    w("")
    w("## Index, by kind")
    for k, group in grouped(entries):
        w("")
        w(f"### {k.heading}")
        w("")
        w("| # | finding | scope tested | verdict |")
        w("|---|---|---|---|")
        for e in group:
            cell = lambda t: t.replace("|", "\\|")    # |θ| would end the cell
            w(f"| [{e.id}](#{e.anchor}) | {cell(e.title)} | {cell(e.scope)} | {cell(label_of(e))} |")
    w("")
    for key, title, intro in SECTIONS:
        group = [e for e in entries if e.section == key]
        if not group:
            continue
        w(f"## {title}")
        w("")
        if intro:
            w(intro)
            w("")
        for e in group:
            w(f"<a id=\"{e.anchor}\"></a>")
            w(f"### {e.id}. {e.title}")
            w("")
            if e.flag:
                w(f"> **REVIEW**: {e.flag}.")
                w("")
            w(f"- **Printed**, {e.where}: {e.printed}")
            w(f"- **Scope**: {e.scope}.")
            w(f"- **Measured**: {e.measured}")
            w(f"- **Verdict: {label_of(e)}**" + (f" ({gloss_of(e)})" if gloss_of(e) else "") + f". {e.verdict}")
            if e.settle:
                w(f"- **What would settle it**: {e.settle}")
            w("- **Evidence**: " + "; ".join(e.evidence))
            tests = ", ".join(f"`{t}`" for t in e.tests) if e.tests else "none (see the notes)"
            w(f"- **Tests**: {tests}")
            w(f"- **Command**: `{e.command}`")
            for n in e.notes + e.extra_notes:
                w(f"- **Note**: {n}")
            w("")
    w("## Not in this file")
    w("")
    w("Findings of `docs/` and the `PROVENANCE.md` files that are about the harness rather than the paper:")
    w("")
    for n in NOT_HERE:
        w(f"- {n}")
    w("")
    return "\n".join(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    g_ = ap.add_mutually_exclusive_group(required=True)
    g_.add_argument("--markdown", action="store_true", help="write docs/findings.md to standard output")
    g_.add_argument("--check", metavar="DOC", help="exit 1 when DOC differs from what --markdown writes")
    g_.add_argument("--kinds", metavar="README", help="exit 1 unless every entry has a kind and a scope that fit it "
                    "and README's summary lists the same ids under the same kinds as the document")
    g_.add_argument("--rounding", metavar="OUT", help="exit 1 unless the rounding noise of a fresh run's "
                    "OUT/errata/errata.csv lies below the bounds the document states from expected/")
    ap.add_argument("--expected", metavar="DIR", help="read another copy of expected/ (default: the repository's)")
    a = ap.parse_args(argv)
    if a.rounding:
        try:
            rows = lambda root: Data(root).table(E)[1]
            problems = bound_problems(rows(a.expected or os.path.join(ROOT, "expected")), rows(a.rounding))
        except FindingsError as x:
            problems = [str(x)]
        for p in problems:
            print(f"findings: {p}", file=sys.stderr)
        if not problems:
            print(f"findings: every match of {os.path.join(a.rounding, E)} lies below the bound the document states")
        return 1 if problems else 0
    try:
        entries, problems = build(a.expected)
    except FindingsError as x:
        print(f"findings: {x}", file=sys.stderr)
        return 1
    flags = [e.flag for e in entries if e.flag]
    fresh = markdown(entries)
    problems += text_problems(fresh)
    if a.markdown:
        sys.stdout.write(fresh)
        for p in problems + flags:
            print(f"findings: {p}", file=sys.stderr)
        return 1 if problems else 0
    path = a.check or a.kinds
    try:
        with open(path, encoding="utf-8") as f:
            doc = f.read()
    except OSError as x:
        print(f"findings: {path}: {x.strerror}", file=sys.stderr)
        return 1
    if a.kinds:
        problems += readme_problems(entries, doc)
        for p in problems:
            print(f"findings: {p}", file=sys.stderr)
        if not problems:
            print(f"findings: {len(entries)} entries, each with a kind and a scope; {path} lists them under the "
                  f"same kinds (" + ", ".join(f"{k.key} {len(es)}" for k, es in grouped(entries)) + ")")
        return 1 if problems else 0
    bad = False
    for p in problems + flags:
        print(f"findings: {p}", file=sys.stderr)
        bad = True
    if doc != fresh:
        bad = True
        diff = list(difflib.unified_diff(doc.splitlines(), fresh.splitlines(), a.check,
                                         "tools/findings.py --markdown", lineterm="", n=0))
        print(f"findings: {a.check} is out of date with the expected files ({len(diff)} diff lines; "
              f"first ones below). Regenerate it:\n"
              f"    /usr/bin/python3 tools/findings.py --markdown > docs/findings.md", file=sys.stderr)
        for line in diff[:40]:
            print(line, file=sys.stderr)
    if not bad:
        print(f"findings: {a.check} is up to date ({len(entries)} entries, verdicts read from expected/)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())