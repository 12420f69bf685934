"""python3 -m frictionid batch INPUTS... --output DIR [--scheduler tcp://HOST:PORT]: the command
line's ``frictionid batch`` with its fits mapped over a Dask cluster (frictionid.dask).

DIR gets the same summary.csv, summary.json and summary.html as ``frictionid batch`` writes for
the same inputs and options, byte for byte, each written atomically, and with
``--per-run-reports json`` (the default) runs/<label>/report.json. Exit codes are the command line's (docs/design.md §3.1): 0
every run fitted, 4 some runs failed (rows with their error), 2 bad input, 1 a cluster or I/O
failure.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import time
from typing import List, Optional

EXIT_OK, EXIT_FAILURE, EXIT_BAD_INPUT, EXIT_SOME_RUNS_FAILED = 0, 1, 2, 4
EXIT_INTERRUPTED = 130  # as `frictionid batch` after Ctrl-C


class Interrupted(Exception):
    """SIGINT, SIGTERM or SIGHUP during the batch: it ends without writing a summary."""


_received_signal = 0  # the last of those signals, 0 before any


def _stop_on_signals() -> None:
    """Ctrl-C (and SIGTERM, SIGHUP) end the batch as the command line's does, wherever the main
    thread is waiting: the handler raises, and the flag it leaves catches a waiting library
    that swallowed the exception."""
    def handler(signum, frame):
        global _received_signal
        _received_signal = signum
        raise Interrupted(signal.Signals(signum).name)

    global _received_signal
    _received_signal = 0
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, handler)


def _check_interrupted() -> None:
    if _received_signal:
        raise Interrupted(signal.Signals(_received_signal).name)


def _lock_output(output: str, wait: bool):
    """`frictionid batch`'s lock on DIR (the sibling .DIR.lock): two batches, whichever front end
    runs them, never write one directory at once. Waits for it unless --no-wait."""
    from . import _frictionid

    lock = _frictionid.BatchLock(output)
    said = False
    while not lock.try_acquire():
        if not wait:
            raise RuntimeError(f"another frictionid run is writing report directory {output}; "
                               "without --no-wait it waits")
        if not said:
            print(f"frictionid: waiting for another run writing report directory {output}",
                  file=sys.stderr)
            said = True
        time.sleep(0.1)
    return lock
MAX_SEED = 2**32 - 1  # as `frictionid fit --seed` (NLopt keeps 32 bits)


def whole_number(low: int, high: Optional[int] = None):
    def parse(text: str) -> int:
        try:
            value = int(text, 10)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a whole number") from None
        if value < low or (high is not None and value > high):
            bound = f"{low} to {high}" if high is not None else f"at least {low}"
            raise argparse.ArgumentTypeError(f"{value} is out of range ({bound})")
        return value

    return parse


def batch_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python3 -m frictionid batch",
        description="Fit many runs on a Dask cluster into frictionid batch's summary table: "
                    "DIR/summary.csv, DIR/summary.json and DIR/summary.html.")
    p.add_argument("inputs", nargs="+",
                   help="CSV files, globs, directories (their *.csv) or manifest CSVs "
                        "(a `path` column)")
    p.add_argument("--output", "--report", dest="output", required=True, metavar="DIR",
                   help="directory for summary.csv, summary.json, summary.html and runs/")
    p.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                   help="an existing Dask scheduler (default: start a LocalCluster)")
    p.add_argument("--timeout", type=float, default=30.0, metavar="SECONDS",
                   help="give up connecting to --scheduler after this long (exit 1)")
    p.add_argument("--workers", type=whole_number(1), metavar="N",
                   help="worker processes of the LocalCluster (default: one per core)")
    p.add_argument("--model", default="seed", help="seed, corrected or exact")
    p.add_argument("--pressure", default=None, help="pressure law, as frictionid fit "
                                                    "(default hertz)")
    p.add_argument("--contact", default="circle",
                   help="contact spot: circle, ellipse:Q, rect:Q or map:FILE, as frictionid fit")
    p.add_argument("--fix", default="", help="hold parameters fixed: name=value,...")
    p.add_argument("--free", default="", help="fit parameters held by default: h_y, q")
    p.add_argument("--bounds", default="", help="parameter bounds: name=lo:hi,...")
    p.add_argument("--param", default="", help="initial values: name=value,...")
    p.add_argument("--loss", default="none", help="none, huber:S, cauchy:S or soft_l1:S")
    p.add_argument("--noise-model", default="auto",
                   choices=["auto", "constant", "relative", "affine", "additive", "columns"])
    p.add_argument("--intervals", default="model", choices=["model", "sandwich", "profile"])
    p.add_argument("--bootstrap", type=whole_number(0, 100000), default=0)
    p.add_argument("--starts", type=int, default=4)
    p.add_argument("--seed", type=whole_number(0, MAX_SEED), default=1)
    p.add_argument("--global-evaluations", type=int, default=3000)
    p.add_argument("--global-subsample", type=whole_number(1, 10**9), default=400)
    p.add_argument("--global-algorithm", default="crs2",
                   choices=["crs2", "isres", "direct", "esch", "random"])
    p.add_argument("--no-global", action="store_true", help="skip the global stage")
    p.add_argument("--channels", default="", help="channels to fit, e.g. T_x,M_z")
    p.add_argument("--columns", default="", help="rename columns: canonical=header,...")
    p.add_argument("--threads", type=whole_number(0), default=1,
                   help="threads per fit on a worker (results do not depend on it)")
    p.add_argument("--group-by", default="", metavar="COL[,COL]",
                   help="split each CSV into one run per value of the columns")
    p.add_argument("--trend-x", default="mean_N", metavar="COL",
                   help="covariate on the x axis of summary.html's trend plots")
    p.add_argument("--per-run-reports", default="json", choices=["none", "json"],
                   help="json: DIR/runs/<label>/report.json, as frictionid batch")
    p.add_argument("--runs-per-task", type=whole_number(1), metavar="N",
                   help="runs fitted one after another in one Dask task (default: about four "
                        "tasks per worker, at most 50 runs a task)")
    p.add_argument("--no-wait", action="store_true",
                   help="fail at once when another run is writing the same --output directory "
                        "(default: wait for it)")
    p.add_argument("--retries", type=whole_number(0), default=2,
                   help="Dask retries of a task that raised (a lost worker's runs are "
                        "rescheduled regardless)")
    return p


def run_batch(args: argparse.Namespace) -> int:
    from . import _frictionid, dask as fdask

    t_start = time.monotonic()
    o = _frictionid.FitRequest()
    for name in ("model", "contact", "loss", "noise_model", "intervals", "bootstrap", "starts",
                 "seed", "global_evaluations", "global_subsample", "no_global",
                 "global_algorithm", "threads"):
        setattr(o, name, getattr(args, name))
    o.pressure = "hertz" if args.pressure is None else args.pressure
    o.pressure_given = args.pressure is not None
    _frictionid.apply_fit_text(o, fix=args.fix, bounds=args.bounds, start=args.param,
                               channels=args.channels, columns=args.columns, free=args.free)
    if os.path.exists(args.output) and not os.path.isdir(args.output):
        raise _frictionid.InputError(f"{args.output}: --output exists and is not a directory")
    lock = _lock_output(args.output, wait=not args.no_wait)
    try:
        return _run_locked(args, o, t_start)
    finally:
        lock.release()


def _run_locked(args: argparse.Namespace, o, t_start: float) -> int:
    from . import _frictionid, dask as fdask

    # Paths as the client sees them: the workers may run in another directory.
    runs = fdask.plan([os.path.abspath(i) for i in args.inputs], o, _frictionid.name_list("--group-by", args.group_by))
    _frictionid.check_trend_x([run.spec for run in runs], args.trend_x)
    with_reports = args.per_run_reports == "json"

    if args.scheduler:
        from distributed import Client

        with Client(args.scheduler, timeout=f"{args.timeout}s") as client:
            outcome = fdask.run_on_cluster(runs, client, threads=args.threads,
                                           with_reports=with_reports, retries=args.retries,
                                           runs_per_task=args.runs_per_task)
    else:
        outcome = fdask.run_on_cluster(runs, None, threads=args.threads,
                                       with_reports=with_reports, retries=args.retries,
                                       n_workers=args.workers, runs_per_task=args.runs_per_task)

    _check_interrupted()  # an interrupted batch writes nothing: rerun it
    os.makedirs(args.output, exist_ok=True)
    if with_reports:
        for run in runs:
            report = outcome.reports[run.label]
            if report is not None:
                run_dir = os.path.join(args.output, "runs", run.directory)
                os.makedirs(run_dir, exist_ok=True)
                _frictionid.write_file_atomically(os.path.join(run_dir, "report.json"), report)
    rows = [outcome.rows[run.label] for run in runs]
    csv_text, json_text, html_text = _frictionid.summary_files(
        rows, args.trend_x, args.per_run_reports, {run.label: run.directory for run in runs})
    _frictionid.write_file_atomically(os.path.join(args.output, "summary.csv"), csv_text)
    _frictionid.write_file_atomically(os.path.join(args.output, "summary.json"), json_text)
    _frictionid.write_file_atomically(os.path.join(args.output, "summary.html"), html_text)

    table = fdask.summary_frame(csv_text)
    failed = table[table["status"] != "ok"]
    for label, error in zip(failed["label"], failed["error"]):
        print(f"frictionid: run '{label}' failed: {error}", file=sys.stderr)
    where = args.scheduler or "a LocalCluster"
    print(f"batch: {len(runs)} runs: {len(runs) - len(failed)} fitted, {len(failed)} failed; "
          f"{time.monotonic() - t_start:.2f} s on {where}")
    print(f"summary: {args.output}/summary.csv")
    return EXIT_SOME_RUNS_FAILED if len(failed) else EXIT_OK


def main(argv: Optional[List[str]] = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "batch":
        print("usage: python3 -m frictionid batch INPUTS... --output DIR [options] "
              "(see python3 -m frictionid batch --help)", file=sys.stderr)
        return EXIT_BAD_INPUT
    args = batch_parser().parse_args(argv[1:])  # exits 2 on a bad command line
    from . import _frictionid

    _stop_on_signals()
    try:
        return run_batch(args)
    except (Interrupted, KeyboardInterrupt) as e:
        name = str(e) or "SIGINT"
        print(f"frictionid: interrupted ({name}); no summary written, run the same command again",
              file=sys.stderr)
        return EXIT_INTERRUPTED
    except _frictionid.InputError as e:
        print(f"frictionid: error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except Exception as e:  # the cluster (unreachable, runs lost for good) or the file system
        if getattr(_stop_on_signals, "received", 0):  # a library turned the signal into this
            print("frictionid: interrupted; no summary written, run the same command again",
                  file=sys.stderr)
            return EXIT_INTERRUPTED
        print(f"frictionid: error: {type(e).__name__}: {e}", file=sys.stderr)
        return EXIT_FAILURE


if __name__ == "__main__":
    sys.exit(main())
