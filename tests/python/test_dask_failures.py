"""fit_many and python3 -m frictionid batch end with a row per run whatever happens to a task:
a task that raised (after its retries) is a failed row with its error, the other runs are
kept, as `frictionid batch` keeps them. Group labels that collide are an error, as in the CLI.
A FitResult travels back from a Dask worker (it pickles)."""

import numpy as np
import pandas as pd
import pytest

import frictionid
import frictionid.dask as fdask
from frictionid.dask import fit_many

FIT = dict(model="seed", global_evaluations=300)


@pytest.fixture(scope="module")
def thread_client():
    """Workers in this process, so that a patched task function is the one they run."""
    import logging

    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=1, processes=False, threads_per_worker=2,
                      dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        yield client


def test_colliding_group_labels_are_an_error_naming_both_groups():
    frame = pd.DataFrame({"A": ["1_2", "1"], "B": ["3", "2_3"], "v_x": [1.0, 1.0],
                          "omega": [1.0, 1.0], "N": [1.0, 1.0], "R": [1.0, 1.0],
                          "T_x": [1.0, 1.0]})
    with pytest.raises(frictionid.InputError,
                       match=r"the groups \(A='1_2', B='3'\) and \(A='1', B='2_3'\) would "
                             r"share the label '1_2_3'"):
        fit_many(frame, group_by=["A", "B"], **FIT)  # raised before a cluster is started


def test_a_task_that_raises_is_a_failed_row_and_the_other_runs_are_kept(
        campaign, thread_client, monkeypatch):
    real = fdask.fit_run

    def flaky(spec, *args):
        if '"label":"load_2000"' in spec:
            raise MemoryError("worker ran out of memory")
        return real(spec, *args)

    monkeypatch.setattr(fdask, "fit_run", flaky)
    inputs = [campaign / f"load_{load}.csv" for load in (1000, 2000, 3000)]
    table = fit_many(inputs, thread_client, retries=1, **FIT).set_index("label")
    assert list(table["status"]) == ["ok", "failed", "ok"]
    error = table.loc["load_2000", "error"]
    assert "MemoryError" in error and "worker ran out of memory" in error
    assert np.isnan(table.loc["load_2000", "f"])
    assert table.loc["load_1000", "rows"] == 200


def test_a_fit_submitted_to_a_local_cluster_comes_back_as_a_fit_result(dask_client,
                                                                       example_csv):
    frame = pd.read_csv(example_csv, float_precision="round_trip").iloc[::3]
    future = dask_client.submit(frictionid.fit, frame, model="seed", global_search=False,
                                pure=False)
    remote = future.result()
    local = frictionid.fit(frame, model="seed", global_search=False)
    assert isinstance(remote, frictionid.FitResult)
    assert remote.report == local.report
    assert remote.fitted.index.equals(frame.index)


def test_the_module_batch_writes_a_failed_row_and_exits_4_when_a_task_raises(
        campaign, thread_client, monkeypatch, tmp_path, capsys):
    from frictionid.__main__ import main

    real = fdask.fit_run

    def flaky(spec, *args):
        if '"label":"load_3000"' in spec:
            raise OSError("disk vanished")
        return real(spec, *args)

    monkeypatch.setattr(fdask, "fit_run", flaky)
    inputs = [str(campaign / f"load_{load}.csv") for load in (1000, 3000)]
    code = main(["batch", *inputs, "--output", str(tmp_path / "out"), "--model", "seed",
                 "--global-evaluations", "300", "--retries", "0", "--scheduler",
                 thread_client.scheduler.address])
    assert code == 4
    summary = pd.read_csv(tmp_path / "out" / "summary.csv").set_index("label")
    assert list(summary["status"]) == ["ok", "failed"]
    assert "OSError: disk vanished" in summary.loc["load_3000", "error"]
    assert "run 'load_3000' failed" in capsys.readouterr().err


def test_a_bad_row_of_a_dataframe_group_is_named_by_its_index_label(thread_client,
                                                                    example_csv):
    frame = pd.read_csv(example_csv, float_precision="round_trip").iloc[:300].copy()
    frame.index = [f"m{i}" for i in range(len(frame))]
    frame.loc["m123", "N"] = -np.inf
    table = fit_many(frame, thread_client, group_by="N", **FIT).set_index("label")
    failed = table[table["status"] == "failed"]
    assert len(failed) == 1
    assert "row with index 'm123'" in failed["error"].iloc[0]
    assert (table["status"] == "ok").sum() == len(table) - 1
