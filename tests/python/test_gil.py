"""The GIL is released while a fit runs: other Python threads keep running (the timing of two
fits in parallel is in test_gil_parallel_fits.py)."""

import threading
import time

import pytest

import frictionid


@pytest.fixture(scope="module")
def rows():
    # The exact model with the pressure exponent free: a fit of about a second on one core.
    return frictionid.generate("exact", "power:1.5", {"f": 0.8, "kappa": 1.2, "h": 0.05},
                               rows=600, noise=0.01, seed=2)


def one_fit(rows):
    return frictionid.fit(rows, model="exact", pressure="power:1", threads=1, starts=2,
                          global_evaluations=1000)


def test_python_threads_keep_running_during_a_fit(rows):
    done = threading.Event()
    box = {}

    def work():
        box["result"] = one_fit(rows)
        done.set()

    worker = threading.Thread(target=work)
    start = time.perf_counter()
    worker.start()
    last, longest = start, 0.0
    while not done.is_set():
        time.sleep(0.001)
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    worker.join()
    duration = time.perf_counter() - start
    assert "result" in box
    # Holding the GIL would stall this loop for the whole fit.
    assert longest < 0.25 * duration, (longest, duration)
