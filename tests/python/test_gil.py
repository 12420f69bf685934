"""The GIL is released while a fit runs: other Python threads keep running (the timing of two
fits in parallel is in test_gil_parallel_fits.py)."""

import threading
import time


def test_python_threads_keep_running_during_a_fit(second_long_fit):
    done = threading.Event()
    box = {}

    def work():
        box["result"] = second_long_fit()
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
