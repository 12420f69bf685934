"""A fit in any thread can be stopped: by its cancel token, by an Event, by the interpreter's
exit; it reports progress to a callback; Ctrl-C stops a fit in the main thread of a process
within 0.5 s and the next fit works."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import frictionid


@pytest.fixture(scope="module")
def rows():
    # Several seconds of work: the exact model with the exponent free on 3000 rows.
    return frictionid.generate("exact", "power:1.5", {"f": 0.8, "kappa": 1.2, "h": 0.05},
                               rows=3000, noise=0.01, seed=2)


LONG = dict(model="exact", pressure="power:1", threads=1, global_evaluations=6000)


def fit_in_thread(rows, **options):
    out = {}

    def run():
        try:
            out["result"] = frictionid.fit(rows, **LONG, **options)
        except BaseException as e:  # noqa: B902 - the test inspects it
            out["error"] = e
        out["ended"] = time.perf_counter()

    thread = threading.Thread(target=run)
    thread.start()
    return thread, out


@pytest.mark.parametrize("make", [frictionid.CancelToken, threading.Event])
def test_a_token_set_from_another_thread_stops_a_fit_in_a_worker_thread(rows, make):
    token = make()
    thread, out = fit_in_thread(rows, cancel=token)
    time.sleep(0.5)
    set_at = time.perf_counter()
    token.cancel() if hasattr(token, "cancel") else token.set()
    thread.join(10)
    assert not thread.is_alive()
    assert isinstance(out.get("error"), frictionid.FitCancelled), out
    assert isinstance(out["error"], frictionid.FitError)
    assert out["ended"] - set_at < 0.5
    # The next fit runs normally.
    assert frictionid.fit(rows.iloc[:200], model="seed", global_search=False).rows == 200


def test_a_token_set_before_the_fit_stops_it_at_once(rows):
    token = frictionid.CancelToken()
    token.cancel()
    assert token.cancelled and token.is_set()
    with pytest.raises(frictionid.FitCancelled):
        frictionid.fit(rows, **LONG, cancel=token)


def test_progress_reaches_a_callback_in_a_worker_thread(rows):
    seen = []
    small = rows.iloc[:400]
    thread, out = fit_in_thread(small, progress=lambda p: seen.append(
        (threading.get_ident(), dict(p))))
    thread.join(60)
    assert "result" in out, out
    assert seen, "no progress"
    assert {ident for ident, _ in seen} == {thread.ident}
    stages = [p["stage"] for _, p in seen]
    assert set(stages) <= {"global search", "local fit"} and "global search" in stages
    first = seen[0][1]
    assert set(first) == {"stage", "done", "total", "start", "starts", "cost"}


def test_an_exception_in_the_progress_callback_stops_the_fit_and_is_raised(rows):
    def boom(progress):
        raise LookupError("stop here")

    with pytest.raises(LookupError, match="stop here"):
        frictionid.fit(rows, **LONG, progress=boom)


def run_script(code, **kwargs):
    env = dict(os.environ)
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kwargs)


def test_interpreter_exit_cancels_a_fit_running_in_a_worker_thread():
    p = run_script("""
        import threading, time, frictionid
        rows = frictionid.generate("exact", "power:1.5", {"f": 0.8, "kappa": 1.2, "h": 0.05},
                                   rows=3000, noise=0.01, seed=2)
        def work():
            try:
                frictionid.fit(rows, model="exact", pressure="power:1", threads=1,
                               global_evaluations=60000)
            except frictionid.FitCancelled:
                print("cancelled", flush=True)
        threading.Thread(target=work).start()   # not a daemon: exit waits for it
        time.sleep(0.5)
        print("exiting", flush=True)
    """)
    out, err = p.communicate(timeout=60)
    assert p.returncode == 0, err
    assert out.split() == ["exiting", "cancelled"], (out, err)


SIGINT_CHILD = """
    import json, sys, time, frictionid
    options = json.loads(sys.argv[1])
    rows = frictionid.generate(options.pop("truth"), "power:1.5",
                               {"f": 0.8, "kappa": 1.2, "h": 0.05}, rows=3000, noise=0.01,
                               seed=2)
    print("ready", flush=True)
    stages = []

    def progress(p):  # says when each stage starts, so that the signal lands inside it
        if not stages or stages[-1] != p["stage"]:
            stages.append(p["stage"])
            print(p["stage"], flush=True)

    try:
        frictionid.fit(rows, threads=1, progress=progress, **options)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.time(), flush=True)
    r = frictionid.fit(rows.iloc[:200], model="seed", global_search=False)
    print("next", r.rows, flush=True)
"""

EXACT = dict(truth="exact", model="exact", pressure="power:1", global_evaluations=6000)


@pytest.mark.parametrize("stage, options, delay", [
    ("ready", EXACT, 0.0),
    ("global search", EXACT, 0.0),
    ("global search", EXACT, 1.0),
    ("local fit", dict(EXACT, global_search=False), 0.1),
    ("local fit", dict(EXACT, global_evaluations=100), 0.0),
    # No progress while the bootstrap refits: 5000 of them take seconds, the fit before it
    # a few milliseconds.
    ("ready", dict(truth="seed", model="seed", global_search=False, bootstrap=5000), 1.0),
])
def test_sigint_ends_a_main_thread_fit_within_half_a_second_and_the_next_fit_works(
        stage, options, delay):
    import json

    p = subprocess.Popen([sys.executable, "-c", textwrap.dedent(SIGINT_CHILD),
                          json.dumps(options)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    seen = []
    while not seen or seen[-1] != stage:
        line = p.stdout.readline()
        assert line, (seen, p.communicate())
        seen.append(line.strip())
    time.sleep(delay)
    sent = time.time()
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    lines = [line for line in out.split("\n") if line not in ("global search", "local fit")]
    assert lines[0].startswith("interrupted"), (stage, seen, out, err)
    assert float(lines[0].split()[1]) - sent < 0.5, stage
    assert lines[1] == "next 200", (out, err)
    assert p.returncode == 0, err
