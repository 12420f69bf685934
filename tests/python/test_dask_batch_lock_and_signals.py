"""python3 -m frictionid batch takes the lock `frictionid batch` takes (one lock, one rule for
both front ends), and Ctrl-C ends it with exit 130, one line and no summary, as the command line
does."""

import os
import signal
import subprocess
import sys
import time

import pytest


# Profile intervals and 2000 bootstrap refits: about a second a run even on a quiet machine, so
# that a batch of a dozen runs is still at work when the test acts.
SLOW = ["--intervals", "profile", "--bootstrap", "2000"]


def make_runs(exe, directory, count, rows=2000):
    directory.mkdir()
    for k in range(count):
        subprocess.run([exe, "generate", "--model", "exact", "--param", "f=0.8,kappa=1.2,h=0.1",
                        "--rows", str(rows), "--noise", "0.01", "--seed", str(k + 1), "--output",
                        str(directory / f"run{k:02d}.csv")], check=True, capture_output=True)


def module_batch(inputs, output, *extra):
    return [sys.executable, "-m", "frictionid", "batch", str(inputs), "--output", str(output),
            "--model", "exact", "--workers", "1", *extra]


def test_the_module_batch_waits_for_a_cli_batch_holding_its_lock_and_no_wait_fails(
        exe, tmp_path):
    make_runs(exe, tmp_path / "in", 12)
    out = tmp_path / "out"
    cli = subprocess.Popen([exe, "batch", str(tmp_path / "in"), "--model", "exact", "--jobs", "1",
                            *SLOW, "--report", str(out)], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
    lock = tmp_path / ".out.lock"
    deadline = time.monotonic() + 30
    while not lock.exists() and time.monotonic() < deadline:
        time.sleep(0.01)
    assert lock.exists(), "the command line's batch did not take its lock"
    refused = subprocess.run(module_batch(tmp_path / "in", out, "--no-wait"), capture_output=True,
                             text=True, timeout=120)
    still_running = cli.poll() is None
    cli.communicate(timeout=300)
    assert still_running, "the command line's batch ended before the module's ran"
    assert refused.returncode == 1, refused.stderr
    assert "another frictionid run is writing report directory" in refused.stderr


def test_ctrl_c_ends_the_module_batch_with_130_one_line_and_no_summary(exe, tmp_path):
    make_runs(exe, tmp_path / "in", 20)
    out = tmp_path / "out"
    p = subprocess.Popen(module_batch(tmp_path / "in", out, *SLOW),
                         stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    time.sleep(6)  # the cluster is up and fitting
    assert p.poll() is None, "the batch ended before Ctrl-C: " + p.communicate()[1]
    os.killpg(p.pid, signal.SIGINT)  # as a terminal's Ctrl-C reaches the whole group
    try:
        _, err = p.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        pytest.fail("the batch did not end within 60 s of Ctrl-C")
    assert p.returncode == 130, err
    lines = [line for line in err.splitlines() if line.startswith("frictionid:")]
    assert len(lines) == 1 and "interrupted" in lines[0], err
    assert not (out / "summary.csv").exists()
