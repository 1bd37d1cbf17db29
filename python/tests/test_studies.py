"""spectrum, fragility and eq27 against `rocking spectrum`, `fragility` and `eq27`, on synthetic
records written by `rocking record synth` (no shared records needed) and on a shared record."""
import numpy as np
import pytest

import rocking_q as rq
from conftest import NORCIA, assert_columns, assert_same, cli


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory):
    """Three synthetic records as files (t, a in m/s^2) and as the module's Records read from them."""
    folder = tmp_path_factory.mktemp("synthetic")
    paths = []
    for name, words in [("pulse", ["--pulse", "0.6,0.8,0.4,2.2"]), ("noise", ["--stochastic", 3]),
                        ("pulse2", ["--pulse", "-0.4,1.5,1.2,1.6,2"])]:
        path = folder / (name + ".txt")
        cli("record", "synth", *words, "--dt", 0.01, "--duration", 12, "--output", path)
        paths.append(str(path))
    return paths


def without(result, *keys):
    return {k: v for k, v in result.items() if k not in keys}


def check_spectrum(got, expected):
    assert_same(without(got, "spectra"), without(expected, "spectra"))
    assert len(got.spectra) == len(expected["spectra"])
    for k, (g, e) in enumerate(zip(got.spectra, expected["spectra"])):
        assert_same(without(g, "points"), without(e, "points"), "spectra[%d]" % k)
        assert_columns(g.points, e["points"], "spectra[%d].points" % k)


def test_spectrum_is_rocking_spectrum(synthetic):
    path = synthetic[0]
    expected = cli("spectrum", path, "--alpha", "0.1,0.15", "--points", 30, "--p-min", 1, "--p-max", 10,
                   "--unit", "m/s2")
    record = rq.read_record(path, unit="m/s2")
    for jobs in (1, 2):
        check_spectrum(rq.spectrum(record, alpha=[0.1, 0.15], points=30, p_min=1, p_max=10, jobs=jobs), expected)
    assert any(s["intervals"] for s in expected["spectra"])  # the test sees intervals, not only empty lists


def test_spectrum_on_a_shared_record(records):
    path = str(records / NORCIA)
    expected = cli("spectrum", path, "--alpha", 0.15, "--points", 40, "--p-min", 1, "--p-max", 4)
    check_spectrum(rq.spectrum(path, alpha=0.15, points=40, p_min=1, p_max=4), expected)


def check_fragility(got, expected):
    assert_same(without(got, "blocks"), without(expected, "blocks"))
    for k, (g, e) in enumerate(zip(got.blocks, expected["blocks"])):
        assert_same(without(g, "empirical", "stripes"), without(e, "empirical", "stripes"), "blocks[%d]" % k)
        assert_columns(g.empirical, e["empirical"], "blocks[%d].empirical" % k)
        assert ("stripes" in g) == ("stripes" in e), "blocks[%d]: stripes in one only" % k
        if "stripes" in e:
            assert_columns(g.stripes, e["stripes"], "blocks[%d].stripes" % k)
    assert len(got.blocks) == len(expected["blocks"])


def test_fragility_is_rocking_fragility(synthetic):
    expected = cli("fragility", *synthetic, "--alpha", "0.1,0.15", "--p", "2,4", "--points", 20, "--q-max", 8,
                   "--bootstrap", 50, "--seed", 3, "--unit", "m/s2")
    records = [rq.read_record(p, unit="m/s2") for p in synthetic]
    for jobs in (1, 2):
        got = rq.fragility(records, alpha=[0.1, 0.15], p=[2, 4], points=20, q_max=8, bootstrap=50, seed=3, jobs=jobs)
        check_fragility(got, expected)
    assert any(b["fit"] and b["fit"]["bootstrap"] for b in expected["blocks"])
    # Without a bootstrap: fit.bootstrap is None, as the JSON's null.
    expected = cli("fragility", *synthetic[:2], "--alpha", 0.15, "--p", 3, "--points", 15, "--unit", "m/s2")
    check_fragility(rq.fragility(records[:2], alpha=0.15, p=3, points=15), expected)


def test_eq27_is_rocking_eq27(synthetic):
    words = ["--alpha", "0.1,0.2", "--p-min", 1, "--p-max", 4, "--p-points", 2, "--q-max", 8, "--unit", "m/s2"]
    records = [rq.read_record(p, unit="m/s2") for p in synthetic]
    kwargs = dict(alpha=[0.1, 0.2], p_min=1, p_max=4, p_points=2, q_max=8)
    expected = cli("eq27", *synthetic, *words, "--bootstrap", 30, "--seed", 2)
    got = rq.eq27(records, bootstrap=30, seed=2, jobs=2, **kwargs)
    assert_same(got, expected)
    assert len(got.case_points["q"]) == expected["cases"]
    expected = cli("eq27", *synthetic, *words)
    assert_same(rq.eq27(records, jobs=1, **kwargs), expected)
    assert expected["bootstrap"] is None


def test_the_engineers_blocks_and_restitution_are_the_command_lines(synthetic):
    # Issue 40: blocks as built (fragility's block, spectrum's mark) and restitution on
    # every study, as the command line's --block, --mark and --restitution.
    records = [rq.read_record(p, unit="m/s2") for p in synthetic]
    expected = cli("fragility", *synthetic[:2], "--block", "0.6x4,0.45x3", "--restitution", 0.7, "--points", 15,
                   "--unit", "m/s2")
    got = rq.fragility(records[:2], block="0.6x4,0.45x3", restitution=0.7, points=15)
    check_fragility(got, expected)
    assert [b.built for b in got.blocks] == ["0.6x4", "0.45x3"] and "restitution 0.7" in got.model
    expected = cli("spectrum", synthetic[0], "--mark", "0.6x4", "--alpha", 0.1, "--points", 30, "--p-min", 1,
                   "--p-max", 10, "--restitution", 0.5, "--unit", "m/s2")
    got = rq.spectrum(records[0], mark="0.6x4", alpha=0.1, points=30, p_min=1, p_max=10, restitution=0.5)
    check_spectrum(got, expected)
    assert [m.built for m in got.marks] == ["0.6x4"] and len(got.spectra) == 2
    words = ["--alpha", 0.1, "--p-min", 2, "--p-max", 2, "--p-points", 1, "--q-max", 8, "--restitution", "0.8",
             "--unit", "m/s2"]
    assert_same(rq.eq27(records, alpha=0.1, p_min=2, p_max=2, p_points=1, q_max=8, restitution=0.8),
                cli("eq27", *synthetic, *words))
    with pytest.raises(ValueError, match="block gives each block's alpha and p"):
        rq.fragility(records[:2], block="0.6x4", alpha=0.1)


def test_floor_is_the_command_lines(records):
    # floor="T1,G" as --floor T1,G (issue 40): the floor's record in place of the ground's.
    path = str(records / NORCIA)
    block = ["--thickness", 0.25, "--height", 2, "--floor", "0.5,1.5"]
    assert_same(rq.simulate(record=path, thickness=0.25, height=2, floor="0.5,1.5", dt=None),
                cli("simulate", "--record", path, *block))
    assert_same(rq.assess(path, thickness=0.25, height=2, floor="0.5,1.5"), cli("assess", path, *block))
    check_spectrum(rq.spectrum(path, alpha=0.12, points=30, floor="0.5,1.5"),
                   cli("spectrum", path, "--alpha", 0.12, "--points", 30, "--floor", "0.5,1.5"))
    with pytest.raises(ValueError, match="^floor: floor model '0.5'"):
        rq.assess(path, thickness=0.25, height=2, floor="0.5")


def test_a_study_takes_records_made_from_arrays(synthetic):
    # The same samples as an array give the same study; only the record's name and file differ.
    from_file = rq.read_record(synthetic[1], unit="m/s2")
    from_array = rq.Record(np.array(from_file.accel), from_file.dt, name="noise")
    a = rq.spectrum(from_file, alpha=0.12, points=25, p_min=1, p_max=8)
    b = rq.spectrum(from_array, alpha=0.12, points=25, p_min=1, p_max=8)
    assert b.file == "noise" and b.name == "noise"
    assert a.spectra[0].points.max_theta.tolist() == b.spectra[0].points.max_theta.tolist()
    assert [dict(i, lower=dict(i["lower"] or {}), upper=dict(i["upper"] or {})) for i in a.spectra[0].intervals] == \
        [dict(i, lower=dict(i["lower"] or {}), upper=dict(i["upper"] or {})) for i in b.spectra[0].intervals]


def test_fragility_refine_is_rocking_fragility_refine(tmp_path):
    """method="refine" (issue 39): every field of `rocking fragility --method refine --json`, the
    first overturning, its bracket and check, the first robust collapse, the bands and the counts."""
    path = tmp_path / "s3.txt"
    cli("record", "synth", "--stochastic", 3, "--dt", 0.01, "--duration", 20, "--output", path)
    expected = cli("fragility", path, "--unit", "m/s2", "--alpha", 0.1, "--p", "2,3", "--q-max", 2, "--points", 20,
                   "--method", "refine", "--width", 1e-3, "--robust-width", 1e-2)
    record = rq.read_record(str(path), unit="m/s2")
    for jobs in (1, 2):
        got = rq.fragility([record], alpha=0.1, p=[2, 3], q_max=2, points=20, method="refine", width=1e-3,
                           robust_width=1e-2, jobs=jobs)
        check_fragility(got, expected)
    first = expected["blocks"][1]["records"][0]
    assert first["first_overturning"]["q"] < first["first_robust_collapse"]["q"]  # an island below the robust collapse
    # The capacity three ways (issue 39, item 3): each block's fits by name and its stripes.
    for block in expected["blocks"]:
        assert sorted(block["fits"]) == ["first_overturning", "first_robust_collapse", "stripes"]
        assert len(block["stripes"]) == 19
    assert expected["grid"]["stripe_half_width"] > 0
    assert expected["grid"]["method"] == "refine"
    with pytest.raises(ValueError, match="^width goes with method='refine'"):
        rq.fragility([record], alpha=0.1, p=2, width=1e-3)
    with pytest.raises(ValueError, match=r"^method: grid or refine \(got 'dense'\)"):
        rq.fragility([record], alpha=0.1, p=2, method="dense")
    with pytest.raises(ValueError, match=r"^width: must be in \[1e-7, 0.1\]"):
        rq.fragility([record], alpha=0.1, p=2, method="refine", width=1.0)


def test_spectrum_refine_is_rocking_spectrum_refine(tmp_path):
    """method="refine" (issue 39): every field of `rocking spectrum --method refine --json`, the first
    overturning and its boundary, the first robust collapse, the bands and the counts."""
    path = tmp_path / "s3.txt"
    cli("record", "synth", "--stochastic", 3, "--dt", 0.01, "--duration", 20, "--output", path)
    expected = cli("spectrum", path, "--unit", "m/s2", "--alpha", "0.1,0.15", "--p-min", 1, "--p-max", 6, "--points", 20,
                   "--method", "refine", "--width", 1e-3, "--robust-width", 1e-2)
    record = rq.read_record(str(path), unit="m/s2")
    for jobs in (1, 2):
        got = rq.spectrum(record, alpha=[0.1, 0.15], p_min=1, p_max=6, points=20, method="refine", width=1e-3,
                          robust_width=1e-2, jobs=jobs)
        check_spectrum(got, expected)
    s = expected["spectra"][0]
    assert s["first_overturning"]["p"] < s["table1"]["p"]  # islands below Table 1's p
    assert expected["method"] == "refine" and len(s["bands"]) == 19
    with pytest.raises(ValueError, match="^width goes with method='refine'"):
        rq.spectrum(record, alpha=0.1, width=1e-3)
    with pytest.raises(ValueError, match=r"^method: grid or refine \(got 'dense'\)"):
        rq.spectrum(record, alpha=0.1, method="dense")
    with pytest.raises(ValueError, match=r"^robust_width: must be in \[1e-7, 1\] \(in ln p\)"):
        rq.spectrum(record, alpha=0.1, method="refine", robust_width=2.0)


def test_eq27_refine_is_rocking_eq27_refine(synthetic):
    """method="refine" (issue 39): every field of `rocking eq27 --method refine --json`, the shares
    under the first overturning and, in first_robust_collapse, under the first robust collapse."""
    words = ["--alpha", "0.1,0.2", "--p-min", 1, "--p-max", 4, "--p-points", 2, "--q-max", 8, "--unit", "m/s2",
             "--method", "refine", "--width", 1e-3, "--robust-width", 1e-2]
    records = [rq.read_record(p, unit="m/s2") for p in synthetic]
    kwargs = dict(alpha=[0.1, 0.2], p_min=1, p_max=4, p_points=2, q_max=8, method="refine", width=1e-3,
                  robust_width=1e-2)
    expected = cli("eq27", *synthetic, *words, "--bootstrap", 30, "--seed", 2)
    for jobs in (1, 2):
        got = rq.eq27(records, bootstrap=30, seed=2, jobs=jobs, **kwargs)
        assert_same(got, expected)
    assert expected["capacity"] == "first_overturning" and expected["robust_width"] == 0.01
    robust = got.first_robust_collapse
    assert len(robust.case_points["q"]) == expected["cases"]
    # Case by case the first overturning is at or below the robust collapse, and below it somewhere.
    first_q, robust_q = got.case_points["q"], robust.case_points["q"]
    assert all(f <= r for f, r in zip(first_q, robust_q)) and any(f < r for f, r in zip(first_q, robust_q))
    # The grid method's result has no capacities, as the command's.
    plain = rq.eq27(records, jobs=1, **dict(kwargs, method="grid", width=None, robust_width=None))
    assert "first_robust_collapse" not in plain and "capacity" not in plain
    with pytest.raises(ValueError, match="^width goes with method='refine'"):
        rq.eq27(records, width=1e-3)
    with pytest.raises(ValueError, match=r"^method: grid or refine \(got 'dense'\)"):
        rq.eq27(records, method="dense")
    with pytest.raises(ValueError, match=r"^robust_width: must be in \[1e-7, 1\]"):
        rq.eq27(records, method="refine", robust_width=2.0)


def test_study_arguments_are_checked():
    r = rq.record_synth(pulse=(0.6, 0.8, 0.4, 2.2), dt=0.01, duration=12)
    with pytest.raises(ValueError, match=r"^alpha: each must be in \(0, pi/4\)"):
        rq.spectrum(r, alpha=[0.1, 0.9])
    with pytest.raises(ValueError, match="^p_max: must be above p_min"):
        rq.spectrum(r, alpha=0.1, p_min=5, p_max=2)
    with pytest.raises(ValueError, match=r"^mark 0.6x400: its p, 0.191801 rad/s \(H 400 m\), lies outside the spectrum's p range \[0.3, 30\] rad/s \(p_min, p_max\)$"):
        rq.spectrum(r, mark="0.6x400")
    with pytest.raises(ValueError, match="^bootstrap needs seed"):
        rq.fragility([r], alpha=0.1, p=2, bootstrap=10)
    with pytest.raises(ValueError, match="^seed goes with bootstrap"):
        rq.eq27([r], seed=3)
    with pytest.raises(ValueError, match="^jobs: must be between 1 and 4096"):
        rq.fragility([r], alpha=0.1, p=2, jobs=0)
    with pytest.raises(TypeError, match="^records: expected a list of records"):
        rq.fragility(r, alpha=0.1, p=2)


def test_friction_puts_the_studies_on_the_sliding_model(tmp_path):
    # friction=MU as --friction MU (issue 41): the same intervals, fit and
    # first overturning as the command line's, and its refusals.
    r = rq.record_synth(stochastic=3, dt=0.01, duration=15)
    path = tmp_path / "s.txt"
    np.savetxt(path, np.asarray(r.accel), fmt="%.17g")  # one column, m/s^2, read back bit for bit
    s = rq.spectrum(r, alpha=0.1, points=30, p_min=1, p_max=10, friction=0.4)
    c = cli("spectrum", path, "--unit", "m/s2", "--dt", r.dt, "--alpha", 0.1, "--points", 30, "--p-min", 1,
            "--p-max", 10, "--friction", 0.4)
    assert "Coulomb friction mu = 0.4" in s["model"] and s["model"] == c["model"]
    assert [(i["from"], i["to"]) for i in s["spectra"][0]["intervals"]] == \
        [(i["from"], i["to"]) for i in c["spectra"][0]["intervals"]]
    a = rq.assess(r, alpha=0.1, p=6.5, friction=0.4, width=0.01)
    assert a["records"][0]["first_overturning"]["found"] and "mu = 0.4" in a["model"]
    with pytest.raises(ValueError, match="^restitution: does not apply with friction"):
        rq.spectrum(r, alpha=0.1, friction=0.4, restitution=0.9)
    with pytest.raises(ValueError, match=r"^friction: the friction coefficient must be in \(0, 1e6\] \(got 0\)"):
        rq.fragility([r], alpha=0.1, p=2, friction=0)


def test_imperfect_blocks_start_where_they_stand_and_lift(tmp_path):
    # imperfection={...} as the command line's flags (issue 41): a spectrum with
    # fc and no p_min starts where collapse's scan starts (the blocks that stand);
    # a leaning block's IDA starts where it lifts, (alpha - lean)/alpha, as
    # rocking fragility's per-block q_start; both equal to the command line's.
    r = rq.record_synth(stochastic=3, dt=0.01, duration=15)
    path = tmp_path / "s.txt"
    np.savetxt(path, np.asarray(r.accel), fmt="%.17g")
    s = rq.spectrum(r, alpha=0.1, points=4, imperfection={"fc": 1})
    c = cli("spectrum", path, "--unit", "m/s2", "--dt", r.dt, "--alpha", 0.1, "--points", 4, "--fc", 1)
    first = cli("collapse", path, "--unit", "m/s2", "--dt", r.dt, "--alpha", 0.1, "--fc", 1)
    assert s["grid"]["p_min"] == c["grid"]["p_min"] == first["p"] > 0.3
    f = rq.fragility([r], alpha=0.15, p=3, points=15, imperfection={"lean": 0.05})
    c = cli("fragility", path, "--unit", "m/s2", "--dt", r.dt, "--alpha", 0.15, "--p", 3, "--points", 15, "--lean", 0.05)
    assert f["blocks"][0]["q_start"] == c["blocks"][0]["q_start"]
    assert abs(f["blocks"][0]["q_start"] - 0.1 / 0.15) < 1e-15
    with pytest.raises(ValueError, match="crushes its base"):
        rq.spectrum(r, alpha=0.1, points=4, p_min=0.3, imperfection={"fc": 1})
