"""fit_many's runs travel to the workers in groups and with paths the client resolved: the table
does not depend on how runs are grouped into tasks, and a relative input names the client's file
even when the workers run in another directory."""

import os

from frictionid.dask import fit_many


def test_the_table_does_not_depend_on_how_runs_are_grouped_into_tasks(campaign, dask_client):
    one = fit_many(str(campaign), dask_client, model="exact", runs_per_task=1)
    grouped = fit_many(str(campaign), dask_client, model="exact", runs_per_task=3)
    auto = fit_many(str(campaign), dask_client, model="exact")
    assert grouped.attrs["summary_csv"] == one.attrs["summary_csv"]
    assert auto.attrs["summary_csv"] == one.attrs["summary_csv"]
    # The bad file is a failed row of its own, not a failed group.
    assert list(grouped["status"]) == ["failed", "ok", "ok", "ok"]


def test_a_relative_input_is_resolved_where_the_client_runs(campaign, dask_client, tmp_path):
    # The workers started in the session's directory; the client now runs in another one.
    here = os.getcwd()
    try:
        os.chdir(campaign.parent)
        table = fit_many(os.path.join(campaign.name, "load_1000.csv"), dask_client,
                         model="exact")
    finally:
        os.chdir(here)
    assert list(table["status"]) == ["ok"], table["error"].tolist()
