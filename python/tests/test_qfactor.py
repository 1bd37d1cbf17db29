"""q, q_info, response and the closed forms against `rocking q` and `rocking response`."""
import numpy as np
import pytest

import rocking_q as rq
from conftest import SOURCE, assert_same, cli, cli_error, cli_or_refusal, read_csv

XS = [1e-3, 0.05, 0.5, 1.0, 3.0, 20.0]


@pytest.mark.parametrize("case", [1, 2, 3, 4, 5])
@pytest.mark.parametrize("pulses", [None, 1, 6, 7])
def test_q_info_is_rocking_q(case, pulses):
    answered = 0
    for x in XS:
        extra = [] if pulses is None else ["--pulses", pulses]
        expected, refusal = cli_or_refusal("q", "--case", case, "--x", x, *extra)
        if refusal is not None:  # e.g. case 3 to 6 pulses at small x: no q collapses the block
            with pytest.raises(ValueError) as e:
                rq.q_info(x, case=case, pulses=pulses)
            assert str(e.value) == refusal
            continue
        got = rq.q_info(x, case=case, pulses=pulses)
        assert_same(got, expected, "q_info(%g, case=%d, pulses=%s)" % (x, case, pulses))
        assert rq.q(x, case=case, pulses=pulses) == expected["q"]
        answered += 1
    assert answered >= 3


def test_a_train_as_text_or_pairs_is_rocking_q_train():
    for text, pairs in [("1:1,-0.5:2", [(1, 1), (-0.5, 2)]), ("0.7:0.3,-0.2:0.5,0.4:1", [[0.7, 0.3], [-0.2, 0.5], [0.4, 1]])]:
        for x in XS:
            expected = cli("q", "--train", text, "--x", x)
            assert_same(rq.q_info(x, train=text), expected)
            assert_same(rq.q_info(x, train=pairs), expected)  # its name is the same text
            assert_same(rq.q_info(x, train=np.array(pairs, dtype=float)), expected)


def test_q_is_vectorised_over_x_in_any_shape():
    x = np.array([[0.05, 0.5, 1.0], [2.0, 3.0, 20.0]])
    q = rq.q(x, case=2, pulses=6)
    assert isinstance(q, np.ndarray) and q.shape == (2, 3) and q.dtype == np.float64
    for index in np.ndindex(x.shape):
        assert q[index] == cli("q", "--case", 2, "--pulses", 6, "--x", x[index])["q"]
    assert isinstance(rq.q(0.5, case=2), float)
    assert rq.q([0.5, 1.0], case=2).tolist() == [rq.q(0.5, case=2), rq.q(1.0, case=2)]
    assert rq.q(np.float32(0.5), case=2) == rq.q(float(np.float32(0.5)), case=2)


def test_the_closed_forms_are_the_fig04_scene_s():
    # fig04.csv holds q_case(i, x) at %.17g: the module's closed forms must give the same doubles.
    _, table = read_csv(SOURCE / "expected" / "fig04" / "fig04.csv")
    x = np.array(table["x"])
    assert np.array_equal(x, np.arange(5, 201) / 100.0)
    for i, f in enumerate([rq.q1, rq.q2, rq.q3, rq.q4, rq.q5], start=1):
        assert f(x).tolist() == table["q%d" % i], "q%d" % i
        assert rq.q_case(i, x).tolist() == table["q%d" % i]


def test_the_6_plus_1_forms_agree_with_the_engine():
    # Eqs. 27 and 28 in closed form against the superposition engine (a different formula): 1e-13 relative.
    x = np.geomspace(1e-3, 50, 200)
    np.testing.assert_allclose(rq.q2_n6(x), rq.q(x, case=2, pulses=6), rtol=1e-13, atol=0)
    np.testing.assert_allclose(rq.q4_n6(x), rq.q(x, case=4, pulses=6), rtol=1e-13, atol=0)


@pytest.mark.parametrize("args", [
    dict(x=0.5, case=2),
    dict(x=0.8, case=4, steps=30),
    dict(x=0.5, case=2, pulses=6, q=2.0, steps=12),
    dict(x=0.5, train="1:1,-0.5:2", steps=7),
    dict(x=400, case=2, q=5, steps=10),          # theta leaves the double range: the rows stop
])
def test_response_is_rocking_response(args):
    words = ["response", "--x", args["x"]]
    for key in ("case", "pulses", "train", "q", "steps"):
        if key in args:
            words += ["--" + key, args[key]]
    expected = cli(*words)
    got = rq.response(**args)
    assert_same(got, expected)
    assert got.samples.shape == (len(expected["samples"]), 3)
    assert got.theta_over_alpha.tolist() == [row[1] for row in expected["samples"]]
    if args["x"] == 400:
        assert got.rows_complete is False and got.rows_end_at == 1.8


def test_errors_carry_the_library_s_message():
    # A train that cannot collapse the block: the library's message, as the command prints it.
    message, code = cli_error("q", "--train", "1:1,-10:1", "--x", 0.5)
    assert code == 1
    with pytest.raises(ValueError) as e:
        rq.q(0.5, train="1:1,-10:1")
    assert str(e.value) == message
    with pytest.raises(ValueError, match=r"^x\[1\]: x = p\*to must be >= 1e-150"):
        rq.q(np.array([0.5, -1.0]), case=2)
    with pytest.raises(ValueError, match=r"^x = p\*to must be a number >= 1e-150"):
        rq.q2(0.0)
    with pytest.raises(ValueError, match="first pulse must be positive"):
        rq.q(0.5, train=[(-1, 1)])
    with pytest.raises(ValueError, match="give exactly one of case and train"):
        rq.q(0.5, case=2, train="1:1")
    with pytest.raises(ValueError, match="case: must be 1, 2, 3, 4 or 5"):
        rq.q_info(0.5, case=7)
    with pytest.raises(ValueError, match="pulses goes with case"):
        rq.q(0.5, train="1:1", pulses=3)
    with pytest.raises(ValueError, match=r"^x: must be > 0"):
        rq.response(-1.0, case=2)


def test_results_keep_the_document_s_kinds_and_order():
    """The library's document converted (python/src/json_value.cpp): an integer an int, a double a
    float, null None, the keys in the command's order, with the module's own fields after them."""
    info = rq.q_info(0.5, case=2)
    assert type(info) is rq.Result and type(info["pulses"]) is int and type(info["x"]) is float
    expected = cli("q", "--case", 2, "--x", 0.5)
    assert list(info)[:len(expected)] == list(expected) and list(info)[len(expected):] == ["t_fin_over_to"]
    # Rows ended by an overflow: where they end a float; complete rows: None, as the JSON's null.
    ended = rq.response(800, case=2, q=10, steps=10)
    assert ended["rows_complete"] is False and type(ended["rows_end_at"]) is float and ended["rows_end_at"] == 1.0
    complete = rq.response(0.5, case=2)
    assert complete["rows_end_at"] is None and complete["rows_end_reason"] is None
    assert isinstance(complete["samples"], np.ndarray) and complete["samples"].shape == (21, 3)
