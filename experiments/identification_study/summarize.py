#!/usr/bin/python3
"""Tables and plot of the coverage study from coverage_study's per-fit CSV (standard library).

    summarize.py FITS_CSV OUT_DIR NOTE WALL_S SCRATCH_DIR

Writes OUT_DIR/results.md, OUT_DIR/results.csv (one line per cell, method and parameter) and
OUT_DIR/coverage.svg (via gnuplot; the data and script go to SCRATCH_DIR).
"""
import csv
import math
import os
import statistics
import subprocess
import sys
from collections import defaultdict

fits_csv, out_dir, note, wall, scratch = sys.argv[1:6]
wall = float(wall)

NOISES = ("relative", "absolute", "affine")
MODELS = ("seed", "corrected", "exact")
PARAMS = ("f", "kappa", "h", "a", "b", "b_tilde", "m", "p0")
SYMBOL = {"kappa": "κ", "b_tilde": "b̃"}
LO, HI = 0.93, 0.97

fits = defaultdict(dict)  # (noise, model, columns, noise_model) -> replicate -> {param: row}
status = defaultdict(dict)
for r in csv.DictReader(open(fits_csv)):
    key = (r["noise"], r["model"], r["columns"], r["noise_model"])
    status[key][r["replicate"]] = r
    if r["status"] != "failed":
        fits[key].setdefault(r["replicate"], {})[r["parameter"]] = r


def num(x):
    return float(x) if x not in ("", None) else None


def coverage(hits):
    n = len(hits)
    if n == 0:
        return float("nan"), float("nan"), 0
    p = sum(hits) / n
    return p, math.sqrt(max(p * (1 - p), 1e-12) / n), n


def summarize(key):
    reps = fits[key]
    st = status[key]
    out = []
    if not reps:
        return out
    names = [p for p in PARAMS if p in next(iter(reps.values()))]
    for p in names:
        rows = [reps[i][p] for i in reps if p in reps[i]]
        truth = float(rows[0]["truth"])
        est = [float(r["value"]) for r in rows]
        se = [num(r["stderr"]) for r in rows if num(r["stderr"]) is not None]
        sw = [num(r["stderr_sandwich"]) for r in rows if num(r["stderr_sandwich"]) is not None]
        mb = [float(r["ci_lo"]) <= truth <= float(r["ci_hi"]) for r in rows if r["ci_lo"]]
        hc = [float(r["hc3_lo"]) <= truth <= float(r["hc3_hi"]) for r in rows if r["hc3_lo"]]
        sd = statistics.stdev(est)
        bias = statistics.fmean(est) - truth
        rmse = math.sqrt(statistics.fmean([(e - truth) ** 2 for e in est]))
        c_mb, e_mb, n_mb = coverage(mb)
        c_hc, e_hc, n_hc = coverage(hc)
        out.append(dict(
            noise=key[0], model=key[1], sigma_columns=key[2], noise_model=key[3], parameter=p,
            truth=truth, fits=len(rows), failed=sum(r["status"] == "failed" for r in st.values()),
            not_converged=sum(r["status"] == "not_converged" for r in st.values()),
            bias=bias, rel_bias=bias / truth, bias_over_se_of_mean=bias / (sd / math.sqrt(len(est))),
            rmse=rmse, rel_rmse=rmse / abs(truth), sd=sd,
            mean_stderr=statistics.fmean(se) if se else float("nan"),
            mean_stderr_sandwich=statistics.fmean(sw) if sw else float("nan"),
            sd_over_stderr=sd / statistics.fmean(se) if se else float("nan"),
            sd_over_stderr_sandwich=sd / statistics.fmean(sw) if sw else float("nan"),
            coverage=c_mb, coverage_se=e_mb, intervals=n_mb,
            coverage_hc3=c_hc, coverage_hc3_se=e_hc, intervals_hc3=n_hc,
            median_fit_s=statistics.median(float(r["seconds"]) for r in st.values())))
    return out


def chosen_share(key):
    """Share of fits whose BIC choice per channel matches the noise that generated the data."""
    want = {"relative": "relative", "absolute": "constant", "affine": "affine"}[key[0]]
    per_channel = defaultdict(int)
    n = 0
    for rep in fits[key].values():
        r = next(iter(rep.values()))
        n += 1
        for c, m in zip(("T_x", "T_y", "M_z", "M_roll"), r["chosen"].split("/")):
            per_channel[c] += m == want
    return {c: per_channel[c] / n for c in ("T_x", "T_y", "M_z", "M_roll")}, n


allrows = []
for noise in NOISES:
    for model in MODELS:
        for cols in ("no", "yes"):
            for nm in ("auto", "constant"):
                allrows += summarize((noise, model, cols, nm))
with open(os.path.join(out_dir, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(allrows[0]))
    w.writeheader()
    w.writerows(allrows)

by = {(r["noise"], r["model"], r["sigma_columns"], r["noise_model"], r["parameter"]): r for r in allrows}
sym = lambda p: SYMBOL.get(p, p)
pct = lambda c, e: f"{100 * c:.1f} ± {100 * e:.1f}"
flag = lambda c: "" if LO <= c <= HI else " ✗"

L = [note, "", f"Whole study {wall:.0f} s wall.", ""]
L += ["### Default method (`--noise-model auto`; with σ columns that is `columns`)", "",
      "Coverage: share of fits whose interval contains the truth, ± binomial standard error; ✗ marks "
      "a cell outside 93–97 %. Model-based: `ci95` of report.json (value ± t·stderr). HC3: "
      "value ± t·`stderr_sandwich`. SD/s.e.: standard deviation of the estimates over the mean "
      "reported standard error (1 when the standard error is right).", "",
      "| noise | model | σ columns | parameter | fits | rel. bias | bias / SE(mean) | rel. RMSE | "
      "coverage, model-based | SD / s.e. | coverage, HC3 | SD / s.e. HC3 |",
      "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
misses = []
for noise in NOISES:
    for model in MODELS:
        for cols in ("no", "yes"):
            for p in PARAMS:
                r = by.get((noise, model, cols, "auto", p))
                if r is None:
                    continue
                if not LO <= r["coverage"] <= HI:
                    misses.append(("model-based", r))
                if not LO <= r["coverage_hc3"] <= HI:
                    misses.append(("HC3", r))
                fails = f" ({r['failed']} failed)" if r["failed"] else ""
                L.append(f"| {noise} | {model} | {cols} | {sym(p)} | {r['fits']}{fails} | "
                         f"{100 * r['rel_bias']:+.3f} % | {r['bias_over_se_of_mean']:+.1f} | "
                         f"{100 * r['rel_rmse']:.3f} % | {pct(r['coverage'], r['coverage_se'])} %"
                         f"{flag(r['coverage'])} | {r['sd_over_stderr']:.2f} | "
                         f"{pct(r['coverage_hc3'], r['coverage_hc3_se'])} %{flag(r['coverage_hc3'])} | "
                         f"{r['sd_over_stderr_sandwich']:.2f} |")

L += ["", "### Precision and coverage: default (auto) vs the old-style baseline (`--noise-model constant`), no σ columns", "",
      "Same datasets (replicate i has the same noise draw in both); the baseline on the first "
      "replicates only. RMSE ratio < 1: the default is more precise.", "",
      "| noise | model | parameter | rel. RMSE auto | rel. RMSE constant | RMSE ratio auto / constant | coverage auto | coverage constant | SD / s.e. constant |",
      "|---|---|---|---:|---:|---:|---:|---:|---:|"]
worse = []
for noise in NOISES:
    for model in MODELS:
        for p in PARAMS:
            a = by.get((noise, model, "no", "auto", p))
            c = by.get((noise, model, "no", "constant", p))
            if a is None or c is None:
                continue
            # RMSE of auto on the same replicates as the baseline, for a paired ratio.
            reps = [i for i in fits[(noise, model, "no", "constant")] if p in fits[(noise, model, "no", "constant")][i]
                    and i in fits[(noise, model, "no", "auto")] and p in fits[(noise, model, "no", "auto")][i]]
            t = a["truth"]
            ra = math.sqrt(statistics.fmean([(float(fits[(noise, model, "no", "auto")][i][p]["value"]) - t) ** 2 for i in reps]))
            rc = math.sqrt(statistics.fmean([(float(fits[(noise, model, "no", "constant")][i][p]["value"]) - t) ** 2 for i in reps]))
            if ra > rc * 1.005:  # worse by more than 0.5 %
                worse.append((noise, model, p, ra / rc))
            L.append(f"| {noise} | {model} | {sym(p)} | {100 * ra / abs(t):.3f} % | {100 * rc / abs(t):.3f} % | "
                     f"{ra / rc:.3f} | {pct(a['coverage'], a['coverage_se'])} % | "
                     f"{pct(c['coverage'], c['coverage_se'])} % | {c['sd_over_stderr']:.2f} |")

L += ["", "### Noise model chosen by BIC (auto, no σ columns)", "",
      "Share of fits whose per-channel choice is the form that generated the data (relative → "
      "relative, absolute → constant, affine → affine).", "",
      "| noise | model | fits | T_x | T_y | M_z | M_roll |", "|---|---|---:|---:|---:|---:|---:|"]
for noise in NOISES:
    for model in MODELS:
        key = (noise, model, "no", "auto")
        if not fits[key]:
            continue
        share, n = chosen_share(key)
        L.append(f"| {noise} | {model} | {n} | " + " | ".join(f"{100 * share[c]:.1f} %" for c in share) + " |")

L += ["", "### Cells outside 93–97 %", ""]
if misses:
    for method, r in misses:
        cov = r["coverage"] if method == "model-based" else r["coverage_hc3"]
        se = r["coverage_se"] if method == "model-based" else r["coverage_hc3_se"]
        ratio = r["sd_over_stderr"] if method == "model-based" else r["sd_over_stderr_sandwich"]
        L.append(f"- {method}: {r['noise']} / {r['model']} / σ columns {r['sigma_columns']} / "
                 f"{sym(r['parameter'])}: {pct(cov, se)} % (SD / s.e. {ratio:.2f}, bias / SE(mean) "
                 f"{r['bias_over_se_of_mean']:+.1f})")
else:
    L.append("- none")
L += ["", "### Parameters where the default is less precise than the baseline (RMSE ratio > 1.005)", ""]
L += [f"- {n} / {m} / {sym(p)}: ratio {q:.3f}" for n, m, p, q in worse] or ["- none"]
open(os.path.join(out_dir, "results.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))

# Plot: coverage of the default method per cell and parameter, model-based and HC3.
os.makedirs(scratch, exist_ok=True)
dat = os.path.join(scratch, "coverage.dat")
i, seps, labels = 0, [], []
with open(dat, "w") as fh:
    for noise in NOISES:
        for cols in ("no", "yes"):
            for model in MODELS:
                for p in PARAMS:
                    r = by.get((noise, model, cols, "auto", p))
                    if r is None:
                        continue
                    fh.write(f'{i} {100 * r["coverage"]} {100 * r["coverage_se"]} '
                             f'{100 * r["coverage_hc3"]} {100 * r["coverage_hc3_se"]} '
                             f'"{model[:2]} {sym(p)}"\n')
                    i += 1
            labels.append((i, f"{noise}, {'σ columns' if cols == 'yes' else 'auto'}"))
            seps.append(i - 0.5)
gp = os.path.join(scratch, "coverage.gp")
with open(gp, "w") as g:
    g.write('set terminal svg size 1400,520 dynamic enhanced font "Helvetica,11"\n')
    g.write(f'set output "{os.path.join(out_dir, "coverage.svg")}"\n')
    g.write('set title "Coverage of the 95 % intervals, default noise model (se: seed, co: corrected, ex: exact)"\n')
    g.write('set ylabel "coverage [%]"\nset yrange [85:100]\nset grid y\nset xtics rotate by -90 font ",8"\n')
    g.write(f'set xrange [-0.5:{i - 0.5}]\nset key bottom right\n')
    g.write('set object 1 rect from graph 0, first 93 to graph 1, first 97 fc rgb "#e8f4e8" fs solid noborder behind\n')
    start = -0.5
    for k, (end, lab) in enumerate(labels):
        g.write(f'set label {k + 1} "{lab}" at {(start + end - 0.5) / 2}, 99 center font ",10"\n')
        start = end - 0.5
    for k, s in enumerate(seps[:-1]):
        g.write(f'set arrow {k + 1} from {s}, 85 to {s}, 100 nohead dt 3 lc "gray"\n')
    g.write(f'plot "{dat}" using ($1-0.15):2:3:xtic(6) with yerrorbars pt 7 ps 0.6 lc "#1f77b4" title "model-based ci95", '
            f'"{dat}" using ($1+0.15):4:5 with yerrorbars pt 6 ps 0.6 lc "#d62728" title "HC3 sandwich", '
            '95 with lines dt 2 lc "black" title "nominal 95 %"\n')
subprocess.run(["gnuplot", gp], check=True)
