"""The kinds of finding, and the checks that keep each entry of tools/findings_*.py honest about its kind.

A verdict word means one thing.  "fails" alone would mix a misprint, a claim that does not hold
where the paper makes it, and a claim pushed beyond where the paper makes it; a reviewer can sign
only the first two as errors of the paper.  So every entry has a KIND, and its verdict label (read
from the data) must be one of that kind's labels.  The kinds, in the order the document, the
report and the README list them (the paper's errors first, then what the model shows beyond it):

    erratum      a printed formula or number is wrong
    fails        a claim fails inside the paper's stated scope
    partial      a claim holds only in part of its scope
    unverified   possibly not the paper's (the extracted text, not the typeset paper)
    beyond       a claim tested beyond the paper's scope: a finding about the model
    caveat       on something the paper does not claim
    holds        the claim, or the printed formula, holds

Every entry also states its SCOPE: what it was tested on, and for the kinds whose meaning
depends on it (fails, partial, beyond, caveat) what the paper itself states or claims.

Standard library only; tools/findings.py imports it, tests/findings_kinds_test.py mutates entries
to show that each check fails when it should.
"""
import math
import re


class Kind:
    def __init__(self, key, heading, labels, meaning, gloss="", qualifier=None, paper_scope=False):
        self.key = key
        self.heading = heading          # the group's heading in the document, the report and the README
        self.labels = labels            # the verdict labels of this kind (a regular expression, whole match)
        self.meaning = meaning          # the definition the document gives once, at the top
        self.gloss = gloss              # said beside the verdict of every entry of this kind
        self.qualifier = qualifier      # a clause using "fail" must carry this phrase (None: no rule)
        self.paper_scope = paper_scope  # the scope must say what the paper states ("the paper")

    def fits(self, label):
        return re.fullmatch(self.labels, label) is not None


KINDS = [
    Kind("erratum", "Errata", r"erratum( \(.+\))?",
         "**erratum**: a printed formula or number is wrong: the paper's own definitions, evaluated here, give "
         "another, and the entry gives the corrected form."),
    Kind("fails", "Claims that fail in the paper's scope", r"fails in scope",
         "**fails in scope**: a claim of the paper does not hold inside the range, the criterion and the kind of "
         "input the paper states for it (the entry's scope says which).", paper_scope=True),
    Kind("partial", "Claims that hold only in part of their scope", r"holds only (for|with|above|below) .+",
         "**holds only for ...**: a claim holds on part of the range the paper states or implies and not on the "
         "rest; the label says where it holds.", paper_scope=True),
    Kind("unverified", "Unverified", r"unverified( \(.+\))?",
         "**unverified**: the text extracted from the PDF disagrees with the engine, but the typeset paper has not "
         "been checked: a suspected extraction artefact, not an erratum, until it is; the entry says what would "
         "settle it.",
         gloss="possibly not the paper's: see what would settle it"),
    Kind("beyond", "Beyond the paper's scope", r"(fails|holds) beyond the paper's (range|criterion|records|model)",
         "**fails beyond the paper's range / criterion / records / model**: a claim tested on a range, a collapse "
         "criterion, records and scalings, or a model (a sliding base) the paper does not use, and found not to hold "
         "there: a finding about the model the paper proposes, not an error of the paper.",
         gloss="a finding about the model, not an error of the paper", qualifier="beyond the paper's",
         paper_scope=True),
    Kind("caveat", "Caveats", r"caveat: .+",
         "**caveat: ...**: a property a reader might assume and the paper does not claim (the label names it); not "
         "an error of the paper.",
         gloss="the paper does not claim it; not an error of the paper", qualifier="not claimed by the paper",
         paper_scope=True),
    Kind("holds", "Claims that hold", r"holds( \(.+\))?",
         "**holds**: the claim, or the printed formula, holds on the scope tested, which covers the paper's; a "
         "bracket adds what the measurement found (e.g. \"never binds\")."),
]
BY_KEY = {k.key: k for k in KINDS}

# A match between a printed formula and the engine is a difference below this (errata.csv's
# threshold); what is left is rounding noise, which differs from build to build.  Its size is set
# by the cancellation in the quantity, not by the value one build happens to give: a difference
# that is exactly 0 in expected/ (eq. 20) is 3.5e-14 on the build that wrote this module, so no
# bound is stated below 1e-13.
MATCH = 1e-9
NOISE_FLOOR = -13


def bound_exponent(v):
    """n of the bound 1e-n for rounding noise v: the power of ten at least sqrt(10) |v|, and at least 1e-13."""
    v = abs(float(v))
    if not v < MATCH:
        raise ValueError(f"{v!r} is not rounding noise (a match is below {MATCH:g})")
    n = NOISE_FLOOR
    while 10.0 ** n < v * math.sqrt(10):
        n += 1
    return -n


def bound(v):
    """Rounding noise as a bound that another build's rounding keeps: "below 1e-13" for E1's 3.109e-15
    here and 2.818e-15 elsewhere alike."""
    return f"below 1e-{bound_exponent(v)}"


def bound_problems(expected_rows, fresh_rows):
    """Where a fresh run's rounding noise breaks the bound the document states from expected/: the rows
    of errata.csv (dicts) that match in both, by equation."""
    fresh = {r["equation"]: r for r in fresh_rows}
    out = []
    for r in expected_rows:
        f = fresh.get(r["equation"])
        if f is None:
            out.append(f"{r['equation']}: not in the fresh run")
        elif f["verdict"] != r["verdict"]:
            out.append(f"{r['equation']}: {r['verdict']} in expected/, {f['verdict']} in the fresh run")
        elif r["verdict"] == "matches":
            n = bound_exponent(r["largest_difference"])
            if not abs(float(f["largest_difference"])) < 10.0 ** -n:
                out.append(f"{r['equation']}: the document says {bound(r['largest_difference'])}, the fresh run gives "
                           f"{f['largest_difference']}")
    return out


_FAIL = re.compile(r"\bfail(s|ed|ing|ure|ures)?\b", re.I)
_CLAUSE = re.compile(r"(?<=[.;])\s+")


def unqualified_fails(text, qualifier):
    """The clauses of text that use the word "fail" without the qualifier."""
    return [c for c in _CLAUSE.split(text) if _FAIL.search(c) and qualifier.lower() not in c.lower()]


def curated_texts(e):
    """What an entry says in its own words (the printed quote is the paper's and is left out)."""
    out = [("title", e.title), ("label", e.stands), ("scope", e.scope or ""), ("measured", e.measured)]
    if getattr(e, "label", None) is not None:
        out.append(("verdict label", e.label))
        out.append(("verdict", e.verdict))
    out += [("note", n) for n in list(e.notes) + list(getattr(e, "extra_notes", []))]
    if e.settle:
        out.append(("what would settle it", e.settle))
    return out


def entry_problems(e):
    """Why an entry cannot be signed as it stands: no kind, no scope, a label outside its kind, an
    unqualified "fail" in a caveat or a finding beyond the paper's scope."""
    out = []
    kind = BY_KEY.get(e.kind)
    if kind is None:
        return [f"{e.id}: kind {e.kind!r} is not one of {', '.join(k.key for k in KINDS)}"]
    if not (e.scope or "").strip():
        out.append(f"{e.id}: no scope (what it was tested on)")
    elif kind.paper_scope and "the paper" not in e.scope:
        out.append(f"{e.id}: its scope must say what the paper states or claims (a {kind.key} is judged against it)")
    if not kind.fits(e.stands):
        out.append(f"{e.id}: the verdict '{e.stands}' is not a label of kind {kind.key} ({kind.labels})")
    if kind.key == "unverified" and not (e.settle or "").strip():
        out.append(f"{e.id}: an unverified finding must say what would settle it")
    if kind.qualifier:
        for where, text in curated_texts(e):
            for c in unqualified_fails(text, kind.qualifier):
                out.append(f"{e.id}: its {where} says \"fail\" without \"{kind.qualifier}\" (a {kind.key} is not an "
                           f"error of the paper): \"{c.strip()}\"")
    return out


def grouped(entries):
    """[(kind, entries of that kind)] in KINDS order, kinds without entries left out."""
    return [(k, [e for e in entries if e.kind == k.key]) for k in KINDS if any(e.kind == k.key for e in entries)]


# Residuals quoted in digits (3.109e-15): rounding noise stated as if it were a result.
_DIGITS = re.compile(r"(?<![\w.])(\d\.\d+|[2-9])e-(\d+)\b")


def noise_in_digits(text):
    return [m.group(0) for m in _DIGITS.finditer(text) if float(m.group(0)) < MATCH]


# ---------------------------------------------------------------------------------------
# The README's summary, "## What the paper gets wrong": bold kind headings, each followed by
# the ids of its findings as links into docs/findings.md.

README_SECTION = "## What the paper gets wrong"
_HEADING = re.compile(r"^\*\*([^*]+)\*\*")
_LINK = re.compile(r"\[([A-Z][0-9][0-9a-z]*)\]\(docs/findings\.md#([a-z0-9]+)\)")


def readme_groups(text):
    """[(heading, [ids])] of the README's summary, in its order; raises ValueError when it is missing."""
    lines = text.splitlines()
    try:
        start = lines.index(README_SECTION)
    except ValueError:
        raise ValueError(f"no line '{README_SECTION}'") from None
    groups, current = [], None
    for i, line in enumerate(lines[start + 1:], start + 2):
        if line.startswith("## "):
            break
        m = _HEADING.match(line)
        if m:
            current = (m.group(1), [], i)
            groups.append(current)
        for link in _LINK.finditer(line):
            if link.group(2) != link.group(1).lower():
                raise ValueError(f"line {i}: [{link.group(1)}] links to #{link.group(2)}")
            if current is None:
                raise ValueError(f"line {i}: {link.group(1)} comes before any kind heading")
            current[1].append(link.group(1))
    return [(h, ids) for h, ids, _ in groups]


def readme_problems(entries, text):
    """Where the README's summary does not list the same ids under the same kinds, in the same order."""
    try:
        groups = readme_groups(text)
    except ValueError as x:
        return [f"README: {x}"]
    want = [(k.heading, [e.id for e in es]) for k, es in grouped(entries)]
    out = []
    headings = {k.heading for k in KINDS}
    for h, _ in groups:
        if h not in headings:
            out.append(f"README: '**{h}**' is not a kind heading ({'; '.join(k.heading for k in KINDS)})")
    have = [(h, ids) for h, ids in groups if h in headings]
    if [h for h, _ in have] != [h for h, _ in want]:
        out.append(f"README: kind headings {[h for h, _ in have]}, the document's {[h for h, _ in want]}")
    have_d, want_d = dict(have), dict(want)
    for h, ids in want:
        got = have_d.get(h, [])
        missing = [i for i in ids if i not in got]
        extra = [i for i in got if i not in ids]
        twice = sorted({i for i in got if got.count(i) > 1})
        if missing:
            out.append(f"README: under '{h}' it lacks {', '.join(missing)}")
        if extra:
            out.append(f"README: under '{h}' it lists {', '.join(extra)}, which the document puts elsewhere")
        if twice:
            out.append(f"README: under '{h}' it lists {', '.join(twice)} twice")
    for h, got in have:
        if h not in want_d and got:
            out.append(f"README: under '{h}' it lists {', '.join(got)}, a kind the document has no entries of")
    return out
