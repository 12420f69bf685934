#!/usr/bin/python3
"""Tables and plot of the coverage study from coverage_study's per-fit CSV (standard library).

    summarize.py FITS_CSV OUT_DIR NOTE WALL_S SCRATCH_DIR [--merge intervals|designs]

Writes OUT_DIR/results.md, OUT_DIR/results.csv (one line per cell, method and parameter) and
OUT_DIR/coverage.svg (via gnuplot; the data and script go to SCRATCH_DIR).

The cells fall in three groups, each with its own section of results.md: the default cells, the
interval cells (profile and bootstrap) and the design cells (additive noise, few rows, eps only
above 1.5, noise-free channels). --merge G: FITS_CSV holds only group G (coverage_study --cells
G). The other groups are taken unchanged from OUT_DIR/results.csv and their sections of
OUT_DIR/results.md; NOTE and WALL_S then describe the run of G only. (--merge alone: intervals.)
"""
import csv
import math
import os
import statistics
import subprocess
import sys
from collections import defaultdict

fits_csv, out_dir, note, wall, scratch = sys.argv[1:6]
opts = sys.argv[6:]
if opts == ["--merge"]:
    opts = ["--merge", "intervals"]
if opts and not (len(opts) == 2 and opts[0] == "--merge" and opts[1] in ("intervals", "designs")):
    sys.exit(f"summarize.py: unknown option {' '.join(opts)}")
merge = opts[1] if opts else None  # the group FITS_CSV holds; None: every group
wall = float(wall)
INTERVAL_CELLS = "profile+bootstrap"  # the methods column of the profile and bootstrap cells
INTERVAL_HEADING = "### Other interval methods: profile likelihood and wild bootstrap"
DESIGN_HEADING = "### Designs: additive noise, few rows, ε only above 1.5, noise-free channels"
HEADINGS = {"intervals": INTERVAL_HEADING, "designs": DESIGN_HEADING}
# The design cells (coverage_study.cpp, kDesigns): name, what it changes, its noise condition.
DESIGNS = {
    "rows600": "600 rows, additive noise",
    "rows60": "60 rows, additive noise",
    "rows20": "20 rows",
    "rows8": "8 rows",
    "eps1.5": "ε only in 1.5–100",
    "noisefree": "T_x and M_z noise-free",
}

NOISES = ("relative", "absolute", "affine", "additive")
MODELS = ("seed", "corrected", "exact")
PARAMS = ("f", "kappa", "h", "a", "b", "b_tilde", "m", "p0")
SYMBOL = {"kappa": "κ", "b_tilde": "b̃"}
LO, HI = 0.93, 0.97

def group(r):
    """The group of a per-fit line or a results.csv line: default, intervals or designs."""
    if (r.get("design") or "default") != "default":
        return "designs"
    return "intervals" if r.get("methods") == INTERVAL_CELLS else "default"


# (noise, model, columns, noise_model, methods, design) -> replicate -> {param: row}
fits = defaultdict(dict)
status = defaultdict(dict)
for r in csv.DictReader(open(fits_csv)):
    key = (r["noise"], r["model"], r["columns"], r["noise_model"], r.get("methods", "default"),
           r.get("design") or "default")
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
        if key[5] != "default":
            # Design cells: the interval the default states (ci95_profile for a parameter with
            # |r| > 0.99 to another, which the default profiles too; ci95 otherwise), and the
            # profile interval of every parameter where the cell asked for it.
            shown = [(float(r["profile_lo"]) <= truth <= float(r["profile_hi"]))
                     if r["correlated"] == "1" and r["profile_lo"]
                     else float(r["ci_lo"]) <= truth <= float(r["ci_hi"])
                     for r in rows if r["ci_lo"]]
            pr = [r for r in rows if r["profile_lo"]]
            pf = [float(r["profile_lo"]) <= truth <= float(r["profile_hi"]) for r in pr]
            pw = [(float(r["profile_hi"]) - float(r["profile_lo"])) * float(r["stderr"])
                  / (float(r["ci_hi"]) - float(r["ci_lo"])) for r in pr if r["stderr"] and r["ci_lo"]]
            c_sh, e_sh, n_sh = coverage(shown)
            c_pr, e_pr, n_pr = coverage(pf)
            fitted = [r for r in st.values() if r["status"] != "failed"]
            extra = dict(
                coverage_shown=c_sh, coverage_shown_se=e_sh, intervals_shown=n_sh,
                profiled_by_default=sum(r["correlated"] == "1" for r in rows) / len(rows),
                coverage_profile=c_pr, coverage_profile_se=e_pr, intervals_profile=n_pr,
                profiles_open=sum(r["profile_closed"] != "1" for r in pr),
                mean_profile_halfwidth_over_t=statistics.fmean(pw) if pw else float("nan"),
                sd_over_profile_halfwidth_over_t=sd / statistics.fmean(pw) if pw else float("nan"),
                median_dof=statistics.median(int(r["dof"]) for r in fitted),
                share_floor_warning=sum(int(r["floored"]) > 0 for r in fitted) / len(fitted),
                share_any_warning=sum(int(r["warnings"]) > 0 for r in fitted) / len(fitted))
        out.append(dict(
            noise=key[0], design=key[5], model=key[1], sigma_columns=key[2], noise_model=key[3],
            methods=key[4], parameter=p,
            truth=truth, fits=len(rows), failed=sum(r["status"] == "failed" for r in st.values()),
            not_converged=sum(r["status"] == "not_converged" for r in st.values()),
            bias=bias, rel_bias=bias / truth, bias_over_se_of_mean=bias / (sd / math.sqrt(len(est))) if sd > 0 else float("nan"),
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


def chosen_counts(key):
    """Per channel, the noise models chosen over the cell's fits, most frequent first."""
    per_channel = {c: defaultdict(int) for c in ("T_x", "T_y", "M_z", "M_roll")}
    n = 0
    for rep in fits[key].values():
        r = next(iter(rep.values()))
        n += 1
        for c, m in zip(per_channel, r["chosen"].split("/")):
            per_channel[c][m] += 1
    return {c: sorted(v.items(), key=lambda kv: -kv[1]) for c, v in per_channel.items()}, n


def warning_shares(key):
    """The share of the cell's fits with a warning of each kind (coverage_study's warning_kinds)."""
    counts, n = defaultdict(int), 0
    for rep in fits[key].values():
        r = next(iter(rep.values()))
        n += 1
        for kind in set(filter(None, r.get("warning_kinds", "").split(";"))):
            counts[kind] += 1
    return sorted(((k, c / n) for k, c in counts.items()), key=lambda kv: -kv[1])


allrows = []
for design in ["default"] + list(DESIGNS):
    for noise in NOISES:
        for model in MODELS:
            for cols in ("no", "yes"):
                for nm in ("auto", "constant", "relative", "additive"):
                    for iv in ("default", INTERVAL_CELLS, "profile"):
                        allrows += summarize((noise, model, cols, nm, iv, design))
if merge:
    # Keep the other groups' lines as written (strings, so the numbers stay byte for byte); a
    # file from before the interval cells has no methods column, one from before the design
    # cells no design column.
    kept = [dict(r, methods=r.get("methods") or "default", design=r.get("design") or "default")
            for r in csv.DictReader(open(os.path.join(out_dir, "results.csv")))]
    allrows = [r for r in kept if group(r) != merge] + [r for r in allrows if group(r) == merge]
fieldnames = []  # every column of any line, in the order of first appearance
for r in allrows:
    fieldnames += [k for k in r if k not in fieldnames]
with open(os.path.join(out_dir, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=fieldnames, restval="")
    w.writeheader()
    w.writerows(allrows)

by = {(r["noise"], r["model"], r["sigma_columns"], r["noise_model"], r["methods"], r["parameter"]): r
      for r in allrows if group(r) != "designs"}
# The design cells of the default method (no σ columns, auto), and every design cell.
by_design = {(r["design"], r["model"], r["parameter"]): r for r in allrows if group(r) == "designs"
             and (r["sigma_columns"], r["noise_model"]) == ("no", "auto")}
by_variant = {(r["design"], r["model"], r["sigma_columns"], r["noise_model"], r["parameter"]): r
              for r in allrows if group(r) == "designs"}
FORM = {"additive": "additive", "relative": "relative"}  # the noise model of the generating form
sym = lambda p: SYMBOL.get(p, p)
pct = lambda c, e: f"{100 * c:.1f} ± {100 * e:.1f}"
flag = lambda c: "" if LO <= c <= HI else " ✗"

def md_sections(text):
    """results.md split into its groups' sections: default (everything before the first other
    heading), intervals and designs (each from its heading to the next)."""
    cuts = sorted((text.find("\n" + h), g) for g, h in HEADINGS.items() if "\n" + h in text)
    out = {"default": text[:cuts[0][0]] if cuts else text}
    for (start, g), nxt in zip(cuts, cuts[1:] + [(len(text), None)]):
        out[g] = text[start + 1:nxt[0]]
    return {g: t.strip("\n") for g, t in out.items()}


kept_md = md_sections(open(os.path.join(out_dir, "results.md")).read()) if merge else {}
if merge:
    # The default cells as they stand.
    L = kept_md["default"].split("\n")
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
                reps = [i for i in fits[(noise, model, "no", "constant", "default", "default")] if p in fits[(noise, model, "no", "constant", "default", "default")][i]
                        and i in fits[(noise, model, "no", "auto", "default", "default")] and p in fits[(noise, model, "no", "auto", "default", "default")][i]]
                t = a["truth"]
                ra = math.sqrt(statistics.fmean([(float(fits[(noise, model, "no", "auto", "default", "default")][i][p]["value"]) - t) ** 2 for i in reps]))
                rc = math.sqrt(statistics.fmean([(float(fits[(noise, model, "no", "constant", "default", "default")][i][p]["value"]) - t) ** 2 for i in reps]))
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
            key = (noise, model, "no", "auto", "default", "default")
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
if merge and merge != "intervals":
    if "intervals" in kept_md:
        L += ["", kept_md["intervals"]]
elif icells:
    first = next(r for r in allrows if r["methods"] == INTERVAL_CELLS)
    L += ["", INTERVAL_HEADING, ""]
    if merge == "intervals":
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

# The design cells: the same fits' ci95, the interval the default states, HC3 and the profile.
dcells = [(d, model) for d in DESIGNS for model in MODELS
          if any(k[:2] == (d, model) for k in by_design)]
if merge and merge != "designs":
    if "designs" in kept_md:
        L += ["", kept_md["designs"]]
elif dcells:
    L += ["", DESIGN_HEADING, ""]
    if merge == "designs":
        L += [note, "", f"Design cells {wall:.0f} s wall.", ""]
    profiled = any(f(r.get("coverage_profile")) == f(r.get("coverage_profile")) and
                   int(r["intervals_profile"]) == int(r["fits"]) for r in by_design.values())
    L += ["Default noise model (auto), no σ columns, default fit settings; one change to the design "
          "each (coverage_study.cpp, `kDesigns`): additive noise (the `additive` condition: σ = s_abs + "
          "s_rel |y|, s_rel = 2 / 0.2 / 1 / 0.1 % and s_abs = 0.1 / 2 / 0.5 / 1 % of the RMS for T_x / T_y "
          "/ M_z / M_roll) on 600 and on 60 rows; 20 and 8 rows; ε only in 1.5–100 (600 rows); T_x "
          "and M_z noise-free (600 rows). The last four with the `relative` condition (s_rel = 1 / 3 / "
          "2 / 0.5 %). σ_abs is a fraction of the channel's RMS over the default design's 600 rows "
          "in every design. Replicate i has the same noise draw as replicate i of the default cells "
          "of its condition and model (on its own rows).", "",
          "Intervals, all from the same fits: **ci95** (value ± t·stderr; the interval report.md's table "
          "shows by default); **stated**: the interval the default fit states, `ci95_profile` for a "
          "parameter with |r| > 0.99 to another (computed by default and quoted in the correlation "
          "warning; report.json has it for exactly these) and `ci95` otherwise — “profiled” gives the "
          "share of fits where that was the profile; **HC3** (value ± t·`stderr_sandwich`)"
          + ("; **profile**: `ci95_profile` of every parameter (the cells ran with `--intervals "
             "profile`, which leaves the estimate, ci95 and HC3 as the default fit has them)." if profiled else ".")
          + " SD/s.e.: SD of the estimates over the mean standard error (profile: half-width over t).", "",
          "| design | model | parameter | fits | rel. bias | bias / SE(mean) | rel. RMSE | coverage, ci95 | SD / s.e. | "
          "coverage, stated (profiled) | coverage, HC3 | SD / s.e. HC3 | coverage, profile | SD / profile s.e. |",
          "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    TEXT = ("noise", "design", "model", "sigma_columns", "noise_model", "methods", "parameter")
    numeric = lambda r: {k: v if k in TEXT else f(v) for k, v in r.items()}  # kept lines are text
    signed = lambda x: f"{x:+.1f}" if x == x else "–"  # nan: every estimate the same (SD 0)
    dmiss = []
    for d, model in dcells:
        for p in PARAMS:
            r = by_design.get((d, model, p))
            if r is None:
                continue
            r = numeric(r)
            if not LO <= r["coverage_shown"] <= HI:
                dmiss.append(r)
            fails = f" ({r['failed']:.0f} failed)" if r["failed"] else ""
            opened = f" ({r['profiles_open']:.0f} open)" if r["profiles_open"] else ""
            prof = (f"{pct(r['coverage_profile'], r['coverage_profile_se'])} %{flag(r['coverage_profile'])}"
                    f"{opened} | "
                    f"{r['sd_over_profile_halfwidth_over_t']:.2f}"
                    if r["intervals_profile"] == r["fits"] else "– | –")
            L.append(f"| {DESIGNS[d]} | {model} | {sym(p)} | {r['fits']:.0f}{fails} | {100 * r['rel_bias']:+.3f} % | "
                     f"{signed(r['bias_over_se_of_mean'])} | {100 * r['rel_rmse']:.3f} % | "
                     f"{pct(r['coverage'], r['coverage_se'])} %{flag(r['coverage'])} | {r['sd_over_stderr']:.2f} | "
                     f"{pct(r['coverage_shown'], r['coverage_shown_se'])} %{flag(r['coverage_shown'])}"
                     f" ({100 * r['profiled_by_default']:.0f} %) | "
                     f"{pct(r['coverage_hc3'], r['coverage_hc3_se'])} %{flag(r['coverage_hc3'])} | "
                     f"{r['sd_over_stderr_sandwich']:.2f} | {prof} |")
    L += ["", "Per cell: range of the stated interval's coverage over the parameters (and of HC3 and the "
          "profile), median dof, share of fits with the noise-free warning, with any warning, median fit "
          "time (one thread, two fits at a time; with the profile of every parameter where it was asked), "
          "the warnings by kind (share of fits; `sandwich`: model-based and HC3 standard errors differ, "
          "`law`: a, b or m differs from the pressure law, `correlation`: |r| > 0.99, `noise-free`: a "
          "channel at rounding level, σ floored; see docs/physics.md §8.9) "
          "and the noise model chosen per channel (most frequent; `fixed`: the fixed scales of §8.2 "
          "with one σ pooled over all cells, the fallback below k + 2 rows per channel).", "",
          "| design | model | fits | stated | HC3 | profile | dof | noise-free warning | any warning | warnings by kind | fit [s] | T_x | T_y | M_z | M_roll |",
          "|---|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---|---|---|---|"]
    rng = lambda xs: f"{100 * min(xs):.1f}–{100 * max(xs):.1f} %" if xs and all(x == x for x in xs) else "–"
    for d, model in dcells:
        rs = [numeric(r) for (dd, mm, _), r in by_design.items() if (dd, mm) == (d, model)]
        keys = [k for k in fits if (k[5], k[1], k[2], k[3]) == (d, model, "no", "auto")]
        key = keys[0] if keys else None
        if key is not None:
            counts, n = chosen_counts(key)
            chosen = [", ".join(f"{m} {100 * c / n:.0f} %" for m, c in counts[ch][:2]) for ch in counts]
            kinds = ", ".join(f"{k} {100 * x:.1f} %" for k, x in warning_shares(key)) or "–"
        else:
            chosen, kinds = ["–"] * 4, "–"
        r0 = rs[0]
        L.append(f"| {DESIGNS[d]} | {model} | {r0['fits']:.0f} | {rng([r['coverage_shown'] for r in rs])} | "
                 f"{rng([r['coverage_hc3'] for r in rs])} | "
                 f"{rng([r['coverage_profile'] for r in rs]) if r0['intervals_profile'] == r0['fits'] else '–'} | "
                 f"{r0['median_dof']:.0f} | {100 * r0['share_floor_warning']:.1f} % | {100 * r0['share_any_warning']:.1f} % | {kinds} | "
                 f"{r0['median_fit_s']:.3f} | " + " | ".join(chosen) + " |")
    vcells = [(d, model) for d, model in dcells
              if any(k[:3] == (d, model, "yes") for k in by_variant)]
    if vcells:
        L += ["", "Few rows: the same datasets fitted with the true σ in σ columns (no noise estimate; "
              "the default then uses them) and with `--noise-model` set to the form that generated "
              "the noise (additive for the 60-row cells, relative for 20 and 8 rows), against the "
              "default (auto). Coverage of ci95 and SD / s.e.; ✗ outside 93–97 %.", "",
              "| design | model | parameter | auto | SD / s.e. | σ columns | SD / s.e. | generating form | SD / s.e. | HC3, generating form |",
              "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
        for d, model in vcells:
            for p in PARAMS:
                a = by_variant.get((d, model, "no", "auto", p))
                c = by_variant.get((d, model, "yes", "auto", p))
                g = next((by_variant[k] for k in by_variant
                          if k[:3] == (d, model, "no") and k[3] in FORM and k[4] == p), None)
                if a is None or c is None or g is None:
                    continue
                a, c, g = numeric(a), numeric(c), numeric(g)
                L.append(f"| {DESIGNS[d]} | {model} | {sym(p)} | "
                         + " | ".join(f"{pct(x['coverage'], x['coverage_se'])} %{flag(x['coverage'])} | "
                                      f"{x['sd_over_stderr']:.2f}" for x in (a, c, g))
                         + f" | {pct(g['coverage_hc3'], g['coverage_hc3_se'])} %{flag(g['coverage_hc3'])} |")
    L += ["", "Design cells whose stated interval is outside 93–97 %:", ""]
    for r in dmiss:
        variants = []
        for cols, label in (("yes", "σ columns"), ("no", "generating form")):
            v = next((numeric(by_variant[k]) for k in by_variant
                      if k[:3] == (r["design"], r["model"], cols) and k[4] == r["parameter"]
                      and (cols == "yes" or k[3] in FORM)), None)
            if v is not None:
                variants.append((label, v["coverage"]))
        alt = [m for m, c in [("HC3", r["coverage_hc3"]), ("profile", r["coverage_profile"]),
                              ("ci95", r["coverage"])] + variants
               if c == c and LO <= c <= HI]
        L.append(f"- {DESIGNS[r['design']]} / {r['model']} / {sym(r['parameter'])}: "
                 f"{pct(r['coverage_shown'], r['coverage_shown_se'])} % (SD / s.e. {r['sd_over_stderr']:.2f}, "
                 f"bias / SE(mean) {signed(r['bias_over_se_of_mean'])}); within 93–97 %: {', '.join(alt) or 'none'}"
                 + ("; the estimate is exact to rounding (RMSE below 1e-6 of the value): the interval is "
                    "the bound the σ floor of the noise-free channels gives" if r["rel_rmse"] < 1e-6 else ""))
    if not dmiss:
        L.append("- none")
open(os.path.join(out_dir, "results.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))

# Plot: coverage per cell and parameter; the default cells with the model-based and HC3
# intervals, the interval cells also with the profile and the bootstrap ("?": no such interval);
# below them, when there are design cells, those with ci95, HC3, the profile and the stated one.
os.makedirs(scratch, exist_ok=True)
cov = lambda r, m: (f"{100 * f(r[m])} {100 * f(r[m + '_se'])}" if r.get(m) not in ("", None) else "? ?")


def panel(name, groups, methods):
    """Writes one panel's data: groups of (label, [row, ...]); returns its gnuplot settings."""
    dat = os.path.join(scratch, f"{name}.dat")
    i, seps, labels, low = 0, [], [], 85.0
    with open(dat, "w") as fh:
        for label, rows in groups:
            start_i = i
            for tic, r in rows:
                low = min([low] + [f(r[m]) * 100 - 2 for m in methods if r.get(m) not in ("", None)])
                fh.write(f'{i} {" ".join(cov(r, m) for m in methods)} "{tic}"\n')
                i += 1
            if i > start_i:
                labels.append((i, label))
                seps.append(i - 0.5)
    low = math.floor(low)
    g = [f'set ylabel "coverage [%]"\nset yrange [{low}:100]\nset grid y\nset xtics rotate by -90 font ",8"\n',
         f'set xrange [-0.5:{i - 0.5}]\nset key bottom right\nset datafile missing "?"\n',
         'set object 1 rect from graph 0, first 93 to graph 1, first 97 fc rgb "#e8f4e8" fs solid noborder behind\n',
         'unset label\nunset arrow\n']
    start = -0.5
    for k, (end, lab) in enumerate(labels):
        g.append(f'set label {k + 1} "{lab}" at {(start + end - 0.5) / 2}, 99 center font ",10"\n')
        start = end - 0.5
    for k, sep in enumerate(seps[:-1]):
        g.append(f'set arrow {k + 1} from {sep}, {low} to {sep}, 100 nohead dt 3 lc "gray"\n')
    return dat, "".join(g)


STYLE = {"coverage": ('pt 7 ps 0.6 lc "#1f77b4"', "model-based ci95"),
         "coverage_hc3": ('pt 6 ps 0.6 lc "#d62728"', "HC3 sandwich"),
         "coverage_profile": ('pt 9 ps 0.6 lc "#2ca02c"', "profile likelihood"),
         "coverage_bootstrap": ('pt 5 ps 0.5 lc "#9467bd"', "wild bootstrap"),
         "coverage_shown": ('pt 13 ps 0.7 lc "#ff7f0e"', "stated (profile where |r| > 0.99)")}


def plot_line(dat, methods):
    step = 0.14
    parts = []
    for j, m in enumerate(methods):
        style, title = STYLE[m]
        x = f"($1{(j - (len(methods) - 1) / 2) * step:+.2f})"
        parts.append(f'"{dat}" using {x}:{2 + 2 * j}:{3 + 2 * j}{":xtic(" + str(2 + 2 * len(methods)) + ")" if j == 0 else ""} '
                     f'with yerrorbars {style} title "{title}"')
    return "plot " + ", ".join(parts) + ', 95 with lines dt 2 lc "black" title "nominal 95 %"\n'


top_methods = ("coverage", "coverage_hc3", "coverage_profile", "coverage_bootstrap")
top = []
for noise, cols, iv in [(noise, cols, "default") for noise in NOISES for cols in ("no", "yes")] + \
                       [(noise, "no", INTERVAL_CELLS) for noise in NOISES]:
    rows = [(f"{model[:2]} {sym(p)}", by[(noise, model, cols, "auto", iv, p)])
            for model in MODELS for p in PARAMS if (noise, model, cols, "auto", iv, p) in by]
    kind = "profile, bootstrap" if iv == INTERVAL_CELLS else ("σ columns" if cols == "yes" else "auto")
    top.append((f"{noise}, {kind}", rows))
bottom_methods = ("coverage", "coverage_hc3", "coverage_profile", "coverage_shown")
bottom = [(DESIGNS[d], [(f"{model[:2]} {sym(p)}", by_design[(d, model, p)])
                        for model in MODELS for p in PARAMS if (d, model, p) in by_design])
          for d in DESIGNS]
gp = os.path.join(scratch, "coverage.gp")
with open(gp, "w") as g:
    both = any(rows for _, rows in bottom)
    g.write(f'set terminal svg size 1600,{1120 if both else 560} dynamic enhanced font "Helvetica,11"\n')
    g.write(f'set output "{os.path.join(out_dir, "coverage.svg")}"\n')
    if both:
        g.write("set multiplot layout 2,1\n")
    dat, settings = panel("coverage", top, top_methods)
    g.write('set title "Coverage of the 95 % intervals, default noise model (se: seed, co: corrected, ex: exact)"\n')
    g.write(settings + plot_line(dat, top_methods))
    if both:
        dat, settings = panel("coverage_designs", bottom, bottom_methods)
        g.write('set title "Design cells: additive noise, few rows, ε only above 1.5, noise-free channels"\n')
        g.write(settings + plot_line(dat, bottom_methods))
        g.write("unset multiplot\n")
subprocess.run(["gnuplot", gp], check=True)
