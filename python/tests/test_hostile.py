"""Hostile input, as a fuzzer or a careless caller gives it: each is refused with an exception whose
message names the argument (or the file), never a crash, an abort, a hang or a silent wrong number.

A call that could kill the interpreter runs in a subprocess, so that a regression fails one test
instead of ending the run.
"""
import os
import subprocess
import sys

import numpy as np
import pytest

import rocking_q as rq
from conftest import cli_error


def in_subprocess(code, timeout=60):
    """Runs code after `import rocking_q as rq` in a fresh interpreter: (exit status, stdout, stderr)."""
    done = subprocess.run([sys.executable, "-c", "import numpy as np, rocking_q as rq\n" + code],
                          capture_output=True, text=True, timeout=timeout, env=dict(os.environ))
    return done.returncode, done.stdout, done.stderr


def raises_in_subprocess(code, error, message):
    """code raises error with message (a prefix) in a fresh interpreter, which survives it."""
    probe = ("try:\n    %s\nexcept %s as e:\n    print('raised:' + str(e))\nelse:\n    print('returned')\n"
             % (code, error))
    status, out, err = in_subprocess(probe)
    assert status == 0, "the interpreter died (exit %d): %s" % (status, err.strip()[-400:])
    assert out.startswith("raised:" + message), out + err


# ---- GSL ----

def test_a_gamma_shape_beyond_gsl_s_inverse_is_refused_not_aborted():
    # alpha2 = 1e300 made GSL's gamma inverse fail to converge, and GSL's default handler aborted
    # the process (the command line's too): the library now bounds alpha2.
    for alpha2 in ("1e300", "1e20", "5e5"):
        raises_in_subprocess(
            "rq.record_synth(stochastic=1, params={'alpha1': 1, 'alpha2': %s, 'alpha3': 1}, dt=0.01, duration=20)"
            % alpha2, "ValueError", "params: alpha2 must be in (1, 100000]")
    message, code = cli_error("record", "synth", "--stochastic", 1, "--dt", 0.01, "--duration", 20,
                              "--params", "alpha1=1,alpha2=1e300,alpha3=1")
    assert code == 2 and message.startswith("--params: alpha2 must be in (1, 100000]"), message
    # The largest alpha2 taken still runs (the Arias route gives at most 50000.5: shape 1e5).
    assert rq.record_synth(stochastic=1, params={"alpha1": 1, "alpha2": 1e5, "alpha3": 4000}, dt=0.01,
                           duration=20).samples == 2001


def test_a_gsl_error_during_a_call_is_a_runtime_error_not_an_abort():
    # No public argument is known to reach GSL's error handler any more (above); the hook makes GSL
    # fail during a call, as an unforeseen input would.  GSL's default handler aborted the process.
    raises_in_subprocess("rq._provoke_gsl_error()", "RuntimeError", "GSL error: ")
    # GSL's first error during the call, where GSL raised it (its file and line), and why.
    with pytest.raises(RuntimeError, match=r"^GSL error: .* \(.*gamma.*\.c:\d+, .*\); the call's result is not "
                                           r"trusted \(GSL's default handler would have aborted the process\)$"):
        rq._provoke_gsl_error()
    assert rq.q(0.5, case=2) > 0  # the next call is not blamed for it


def test_outside_the_module_s_calls_gsl_s_handler_is_unchanged():
    # Another user of GSL in the process (here through ctypes) still gets GSL's default handler.
    status, out, err = in_subprocess(
        "import ctypes, ctypes.util\n"
        "gsl = ctypes.CDLL(ctypes.util.find_library('gsl') or 'libgsl.so')\n"
        "gsl.gsl_cdf_gamma_Pinv.restype = ctypes.c_double\n"
        "gsl.gsl_cdf_gamma_Pinv.argtypes = [ctypes.c_double] * 3\n"
        "print(gsl.gsl_cdf_gamma_Pinv(0.95, 1e7, 1.0))\n")
    assert status != 0 and "Default GSL error handler invoked" in err, (status, out, err)


# ---- Record: made without its constructor ----

UNINITIALISED = ["repr(r)", "r.header", "r.accel", "len(r)", "r.in_g()", "r.dt", "r.name", "r.path", "r.format",
                 "r.samples", "r.pga_ms2", "r.pga_g", "r.duration", "r.__getstate__()", "pickle.dumps(r)",
                 "copy.deepcopy(r)"]


def test_a_record_never_initialised_is_refused_not_a_crash():
    # Record.__new__ without __init__ (as pickle makes one before __setstate__): its methods read
    # memory never written, and repr, header and pickling died with SIGSEGV.
    probes = "".join(
        "print(%r, flush=True)\ntry:\n    %s\nexcept TypeError as e:\n    print('TypeError:', e, flush=True)\n"
        "else:\n    print('returned', flush=True)\n" % (p, p) for p in UNINITIALISED)
    status, out, err = in_subprocess("import copy, pickle\nr = rq.Record.__new__(rq.Record)\n" + probes)
    assert status == 0, "died after %r (exit %d): %s" % (out.splitlines()[-1:], status, err[-300:])
    lines = out.splitlines()
    for probe, answer in zip(lines[::2], lines[1::2]):
        assert answer.startswith("TypeError: Record: not initialised (made by Record.__new__ without "
                                 "calling Record(...))"), (probe, answer)
    r = rq.Record.__new__(rq.Record)
    for call in (lambda: rq.record_info(r), lambda: rq.simulate(record=r, alpha=0.15, p=2),
                 lambda: rq.fragility([r], alpha=0.1, p=2)):
        with pytest.raises(TypeError, match=r"^records?(\[0\])?: a rocking_q.Record never initialised "
                                            r"\(made by Record.__new__ without calling Record\(...\)\)$"):
            call()
    rq.Record.__init__(r, [0.1, 0.2, 0.3], 0.01)  # initialised late, it works
    assert r.accel.tolist() == [0.1, 0.2, 0.3]


def test_a_pickled_state_is_checked_as_the_constructor_checks():
    import pickle
    good = rq.Record([0.1, -0.2, 0.3], 0.01, unit="g", name="three")
    state = good.__getstate__()
    assert pickle.loads(pickle.dumps(good)).accel.tolist() == good.accel.tolist()

    def with_(k, v):
        return state[:k] + (v,) + state[k + 1:]
    for bad, error, message in [
        (with_(3, -1.0), ValueError, r"^Record.__setstate__: dt must be > 0 \(got -1\)$"),
        (with_(3, float("nan")), ValueError, r"^Record.__setstate__: dt must be > 0 \(got nan\)$"),
        (with_(4, np.array([1.0])), ValueError, r"^Record.__setstate__: a record needs at least 2 samples \(got 1\)$"),
        (with_(4, np.array([0.1, np.inf, 0.2])), ValueError, r"^Record.__setstate__: accel\[1\] is not finite$"),
        (with_(4, np.array([[0.1, 0.2]])), ValueError, r"^Record.__setstate__: accel: expected a 1-D array"),
        (with_(1, "array"), TypeError, r"^Record.__setstate__: not the state of a pickled rocking_q.Record"),
        (with_(5, {b"k": 3}), TypeError, r"^Record.__setstate__: not the state of a pickled rocking_q.Record"),
        (state[:5], TypeError, r"^Record.__setstate__: not the state of a pickled rocking_q.Record"),
        ((1, 2, 3, 4, 5, 6), TypeError, r"^Record.__setstate__: not the state of a pickled rocking_q.Record"),
        (None, TypeError, r"^Record.__setstate__: not the state of a pickled rocking_q.Record"),
    ]:
        r = rq.Record.__new__(rq.Record)
        with pytest.raises(error, match=message):
            r.__setstate__(bad)


# ---- Files: names that are not text ----

def test_a_file_name_that_is_not_utf8_stays_in_the_message(tmp_path):
    # A name with bytes that are not UTF-8 (os.fsdecode's surrogates): the message that carried it
    # could not be decoded, and the exception came with no message at all.
    folder = os.fsencode(tmp_path)
    short = folder + b"/short\xff\xfe.txt"
    with open(short, "w") as f:
        f.write("0.1\n0.2\n0.3\n")
    record = rq.read_record(short, unit="g", dt=0.01)
    assert record.path == os.fsdecode(short)
    with pytest.raises(RuntimeError) as e:
        rq.record_info(record)
    assert str(e.value) == os.fsdecode(short) + ": half_periods: a record needs >= 4 samples and dt > 0"
    missing = folder + b"/missing\xff.asc"
    with pytest.raises(rq.RecordError) as e:
        rq.read_record(os.fsdecode(missing))
    # The command line's message, its bytes read back as os.fsdecode reads a name.
    done = subprocess.run([os.environ.get("ROCKING_CLI", "build/rocking"), "record", "info", missing],
                          capture_output=True)
    assert done.returncode == 1
    assert str(e.value) == os.fsdecode(done.stderr.splitlines()[0])[len("rocking record: "):]
    assert str(e.value).startswith(os.fsdecode(missing) + ":0: cannot open the file")


def test_a_path_with_a_nul_is_refused_not_cut_short(tmp_path):
    # The reader saw the name up to its NUL: "two.txt\0junk" read two.txt.  Python's open() refuses it.
    two = tmp_path / "two.txt"
    two.write_text("0.1\n0.2\n0.3\n0.4\n")
    with pytest.raises(ValueError, match=r"^path: embedded null byte$"):
        rq.read_record(str(two) + "\0junk", unit="g", dt=0.01)
    with pytest.raises(ValueError, match=r"^path: embedded null byte$"):
        rq.read_record(str(two) + "\0junk")
    with pytest.raises(ValueError, match=r"^record: embedded null byte$"):
        rq.record_info(str(two).encode() + b"\0")
    with pytest.raises(ValueError, match=r"^records\[1\]: embedded null byte$"):
        rq.fragility([rq.Record([0.1, 0.2, 0.3, 0.4], 0.01), str(two) + "\0"], alpha=0.1, p=2)
