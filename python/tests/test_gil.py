"""Long calls release the GIL: while one runs in a thread, Python code in another thread goes on.

The check does not time speed-ups, which depend on the machine's load.  It asks whether
the main thread ran Python code during the middle half of the call: it records a
timestamp every millisecond or so while a worker thread is inside the call.  A call that
held the GIL would block the main thread from just after the call began to just before
it returned, so no timestamp could fall in its middle half, however loaded the machine.
The workloads grow until a call lasts at least MIN_SECONDS, so that the middle half is
long enough (>= 0.1 s) for the scheduler to give the main thread a turn.
"""
import concurrent.futures
import threading
import time

import numpy as np
import pytest

import rocking_q as rq

MIN_SECONDS = 0.2


def progress_during(call):
    """Runs call() in a thread; returns (its duration, the main thread's timestamps inside its middle half)."""
    box = {}

    def worker():
        box["start"] = time.perf_counter()
        try:
            box["result"] = call()
        except BaseException as e:  # re-raised in the main thread
            box["error"] = e
        box["end"] = time.perf_counter()

    stamps = []
    thread = threading.Thread(target=worker)
    thread.start()
    while thread.is_alive():
        stamps.append(time.perf_counter())
        time.sleep(0.001)
    thread.join()
    if "error" in box:
        raise box["error"]
    d = box["end"] - box["start"]
    inside = [s for s in stamps if box["start"] + d / 4 <= s <= box["end"] - d / 4]
    return d, inside


def assert_releases_the_gil(make_call, what):
    """make_call(scale) -> a call whose work grows with scale; scale doubles until it lasts MIN_SECONDS."""
    for scale in (2 ** k for k in range(12)):
        d, inside = progress_during(make_call(scale))
        if d >= MIN_SECONDS:
            assert inside, ("%s held the GIL: the main thread made no progress during the middle half of a "
                            "%.2f s call" % (what, d))
            return
    pytest.fail("%s never took %.1f s: the check needs a longer call" % (what, MIN_SECONDS))


def noise(seconds, dt=0.005, seed=1, g=0.1):
    """A long random record, g its standard deviation in g: cheap to make, the work is in the call."""
    rng = np.random.default_rng(seed)
    return rq.Record(g * rng.standard_normal(int(seconds / dt)), dt, unit="g", name="noise %g s" % seconds)


def test_simulate_on_a_record_releases_the_gil():
    # A block that rocks through the whole record without falling (1e5 impacts in 1000 s).
    def make(scale):
        record = noise(1000 * scale)
        return lambda: rq.simulate(record=record, alpha=0.2, p=3, restitution="housner",
                                   criterion="overturning", dt=None)
    assert_releases_the_gil(make, "simulate(record=...)")


def test_spectrum_releases_the_gil():
    record = noise(30)
    assert_releases_the_gil(lambda scale: lambda: rq.spectrum(record, alpha=0.1, points=20 * scale, jobs=1),
                            "spectrum")


def test_fragility_releases_the_gil():
    records = [noise(20, seed=s) for s in (1, 2)]
    assert_releases_the_gil(lambda scale: lambda: rq.fragility(records, alpha=0.1, p=2, points=10 * scale, jobs=1),
                            "fragility")


def test_eq27_releases_the_gil():
    records = [noise(20, seed=s) for s in (3, 4)]
    assert_releases_the_gil(
        # scale + 1 p: one p on a range is refused (issue 38).
        lambda scale: lambda: rq.eq27(records, alpha=0.1, p_points=scale + 1, p_min=1, p_max=5, jobs=1), "eq27")


def test_collapse_and_record_info_release_the_gil():
    # alpha 0.3: no p up to 30 rad/s overturns the block, so the search runs its whole scan.
    assert_releases_the_gil(lambda scale: (lambda r: lambda: rq.collapse(r, alpha=0.3))(noise(20 * scale)),
                            "collapse")
    assert_releases_the_gil(lambda scale: (lambda r: lambda: rq.record_info(r))(noise(100 * scale)),
                            "record_info")


def test_a_thread_pool_gives_the_results_of_one_thread():
    # Two threads running studies on the same Records at once: the same results as one after the other.
    records = [noise(20, seed=s) for s in (5, 6)]
    jobs = [lambda: rq.fragility(records, alpha=0.1, p=2, points=12, jobs=1),
            lambda: rq.eq27(records, alpha=0.1, p_points=2, p_min=1, p_max=4, q_max=5, jobs=1),
            lambda: rq.simulate(record=records[0], alpha=0.05, p=3, criterion="overturning", dt=0.01),
            lambda: rq.spectrum(records[1], alpha=[0.05, 0.1], points=20, jobs=1)]
    alone = [job() for job in jobs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        together = [f.result() for f in [pool.submit(job) for job in jobs]]
    for a, b in zip(alone, together):
        assert repr(a) == repr(b)
        assert a.keys() == b.keys()
    assert alone[2].theta.tolist() == together[2].theta.tolist()
