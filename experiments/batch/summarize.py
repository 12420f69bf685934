#!/usr/bin/python3
"""Summarises experiments/batch/run.sh: results.md (times, speed-ups, agreement) and results.svg
(f against load and kappa per run, separate fits against the joint fit). Standard library,
numpy and matplotlib (Debian's python3-matplotlib)."""
import argparse
import csv
import json
import math
import os
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

KAPPA, H = 1.3, 0.12
PARAMS = ("f", "kappa", "h", "a", "b", "m")


def times(out, name):
    wall, user, sys_ = (float(x) for x in open(os.path.join(out, name + ".time")).read().split())
    return wall, user + sys_


def table(path):
    with open(path, newline="") as fh:
        return {row["label"]: row for row in csv.DictReader(fh)}


def main():
    ap = argparse.ArgumentParser()
    for k in ("out", "here", "binary", "load"):
        ap.add_argument("--" + k, required=True)
    for k in ("runs", "rows", "single", "jobs", "bytes", "cpus"):
        ap.add_argument("--" + k, type=int, required=True)
    a = ap.parse_args()
    manifest = table(os.path.join(a.out, "manifest.csv"))
    batch = table(os.path.join(a.out, "batch", "summary.csv"))
    warm = table(os.path.join(a.out, "warm", "summary.csv"))
    shared = table(os.path.join(a.out, "shared", "shared.csv"))
    joint = json.load(open(os.path.join(a.out, "shared", "shared.json")))
    single_labels = open(os.path.join(a.out, "single.txt")).read().split()

    # Agreement of the batch's rows with single fits of the same files, bit for bit.
    same = differ = 0
    for label in single_labels:
        rep = json.load(open(os.path.join(a.out, "single", label, "report.json")))
        for name, p in rep["parameters"].items():
            if float(batch[label][name]) == p["value"]:
                same += 1
            else:
                differ += 1
    scipy_wall = [json.load(open(os.path.join(a.out, "scipy", l + ".json")))["wall_s"]
                  for l in single_labels]

    # Warm-started rows against the full search's: worst distance in standard errors and
    # relative, over the parameters with a standard error; runs that fell back to the full search.
    warm_se = warm_rel = 0.0
    warm_values = 0
    for label, row in batch.items():
        if row["status"] != "ok" or warm[label]["status"] != "ok":
            continue
        for name in PARAMS:
            if not row[name + "_stderr"]:
                continue
            c, w = float(row[name]), float(warm[label][name])
            warm_se = max(warm_se, abs(w - c) / float(row[name + "_stderr"]))
            warm_rel = max(warm_rel, abs(w - c) / abs(c))
            warm_values += 1
    full_search = sum(
        1 for l in warm
        if "warm start" not in json.load(open(os.path.join(a.out, "warm", "runs", l, "report.json")))[
            "global_search"]["algorithm"])

    t = {k: times(a.out, k) for k in ("batch", "warm", "shared", "single", "scipy")}
    per = lambda k, n: 1000.0 * t[k][0] / n  # noqa: E731  ms of wall per run
    ok = [l for l in batch if batch[l]["status"] == "ok"]
    kappa_sep = [float(batch[l]["kappa"]) for l in ok]
    kappa_se = [float(batch[l]["kappa_stderr"]) for l in ok if batch[l]["kappa_stderr"]]
    kj = joint["shared"]["kappa"]
    hj = joint["shared"]["h"]
    loads = sorted({int(manifest[l]["load"]) for l in manifest})

    lines = [
        "# A campaign fitted five ways",
        "",
        f"{a.runs} runs of {a.rows} rows ({a.bytes / 1e6:.1f} MB of CSV): seed model, Hertz "
        "pressure, 1 % noise, a friction f per load, κ = 1.3 and h = 0.12 common to every run. "
        f"Binary: {a.binary}. {a.cpus} CPUs, `--jobs {a.jobs}`; load average {a.load}. Wall "
        "times on a shared machine: the CPU column (user + system) is the steadier figure.",
        "",
        "| method | runs | wall [s] | CPU [s] | wall per run [ms] |",
        "|---|---:|---:|---:|---:|",
        f"| `frictionid batch` (report.json per run) | {a.runs} | {t['batch'][0]:.2f} | "
        f"{t['batch'][1]:.2f} | {per('batch', a.runs):.1f} |",
        f"| `frictionid batch --warm-start` (report.json per run) | {a.runs} | {t['warm'][0]:.2f} | "
        f"{t['warm'][1]:.2f} | {per('warm', a.runs):.1f} |",
        f"| `frictionid batch --shared kappa,h` (own fits + joint fit) | {a.runs} | "
        f"{t['shared'][0]:.2f} | {t['shared'][1]:.2f} | {per('shared', a.runs):.1f} |",
        f"| loop of `frictionid fit` (full report each) | {a.single} | {t['single'][0]:.2f} | "
        f"{t['single'][1]:.2f} | {per('single', a.single):.1f} |",
        f"| loop of scipy `least_squares` (local stage only, one process each) | {a.single} | "
        f"{t['scipy'][0]:.2f} | {t['scipy'][1]:.2f} | {per('scipy', a.single):.1f} |",
        "",
        f"- Batch against a loop of single fits: {per('single', a.single) / per('batch', a.runs):.1f}× "
        "less wall per run; against the scipy loop "
        f"{per('scipy', a.single) / per('batch', a.runs):.1f}× (scipy's `least_squares` call alone: "
        f"median {1000 * statistics.median(scipy_wall):.1f} ms per run, without the global stage "
        "and noise model frictionid's fit includes).",
        f"- Warm start: {per('batch', a.runs) / per('warm', a.runs):.1f}× less wall than the batch "
        f"without it; {full_search} of {a.runs} runs got the full search (the first, and those "
        f"failing the check); its {warm_values} determined values lie within "
        f"{warm_se:.1g} standard errors ({warm_rel:.1g} relative) of the full search's.",
        f"- Agreement: of {same + differ} parameter values of the first {a.single} runs, {same} "
        "equal the single `fit` of the same file bit for bit.",
        f"- Joint fit: κ = {kj['value']:.6f} ± {kj['stderr']:.2g}, h = {hj['value']:.6f} ± "
        f"{hj['stderr']:.2g} (truth 1.3, 0.12; {abs(kj['value'] - KAPPA) / kj['stderr']:.1f} and "
        f"{abs(hj['value'] - H) / hj['stderr']:.1f} standard errors away); "
        f"{joint['solver']['iterations']} iterations, {joint['solver']['linear_solver']}, "
        f"reduced χ² {joint['reduced_chi2']:.3f}.",
        f"- Separate fits: κ scatters with SD {statistics.pstdev(kappa_sep):.2g} around "
        f"{statistics.mean(kappa_sep):.5f}, median stderr {statistics.median(kappa_se):.2g}: "
        f"the joint stderr is {statistics.median(kappa_se) / kj['stderr']:.1f}× smaller "
        f"(√runs = {math.sqrt(len(ok)):.1f}).",
        "",
        "| load [N] | f true | f separate: mean ± SD | f joint: mean ± SD | joint stderr (median) |",
        "|---:|---:|---:|---:|---:|",
    ]
    for n in loads:
        ls = [l for l in ok if int(manifest[l]["load"]) == n]
        fs = [float(batch[l]["f"]) for l in ls]
        fj = [float(shared[l]["f"]) for l in ls]
        se = [float(shared[l]["f_stderr"]) for l in ls]
        lines.append(f"| {n} | {float(manifest[ls[0]]['f_true']):.4f} | {statistics.mean(fs):.5f} ± "
                     f"{statistics.pstdev(fs):.2g} | {statistics.mean(fj):.5f} ± "
                     f"{statistics.pstdev(fj):.2g} | {statistics.median(se):.2g} |")
    lines += ["", "![f per run and kappa: separate fits against the joint fit](results.svg)", ""]
    with open(os.path.join(a.here, "results.md"), "w") as fh:
        fh.write("\n".join(lines))

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    # Left: each run's f minus the truth, separate fits (grey, left) and joint (blue, right).
    for l in ok:
        n = int(manifest[l]["load"])
        truth = float(manifest[l]["f_true"])
        ax1.plot(n - 120, 1e3 * (float(batch[l]["f"]) - truth), ".", color="0.6", ms=2)
        ax1.plot(n + 120, 1e3 * (float(shared[l]["f"]) - truth), ".", color="tab:blue", ms=2)
    ax1.axhline(0.0, color="k", lw=1)
    ax1.plot([], [], ".", color="0.6", label="separate fits")
    ax1.plot([], [], ".", color="tab:blue", label="joint fit (κ, h shared)")
    ax1.set_xlabel("load N [N]")
    ax1.set_ylabel("f − f_true [10⁻³]")
    ax1.set_title("friction per run", fontsize=10)
    ax1.legend(fontsize=8)
    # Right: the runs' own kappa against the one joint kappa.
    ax2.hist(kappa_sep, bins=40, color="0.7", label=f"separate fits ({len(kappa_sep)} runs)")
    ax2.axvspan(kj["ci95"][0], kj["ci95"][1], color="tab:blue", alpha=0.6, label="joint ci95")
    ax2.axvline(KAPPA, color="k", lw=1, label="truth")
    ax2.set_xlabel("κ")
    ax2.set_ylabel("runs")
    ax2.set_title("tilt κ: each run alone and all runs together", fontsize=10)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.here, "results.svg"), metadata={"Date": None})


if __name__ == "__main__":
    main()
