#!/usr/bin/env bash
# Does `frictionid fit` recover known parameters, and are its 95 % intervals honest?
#  A. Monte Carlo: N datasets (1 % relative Gaussian noise, ROWS rows, the default design) from
#     one truth, fitted with the seed model and with the exact model (Hertz pressure): bias,
#     RMSE, mean reported standard error vs the empirical spread, and the empirical coverage of
#     report.json's ci95 per parameter; with the default weighting (sigma = RMS of each channel,
#     covariance scaled by the reduced chi^2) and with per-row sigma columns (--sigma-columns).
#     Part A uses --global-evaluations 500 (6x cheaper than the default 3000 for the exact model).
#  B. Global stage: T random truths, noise-free data, default fit settings (bounds box only, no
#     initial guess) and the same with 500 evaluations: success = every parameter within 1e-6
#     relative of the truth.
# See the "Identification study" section of experiments/README.md.
#
#   experiments/identification_study/run.sh        # binary: $FRICTIONID, else build/frictionid
#   N=100 NS=50 T=20 experiments/identification_study/run.sh   # a quick smaller run
#
# Writes results.csv, results.md and coverage.svg here; scratch files to out/.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"

N="${N:-500}"          # Monte Carlo datasets per model, default weighting
NS="${NS:-250}"        # ... and with sigma columns
T="${T:-100}"          # random truths per model for the global-stage study
ROWS="${ROWS:-200}"
JOBS="${JOBS:-2}"      # parallel fits
LAW=hertz
TRUTH="f=0.9,kappa=1.15,h=0.08"   # seed: a, b, m follow the Hertz law (0.7205, 25, 7.580)
MC_BUDGET=500      # --global-evaluations in part A (part B checks that 500 suffices)
TRUTH_SEED=20261122

out="$here/out"
rm -rf "$out"
mkdir -p "$out/mc" "$out/global"
cp "$bin" "$out/frictionid"   # a private copy: a rebuild of build/ cannot interfere
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"
export bin LAW ROWS

# One job: generate (seeded) and fit; every file of the job stays in its own directory.
job() {  # kind model id param_spec weighting budget
  local kind=$1 model=$2 id=$3 param=$4 weight=$5 budget=$6 noise sig=()
  local dir="$out/$kind/${model}_${weight}_${budget}_$id"
  mkdir -p "$dir"
  if [[ $kind = mc ]]; then noise=0.01; else noise=0; fi
  [[ $weight = sigma ]] && sig=(--sigma-columns)
  "$bin" generate --model "$model" --pressure "$LAW" --param "$param" --rows "$ROWS" \
    --noise "$noise" --seed "$id" "${sig[@]}" --output "$dir/data.csv" --truth "$dir/truth.json" \
    > /dev/null 2>&1
  local rc=0 t0 t1
  t0=$(date +%s.%N)
  "$bin" fit "$dir/data.csv" --model "$model" --pressure "$LAW" --global-evaluations "$budget" \
    --report "$dir/report" \
    > "$dir/fit.log" 2>&1 || rc=$?
  t1=$(date +%s.%N)
  echo "$rc $(echo "$t1 - $t0" | bc)" > "$dir/status"
  rm -f "$dir/data.csv" "$dir"/report/*.svg "$dir"/report/*.dat   # keep report.json only
}
export -f job
export out

# Random truths for part B (seed: a, b, m drawn like experiments/global_search).
"$py" - "$T" "$TRUTH_SEED" > "$out/global/truths.csv" <<'PY'
import math, random, sys
n, seed = int(sys.argv[1]), int(sys.argv[2])
rng = random.Random(seed)
logu = lambda lo, hi: math.exp(rng.uniform(math.log(lo), math.log(hi)))
print("id,f,kappa,h,a,b,m")
for i in range(n):
    f, kappa, h = logu(0.2, 2.0), logu(0.3, 3.0), rng.uniform(-0.5, 0.5)
    a, b = rng.uniform(0.3, 3.5), logu(5.0, 200.0)
    m = logu(max(((1 + kappa) / kappa) ** 2, 1.5), 100.0)
    print(",".join([str(i)] + [repr(x) for x in (f, kappa, h, a, b, m)]))
PY

{
  for model in seed exact; do
    for weight in default sigma; do
      n=$N; [[ $weight = sigma ]] && n=$NS
      for (( i = 1; i <= n; i++ )); do echo "mc $model $i $TRUTH $weight $MC_BUDGET"; done
    done
  done
  tail -n +2 "$out/global/truths.csv" | while IFS=, read -r id f kappa h a b m; do
    for budget in 3000 500; do
      echo "global seed $id f=$f,kappa=$kappa,h=$h,a=$a,b=$b,m=$m default $budget"
      echo "global exact $id f=$f,kappa=$kappa,h=$h default $budget"
    done
  done
} > "$out/jobs.txt"

echo "run.sh: $(wc -l < "$out/jobs.txt") generate+fit jobs on $JOBS cores ..." >&2
start=$(date +%s.%N)
xargs -P "$JOBS" -L 1 bash -c 'job "$@"' _ < "$out/jobs.txt"
wall=$(echo "$(date +%s.%N) - $start" | bc)

"$py" - "$out" "$here" "$binary_id" "$wall" "$N" "$T" "$ROWS" "$JOBS" "$MC_BUDGET" "$NS" <<'PY'
import csv, glob, json, math, os, statistics, sys
out, here, binary_id, wall, N, T, ROWS, JOBS, MC_BUDGET, NS = sys.argv[1:11]
wall, N, T, NS = float(wall), int(N), int(T), int(NS)

def load(dir_):
    rc, secs = open(os.path.join(dir_, "status")).read().split()
    rep = os.path.join(dir_, "report", "report.json")
    truth = json.load(open(os.path.join(dir_, "truth.json")))["parameters"]
    return int(rc), float(secs), (json.load(open(rep)) if int(rc) == 0 and os.path.exists(rep) else None), truth

rows, summary = [], []
for model in ("seed", "exact"):
    for weight in ("default", "sigma"):
        fits = [load(d) for d in sorted(glob.glob(os.path.join(out, "mc", f"{model}_{weight}_{MC_BUDGET}_*")))]
        ok = [f for f in fits if f[2] is not None]
        names = [n for n, p in ok[0][2]["parameters"].items() if not p["fixed"]]
        for n in names:
            true = ok[0][3][n]
            est = [f[2]["parameters"][n]["value"] for f in ok]
            se = [f[2]["parameters"][n]["stderr"] for f in ok if f[2]["parameters"][n]["stderr"] is not None]
            ci = [f[2]["parameters"][n]["ci95"] for f in ok if f[2]["parameters"][n]["ci95"] is not None]
            cover = sum(lo <= true <= hi for lo, hi in ci)
            bias = statistics.fmean(est) - true
            sd = statistics.stdev(est)
            rmse = math.sqrt(statistics.fmean([(e - true) ** 2 for e in est]))
            cov = cover / len(ci) if ci else float("nan")
            rows.append(dict(model=model, weighting=weight, parameter=n, truth=true, fits=len(ok),
                             failed=len(fits) - len(ok), mean=statistics.fmean(est), bias=bias,
                             rel_bias=bias / true, bias_over_se_of_mean=bias / (sd / math.sqrt(len(est))),
                             rmse=rmse, rel_rmse=rmse / abs(true), sd=sd,
                             mean_reported_stderr=statistics.fmean(se) if se else float("nan"),
                             coverage95=cov, coverage_se=math.sqrt(max(cov * (1 - cov), 1e-12) / len(ci)) if ci else float("nan"),
                             median_fit_s=statistics.median(f[1] for f in fits)))
with open(os.path.join(here, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(rows[0]))
    w.writeheader(); w.writerows(rows)

# Part B.
truths = {r["id"]: r for r in csv.DictReader(open(os.path.join(out, "global", "truths.csv")))}
gl = []
for model, names, budget in (("seed", ["f", "kappa", "h", "a", "b", "m"], 3000), ("seed", ["f", "kappa", "h", "a", "b", "m"], 500),
                             ("exact", ["f", "kappa", "h"], 3000), ("exact", ["f", "kappa", "h"], 500)):
    succ, worst_digits, secs, failed, misses = 0, [], [], 0, []
    for id_, tr in truths.items():
        rc, s, rep, _ = load(os.path.join(out, "global", f"{model}_default_{budget}_{id_}"))
        secs.append(s)
        if rep is None:
            failed += 1; misses.append(id_); continue
        rel = {n: abs(rep["parameters"][n]["value"] - float(tr[n])) / abs(float(tr[n])) for n in names}
        worst = max(rel.values())
        worst_digits.append(17.0 if worst == 0 else min(17.0, -math.log10(worst)))
        if worst <= 1e-6:
            succ += 1
        else:
            misses.append(f"{id_} ({max(rel, key=rel.get)} {worst:.1e})")
    gl.append(dict(model=model, global_evaluations=budget, truths=len(truths), successes=succ, failed_exit=failed,
                   median_min_digits=statistics.median(worst_digits) if worst_digits else float("nan"),
                   min_min_digits=min(worst_digits) if worst_digits else float("nan"),
                   median_fit_s=statistics.median(secs), misses="; ".join(misses)))
with open(os.path.join(here, "results_global.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(gl[0]))
    w.writeheader(); w.writerows(gl)

g = lambda x, d=4: f"{x:.{d}g}"
L = [f"{binary_id}; {JOBS} parallel jobs on {os.cpu_count()} CPUs; whole study {wall:.0f} s wall.", "",
     f"**A. Monte Carlo**: {N} datasets per model with the default weighting, {NS} with sigma columns, Hertz pressure, truth f = 0.9, "
     f"κ = 1.15, h = 0.08 (seed: a, b, m of the Hertz law), {ROWS} rows of the default design, 1 % "
     "relative noise (`generate --noise 0.01 --seed i`), default fit settings except "
     f"`--global-evaluations {MC_BUDGET}` (see B). Coverage: share of "
     "fits whose ci95 contains the truth (± its binomial standard error).", "",
     "| model | weighting | parameter | truth | bias | bias / SE(mean) | rel. RMSE | SD of estimates | mean reported s.e. | coverage of ci95 | fits (failed) | median fit [s] |",
     "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
for r in rows:
    L.append(f"| {r['model']} | {r['weighting']} | {r['parameter']} | {g(r['truth'])} | {r['bias']:+.2e} | "
             f"{r['bias_over_se_of_mean']:+.1f} | {100 * r['rel_rmse']:.3f} % | {r['sd']:.3g} | "
             f"{r['mean_reported_stderr']:.3g} | {100 * r['coverage95']:.1f} ± {100 * r['coverage_se']:.1f} % | "
             f"{r['fits']} ({r['failed']}) | {r['median_fit_s']:.2f} |")
L += ["", f"**B. Global stage from the bounds box alone**: {T} random truths per model (f log-uniform "
      "0.2–2, κ log-uniform 0.3–3, h uniform ±0.5; seed also a uniform 0.3–3.5, b log-uniform 5–200, "
      "m log-uniform from the consistency bound to 100), noise-free data, default `fit` settings "
      "(crs2, 3000 evaluations, 4 starts; and with 500 evaluations). Success: every parameter within "
      "1e-6 relative.", "",
      "| model | global evaluations | successes | exit ≠ 0 | median digits of the worst parameter | fewest digits | median fit [s] | misses |",
      "|---|---:|---:|---:|---:|---:|---:|---|"]
for r in gl:
    L.append(f"| {r['model']} | {r['global_evaluations']} | {r['successes']}/{r['truths']} | {r['failed_exit']} | {r['median_min_digits']:.1f} | "
             f"{r['min_min_digits']:.1f} | {r['median_fit_s']:.2f} | {r['misses'] or '–'} |")
open(os.path.join(here, "results.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))

# Coverage plot.
dat = os.path.join(out, "coverage.dat")
with open(dat, "w") as fh:
    for i, r in enumerate(rows):
        fh.write(f'{i} {100 * r["coverage95"]} {100 * r["coverage_se"]} "{r["model"]}/{r["weighting"][0]} {r["parameter"]}"\n')
with open(os.path.join(out, "coverage.gp"), "w") as gp:
    gp.write('set terminal svg size 1000,450 dynamic enhanced font "Helvetica,11"\n')
    gp.write(f'set output "{os.path.join(here, "coverage.svg")}"\n')
    gp.write('set title "Empirical coverage of the reported 95 % intervals (d: default weighting, s: sigma columns)"\n')
    gp.write('set ylabel "coverage [%]"\nset yrange [50:100]\nset grid y\nset xtics rotate by -60 font ",9"\n')
    gp.write(f'set xrange [-0.5:{len(rows) - 0.5}]\nset key bottom left\n')
    gp.write(f'plot "{dat}" using 1:2:3:xtic(4) with yerrorbars pt 7 title "coverage ± 1 s.e.", 95 with lines dt 2 lc "black" title "nominal 95 %"\n')
os.system(f"gnuplot {os.path.join(out, 'coverage.gp')}")
PY
echo "run.sh: wrote $here/results.md, results.csv, results_global.csv, coverage.svg" >&2
