"""The machinery every entry of the findings is written with: reading the expected CSV files,
printing their numbers, and the @entry decorator that records a finding.

    Data             the expected CSV files (expected/<scene>/*.csv), read on demand; it
                     remembers which rows the entries used, so that tools/findings.py can fail
                     on a row of a claims/summary file that no entry covers
    g, pct, code     a number or a name as the document prints it
    ev               one piece of evidence: output file, row, column, value
    Entry, entry     a finding: its curated part (the decorator's arguments) and its live
                     part (the decorated function of the data); entries_of(module) gives a
                     module's entries in the order it defines them

The entries themselves are in tools/findings_<section>.py, one module per section or group
of sections of the document; tools/findings.py assembles them, in its MODULES order, into
docs/findings.md and the report's findings pages.  Standard library only.
"""
import csv
import os


class FindingsError(Exception):
    pass


# ---------------------------------------------------------------------------------------
# Reading the expected CSV files.

class Data:
    """The expected CSV files, read on demand; remembers which rows the entries used."""

    def __init__(self, expected):
        self.root = expected
        self.tables = {}
        self.used = {}

    def table(self, name):
        """(header, rows as dicts) of expected/<name>, e.g. 'errata/errata.csv'."""
        if name not in self.tables:
            path = os.path.join(self.root, name)
            if not os.path.exists(path):
                raise FindingsError(f"{path}: missing (an entry reads it)")
            with open(path, newline="") as f:
                lines = [l for l in f if not l.startswith("#") and l.strip()]
            rows = list(csv.reader(lines))
            header = rows[0]
            self.tables[name] = (header, [dict(zip(header, r)) for r in rows[1:]])
            self.used[name] = set()
        return self.tables[name]

    def rows(self, name, /, **match):
        """Every row whose columns equal `match` (all rows without it); marks them used."""
        header, rows = self.table(name)
        for k in match:
            if k not in header:
                raise FindingsError(f"expected/{name}: no column '{k}' (columns: {', '.join(header)})")
        out = []
        for i, r in enumerate(rows):
            if all(r[k] == str(v) for k, v in match.items()):
                out.append(r)
                self.used[name].add(i)
        return out

    def rows_where(self, name, pred):
        """Every row for which pred(row) holds; marks them used."""
        _, rows = self.table(name)
        out = []
        for i, r in enumerate(rows):
            if pred(r):
                out.append(r)
                self.used[name].add(i)
        return out

    def row(self, name, /, **match):
        found = self.rows(name, **match)
        if len(found) != 1:
            what = ", ".join(f"{k} = '{v}'" for k, v in match.items())
            raise FindingsError(f"expected/{name}: {len(found)} rows with {what}, the entry needs exactly one")
        return found[0]

    def value(self, name, column, /, **match):
        r = self.row(name, **match)
        if column not in r:
            raise FindingsError(f"expected/{name}: no column '{column}'")
        return r[column]


def num(s):
    return float(s)


def g(v, n=4):
    """A number as the document prints it: n significant digits, no trailing noise."""
    try:
        v = float(v)
    except (TypeError, ValueError):
        return str(v)
    if v == 0:
        return "0"
    if abs(v) >= 1e-3 and abs(v) < 1e5:
        s = f"{v:.{n}g}"
    else:
        s = f"{v:.{max(n - 1, 1)}e}"
        m, e = s.split("e")
        s = f"{m}e{int(e)}"
    return s


def pct(v, n=3):
    return f"{g(100 * float(v), n)} %"


def code(s):
    return f"`{s}`"


def ev(name, what, column, value):
    """One piece of evidence: output file, row, column, value and its expected copy."""
    return (f"`out/{name}`, {what}, column `{column}` = {value} "
            f"(expected copy `expected/{name}`)")


# ---------------------------------------------------------------------------------------
# The entries.  Each is a function of the data returning the live part (verdict label,
# verdict sentence with its numbers, evidence); the curated part is in the decorator.
# `stands` is the verdict label the curated wording assumes: when the data give another,
# the entry is flagged and --check fails.

class Entry:
    def __init__(self, id, section, title, where, printed, measured, tests, command, stands, scenes,
                 build, kind=None, scope=None, settle=None, notes=()):
        self.id, self.section, self.title, self.where = id, section, title, where
        self.printed, self.measured, self.tests, self.command = printed, measured, list(tests), command
        self.stands, self.scenes, self.build_fn, self.notes = stands, list(scenes), build, list(notes)
        self.kind, self.scope, self.settle = kind, scope, settle
        self.module = build.__module__      # where the entry is written: tools/<module>.py

    def build(self, data):
        live = self.build_fn(data)
        self.label = live["label"]
        v = live["verdict"]
        # The sentence follows the label: drop a repeated "label: " at its start.
        for lead in (self.label + ": ", self.label.split(" (")[0] + ": "):
            if v.startswith(lead):
                v = v[len(lead):]
                break
        # Capitalised unless it opens with a symbol (q2, to, x): "q2 = q4 at ..." stays.
        first = v.split(" ", 1)[0]
        symbol = any(ch.isdigit() for ch in first) or first in ("to", "x", "p", "q")
        self.verdict = v if symbol else v[0].upper() + v[1:]
        self.evidence = live["evidence"]
        self.extra_notes = live.get("notes", [])
        self.flag = None
        if self.label != self.stands:
            self.flag = (f"the curated wording of {self.id} assumes the verdict '{self.stands}', but the expected "
                         f"files now give '{self.label}': review the entry in tools/{self.module}.py")
        return self

    @property
    def anchor(self):
        return self.id.lower()


# Each entry module's entries, in the order the module defines them: the document's order is
# then the order of tools/findings.py's MODULES, whatever order the modules are imported in.
_BY_MODULE = {}


def entry(**kw):
    def wrap(fn):
        _BY_MODULE.setdefault(fn.__module__, []).append(Entry(build=fn, **kw))
        return fn
    return wrap


def entries_of(module):
    """The entries defined in `module`, in the order it defines them."""
    return list(_BY_MODULE.get(module.__name__, []))
