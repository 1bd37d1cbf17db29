"""simulate and block against `rocking simulate` (its --json and its --output rows)."""
import numpy as np
import pytest

import rocking_q as rq
from conftest import NORCIA, assert_same, cli, cli_error, read_csv

# Each case: the module's keywords, the command's options.
PULSES = [
    (dict(alpha=0.15, p=2, case=2, x=0.5, rd=0.9),
     ["--alpha", 0.15, "--p", 2, "--case", 2, "--x", 0.5, "--rd", 0.9]),
    (dict(alpha=0.15, half_height=2, case=2, x=0.5, rd=0.9, model="full", solver="dopri5", rtol=1e-8,
          restitution="housner", criterion="overturning"),
     ["--alpha", 0.15, "--half-height", 2, "--case", 2, "--x", 0.5, "--rd", 0.9, "--model", "full", "--solver",
      "dopri5", "--rtol", 1e-8, "--restitution", "housner", "--criterion", "overturning"]),
    (dict(alpha=0.2, height=3, train="1:1,-0.5:2", to=0.3, pga=0.5, criterion="peak-rotation", restitution=0.9,
          solver="gsl-rk8pd", atol=1e-9),
     ["--alpha", 0.2, "--height", 3, "--train", "1:1,-0.5:2", "--to", 0.3, "--pga", 0.5, "--criterion",
      "peak-rotation", "--restitution", 0.9, "--solver", "gsl-rk8pd", "--atol", 1e-9]),
    (dict(alpha=0.15, p=2, one_sine=True, ap=0.45, wp=6),
     ["--alpha", 0.15, "--p", 2, "--one-sine", "--ap", 0.45, "--wp", 6]),
    (dict(alpha=0.1, p=3, case=4, pulses=6, x=1.2, q=3.5, restitution="housner", criterion="overturning"),
     ["--alpha", 0.1, "--p", 3, "--case", 4, "--pulses", 6, "--x", 1.2, "--q", 3.5, "--restitution", "housner",
      "--criterion", "overturning"]),
    (dict(alpha=0.15, p=2, case=1, x=0.5, rd=3, criterion="overturning"),   # falls during the input
     ["--alpha", 0.15, "--p", 2, "--case", 1, "--x", 0.5, "--rd", 3, "--criterion", "overturning"]),
]


@pytest.mark.parametrize("kwargs,words", PULSES)
def test_simulate_is_rocking_simulate(kwargs, words):
    got = rq.simulate(dt=None, **kwargs)
    assert_same(got, cli("simulate", *words))
    assert len(got.t) == 0  # no theta(t) without dt, as simulate without --output


@pytest.mark.parametrize("kwargs,words", PULSES)
def test_theta_of_t_is_simulate_output(kwargs, words, tmp_path):
    out = tmp_path / "theta.csv"
    expected = cli("simulate", *words, "--output", out, "--dt", 0.005)
    got = rq.simulate(dt=0.005, **kwargs)
    assert_same(got, expected)
    notes, table = read_csv(out)
    assert got.t.tolist() == table["t"]
    assert got.theta_over_alpha.tolist() == table["theta_over_alpha"]
    assert got.omega_over_alpha_p.tolist() == table["omega_over_alpha_p"]
    assert notes["solver"] == got.solver_description and notes["model"] == got.model
    assert notes["input"] == got.input and notes["criterion"] == got.criterion
    assert np.array_equal(got.theta, got.theta_over_alpha * kwargs["alpha"]) or \
        np.allclose(got.theta / kwargs["alpha"], got.theta_over_alpha, rtol=1e-15, atol=0)
    assert len(got.t) > 10


def test_the_overturning_motion_is_followed_with_free_time():
    # Free rocking after t_fin kept for free_time seconds: the rows reach the fall.
    r = rq.simulate(alpha=0.15, p=2, case=2, x=0.5, rd=0.9, dt=0.01, free_time=5)
    assert r.overturned and not r.overturned_during_input
    assert r.t[-1] >= r.t_overturn - 0.01 and abs(r.theta[-1]) > 0.15


def test_a_record_is_simulated_as_the_command_line_does(records, tmp_path):
    path = str(records / NORCIA)
    words = ["--record", path, "--alpha", 0.15, "--p", 2, "--restitution", "housner", "--criterion", "overturning"]
    expected = cli("simulate", *words)
    got = rq.simulate(record=path, alpha=0.15, p=2, restitution="housner", criterion="overturning", dt=None)
    assert_same(got, expected)
    assert got.impacts == 368 and got.collapse is False  # README's example
    # The same from a Record read once, and from its samples as an array with its name.
    record = rq.read_record(path)
    assert_same(rq.simulate(record=record, alpha=0.15, p=2, restitution="housner", criterion="overturning", dt=None), expected)
    again = rq.Record(record.accel.copy(), record.dt, name=record.name)
    assert_same(rq.simulate(record=again, alpha=0.15, p=2, restitution="housner", criterion="overturning", dt=None), expected)
    # Scaled to a q, with theta(t) rows.
    out = tmp_path / "theta.csv"
    expected = cli("simulate", *words, "--q", 3, "--output", out, "--dt", 0.01)
    got = rq.simulate(record=record, alpha=0.15, p=2, restitution="housner", criterion="overturning", q=3, dt=0.01)
    assert_same(got, expected)
    assert got.theta_over_alpha.tolist() == read_csv(out)[1]["theta_over_alpha"]


def test_block_is_the_geometry_of_assess_and_simulate():
    b = rq.block(alpha=0.15, height=3)
    assert b.p == rq.simulate(alpha=0.15, height=3, case=2, x=0.5, rd=0.5, dt=None).p
    assert b.half_height == pytest.approx(1.5, rel=1e-15)
    assert b.housner_restitution == 1 - 1.5 * np.sin(0.15) ** 2
    assert rq.block(alpha=0.15, p=2).R == 0


def test_errors_are_the_command_line_s():
    with pytest.raises(ValueError, match="alpha A goes with exactly one of p, half_height and height"):
        rq.simulate(alpha=0.15, p=2, height=3, case=2, x=0.5, rd=0.9)
    with pytest.raises(ValueError, match="give exactly one input"):
        rq.simulate(alpha=0.15, p=2)
    with pytest.raises(ValueError, match=r"^solver: unknown solver 'rk4' \(exact, dopri5"):
        rq.simulate(alpha=0.15, p=2, case=2, x=0.5, rd=0.9, solver="rk4")
    with pytest.raises(ValueError, match=r"^restitution: "):
        rq.simulate(alpha=0.15, p=2, case=2, x=0.5, rd=0.9, restitution=1.5)
    with pytest.raises(ValueError, match=r"^rtol: must be in \[100 eps, 1\)"):
        rq.simulate(alpha=0.15, p=2, case=2, x=0.5, rd=0.9, solver="dopri5", rtol=1e-20)
    with pytest.raises(ValueError, match="give dt >= "):
        rq.simulate(alpha=0.15, p=2, case=2, x=0.5, rd=0.9, dt=1e-9)
    with pytest.raises(ValueError, match=r"^alpha: the slenderness must be in \(0, pi/4\) rad \(got 1\)"):
        rq.simulate(alpha=1.0, p=2, case=2, x=0.5, rd=0.9)
    # An input the library refuses: its message, as the command prints it (exit 1).
    message, code = cli_error("simulate", "--case", 2, "--x", 0.5, "--rd", 0.9, "--alpha", 0.15, "--p", 2,
                              "--model", "full", "--solver", "exact")
    assert code == 1
    with pytest.raises(ValueError) as e:
        rq.simulate(alpha=0.15, p=2, case=2, x=0.5, rd=0.9, model="full", solver="exact")
    assert str(e.value) == message


def test_friction_is_simulate_friction_json(tmp_path):
    # simulate(friction=MU) as rocking simulate --friction MU --json (issue 41): every field
    # the same, the rows as --output's, and its refusals.
    args = dict(train=[(1, 1), (-1, 1)], to=0.3, pga=0.3, alpha=0.2, height=3)
    s = rq.simulate(friction=0.6, **args)
    c = cli("simulate", "--train", "1:1,-1:1", "--to", 0.3, "--pga", 0.3, "--alpha", 0.2, "--height", 3,
            "--friction", 0.6)
    rows = {"t", "theta", "omega", "theta_over_alpha", "omega_over_alpha_p", "slip_m", "slip_rate_m_s",
            "regime"}  # --output's, every dt = 0.01 s
    assert set(s) == set(c) | rows and all(s[k] == c[k] for k in c), [k for k in c if s.get(k) != c[k]]
    out = tmp_path / "rows.csv"
    cli("simulate", "--train", "1:1,-1:1", "--to", 0.3, "--pga", 0.3, "--alpha", 0.2, "--height", 3,
        "--friction", 0.6, "--output", out)
    notes, table = read_csv(out)
    assert len(s["t"]) == len(table["t"]) > 50 and s["t"].tolist() == table["t"]
    assert s["slip_m"].tolist() == table["slip_m"] and s["slip_rate_m_s"].tolist() == table["slip_rate_m_s"]
    assert s["theta"].tolist() == [v * 0.2 for v in table["theta_over_alpha"]] or \
        np.allclose(s["theta"] / 0.2, table["theta_over_alpha"], rtol=1e-15, atol=0)
    assert s["regime"] == table["regime"] and s["regime"][0] == "rest"
    assert s["theta_over_alpha"].tolist() == table["theta_over_alpha"]
    assert s["omega_over_alpha_p"].tolist() == table["omega_over_alpha_p"]
    assert "Coulomb friction mu = 0.6" in s["model"] and s["energy"]["balance_error_over_gR"] < 1e-8
    with pytest.raises(ValueError, match="^friction: model, solver, restitution, paper and atol do not apply"):
        rq.simulate(friction=0.6, restitution=0.9, **args)
    with pytest.raises(ValueError, match=r"^friction: the friction coefficient must be in \(0, 1e6\]"):
        rq.simulate(friction=-1, **args)
