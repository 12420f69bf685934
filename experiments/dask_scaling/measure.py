"""Throughput of frictionid.dask against the number of worker processes, and the scheduler's
overhead per run. Called by run.sh with the campaign directories it generated; prints a Markdown
table body on stdout (run.sh writes results.md).

    measure.py NORMAL_DIR TRIVIAL_DIR REPS
"""

import logging
import os
import statistics
import sys
import time

from distributed import Client, LocalCluster

from frictionid import _fit, _frictionid
from frictionid import dask as fdask

FIT = dict(model="exact", pressure="hertz")


def median_time(action, reps):
    times = []
    for _ in range(reps):
        t = time.perf_counter()
        action()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def noop(x):
    return x


def main():
    normal_dir, trivial_dir, reps = sys.argv[1], sys.argv[2], int(sys.argv[3])
    options = _fit.options(**FIT, threads=1)
    # Seed model, no global stage, 20 rows: a fit of a few milliseconds, so that what a run costs
    # beyond it through Dask is the scheduler's and the transport's share.
    trivial_options = _fit.options(model="seed", pressure="hertz", threads=1,
                                   global_search=False)
    normal = fdask.plan([normal_dir], options, "")
    trivial = fdask.plan([trivial_dir], trivial_options, "")

    def in_process(runs):
        for run in runs:
            fdask.fit_run(run.spec, 1, False)

    lines = []
    t_normal_1 = median_time(lambda: in_process(normal), reps)
    t_trivial_1 = median_time(lambda: in_process(trivial), reps)
    lines.append(("in process, 1 thread (no Dask)", "—", len(normal) / t_normal_1,
                  t_trivial_1 / len(trivial) * 1e3))

    overhead = {}
    for workers in (1, 2):
        t = time.perf_counter()
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          host="127.0.0.1", dashboard_address=None,
                          silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
            startup = time.perf_counter() - t
            fdask.run_on_cluster(normal[:workers], client)  # warm: imports on every worker
            t_normal = median_time(lambda: fdask.run_on_cluster(normal, client), reps)
            t_trivial = median_time(lambda: fdask.run_on_cluster(trivial, client), reps)
            lines.append((f"fit_many on {workers} worker process(es)", f"{startup:.1f}",
                          len(normal) / t_normal, t_trivial / len(trivial) * 1e3))
            if workers == 1:
                # One task at a time: the full round trip client -> scheduler -> worker -> back.
                rt = median_time(lambda: client.submit(noop, 1, pure=False).result(), 500)
                # Many at once: what the scheduler sustains (tasks/s) when it is the bottleneck.
                n = 2000
                t_many = median_time(
                    lambda: client.gather(client.map(noop, range(n), pure=False)), 3)
                overhead = {"round_trip_ms": rt * 1e3, "tasks_per_s": n / t_many,
                            "trivial_ms": t_trivial / len(trivial) * 1e3}

    print("| how | cluster start [s] | runs/s (%d runs, exact, 200 rows, global 3000) | "
          "ms per trivial run (%d runs, seed, 20 rows, --no-global) |" % (len(normal), len(trivial)))
    print("|---|---:|---:|---:|")
    for how, startup, rate, trivial_ms in lines:
        print(f"| {how} | {startup} | {rate:.2f} | {trivial_ms:.1f} |")
    inproc_ms = t_trivial_1 / len(trivial) * 1e3
    print()
    print(f"- in-process fit of a trivial run: {inproc_ms:.2f} ms; through fit_many on one "
          f"worker: {overhead['trivial_ms']:.2f} ms, so Dask adds "
          f"{overhead['trivial_ms'] - inproc_ms:.2f} ms per run when runs are queued")
    print(f"- no-op task, one at a time (submit -> result): {overhead['round_trip_ms']:.2f} ms "
          "round trip")
    print(f"- no-op tasks, 2000 submitted at once, 1 worker: {overhead['tasks_per_s']:.0f} "
          "tasks/s")


if __name__ == "__main__":
    main()
