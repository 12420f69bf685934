"""Two fits in two Python threads finish in about the time of one on two cores (the GIL is
released). CTest runs this file alone (RUN_SERIAL): other tests would take the second core."""

import hashlib
import os
import threading
import time

import pytest


def parallel_ratio(task):
    """Wall time of two runs of task in two threads over that of two runs in a row."""
    start = time.perf_counter()
    task()
    task()
    serial = time.perf_counter() - start
    threads = [threading.Thread(target=task) for _ in range(2)]
    start = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return (time.perf_counter() - start) / serial


BLOCK = bytes(48 << 20)


def hash_block():
    hashlib.sha256(BLOCK).digest()  # releases the GIL: the parallelism the machine offers now


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="needs two cores")
def test_two_fits_in_threads_take_about_the_time_of_one(second_long_fit):
    results = []
    second_long_fit()  # warm up: first use of the tables, page faults
    hash_block()
    attempts = []
    for _ in range(3):  # other processes on the machine may take the second core for a while
        fit_ratio = parallel_ratio(lambda: results.append(second_long_fit()))
        reference = parallel_ratio(hash_block)
        attempts.append((round(fit_ratio, 2), round(reference, 2)))
        # Ideal 0.5 on two idle cores; with the GIL held it would be 1 or more.
        if fit_ratio < 0.8:
            break
    else:
        # Fail only where sha256 clearly had a free second core and the fits ran one at a
        # time, as they would with the GIL held.
        if any(ref < 0.65 and fit > 0.95 for fit, ref in attempts):
            pytest.fail(f"no parallel speed-up: (fit, sha256) ratios {attempts}")
        pytest.skip(f"the machine offered no second core: (fit, sha256) ratios {attempts}")
    assert all(r.params == results[0].params for r in results)
