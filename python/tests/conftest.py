"""Shared pieces of the rocking_q tests: the command line beside the module, the
shared records, and the comparison of a result with the command's --json.

The command line writes every number of --json with %.17g, which reads back as the
same double: a result must equal it exactly, not within a tolerance.
ctest sets ROCKING_CLI (the build's rocking), ROCKING_SOURCE_DIR and PYTHONPATH;
ROCKING_RECORDS moves the shared records (default: ../shared/records beside the
source tree).
"""
import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

SOURCE = Path(os.environ.get("ROCKING_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("ROCKING_CLI", str(SOURCE / "build" / "rocking"))
RECORDS = Path(os.environ.get("ROCKING_RECORDS", SOURCE.parent / "shared" / "records"))

NORCIA = "esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC"


def _reject(constant):
    raise ValueError("bare " + constant + " in --json")


def cli(*args, files=()):
    """The command's --json, parsed strictly (no NaN or Infinity); fails on a refusal."""
    words = [CLI] + [str(a) for a in args] + ["--json"]
    done = subprocess.run(words, capture_output=True)
    assert done.returncode == 0, "%s exited %d: %s" % (" ".join(words), done.returncode, done.stderr.decode())
    return json.loads(done.stdout, parse_constant=_reject)


def cli_or_refusal(*args):
    """(the --json, None) when the command answers, (None, its message) when it refuses the input (exit 1)."""
    words = [CLI] + [str(a) for a in args] + ["--json"]
    done = subprocess.run(words, capture_output=True)
    if done.returncode == 0:
        return json.loads(done.stdout, parse_constant=_reject), None
    assert done.returncode == 1, "%s exited %d: %s" % (" ".join(words), done.returncode, done.stderr.decode())
    line = done.stderr.decode().splitlines()[0]
    return None, line[len("rocking %s: " % args[0]):]


def cli_error(*args):
    """The command's one-line message of a refusal, without its 'rocking SUBCOMMAND: ' prefix, and its exit code."""
    done = subprocess.run([CLI] + [str(a) for a in args], capture_output=True)
    assert done.returncode in (1, 2), "expected a refusal, got exit %d" % done.returncode
    line = done.stderr.decode().splitlines()[0]
    prefix = "rocking %s: " % args[0]
    assert line.startswith(prefix), line
    return line[len(prefix):], done.returncode


def records_dir():
    """The shared records, or a skip that says where they were looked for."""
    if not (RECORDS / "esm").is_dir():
        pytest.skip("needs the shared records: %s not found (set ROCKING_RECORDS)" % RECORDS)
    return RECORDS


@pytest.fixture
def records():
    return records_dir()


def _as_list(value):
    return value.tolist() if isinstance(value, np.ndarray) else value


def assert_same(actual, expected, where="result"):
    """actual (the module's) equals expected (the --json) in every field the JSON has:
    numbers exactly, booleans as booleans, null as None, lists as lists or arrays."""
    if isinstance(expected, dict):
        assert isinstance(actual, dict), "%s: %r is not a dict" % (where, type(actual))
        missing = sorted(set(expected) - set(actual))
        assert not missing, "%s lacks the JSON's fields %s" % (where, missing)
        for key, value in expected.items():
            assert_same(actual[key], value, "%s[%r]" % (where, key))
    elif isinstance(expected, list):
        actual = _as_list(actual)
        assert isinstance(actual, (list, tuple)), "%s: %r is not a list or an array" % (where, type(actual))
        assert len(actual) == len(expected), "%s: %d items, the JSON has %d" % (where, len(actual), len(expected))
        for k, (a, e) in enumerate(zip(actual, expected)):
            assert_same(a, e, "%s[%d]" % (where, k))
    elif expected is None:
        assert actual is None, "%s: %r where the JSON has null" % (where, actual)
    elif isinstance(expected, bool):
        assert isinstance(actual, (bool, np.bool_)) and bool(actual) == expected, \
            "%s: %r, the JSON has %r" % (where, actual, expected)
    elif isinstance(expected, (int, float)):
        # %.17g writes 2.0 as "2", which JSON reads as an int: the value, not its type, is compared.
        assert isinstance(actual, (int, float, np.integer, np.floating)) and not isinstance(actual, (bool, np.bool_)), \
            "%s: %r is not a number" % (where, actual)
        assert actual == expected, "%s: %r, the JSON has %r (difference %g)" % (
            where, actual, expected, float(actual) - float(expected))
    else:
        assert actual == expected, "%s: %r, the JSON has %r" % (where, actual, expected)


def columns(points):
    """A JSON list of objects as one list per field (the module gives arrays per field); null as NaN."""
    out = {}
    for point in points:
        for key, value in point.items():
            out.setdefault(key, []).append(math.nan if value is None else value)
    return out


def assert_columns(actual, points, where):
    """The module's arrays per field against the JSON's list of objects, exactly (NaN where null)."""
    expected = columns(points)
    for key, values in expected.items():
        got = _as_list(actual[key])
        assert len(got) == len(values), "%s[%r]: %d values, the JSON has %d" % (where, key, len(got), len(values))
        for k, (a, e) in enumerate(zip(got, values)):
            same = (a == e) or (isinstance(e, float) and math.isnan(e) and isinstance(a, float) and math.isnan(a))
            assert same, "%s[%r][%d]: %r, the JSON has %r" % (where, key, k, a, e)


def read_csv(path):
    """A CSV the command line wrote: its '#' notes and its columns (numbers as floats where they parse)."""
    notes, header, rows = {}, None, []
    for line in Path(path).read_text().splitlines():
        if line.startswith("# "):
            key, _, value = line[2:].partition(": ")
            notes[key] = value
        elif header is None:
            header = line.split(",")
        else:
            rows.append(line.split(","))
    def cell(text):
        try:
            return float(text)
        except ValueError:
            return text
    return notes, {name: [cell(r[k]) for r in rows] for k, name in enumerate(header)}
