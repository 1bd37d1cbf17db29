"""Records (read_record, Record, record_info, peak_motion, record_synth, record_floor), collapse and assess
against `rocking record info`, `record synth`, `record floor`, `collapse` and `assess`; record_floor also against
a second exact method in numpy."""
from pathlib import Path

import numpy as np
import pytest

import rocking_q as rq
from conftest import NORCIA, assert_same, cli, cli_error

SOME = [NORCIA, "esm/IT.AQK..HNN.D.20090406.013240.C.ACC.ASC", "esm/TV.MIR01..HNE.D.20120529.070002.C.ACC.ASC",
        "peer/RSN1158_KOCAELI_DZC180.AT2", "peer/RSN1158_KOCAELI_DZC270.AT2"]


@pytest.mark.parametrize("name", SOME)
def test_record_info_is_rocking_record_info(records, name):
    path = str(records / name)
    expected = cli("record", "info", path)
    got = rq.record_info(path)
    assert_same(got, expected)
    record = rq.read_record(path)
    assert_same(rq.record_info(record), expected)
    assert rq.half_periods(record).tolist() == expected["to"]
    assert record.samples == expected["samples"] == len(record) == len(record.accel)
    assert record.path == path and record.format == expected["format"] and record.name == expected["name"]


def esm_values(path):
    """The samples of an ESM file as written (cm/s^2): every line after the 'KEY: value' header."""
    return [float(line) for line in Path(path).read_text().splitlines() if line.strip() and ":" not in line]


def test_a_record_from_an_array_is_the_record_from_its_file(records):
    path = records / NORCIA
    from_file = rq.read_record(path)
    from_array = rq.Record(esm_values(path), 0.005, unit="cm/s2", name="Norcia")
    assert from_array.accel.tolist() == from_file.accel.tolist()  # bit for bit: the same x 0.01
    assert from_array.dt == from_file.dt and from_array.path is None and from_array.name == "Norcia"
    expected = {k: v.tolist() if isinstance(v, np.ndarray) else v
                for k, v in rq.record_info(from_file).items() if k not in ("file", "format", "name")}
    assert_same(rq.record_info(from_array), expected)
    # PEER: samples in g, four header lines.
    peer = records / "peer/RSN1158_KOCAELI_DZC270.AT2"
    values = [float(v) for line in peer.read_text().splitlines()[4:] for v in line.split()]
    assert rq.Record(values, 0.005, unit="g").accel.tolist() == rq.read_record(peer).accel.tolist()


def test_a_record_from_an_array_is_the_plain_text_file_of_its_numbers(tmp_path):
    rng = np.random.default_rng(7)
    values = rng.normal(0, 50, 3001)  # cm/s^2
    one = tmp_path / "one.txt"
    one.write_text("".join("%.17g\n" % v for v in values))
    two = tmp_path / "two.txt"
    two.write_text("".join("%.17g,%.17g\n" % (0.01 * k, v) for k, v in enumerate(values)))
    from_array = rq.Record(values, 0.01, unit="cm/s2", name=str(one))
    for path, words, kwargs in [(one, ["--unit", "cm/s2", "--dt", 0.01], dict(unit="cm/s2", dt=0.01)),
                                (two, ["--unit", "cm/s2"], dict(unit="cm/s2"))]:
        from_file = rq.read_record(path, **kwargs)
        assert from_file.accel.tolist() == from_array.accel.tolist()
        expected = cli("record", "info", path, *words)
        assert_same(rq.record_info(from_file), expected)
        numbers = {k: v for k, v in expected.items() if k not in ("file", "format", "name")}
        assert_same(rq.record_info(from_array), numbers)
    # The one-column file's dt is given; the two-column file's dt is its times' step, 0.01 - 0.
    assert rq.read_record(two, unit="cm/s2").dt == 0.01


def test_the_record_s_numbers_and_its_immutability():
    r = rq.Record([0.0, 1.0, -2.0, 0.5], 0.02, unit="g", name="four")
    assert r.accel.tolist() == [0.0, 9.81, -2 * 9.81, 0.5 * 9.81]
    assert r.pga_ms2 == 2 * 9.81 and r.pga_g == 2 * 9.81 / 9.81 and r.duration == 3 * 0.02
    assert r.in_g().tolist() == [v / 9.81 for v in r.accel.tolist()]
    with pytest.raises(ValueError):
        r.accel[0] = 1.0  # read-only: a study may be reading it in another thread
    view = r.accel
    del r
    assert view.tolist()[1] == 9.81  # the view keeps the record alive


def test_a_record_pickles_whole(records):
    import pickle
    for record in (rq.read_record(records / NORCIA), rq.Record([0.1, -0.2, 0.3, 0.05, -0.1], 0.01, unit="g", name="five"),
                   rq.record_synth(stochastic=4, dt=0.01, duration=5)):
        again = pickle.loads(pickle.dumps(record))
        assert again.accel.tolist() == record.accel.tolist() and again.dt == record.dt
        assert (again.path, again.format, again.name, again.header) == (record.path, record.format, record.name,
                                                                        record.header)
        assert_same(rq.record_info(again), {k: v.tolist() if isinstance(v, np.ndarray) else v
                                            for k, v in rq.record_info(record).items()})


def test_peak_motion_and_record_synth_are_rocking_record_synth(tmp_path):
    cases = [(["--pulse", "0.5,1,0.3,2.5"], dict(pulse=(0.5, 1, 0.3, 2.5))),
             (["--pulse", "-0.3,0.7,1,1.8,3"], dict(pulse=[-0.3, 0.7, 1, 1.8, 3])),
             (["--stochastic", 11], dict(stochastic=11)),
             (["--stochastic", 5, "--params", "Ia=0.3,D5_95=8,tmid=5,fmid=4"],
              dict(stochastic=5, params={"Ia": 0.3, "D5_95": 8, "tmid": 5, "fmid": 4}))]
    for words, kwargs in cases:
        out = tmp_path / "synth.txt"
        expected = cli("record", "synth", *words, "--dt", 0.01, "--duration", 20, "--output", out)
        got = rq.record_synth(dt=0.01, duration=20, **kwargs)
        assert got.name == expected["name"] and got.format == expected["format"]
        assert got.samples == expected["samples"] and got.dt == expected["dt"]
        assert got.accel.tolist() == rq.read_record(out, unit="m/s2").accel.tolist()
        m = rq.peak_motion(got)
        assert_same(m, {k: expected[k] for k in ("pga_ms2", "pgv_ms", "to5_s")})
        for key, value in expected["parameters"].items():
            assert got.header[key] == value or float(got.header[key]) == value, key


@pytest.mark.parametrize("options", [
    dict(),
    dict(restitution=0.9, criterion="final-rotation"),
    dict(criterion="peak-rotation", restitution=1.0),
])
def test_collapse_is_rocking_collapse(records, options):
    path = str(records / NORCIA)
    words = []
    for key, value in options.items():
        words += ["--" + key, value]
    expected = cli("collapse", path, "--alpha", 0.15, *words)
    assert_same(rq.collapse(path, alpha=0.15, **options), expected)


def test_collapse_below_the_range_or_never(tmp_path):
    # A strong constant-ish record overturns at the lowest p; a weak one never lifts the block.
    t = np.arange(0, 10, 0.01)
    strong = rq.Record(0.9 * np.sign(np.sin(0.3 * t + 0.1)), 0.01, unit="g", name="strong")
    weak = rq.Record(0.01 * np.sin(6 * t), 0.01, unit="g", name="weak")
    for record, found in [(strong, True), (weak, False)]:
        path = tmp_path / (record.name + ".txt")
        path.write_text("".join("%.17g\n" % v for v in record.in_g()))
        expected = cli("collapse", path, "--alpha", 0.15, "--unit", "g", "--dt", 0.01)
        got = rq.collapse(rq.read_record(path, unit="g", dt=0.01), alpha=0.15)
        assert_same(got, expected)
        assert got.found is found and (got.below_range is True) == found


@pytest.mark.parametrize("name", SOME)
def test_assess_is_rocking_assess(records, name):
    path = str(records / name)
    for alpha, geometry in [(0.15, ("height", 3)), (0.1, ("half_height", 0.8)), (0.25, ("height", 12))]:
        expected = cli("assess", path, "--alpha", alpha, "--" + geometry[0].replace("_", "-"), geometry[1])
        got = rq.assess(path, alpha=alpha, **{geometry[0]: geometry[1]})
        assert_same(got, expected)
        r = got.records[0]
        assert rq.q2_n6(r.x) == expected["records"][0]["q_eq27"]
        assert rq.peak_motion(path).to5_s == expected["records"][0]["to5"]
        assert r.ratio == r.q_record / r.q_eq27 and r.margin == 1 - r.ratio
    assert rq.assess(str(records / NORCIA), alpha=0.15, height=3).records[0].passes is False  # README: FAILS
    # Two records at once, and the block as built: the same per record, and the fragility over both.
    both = [str(records / NORCIA), path]
    expected = cli("assess", *both, "--thickness", 0.45, "--height", 3)
    got = rq.assess(both, thickness=0.45, height=3)
    assert_same(got, expected)
    assert len(got.records) == 2 and got.thickness == 0.45 and got.given == "dimensions"


def test_a_bad_record_names_its_file_and_line(tmp_path, records):
    # An ESM file whose NDATA disagrees with its samples: RecordError (a ValueError), the reader's message.
    lines = (records / NORCIA).read_text().splitlines()
    bad = tmp_path / "bad.asc"
    bad.write_text("\n".join(lines[:-3]) + "\n")
    message, code = cli_error("record", "info", bad)
    assert code == 1 and message.startswith(str(bad) + ":")
    for call in (lambda: rq.read_record(bad), lambda: rq.record_info(str(bad)), lambda: rq.collapse(bad, alpha=0.15)):
        with pytest.raises(rq.RecordError) as e:
            call()
        assert str(e.value) == message
        assert isinstance(e.value, ValueError)


def test_a_bad_plain_file_names_its_line(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("0.1\n0.2\nx\n0.3\n")
    message, _ = cli_error("record", "info", bad, "--unit", "g", "--dt", 0.01)
    with pytest.raises(rq.RecordError) as e:
        rq.read_record(bad, unit="g", dt=0.01)
    assert str(e.value) == message and (":3:" in message)
    with pytest.raises(ValueError, match="^unit is required"):
        rq.read_record(bad, dt=0.01)
    with pytest.raises(ValueError, match="^unit: 'furlong' is not a unit"):
        rq.read_record(bad, unit="furlong")
    missing = tmp_path / "missing.asc"
    message, _ = cli_error("record", "info", missing)
    with pytest.raises(rq.RecordError) as e:
        rq.read_record(missing)
    assert str(e.value) == message


# Every frequency of a generator at or above 1/(2 dt) (issue 38: fp = 100 Hz at dt = 0.02 s gave a
# PGA of 1e-14 m/s^2, fc = 1000 Hz one of 2e-16): refused by the library, so record_synth says what
# `record synth` says, naming the argument that set it; a default's names dt.
SAMPLING = [
    (["--pulse", "0.5,100,0,2"], dict(pulse=(0.5, 100, 0, 2)), 0.02, 5),          # the carrier
    (["--pulse", "0.5,40,0,4"], dict(pulse=(0.5, 40, 0, 4)), 0.01, 2),           # its sideband at 50 Hz
    (["--stochastic", 1, "--params", "fmid=50,fprime=0,zeta=0.8"],
     dict(stochastic=1, params={"fmid": 50, "fprime": 0, "zeta": 0.8}), 0.01, 20),
    (["--stochastic", 1, "--params", "fmid=30,fprime=1.3,zeta=0.8,tmid=4,D5_95=5"],
     dict(stochastic=1, params={"fmid": 30, "fprime": 1.3, "zeta": 0.8, "tmid": 4, "D5_95": 5}), 0.01, 20),
    (["--stochastic", 1, "--params", "fmid=45,fprime=0"], dict(stochastic=1, params={"fmid": 45, "fprime": 0}), 0.01, 20),
    (["--stochastic", 1, "--params", "fc=1000"], dict(stochastic=1, params={"fc": 1000}), 0.02, 5),
    (["--stochastic", 1, "--params", "Ia=0.5"], dict(stochastic=1, params={"Ia": 0.5}), 0.1, 30),  # a default's fmid
    (["--stochastic", 1, "--params", "tmid=1000"], dict(stochastic=1, params={"tmid": 1000}), 0.01, 20),
]


@pytest.mark.parametrize("words,kwargs,dt,duration", SAMPLING)
def test_record_synth_refuses_what_record_synth_refuses(words, kwargs, dt, duration):
    message, code = cli_error("record", "synth", *words, "--dt", dt, "--duration", duration)
    option = "--pulse" if "--pulse" in words else "--dt" if words[-1] == "Ia=0.5" else "--params"
    assert code == 2 and message.startswith(option + ": "), message
    with pytest.raises(ValueError) as raised:
        rq.record_synth(dt=dt, duration=duration, **kwargs)
    assert "--" + str(raised.value) == message


def test_record_synth_warns_below_ten_samples_per_period():
    # fp + fp/gamma = 10.1 Hz at dt = 0.01 s: 9.9 samples a period, kept and warned of, as the command warns.
    with pytest.warns(RuntimeWarning, match=r"^record_synth: fp \+ fp/gamma = 10\.1 Hz, .* has 9\.901 samples per "
                                            r"period at dt = 0\.01 s, fewer than 10"):
        r = rq.record_synth(pulse=(0.5, 8.08, 0, 4), dt=0.01, duration=2)
    expected = cli("record", "synth", "--pulse", "0.5,8.08,0,4", "--dt", 0.01, "--duration", 2)
    assert [r.header["warning"]] == expected["warnings"]
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fine = rq.record_synth(pulse=(0.5, 7.92, 0, 4), dt=0.01, duration=2)
    assert "warning" not in fine.header


def test_record_floor_is_rocking_record_floor(tmp_path):
    ground = tmp_path / "ground.txt"
    cli("record", "synth", "--stochastic", 7, "--dt", 0.01, "--duration", 30, "--output", ground)
    for words, kwargs in [(["--period", 0.5, "--participation", 1.5], dict(period=0.5, participation=1.5)),
                          (["--period", 1.2, "--participation", -0.4, "--damping", 0.02],
                           dict(period=1.2, participation=-0.4, damping=0.02))]:
        out = tmp_path / "floor.txt"
        expected = cli("record", "floor", ground, "--unit", "m/s2", *words, "--output", out)
        got = rq.record_floor(rq.read_record(ground, unit="m/s2"), **kwargs)
        assert got.accel.tolist() == rq.read_record(out, unit="m/s2").accel.tolist()
        assert (got.name, got.format, got.samples, got.dt) == tuple(expected[k] for k in ("name", "format", "samples", "dt"))
        assert got.pga_ms2 == expected["floor_pga_ms2"]
        assert float(got.header["end_amplitude_m_s2"]) == expected["end_amplitude_ms2"]
        assert {k: float(got.header[k]) for k in ("T1_s", "zeta", "G")} == expected["model"]
        assert got.header["method"] == expected["method"]


def exact_floor_by_expm(a_g, dt, period, participation, damping):
    """A second exact method, numpy only: the state (D, D') with the input f = -a_g and its slope over
    each step appended, z' = M z, M = [[F, b, 0], [0, 0, 1], [0, 0, 0]], stepped by expm(M dt) (Van Loan
    1978), the exponential by scaling and squaring a Taylor series; a_f = (1 - G) a_g - G (2 zeta w D' + w^2 D)."""
    w = 2 * np.pi / period
    M = np.zeros((4, 4))
    M[0, 1], M[1, 0], M[1, 1], M[1, 2], M[2, 3] = 1, -w * w, -2 * damping * w, 1, 1
    A = M * dt
    squarings = max(0, int(np.ceil(np.log2(max(np.abs(A).sum(axis=1).max(), 1e-300) / 0.25))))
    A = A / 2.0 ** squarings
    E, term = np.eye(4), np.eye(4)
    for k in range(1, 20):
        term = term @ A / k
        E = E + term
    for _ in range(squarings):
        E = E @ E
    f = -np.asarray(a_g)
    x, out = np.zeros(2), np.empty(len(f))
    for k in range(len(f)):
        out[k] = (1 - participation) * a_g[k] - participation * (2 * damping * w * x[1] + w * w * x[0])
        if k + 1 < len(f):
            x = E[:2, :2] @ x + E[:2, 2] * f[k] + E[:2, 3] * (f[k + 1] - f[k]) / dt
    return out


def test_record_floor_against_a_second_exact_method(records):
    # The same exact answer by another route: each method's rounding accumulates at most
    # linearly over the N steps (the same rounded map every step), so within N eps of the floor's PGA.
    for ground in (rq.record_synth(stochastic=7, dt=0.01, duration=30), rq.read_record(records / NORCIA)):
        for period, participation, damping in [(0.5, 1.5, 0.05), (0.25, 1.2, 0.1), (2.0, 1.4, 0.02)]:
            got = rq.record_floor(ground, period=period, participation=participation, damping=damping).accel
            other = exact_floor_by_expm(ground.accel, ground.dt, period, participation, damping)
            tol = len(got) * np.finfo(float).eps * np.abs(got).max()
            assert np.abs(got - other).max() < tol, (ground.name, period)


def test_record_floor_refuses_what_record_floor_refuses(tmp_path):
    ground = tmp_path / "ground.txt"
    cli("record", "synth", "--stochastic", 7, "--dt", 0.01, "--duration", 10, "--output", ground)
    record = rq.read_record(ground, unit="m/s2")
    for words, kwargs in [(["--period", 0.02, "--participation", 1], dict(period=0.02, participation=1)),
                          (["--period", -1, "--participation", 1], dict(period=-1, participation=1)),
                          (["--period", 1, "--participation", 1, "--damping", 1], dict(period=1, participation=1, damping=1))]:
        message, code = cli_error("record", "floor", ground, "--unit", "m/s2", *words)
        assert code == 2
        with pytest.raises(ValueError) as raised:
            rq.record_floor(record, **kwargs)
        assert "--" + str(raised.value) == message
    with pytest.raises(ValueError, match="^participation: inf is not a finite number"):
        rq.record_floor(record, period=1, participation=float("inf"))
    with pytest.raises(TypeError):
        rq.record_floor(record, period=1)
    with pytest.warns(RuntimeWarning, match=r"^record_floor: T1 = 0\.09 s has 9 samples per period at dt = 0\.01 s"):
        rq.record_floor(record, period=0.09, participation=1.5)
    huge = rq.Record(1e306 * np.sin(2 * np.pi * 0.01 * np.arange(2000) / 0.5), 0.01, unit="g", name="huge")
    with pytest.raises(RuntimeError, match="^huge: the floor's acceleration at sample"):
        rq.record_floor(huge, period=0.5, participation=1.5, damping=0.01)
