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
