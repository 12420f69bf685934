"""A worker process killed while it fits a run does not lose the run: the scheduler gives the
run to another worker and the table is complete, equal to `frictionid batch`'s."""

import os
import signal
import threading
import time

from frictionid.dask import fit_many

# Runs that take about a second each, so that the kill lands while one is being fitted.
SLOW = dict(model="exact", pressure="hertz", global_evaluations=20000)
CLI_SLOW = ["--model", "exact", "--pressure", "hertz", "--global-evaluations", "20000"]


def test_a_worker_killed_mid_run_loses_no_run(run_cli, campaign, dask_client, tmp_path):
    inputs = [campaign / f"load_{load}.csv" for load in (1000, 2000, 3000)]
    run_cli("batch", *inputs, *CLI_SLOW, "--report", tmp_path / "cli")
    dask_client.wait_for_workers(2)
    pids = dask_client.run(os.getpid)  # worker address -> its process

    outcome = {}
    fitting = threading.Thread(
        target=lambda: outcome.setdefault("table", fit_many(inputs, dask_client, **SLOW)))
    fitting.start()
    victim = None
    deadline = time.monotonic() + 30
    while victim is None and time.monotonic() < deadline:
        busy = [address for address, tasks in dask_client.processing().items()
                if any(str(t).startswith("frictionid-fit") for t in tasks)]
        victim = busy[0] if busy else None
        time.sleep(0.02)
    assert victim is not None, "no run was ever being fitted"
    os.kill(pids[victim], signal.SIGKILL)
    fitting.join(120)
    assert not fitting.is_alive()

    table = outcome["table"]
    assert list(table["status"]) == ["ok"] * 3
    assert table.attrs["summary_csv"] == (tmp_path / "cli" / "summary.csv").read_text()
    # The worker really died (its nanny starts a new process at a new address).
    assert victim not in dask_client.scheduler_info()["workers"]
    dask_client.wait_for_workers(2)
