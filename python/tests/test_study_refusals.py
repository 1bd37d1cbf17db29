"""What the command line refuses before a study (issue 38), refused by the module too, in the
keywords' names: an alpha, a p or a record given twice (its cases counted twice); eq27's
p_points=1 with a range (cut to its start); a run the solvers cannot follow (p times the
record's duration above 1e9, which reached the user as the solver's "no progress"); and a
batch's output that is one of its inputs (the manifest or a record, replaced by the results)."""
import os
import re

import numpy as np
import pytest

import rocking_q as rq
from conftest import assert_same, cli, cli_error

WAVE = np.sin(np.arange(400) * 0.07) * 0.3
R = rq.Record(WAVE, 0.01, unit="g", name="wave")


@pytest.fixture
def wave_files(tmp_path):
    """The wave as a plain-text file in g, and the same file by a second path (a hard link)."""
    path = tmp_path / "wave.txt"
    path.write_text("".join("%.17g\n" % v for v in R.in_g()))
    again = tmp_path / "again.txt"
    os.link(path, again)
    return str(path), str(again)


def as_keyword(message):
    """The command line's refusal in the module's words: "--p-points 1: ... --p-min P alone" is
    "p_points=1: ... p_min=P alone"."""
    return re.sub(r"--([a-z]+(?:-[a-z]+)*)( (?=\d|P\b))?",
                  lambda m: m.group(1).replace("-", "_") + ("=" if m.group(2) else ""), message)


# ---- A value or a record given twice: refused, in the command line's words ----

def test_an_alpha_given_twice_is_refused_by_every_study(wave_files):
    path, _ = wave_files
    plain = ["--unit", "g", "--dt", 0.01]
    message, code = cli_error("eq27", path, *plain, "--alpha", "0.1,0.2,0.10", "--p-points", 1, "--p-min", 2)
    assert code == 2 and message.startswith("--alpha: 0.1 is given twice (values 1 and 3)")
    for call in (lambda: rq.eq27([R], alpha=[0.1, 0.2, 0.10], p_points=1, p_min=2),
                 lambda: rq.fragility([R], alpha=[0.1, 0.2, 0.10], p=2),
                 lambda: rq.spectrum(R, alpha=[0.1, 0.2, 0.10])):
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value) == as_keyword(message)


def test_a_p_given_twice_is_refused_by_fragility(wave_files):
    path, _ = wave_files
    message, code = cli_error("fragility", path, "--unit", "g", "--dt", 0.01, "--alpha", 0.1, "--p", "2,3,2.0")
    assert code == 2 and message.startswith("--p: 2 is given twice (values 1 and 3)")
    with pytest.raises(ValueError) as e:
        rq.fragility([R], alpha=0.1, p=np.array([2, 3, 2.0]))
    assert str(e.value) == as_keyword(message)


def test_a_record_given_twice_is_refused_whatever_its_path_or_form(wave_files):
    # One file by two paths, or a file and an array with its samples and step: each would
    # count its cases twice (0/4 read as 0/8).
    path, again = wave_files
    a, b = (rq.read_record(f, unit="g", dt=0.01) for f in (path, again))
    copy = rq.Record(np.array(a.accel), a.dt, name="copy")
    half = rq.Record(WAVE * 0.5, 0.01, unit="g", name="half")
    for records, first, second, k in [([a, b], path, again, "1 and 2"), ([a, half, copy], path, "copy", "1 and 3"),
                                      ([half, a, half], "half", "half", "1 and 3")]:
        expected = ("^%s: the same record as %s \\(records %s: the same step and samples\\), whose cases would count "
                    "twice: give each record once$" % (second, first, k))
        with pytest.raises(ValueError, match=expected):
            rq.eq27(records, alpha=0.1, p_points=1, p_min=2, q_max=2)
        with pytest.raises(ValueError, match=expected):
            rq.fragility(records, alpha=0.1, p=2, q_max=2, points=2)


def test_records_that_differ_in_their_step_are_two_records():
    # The same samples at another step are another record: not refused.
    other = rq.Record(WAVE, 0.02, unit="g", name="slow")
    r = rq.fragility([R, other], alpha=0.1, p=2, q_max=2, points=2)
    assert [row["file"] for row in r.blocks[0]["records"]] == ["wave", "slow"]


# ---- eq27's p grid: one p is one p ----

def test_eq27_one_p_with_a_range_is_refused_as_the_command_line_refuses(wave_files):
    path, _ = wave_files
    plain = ["--unit", "g", "--dt", 0.01, "--alpha", 0.1]
    for words, kwargs in [(["--p-points", 1, "--p-min", 1, "--p-max", 4], dict(p_points=1, p_min=1, p_max=4)),
                          (["--p-points", 1], dict(p_points=1)),  # the default range, 0.5 to 10
                          (["--p-points", 1000, "--p-min", 1, "--p-max", 1.0000000000001],
                           dict(p_points=1000, p_min=1, p_max=1.0000000000001)),
                          (["--p-points", 3, "--p-min", 2, "--p-max", 2], dict(p_points=3, p_min=2, p_max=2)),
                          (["--p-min", 5, "--p-max", 2], dict(p_min=5, p_max=2))]:
        message, code = cli_error("eq27", path, *plain, *words)
        assert code == 2
        with pytest.raises(ValueError) as e:
            rq.eq27([R], alpha=0.1, **kwargs)
        assert str(e.value) == as_keyword(message), words
    assert as_keyword(cli_error("eq27", path, *plain, "--p-points", 1, "--p-min", 1, "--p-max", 4)[0]) == (
        "p_points=1: one p, but the range runs from 1 to 4 rad/s: give the p as p_min=P alone, or more points")


def test_eq27_one_p_is_p_min_alone_or_with_the_same_p_max(wave_files):
    path, _ = wave_files
    expected = cli("eq27", path, "--unit", "g", "--dt", 0.01, "--alpha", 0.1, "--p-points", 1, "--p-min", 2,
                   "--q-max", 3)
    record = rq.read_record(path, unit="g", dt=0.01)
    for kwargs in (dict(p_min=2), dict(p_min=2, p_max=2)):
        got = rq.eq27([record], alpha=0.1, p_points=1, q_max=3, **kwargs)
        assert got.blocks == "alpha 0.1; p: 1 log-spaced from 2 to 2 rad/s"
        assert [c["p"] for c in got.map] == [2.0]
        assert_same(got, expected)


# ---- A run the solvers cannot follow: refused by its argument, not the solver's "no progress" ----

LONG = rq.Record(WAVE, 1e6, unit="g", name="slow wave")  # 399e6 s: p t above 1e9 from p = 2.6 rad/s
WHY = r": p t = [^ ]+ \(p = [^ ]+ rad/s over [^ ]+ s\) exceeds 1e\+09: the solvers cannot follow so long a run"


@pytest.mark.parametrize("call,given", [
    (lambda: rq.spectrum(LONG, alpha=0.1, points=2), "p_max with record slow wave"),
    (lambda: rq.fragility([LONG], alpha=0.1, p=[2, 3], points=2), "p with record slow wave"),
    (lambda: rq.collapse(LONG, alpha=0.1), "record slow wave"),
    (lambda: rq.simulate(alpha=0.1, p=3, record=LONG), "p, record slow wave"),
    (lambda: rq.simulate(alpha=0.1, height=1, record=LONG), "height, record slow wave"),
    (lambda: rq.simulate(alpha=0.1, p=2, case=2, to=1e12, pga=0.5), "p, to"),
    (lambda: rq.simulate(alpha=0.1, p=2, case=2, x=3e12, pga=0.5), "p, x"),
])
def test_a_run_too_long_for_the_solvers_is_refused_naming_its_arguments(call, given):
    with pytest.raises(ValueError, match="^" + given + WHY):
        call()


def test_eq27_refuses_a_run_too_long_before_the_half_periods():
    # A step the half-periods' CWT takes (2 s), over 1.2e6 s: p_max 1000 rad/s gives p t = 1.2e9.
    long = rq.Record(np.resize(WAVE, 600001), 2.0, unit="g", name="long wave")
    with pytest.raises(ValueError, match="^p_max with record long wave" + WHY):
        rq.eq27([long], alpha=0.1, p_points=1, p_min=1000, p_max=1000)


# ---- rq.batch: an output that is an input, refused before any job ----

@pytest.fixture
def manifest(tmp_path):
    (tmp_path / "r.txt").write_text("0.1\n0.2\n-0.1\n0.05\n0\n")
    (tmp_path / "o.csv.partial").write_text("0.1\n0.3\n-0.1\n0\n")
    m = tmp_path / "m.csv"
    m.write_text("id,kind,record,unit,record_dt,alpha\na,collapse,r.txt,g,0.01,0.1\n"
                 "b,collapse,o.csv.partial,g,0.01,0.1\n")
    return m


def test_a_batch_output_that_is_an_input_is_refused_and_the_input_kept(manifest, tmp_path):
    # The manifest, a record by its path or another spelling, a record where the results'
    # partial file would be written: each was replaced by the results.
    (tmp_path / "sub").mkdir()
    files = lambda: {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
    kept = files()
    for output, role, input_ in [(manifest, "output", "the manifest"),
                                 (tmp_path / "r.txt", "output", "the record of manifest line 2"),
                                 (tmp_path / "sub" / ".." / "r.txt", "output", "the record of manifest line 2"),
                                 (tmp_path / "o.csv", "output's partial file", "the record of manifest line 3")]:
        with pytest.raises(ValueError, match="^%s '[^']*' is the input %s '[^']*': writing it would replace the "
                                             "input; choose another file$" % (role, input_)):
            rq.batch(str(manifest), output=str(output))
        assert files() == kept, output


def test_a_batch_output_that_cannot_be_written_is_refused_before_any_job(manifest, tmp_path):
    with pytest.raises(RuntimeError, match="^output: %s: cannot create a file in %s" %
                       (tmp_path / "none" / "o.csv", tmp_path / "none")):
        rq.batch(str(manifest), output=str(tmp_path / "none" / "o.csv"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.csv", "o.csv.partial", "r.txt"]
