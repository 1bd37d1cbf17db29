"""Arrays in: the shapes and dtypes the module takes, converts or refuses, each refusal a clear message."""
import numpy as np
import pytest

import rocking_q as rq

GOOD = np.array([0.0, 0.1, -0.2, 0.05, 0.0])


@pytest.mark.parametrize("bad,error,message", [
    (np.zeros((3, 2)), ValueError, r"^accel: expected a 1-D array, got 2-D of shape \(3, 2\)$"),
    (np.float64(0.5), ValueError, r"^accel: expected a 1-D array, got 0-D of shape \(\)$"),
    (GOOD.astype(complex), TypeError, r"^accel: dtype complex128 is not a real number type; give float64"),
    (GOOD > 0, TypeError, r"^accel: dtype bool is not a real number type"),
    (np.array(["0.1", "0.2"]), TypeError, r"^accel: dtype <U3 is not a real number type"),
    (np.array([0.1, None, 0.2], dtype=object), TypeError, r"^accel: dtype object is not a real number type"),
    (GOOD.astype(np.longdouble), TypeError, r"^accel: dtype float128 is not a real number type"),
    (np.array(["2020-01-01"], dtype="datetime64[D]"), TypeError, r"^accel: dtype datetime64\[D\] is not a real"),
    ([[0.1, 0.2], [0.3]], TypeError, r"^accel: expected an array of real numbers, got list"),
    ([0.5], ValueError, r"^array: a record needs at least 2 samples \(got 1\)$"),
    ([0.5, np.nan, 0.1], ValueError, r"^array: accel\[1\] = nan m/s2 is not finite$"),
    ([0.5, 1e308, 0.1], None, None),
])
def test_record_samples_are_a_1d_real_array(bad, error, message):
    if error is None:
        with pytest.raises(ValueError, match=r"^big: accel\[1\] = 1e\+308 g is out of range for a double in m/s\^2$"):
            rq.Record(bad, 0.01, unit="g", name="big")
        return
    with pytest.raises(error, match=message):
        rq.Record(bad, 0.01)


def test_record_dt_and_unit_are_checked():
    with pytest.raises(ValueError, match=r"^named: dt must be > 0 \(got 0\)$"):
        rq.Record(GOOD, 0.0, name="named")
    with pytest.raises(ValueError, match=r"^dt: nan is not a finite number$"):
        rq.Record(GOOD, float("nan"), name="named")
    with pytest.raises(ValueError, match=r"^unit: 'mg' is not a unit it knows \(g, m/s2, cm/s2\)$"):
        rq.Record(GOOD, 0.01, unit="mg")
    with pytest.raises(TypeError):
        rq.Record(GOOD, "0.01")


def test_real_dtypes_are_converted_exactly():
    base = rq.Record(GOOD, 0.01).accel.tolist()
    as_float32 = GOOD.astype(np.float32)
    assert rq.Record(as_float32, 0.01).accel.tolist() == [float(v) for v in as_float32]
    assert rq.Record([0, 1, -2, 3], 0.01).accel.tolist() == [0.0, 1.0, -2.0, 3.0]
    assert rq.Record(np.array([0, 1, -2, 3], dtype=np.int16), 0.01).accel.tolist() == [0.0, 1.0, -2.0, 3.0]
    assert rq.Record(np.array([0, 1, 2], dtype=np.uint8), 0.01, unit="cm/s2").accel.tolist() == [0.0, 0.01, 0.02]
    assert rq.Record(GOOD.astype(">f8"), 0.01).accel.tolist() == base          # big-endian
    assert rq.Record(list(GOOD), 0.01).accel.tolist() == base                 # a list
    strided = np.repeat(GOOD, 2)[::2]                                          # not contiguous
    assert not strided.flags.c_contiguous and rq.Record(strided, 0.01).accel.tolist() == base


def test_x_is_any_shape_of_real_numbers():
    assert rq.q1(np.empty((0,))).shape == (0,)
    assert rq.q1(np.full((2, 3, 4), 0.5)).shape == (2, 3, 4)
    assert rq.q1(np.array(0.5)) == rq.q1(0.5) and isinstance(rq.q1(np.array(0.5)), float)
    assert rq.q(np.array([1, 2]), case=1).tolist() == [rq.q(1.0, case=1), rq.q(2.0, case=1)]
    with pytest.raises(TypeError, match=r"^x: dtype complex128 is not a real number type"):
        rq.q(np.array([0.5 + 1j]), case=2)
    with pytest.raises(TypeError, match=r"^x: dtype <U3 is not a real number type"):
        rq.q2_n6("0.5")
    with pytest.raises(TypeError, match=r"^x: dtype bool is not a real number type"):
        rq.q3(np.array([True]))


def test_a_train_is_text_or_n_by_2_pairs():
    assert rq.q(0.5, train=np.array([[1.0, 1.0], [-0.5, 1.0]])) == rq.q(0.5, train="1:1,-0.5:1")
    with pytest.raises(ValueError, match=r"^train: expected \(amplitude, duration\) pairs, an \(n, 2\) array; got 1-D"):
        rq.q(0.5, train=[1.0, 1.0])
    with pytest.raises(ValueError, match=r"^train: expected \(amplitude, duration\) pairs, an \(n, 2\) array; got 2-D"):
        rq.q(0.5, train=np.ones((2, 3)))
    with pytest.raises(TypeError, match=r"^train: dtype complex128"):
        rq.q(0.5, train=np.ones((2, 2), dtype=complex))
    with pytest.raises(ValueError, match=r"^train: pulse train: pulse 2 needs a finite duration > 0"):
        rq.q(0.5, train=[(1, 1), (-0.5, 0)])


def test_study_lists_are_1d():
    r = rq.Record(np.sin(np.arange(500) * 0.05), 0.01, unit="g")
    with pytest.raises(ValueError, match=r"^alpha: expected a 1-D array, got 2-D of shape \(1, 2\)$"):
        rq.spectrum(r, alpha=[[0.1, 0.2]])
    with pytest.raises(TypeError, match=r"^p: dtype complex128"):
        rq.fragility([r], alpha=0.1, p=np.array([2 + 0j]))
    with pytest.raises(TypeError, match=r"^records\[1\]: expected a rocking_q.Record or a file's path, got int"):
        rq.fragility([r, 3], alpha=0.1, p=2)
    with pytest.raises(TypeError, match=r"^record: expected a rocking_q.Record or a file's path, got ndarray"):
        rq.simulate(alpha=0.1, p=2, record=np.zeros(10))
