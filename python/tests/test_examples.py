"""The examples run headless and give the numbers they should: Figure 4 as expected/fig04
(within its TOLERANCES), the wall check as `rocking assess` and `rocking simulate`."""
import importlib.util
import os
import subprocess
import sys

import pytest

from conftest import NORCIA, SOURCE, assert_same, cli, read_csv

EXAMPLES = SOURCE / "examples"


def load(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / (name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def tolerances(folder):
    """expected/<scene>/TOLERANCES: (file, column) -> 'exact' or (abs, rel)."""
    rules = {}
    for line in (folder / "TOLERANCES").read_text().splitlines():
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        rules[(words[0], words[1])] = "exact" if words[2] == "exact" else (float(words[2]), float(words[3]))
    return rules


def within(rule, got, expected):
    if rule == "exact":
        return str(got) == str(expected) or float(got) == float(expected)
    absolute, relative = rule
    return abs(got - expected) <= absolute + relative * abs(expected)


def run(script, *args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("DISPLAY", None)
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], cwd=cwd, env=env,
                          capture_output=True, text=True)
    assert done.returncode == 0, "%s exited %d: %s" % (script, done.returncode, done.stderr)
    return done


def assert_png(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20000, "%s is not a drawn PNG" % path


def test_figure4_is_the_fig04_scene(tmp_path):
    figure4 = load("figure4")
    folder = SOURCE / "expected" / "fig04"
    rules = tolerances(folder)
    _, expected = read_csv(folder / "fig04.csv")
    table = figure4.curves()
    compared = 0
    for column, values in expected.items():
        rule = rules.get(("fig04.csv", column), rules[("fig04.csv", "*")])
        got = table[column].tolist()
        assert len(got) == len(values)
        for k, (g, e) in enumerate(zip(got, values)):
            assert within(rule, g, e), "fig04.csv %s line %d: %r, expected %r (%s)" % (column, k + 6, g, e, rule)
            compared += 1
    assert compared == 196 * 8
    _, points = read_csv(folder / "fig04_points.csv")
    got = figure4.marked_points()
    assert [p[0] for p in got] == points["point"]
    for (name, x, q), xe, qe in zip(got, points["x"], points["q"]):
        assert within(rules[("fig04_points.csv", "*")], x, xe), (name, x, xe)
        assert within(rules[("fig04_points.csv", "*")], q, qe), (name, q, qe)
    # And as a user runs it: headless, a PNG and the crossing printed.
    done = run("figure4.py", "--out", tmp_path, cwd=tmp_path)
    assert_png(tmp_path / "figure4.png")
    assert "q2 = q4 (minimum changes from case 4 to case 2)" in done.stdout and "x = 0.5097911466811" in done.stdout


def test_check_wall_is_assess_and_simulate(records, tmp_path):
    path = str(records / NORCIA)
    check_wall = load("check_wall")
    record, verdict, motion = check_wall.check(path, 3, thickness=0.45)
    assert_same(verdict, cli("assess", path, "--thickness", 0.45, "--height", 3))
    out = tmp_path / "theta.csv"
    expected = cli("simulate", "--record", path, "--thickness", 0.45, "--height", 3, "--output", out, "--dt", 0.01)
    assert_same(motion, expected)
    assert motion.theta_over_alpha.tolist() == read_csv(out)[1]["theta_over_alpha"]
    done = run("check_wall.py", path, "--thickness", 0.45, "--height", 3, "--png", tmp_path / "wall.png", cwd=tmp_path)
    assert_png(tmp_path / "wall.png")
    lines = done.stdout.splitlines()
    r = verdict.records[0]
    assert lines[0] == "IT.NRC HGE 20160824_013632: eq. 27 check FAILS (ratio %.4f, margin %+.1f %%)" % (
        r.ratio, 100 * r.margin)
    assert r.ratio == r.q_record / r.q_eq27
    assert lines[4].startswith("  the record scaled by x") and "%d impacts" % expected["impacts"] in lines[5]