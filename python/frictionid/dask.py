"""frictionid.dask: a campaign of fits (``frictionid batch``) mapped over a Dask cluster.

The client plans the runs with the batch's own C++ planner (the same labels, groups, per-run
options and covariates), each worker reads its run's rows and fits them with the batch's own
code, and the client writes the table with the batch's own writer: the summary is
``frictionid batch``'s, byte for byte (docs/design.md §2.4, §4.5).

What travels to a worker is a short JSON text per run (label, file path, group rows, options);
files are read on the workers, so they must see the same paths as the client (a shared file
system). Rows of a DataFrame are sent to the workers with ``client.scatter``.

>>> from frictionid.dask import fit_many
>>> table = fit_many("campaign/*.csv", model="exact", pressure="hertz")
"""

from __future__ import annotations

import io
import json
import logging
import math
import os
import sys
import uuid
from typing import (TYPE_CHECKING, Any, Dict, Iterable, List, NamedTuple, Optional, Sequence,
                    Tuple, Union)

from . import _data, _fit, _frictionid

if TYPE_CHECKING:
    import pandas

Inputs = Union[str, "os.PathLike[str]", Iterable[Union[str, "os.PathLike[str]"]], Any]

# Task retries for a run whose task raised in Python (a worker that could not import the
# package, say). A worker lost mid-run is not such an error: the scheduler reassigns its tasks
# by itself, up to distributed.scheduler.allowed-failures times.
DEFAULT_RETRIES = 2


class Run(NamedTuple):
    """One planned run: its label, its JSON (what a worker needs) and, for a DataFrame's group,
    its columns (None: the worker reads the run's file)."""

    label: str
    directory: str
    spec: str
    columns: Optional[Dict[str, Any]]


class Outcome(NamedTuple):
    """The runs' summary rows (JSON text, by label) and report.json texts (None when not asked
    for or when the run failed)."""

    rows: Dict[str, str]
    reports: Dict[str, Optional[str]]


def fit_many(
    inputs: Inputs,
    client: Optional[Any] = None,
    *,
    group_by: Optional[Union[str, Sequence[str]]] = None,
    per_run_reports: Optional[str] = None,
    threads: int = 1,
    retries: int = DEFAULT_RETRIES,
    n_workers: Optional[int] = None,
    runs_per_task: Optional[int] = None,
    **fit_options: Any,
) -> "pandas.DataFrame":
    """Fit many runs on a Dask cluster into ``frictionid batch``'s summary table.

    Args:
        inputs: what ``frictionid batch`` takes — a CSV path, a glob, a directory (its
            ``*.csv``), a manifest CSV (a ``path`` column; per-run ``pressure``, ``fix``,
            ``channels``, ``label``; other columns are covariates), or a list of these — or a
            pandas DataFrame with the canonical columns, split into runs by ``group_by``.
        client: a ``distributed.Client``. None starts a ``LocalCluster`` of worker processes
            (``n_workers``, default one per core) on loopback and closes it afterwards.
        group_by: column name(s) (a list, or ``"A,B"``): one run per distinct value, as
            ``--group-by``. Required for a DataFrame. Group values become the labels and
            covariates as text (numbers of ``v_x``, ``v_y``, ``omega``, ``N``, ``R`` and float
            columns in their shortest form, ``2000`` not ``2000.0``).
        per_run_reports: None, or ``"json"`` to gather each run's report.json (the dict, as
            ``frictionid batch --per-run-reports json`` writes it) into
            ``table.attrs["reports"]``, by label (None for a failed run).
        threads: threads per fit on a worker (results do not depend on it); 1 suits workers
            with one thread each.
        retries: Dask retries of a run whose task raised in Python; a fit that fails is not
            retried, it is a ``failed`` row with its error.
        n_workers: worker processes of the LocalCluster started without ``client``.
        runs_per_task: runs fitted one after another in one Dask task (default: about four
            tasks per worker, at most 50 runs a task), so that short fits do not each cost the
            scheduler a task.
        **fit_options: the keyword arguments of :func:`frictionid.fit` (``model``,
            ``pressure``, ``fix``, ``bounds``, ``start``, ``loss``, ``channels``,
            ``noise_model``, ``seed``, ``starts``, ``global_search``, ``global_algorithm``,
            ``global_evaluations``, ``global_subsample``, ``columns``), for every run.

    Returns:
        The summary table (docs/design.md §4.5) as a pandas DataFrame, one row per run sorted by
        label: ``label``, ``status`` (``ok``/``failed``), ``rows``, the parameters with
        ``_stderr``, ``_ci95_lo``, ``_ci95_hi``, ``cost``, ``reduced_chi2``, ``warnings``,
        ``error``, the noise columns and the covariates. ``table.attrs["summary_csv"]`` and
        ``["summary_json"]`` hold the exact text ``frictionid batch`` writes.

    Raises:
        InputError: (a ``ValueError``) an input that matches nothing, a bad manifest, a bad
            option, an unknown group column: nothing is fitted.
    """
    if per_run_reports not in (None, "none", "json"):
        raise ValueError(f"per_run_reports={per_run_reports!r}: expected None or 'json'")
    with_reports = per_run_reports == "json"
    if "threads" in fit_options:
        raise TypeError("threads is fit_many's own argument (threads per fit on a worker)")
    options = _fit.options(**fit_options, threads=threads)
    group_columns = _group_columns(group_by)
    if _is_frame(inputs):
        runs = plan_frame(inputs, options, group_columns, fit_options.get("columns"))
    else:
        runs = plan(_input_list(inputs), options, group_columns)
    outcome = run_on_cluster(runs, client, threads=threads, with_reports=with_reports,
                             retries=retries, n_workers=n_workers, runs_per_task=runs_per_task)
    csv_text, json_text, _ = _frictionid.summary_files(list(outcome.rows.values()))
    table = summary_frame(csv_text)
    table.attrs["summary_csv"] = csv_text
    table.attrs["summary_json"] = json_text
    if with_reports:
        table.attrs["reports"] = {
            label: None if text is None else json.loads(text)
            for label, text in sorted(outcome.reports.items())}
    return table


def plan(inputs: List[str], options: "_frictionid.FitRequest", group_by: List[str]
         ) -> List[Run]:
    """The runs of ``frictionid batch INPUTS --group-by GROUP_BY``, from its own planner."""
    runs = []
    for spec in _frictionid.plan_batch_runs(inputs, options, group_by):
        header = json.loads(spec)
        runs.append(Run(header["label"], header["directory"], spec, None))
    return runs


def plan_frame(frame: Any, options: "_frictionid.FitRequest", group_columns: List[str],
               columns: Optional[Dict[str, str]] = None) -> List[Run]:
    """One run per group of a DataFrame's rows, labelled as ``--group-by`` labels a file's
    groups (the values joined by ``_``), rows in frame order, sorted by label."""
    if not group_columns:
        raise ValueError("fit_many: a DataFrame needs group_by (the column(s) that split it "
                         "into runs)")
    missing = [c for c in group_columns if c not in frame.columns]
    if missing:
        raise _frictionid.InputError(
            f"group_by: no column '{missing[0]}' (columns: {', '.join(map(str, frame.columns))})")
    texts = [_group_text(frame[c], c) for c in group_columns]
    groups: Dict[Tuple[str, ...], List[int]] = {}
    for i, key in enumerate(zip(*texts)):
        groups.setdefault(key, []).append(i)
    runs = []
    owner: Dict[str, Tuple[str, ...]] = {}
    for key, rows in groups.items():
        label = "_".join(key)
        if label in owner:  # ("1_2", "3") and ("1", "2_3"): one label, two groups
            raise _frictionid.InputError(
                f"group_by: the groups {_group_name(group_columns, owner[label])} and "
                f"{_group_name(group_columns, key)} would share the label '{label}' (the "
                f"values joined by '_'); expected group values whose joined labels differ, "
                f"as frictionid batch --group-by requires")
        owner[label] = key
        spec = _frictionid.table_run(label, options, list(zip(group_columns, key)))
        part = frame.iloc[rows]
        runs.append(Run(label, "", spec, _canonical_columns(part, columns)))
    return sorted(runs, key=lambda r: r.label)


def run_on_cluster(runs: List[Run], client: Optional[Any] = None, *, threads: int = 1,
                   with_reports: bool = False, retries: int = DEFAULT_RETRIES,
                   n_workers: Optional[int] = None,
                   runs_per_task: Optional[int] = None) -> Outcome:
    """Fits the runs on ``client``'s workers (or on a LocalCluster started for them)."""
    if client is None:
        from distributed import Client, LocalCluster

        with LocalCluster(n_workers=n_workers or os.cpu_count() or 1, threads_per_worker=1,
                          processes=True, host="127.0.0.1", dashboard_address=None,
                          silence_logs=logging.ERROR) as cluster, Client(cluster) as own:
            return run_on_cluster(runs, own, threads=threads, with_reports=with_reports,
                                  retries=retries, runs_per_task=runs_per_task)
    batch = uuid.uuid4().hex[:8]
    # Each run's rows are sent once, to one worker, rather than inside the task graph. (A list:
    # scatter would take a dict's keys, the column names, for the data's keys.)
    in_memory = [run.columns for run in runs if run.columns is not None]
    scattered = iter(client.scatter(in_memory, hash=False) if in_memory else [])
    columns = [next(scattered) if run.columns is not None else None for run in runs]
    # Runs go to the workers in groups, several to a task, so that the scheduler hands out a
    # few tasks per second rather than one per short fit (experiments/dask_scaling/plan.md);
    # enough groups remain to keep every worker busy to the end.
    size = runs_per_task or _runs_per_task(len(runs), len(client.nthreads()) or 1)
    groups = [list(range(start, min(start + size, len(runs))))
              for start in range(0, len(runs), size)]
    futures = [
        client.submit(fit_runs, [runs[k].spec for k in group], threads, with_reports,
                      [columns[k] for k in group],
                      key=f"frictionid-fit-{group[0]}-{runs[group[0]].directory}-{batch}",
                      retries=retries, pure=False)
        for group in groups]
    # Every run ends as a row: a task that still raised after its retries (or whose workers
    # kept dying, KilledWorker) makes failed rows of its runs, with the error, as a failed fit is
    # in `frictionid batch`; the other runs' results are kept.
    from distributed import as_completed

    progress = _Progress(len(runs)) if sys.stderr.isatty() else None
    runs_of = {future.key: len(group) for future, group in zip(futures, groups)}
    for future in as_completed(futures):
        if progress is not None:
            progress.add(runs_of[future.key])
    if progress is not None:
        progress.close()
    results: List[Tuple[str, Optional[str]]] = [("", None)] * len(runs)
    for group, future in zip(groups, futures):
        if future.status == "finished":
            for k, result in zip(group, future.result()):
                results[k] = result
            continue
        error = future.exception() if future.status == "error" else None
        why = (f"the task failed on the cluster: {type(error).__name__}: {error}"
               if error is not None else f"the task ended as '{future.status}' on the cluster")
        for k in group:
            results[k] = (_frictionid.failed_batch_run(runs[k].spec, why), None)
    return Outcome({run.label: row for run, (row, _) in zip(runs, results)},
                   {run.label: report for run, (_, report) in zip(runs, results)})


def _runs_per_task(runs: int, workers: int) -> int:
    """About four tasks per worker, at most 50 runs a task: short fits share a task, and the
    last tasks are small enough that no worker waits long for another."""
    return max(1, min(50, runs // (4 * workers)))


class _Progress:
    """A one-line count of fitted runs on a terminal's stderr."""

    def __init__(self, total: int) -> None:
        self.total, self.done = total, 0

    def add(self, count: int) -> None:
        self.done += count
        print(f"\rfrictionid batch: {self.done}/{self.total} runs fitted", end="",
              file=sys.stderr, flush=True)

    def close(self) -> None:
        print("\r" + " " * 60 + "\r", end="", file=sys.stderr, flush=True)


def fit_runs(specs: List[str], threads: int, with_report: bool,
             columns: List[Optional[Dict[str, Any]]]) -> List[Tuple[str, Optional[str]]]:
    """Runs on a worker: the runs of one task, one after another. A run that raises (not a
    failed fit, which is a row already) is a failed row of its own; the others go on."""
    out = []
    for spec, data in zip(specs, columns):
        try:
            out.append(fit_run(spec, threads, with_report, data))
        except Exception as e:  # noqa: BLE001 - every run ends as a row
            out.append((_frictionid.failed_batch_run(
                spec, f"the run raised on its worker: {type(e).__name__}: {e}"), None))
    return out


def fit_run(spec: str, threads: int, with_report: bool,
            columns: Optional[Dict[str, Any]] = None) -> Tuple[str, Optional[str]]:
    """Runs on a worker: reads (or builds) one run's rows and fits them. Returns its summary row
    and report.json as JSON text; a failure of the fit is a failed row, not an exception."""
    data = None
    if columns is not None:
        arrays = {k: v for k, v in columns.items() if k != _INDEX}
        try:
            data = _frictionid.dataset_from_columns(arrays, "DataFrame")
        except ValueError as e:
            error = str(e)
            index = columns.get(_INDEX)
            if index is not None and not _data._is_positional(index):
                try:  # again, only to name the row by the frame's index label
                    _frictionid.dataset_from_columns(arrays, "DataFrame", _data.row_labels(index))
                except ValueError as labelled:
                    error = str(labelled)
            return _frictionid.failed_batch_run(spec, error), None
    return _frictionid.fit_batch_run(spec, threads, with_report, data)


def summary_frame(csv_text: str) -> "pandas.DataFrame":
    """summary.csv's text as a DataFrame: numbers as float64 (read back bit-identical), labels
    and errors as text, empty cells as NaN."""
    import pandas as pd

    return pd.read_csv(io.StringIO(csv_text), float_precision="round_trip",
                       dtype={"label": str, "status": str, "error": str}, keep_default_na=False,
                       na_values=[""])


def _group_columns(group_by: Optional[Union[str, Sequence[str]]]) -> List[str]:
    if group_by is None:
        return []
    if isinstance(group_by, str):
        return [c.strip() for c in group_by.split(",") if c.strip()]
    return list(group_by)


def _input_list(inputs: Inputs) -> List[str]:
    """The inputs as absolute paths, resolved in the client's working directory: the workers
    read the files where they run, whose directory may be another."""
    if isinstance(inputs, (str, os.PathLike)):
        return [os.path.abspath(os.fspath(inputs))]
    out = [os.path.abspath(os.fspath(i)) for i in inputs]
    if not out:
        raise _frictionid.InputError("fit_many: no inputs")
    return out


def _is_frame(inputs: Any) -> bool:
    return hasattr(inputs, "iloc") and hasattr(inputs, "columns")


_NUMERIC_COLUMNS = ("v_x", "v_y", "omega", "N", "R")


def _group_text(values: Any, name: str) -> List[str]:
    """A group column's values as text: integers as digits, floats (and the numeric canonical
    columns) in their shortest form that reads back (2000, 0.25), anything else with str()."""
    import pandas as pd

    if name in _NUMERIC_COLUMNS or pd.api.types.is_float_dtype(values):
        return [_shortest(float(v)) for v in values]
    return [str(v) for v in values]


def _shortest(x: float) -> str:
    # As the batch writes a numeric group value: whole numbers without exponent or ".0",
    # others with the fewest digits that read back as the same double (batch_runs.cpp).
    if math.isfinite(x) and x == int(x) and abs(x) < 1e15:
        return str(int(x))
    for digits in range(1, 18):
        text = f"{x:.{digits}g}"
        if float(text) == x:
            return text
    return repr(x)


def _group_name(columns: List[str], values: Tuple[str, ...]) -> str:
    return "(" + ", ".join(f"{c}={v!r}" for c, v in zip(columns, values)) + ")"


# The key of a group's index among its columns: a rejected row is named by its label.
_INDEX = "__index__"


def _canonical_columns(part: Any, columns: Optional[Dict[str, str]]) -> Dict[str, Any]:
    """A group's canonical columns, read as fit() reads a frame (pd.NA, refused dtypes), and
    its index."""
    out: Dict[str, Any] = dict(_data.canonical_arrays(part, _data.column_map(columns),
                                                      "DataFrame"))
    out[_INDEX] = part.index
    return out
