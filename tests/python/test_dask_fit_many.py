"""frictionid.dask.fit_many returns `frictionid batch`'s summary table, for files, a DataFrame
split by a group column, failed runs included (docs/design.md §2.4, §4.5)."""

import json
import subprocess

import pandas as pd
import pytest

import frictionid
from frictionid.dask import fit_many

FIT = dict(model="exact", pressure="hertz", global_evaluations=1000)
CLI_FIT = ["--model", "exact", "--pressure", "hertz", "--global-evaluations", "1000"]


def read_table(path):
    return pd.read_csv(path, float_precision="round_trip", dtype={"label": str, "error": str})


@pytest.fixture(scope="module")
def cli_batch(exe, campaign, tmp_path_factory):
    out = tmp_path_factory.mktemp("cli_batch")
    p = subprocess.run([exe, "batch", str(campaign), *CLI_FIT, "--report", str(out)],
                       capture_output=True, text=True)
    assert p.returncode == 4, p.stderr  # bad.csv fails
    return out


def test_the_table_equals_the_batch_summary(campaign, cli_batch, dask_client):
    table = fit_many(str(campaign), dask_client, **FIT)
    assert table.attrs["summary_csv"] == (cli_batch / "summary.csv").read_text()
    assert table.attrs["summary_json"] == (cli_batch / "summary.json").read_text()
    pd.testing.assert_frame_equal(table, read_table(cli_batch / "summary.csv"))
    assert list(table["label"]) == ["bad", "load_1000", "load_2000", "load_3000"]


def test_a_bad_file_is_a_failed_row_with_its_error(campaign, dask_client):
    table = fit_many([campaign / "bad.csv", campaign / "load_2000.csv"], dask_client, **FIT)
    bad = table.set_index("label").loc["bad"]
    assert bad["status"] == "failed" and bad["rows"] == 0
    assert "bad.csv" in bad["error"] and "missing required column" in bad["error"]
    assert pd.isna(bad["f"])
    good = table.set_index("label").loc["load_2000"]
    assert good["status"] == "ok" and abs(good["f"] - 0.8) < 0.01


def test_a_dataframe_split_by_a_column_equals_the_batch_of_the_file_by_that_column(
        run_cli, dask_client, tmp_path):
    loads = tmp_path / "loads.csv"
    run_cli("generate", "--model", "exact", "--param", "f=0.8,kappa=1.2,h=0.1", "--rows", 300,
            "--noise", 0.01, "--loads", "1000,2000,3000", "--output", loads)
    run_cli("batch", loads, "--group-by", "N", *CLI_FIT, "--report", tmp_path / "cli")
    frame = pd.read_csv(loads, float_precision="round_trip")
    table = fit_many(frame, dask_client, group_by="N", per_run_reports="json", **FIT)
    assert table.attrs["summary_csv"] == (tmp_path / "cli" / "summary.csv").read_text()
    assert list(table["label"]) == ["1000", "2000", "3000"]
    for label, report in table.attrs["reports"].items():
        cli_report = json.loads((tmp_path / "cli" / "runs" / label / "report.json").read_text())
        cli_report.pop("provenance", None)  # the command line that wrote it
        report.pop("provenance", None)
        assert report == cli_report


def test_bad_options_and_inputs_raise_before_any_fit(campaign, tmp_path):
    # No client is given: a LocalCluster would be started only after the plan succeeded.
    with pytest.raises(frictionid.InputError, match="--model 'nope'"):
        fit_many(campaign, model="nope")
    with pytest.raises(frictionid.InputError, match="no such file"):
        fit_many(tmp_path / "missing.csv")
    with pytest.raises(frictionid.InputError, match="group_by: no column 'load'"):
        fit_many(pd.DataFrame({"N": [1.0]}), group_by="load")
    with pytest.raises(ValueError, match="needs group_by"):
        fit_many(pd.DataFrame({"N": [1.0]}))
