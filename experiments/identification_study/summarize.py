#!/usr/bin/python3
"""Tables and plot of the coverage study from coverage_study's per-fit CSV (standard library).

    summarize.py FITS_CSV OUT_DIR NOTE WALL_S SCRATCH_DIR [--merge]

Writes OUT_DIR/results.md, OUT_DIR/results.csv (one line per cell, method and parameter) and
OUT_DIR/coverage.svg (via gnuplot; the data and script go to SCRATCH_DIR).

--merge: FITS_CSV holds only the interval cells (coverage_study --cells intervals). The default
cells are taken unchanged from OUT_DIR/results.csv and the text of OUT_DIR/results.md before the
interval section; NOTE and WALL_S then describe the interval run only.
"""
import csv
import math
import os
import statistics
import subprocess
import sys
from collections import defaultdict

fits_csv, out_dir, note, wall, scratch = sys.argv[1:6]
merge = sys.argv[6:] == ["--merge"]
if sys.argv[6:] and not merge:
    sys.exit(f"summarize.py: unknown option {' '.join(sys.argv[6:])}")
wall = float(wall)
INTERVAL_CELLS = "profile+bootstrap"  # the methods column of the profile and bootstrap cells
INTERVAL_HEADING = "### Other interval methods: profile likelihood and wild bootstrap"

NOISES = ("relative", "absolute", "affine", "additive")
MODELS = ("seed", "corrected", "exact")
PARAMS = ("f", "kappa", "h", "a", "b", "b_tilde", "m", "p0")
SYMBOL = {"kappa": "κ", "b_tilde": "b̃"}
LO, HI = 0.93, 0.97

fits = defaultdict(dict)  # (noise, model, columns, noise_model, methods) -> replicate -> {param: row}
status = defaultdict(dict)
for r in csv.DictReader(open(fits_csv)):
    key = (r["noise"], r["model"], r["columns"], r["noise_model"], r.get("methods", "default"))
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
        extra = {}
        if key[4] == INTERVAL_CELLS:
            # Profile: coverage, and its width as a standard error, half-width / t(0.975, dof)
            # with t from the fit's own model-based interval (ci95 = value -/+ t stderr).
            pr = [r for r in rows if r["profile_lo"]]
            pf = [float(r["profile_lo"]) <= truth <= float(r["profile_hi"]) for r in pr]
            pw = [(float(r["profile_hi"]) - float(r["profile_lo"])) * float(r["stderr"])
                  / (float(r["ci_hi"]) - float(r["ci_lo"])) for r in pr if r["stderr"] and r["ci_lo"]]
            asym = [(float(r["profile_hi"]) - float(r["value"])) / (float(r["value"]) - float(r["profile_lo"]))
                    for r in pr if float(r["value"]) > float(r["profile_lo"])]
            br = [r for r in rows if r["bootstrap_lo"]]
            bf = [float(r["bootstrap_lo"]) <= truth <= float(r["bootstrap_hi"]) for r in br]
            bs = [float(r["stderr_bootstrap"]) for r in br]
            c_pr, e_pr, n_pr = coverage(pf)
            c_bs, e_bs, n_bs = coverage(bf)
            extra = dict(
                coverage_profile=c_pr, coverage_profile_se=e_pr, intervals_profile=n_pr,
                profiles_open=sum(r["profile_closed"] != "1" for r in pr),
                mean_profile_halfwidth_over_t=statistics.fmean(pw) if pw else float("nan"),
                sd_over_profile_halfwidth_over_t=sd / statistics.fmean(pw) if pw else float("nan"),
                median_profile_asymmetry=statistics.median(asym) if asym else float("nan"),
                coverage_bootstrap=c_bs, coverage_bootstrap_se=e_bs, intervals_bootstrap=n_bs,
                mean_stderr_bootstrap=statistics.fmean(bs) if bs else float("nan"),
                sd_over_stderr_bootstrap=sd / statistics.fmean(bs) if bs else float("nan"),
                median_bootstrap_refits=statistics.median(int(r["bootstrap_refits"]) for r in br) if br else 0)
        out.append(dict(
            noise=key[0], model=key[1], sigma_columns=key[2], noise_model=key[3], methods=key[4],
            parameter=p,
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
            median_fit_s=statistics.median(float(r["seconds"]) for r in st.values()), **extra))
    return out


def chosen_share(key):
    """Share of fits whose BIC choice per channel matches the noise that generated the data."""
    want = {"relative": "relative", "absolute": "constant", "affine": "affine",
            "additive": "additive"}[key[0]]
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
                for iv in ("default", INTERVAL_CELLS):
                    allrows += summarize((noise, model, cols, nm, iv))
if merge:
    # Keep the default cells' lines as written (strings, so the numbers stay byte for byte); a
    # file from before the interval cells has no methods column.
    kept = [dict(r, methods=r.get("methods") or "default")
            for r in csv.DictReader(open(os.path.join(out_dir, "results.csv")))]
    allrows = [r for r in kept if r["methods"] != INTERVAL_CELLS] + \
              [r for r in allrows if r["methods"] == INTERVAL_CELLS]
fieldnames = list(max(allrows, key=len))  # an interval cell's line has every column
with open(os.path.join(out_dir, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=fieldnames, restval="")
    w.writeheader()
    w.writerows(allrows)

by = {(r["noise"], r["model"], r["sigma_columns"], r["noise_model"], r["methods"], r["parameter"]): r
      for r in allrows}
sym = lambda p: SYMBOL.get(p, p)
pct = lambda c, e: f"{100 * c:.1f} ± {100 * e:.1f}"
flag = lambda c: "" if LO <= c <= HI else " ✗"

if merge:
    # The default cells as they stand: the text before the interval section.
    kept = open(os.path.join(out_dir, "results.md")).read().split("\n" + INTERVAL_HEADING)[0]
    L = kept.rstrip("\n").split("\n")
else:
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
                    r = by.get((noise, model, cols, "auto", "default", p))
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
                a = by.get((noise, model, "no", "auto", "default", p))
                c = by.get((noise, model, "no", "constant", "default", p))
                if a is None or c is None:
                    continue
                # RMSE of auto on the same replicates as the baseline, for a paired ratio.
                reps = [i for i in fits[(noise, model, "no", "constant", "default")] if p in fits[(noise, model, "no", "constant", "default")][i]
                        and i in fits[(noise, model, "no", "auto", "default")] and p in fits[(noise, model, "no", "auto", "default")][i]]
                t = a["truth"]
                ra = math.sqrt(statistics.fmean([(float(fits[(noise, model, "no", "auto", "default")][i][p]["value"]) - t) ** 2 for i in reps]))
                rc = math.sqrt(statistics.fmean([(float(fits[(noise, model, "no", "constant", "default")][i][p]["value"]) - t) ** 2 for i in reps]))
                if ra > rc * 1.005:  # worse by more than 0.5 %
                    worse.append((noise, model, p, ra / rc))
                L.append(f"| {noise} | {model} | {sym(p)} | {100 * ra / abs(t):.3f} % | {100 * rc / abs(t):.3f} % | "
                         f"{ra / rc:.3f} | {pct(a['coverage'], a['coverage_se'])} % | "
                         f"{pct(c['coverage'], c['coverage_se'])} % | {c['sd_over_stderr']:.2f} |")

    L += ["", "### Noise model chosen by BIC (auto, no σ columns)", "",
          "Share of fits whose per-channel choice is the form that generated the data (relative → "
          "relative, absolute → constant, affine → affine, additive → additive).", "",
          "| noise | model | fits | T_x | T_y | M_z | M_roll |", "|---|---|---:|---:|---:|---:|---:|"]
    for noise in NOISES:
        for model in MODELS:
            key = (noise, model, "no", "auto", "default")
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
# The interval cells: profile likelihood and wild bootstrap next to the model-based and HC3
# intervals of the same fits.
f = lambda x: float(x) if x not in ("", None) else float("nan")
icells = [(noise, model) for noise in NOISES for model in MODELS
          if any(k[:2] == (noise, model) and k[4] == INTERVAL_CELLS for k in by)]
if icells:
    first = next(r for r in allrows if r["methods"] == INTERVAL_CELLS)
    L += ["", INTERVAL_HEADING, ""]
    if merge:
        L += [note, "", f"Interval cells {wall:.0f} s wall.", ""]
    L += [f"Default noise model (auto), no σ columns, the same datasets as the default cells "
          f"(replicate i is the same draw); {first['fits']} replicates per cell (fewer than the default "
          f"cells: each fit refits a few hundred times). Every fit with `--intervals profile "
          f"--bootstrap B` (Rademacher resamples, percentile interval; a median of "
          f"{first['median_bootstrap_refits']:.0f} refits per fit entered it), so the four intervals are paired. Profile s.e.: the profile interval's "
          "half-width over the fit's t(0.975, dof); asymmetry: median over the fits of (upper − "
          "value)/(value − lower). Bootstrap s.e.: the standard deviation of the refits.", "",
          "| noise | model | parameter | fits | rel. bias | rel. RMSE | coverage, model-based | "
          "coverage, HC3 | coverage, profile | SD / profile s.e. | profile asymmetry | "
          "coverage, bootstrap | SD / bootstrap s.e. |",
          "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    imiss = []
    for noise, model in icells:
        for p in PARAMS:
            r = by.get((noise, model, "no", "auto", INTERVAL_CELLS, p))
            if r is None:
                continue
            for method in ("profile", "bootstrap"):
                if not LO <= r[f"coverage_{method}"] <= HI:
                    imiss.append((method, r))
            opened = f" ({r['profiles_open']} open)" if r["profiles_open"] else ""
            L.append(f"| {noise} | {model} | {sym(p)} | {r['fits']} | {100 * r['rel_bias']:+.3f} % | "
                     f"{100 * r['rel_rmse']:.3f} % | {pct(r['coverage'], r['coverage_se'])} %{flag(r['coverage'])} | "
                     f"{pct(r['coverage_hc3'], r['coverage_hc3_se'])} %{flag(r['coverage_hc3'])} | "
                     f"{pct(r['coverage_profile'], r['coverage_profile_se'])} %{flag(r['coverage_profile'])}{opened} | "
                     f"{r['sd_over_profile_halfwidth_over_t']:.2f} | {r['median_profile_asymmetry']:.3f} | "
                     f"{pct(r['coverage_bootstrap'], r['coverage_bootstrap_se'])} %{flag(r['coverage_bootstrap'])} | "
                     f"{r['sd_over_stderr_bootstrap']:.2f} |")
    L += ["", "Profile and bootstrap cells outside 93–97 %:", ""]
    for method, r in imiss:
        ratio = r["sd_over_profile_halfwidth_over_t"] if method == "profile" else r["sd_over_stderr_bootstrap"]
        L.append(f"- {method}: {r['noise']} / {r['model']} / {sym(r['parameter'])}: "
                 f"{pct(r[f'coverage_{method}'], r[f'coverage_{method}_se'])} % (SD / s.e. {ratio:.2f}; "
                 f"model-based on the same fits {pct(r['coverage'], r['coverage_se'])} %)")
    if not imiss:
        L.append("- none")
open(os.path.join(out_dir, "results.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))

# Plot: coverage per cell and parameter; the default cells with the model-based and HC3
# intervals, the interval cells also with the profile and the bootstrap ("?": no such interval).
os.makedirs(scratch, exist_ok=True)
dat = os.path.join(scratch, "coverage.dat")
i, seps, labels, low = 0, [], [], 85.0
cov = lambda r, m: (f"{100 * f(r[m])} {100 * f(r[m + '_se'])}" if r.get(m) not in ("", None) else "? ?")
groups = [(noise, cols, "default") for noise in NOISES for cols in ("no", "yes")] + \
         [(noise, "no", INTERVAL_CELLS) for noise in NOISES]
with open(dat, "w") as fh:
    for noise, cols, iv in groups:
        start_i = i
        for model in MODELS:
            for p in PARAMS:
                r = by.get((noise, model, cols, "auto", iv, p))
                if r is None:
                    continue
                row = [cov(r, m) for m in ("coverage", "coverage_hc3", "coverage_profile", "coverage_bootstrap")]
                low = min([low] + [f(r[m]) * 100 - 2 for m in ("coverage_profile", "coverage_bootstrap")
                                   if r.get(m) not in ("", None)])
                fh.write(f'{i} {" ".join(row)} "{model[:2]} {sym(p)}"\n')
                i += 1
        if i > start_i:
            kind = "profile, bootstrap" if iv == INTERVAL_CELLS else ("σ columns" if cols == "yes" else "auto")
            labels.append((i, f"{noise}, {kind}"))
            seps.append(i - 0.5)
low = math.floor(low)
gp = os.path.join(scratch, "coverage.gp")
with open(gp, "w") as g:
    g.write('set terminal svg size 1600,560 dynamic enhanced font "Helvetica,11"\n')
    g.write(f'set output "{os.path.join(out_dir, "coverage.svg")}"\n')
    g.write('set title "Coverage of the 95 % intervals, default noise model (se: seed, co: corrected, ex: exact)"\n')
    g.write(f'set ylabel "coverage [%]"\nset yrange [{low}:100]\nset grid y\nset xtics rotate by -90 font ",8"\n')
    g.write(f'set xrange [-0.5:{i - 0.5}]\nset key bottom right\nset datafile missing "?"\n')
    g.write('set object 1 rect from graph 0, first 93 to graph 1, first 97 fc rgb "#e8f4e8" fs solid noborder behind\n')
    start = -0.5
    for k, (end, lab) in enumerate(labels):
        g.write(f'set label {k + 1} "{lab}" at {(start + end - 0.5) / 2}, 99 center font ",10"\n')
        start = end - 0.5
    for k, sep in enumerate(seps[:-1]):
        g.write(f'set arrow {k + 1} from {sep}, {low} to {sep}, 100 nohead dt 3 lc "gray"\n')
    g.write(f'plot "{dat}" using ($1-0.21):2:3:xtic(10) with yerrorbars pt 7 ps 0.6 lc "#1f77b4" title "model-based ci95", '
            f'"{dat}" using ($1-0.07):4:5 with yerrorbars pt 6 ps 0.6 lc "#d62728" title "HC3 sandwich", '
            f'"{dat}" using ($1+0.07):6:7 with yerrorbars pt 9 ps 0.6 lc "#2ca02c" title "profile likelihood", '
            f'"{dat}" using ($1+0.21):8:9 with yerrorbars pt 5 ps 0.5 lc "#9467bd" title "wild bootstrap", '
            '95 with lines dt 2 lc "black" title "nominal 95 %"\n')
subprocess.run(["gnuplot", gp], check=True)
