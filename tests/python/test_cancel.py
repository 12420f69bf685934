"""Ctrl-C cancels a running fit: KeyboardInterrupt, within a fraction of a second, and the
next fit runs normally."""

import os
import signal
import threading
import time

import pytest

import frictionid


@pytest.fixture(scope="module")
def rows():
    # A fit of several seconds: the exact model with the exponent free on 3000 rows.
    return frictionid.generate("exact", "power:1.5", {"f": 0.8, "kappa": 1.2, "h": 0.05},
                               rows=3000, noise=0.01, seed=2)


def send_sigint_after(seconds):
    sent = {}

    def fire():
        sent["at"] = time.perf_counter()
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(seconds, fire)
    timer.start()
    return timer, sent


@pytest.mark.parametrize("delay, stage", [(0.05, "global search"), (1.5, "local fits")])
def test_ctrl_c_stops_a_fit_with_keyboard_interrupt(rows, delay, stage):
    timer, sent = send_sigint_after(delay)
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        frictionid.fit(rows, model="exact", pressure="power:1", threads=1, starts=4,
                       global_evaluations=6000)
    stopped = time.perf_counter()
    timer.join()
    assert "at" in sent, f"the fit ended before the signal ({stage})"
    # The observer polls every 50 ms; one model evaluation pass is much shorter.
    assert stopped - sent["at"] < 0.5, stage
    assert stopped - start < 3.0


def test_a_fit_after_a_cancelled_one_runs_normally(rows):
    timer, _ = send_sigint_after(0.05)
    with pytest.raises(KeyboardInterrupt):
        frictionid.fit(rows, model="exact", pressure="power:1", threads=1)
    timer.join()
    small = rows.iloc[:200]
    result = frictionid.fit(small, model="seed", global_search=False)
    assert result.rows == 200
