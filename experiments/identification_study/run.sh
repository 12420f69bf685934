#!/usr/bin/env bash
# Are the 95 % intervals of `frictionid fit` honest under per-channel noise, and is the default
# noise model (auto) at least as precise as one constant scale per channel?
#  A. Coverage study (coverage_study.cpp, the library's Fitter, default settings, one thread per
#     fit): relative, absolute and affine Gaussian noise, each different per channel; the seed,
#     corrected and exact models (Hertz pressure); without and with sigma columns (the true
#     sigma per row); per fit the model-based ci95 and the HC3 sandwich interval; the baseline
#     --noise-model constant on the same datasets; interval cells (relative and affine noise,
#     every model, no sigma columns, NI replicates) that also compute the profile interval and
#     a wild bootstrap of NBOOT resamples; design cells (ND replicates each, every model, default
#     noise model, no sigma columns): additive noise on 600 and 60 rows, 20 and 8 rows, eps only in
#     1.5-100, T_x and M_z noise-free, each fit also with the profile interval of every parameter.
#     Writes results.md, results.csv, coverage.svg.
#  B. (GLOBAL=1 only) Global stage: T random truths, noise-free data, `frictionid fit` with the
#     bounds box only, 3000 and 500 evaluations; writes results_global.csv and results_global.md.
# See the "Identification study" section of experiments/README.md.
#
#   experiments/identification_study/run.sh                  # ~45 min on 2 shared cores
#   N=100 NE=50 NB=50 NI=50 experiments/identification_study/run.sh # a quick smaller run
#   CELLS=intervals experiments/identification_study/run.sh  # only the interval cells (~15 min),
#       merged into the existing results.md/csv/svg; the other cells' numbers are kept as they are
#   CELLS=designs ND=1000 experiments/identification_study/run.sh  # only the design cells
#       (~20 min), merged the same way (DESIGNS=rows8,rows20 for some of them)
#
# Builds the driver in $BUILD_DIR (default build-study, Release, benchmarks on); scratch to out/.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
py=/usr/bin/python3

N="${N:-1000}"         # replicates per default-method cell, seed and corrected models
NE="${NE:-500}"        # ... exact model
NB="${NB:-500}"        # replicates of the constant-noise baseline per cell (no sigma columns)
NI="${NI:-400}"        # replicates per interval cell (profile and bootstrap)
NBOOT="${NBOOT:-199}"  # wild-bootstrap resamples per fit in the interval cells
ND="${ND:-500}"        # replicates per design cell
DESIGNS="${DESIGNS:-}" # design cells to run (rows600,rows60,rows20,rows8,eps1.5,noisefree); empty: all
DI="${DI:-profile}"    # the design cells' --intervals: profile (every parameter) or model
CELLS="${CELLS:-all}"  # all, or intervals or designs (merge those cells into the existing results)
ROWS="${ROWS:-600}"    # rows of generate's default design
JOBS="${JOBS:-2}"      # fits in parallel
BUILD_DIR="${BUILD_DIR:-$root/build-study}"

out="$here/out"
rm -rf "$out"
mkdir -p "$out"
"$root/scripts/install-deps" --experiments >&2

# A. The coverage study.
cmake -S "$root" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DFRICTIONID_BUILD_TESTS=OFF \
  -DFRICTIONID_BUILD_BENCHMARKS=ON > "$out/cmake.log"
cmake --build "$BUILD_DIR" -j "$JOBS" --target coverage_study >> "$out/cmake.log"
cp "$BUILD_DIR/experiments/coverage_study" "$out/coverage_study"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
case "$CELLS" in
  all) merge=() ;;
  intervals|designs) merge=(--merge "$CELLS") ;;
  *) echo "run.sh: CELLS must be all, intervals or designs, not $CELLS" >&2; exit 2 ;;
esac
echo "run.sh: coverage study ($CELLS cells), N=$N NE=$NE NB=$NB NI=$NI NBOOT=$NBOOT ND=$ND ROWS=$ROWS on $JOBS jobs ..." >&2
start=$(date +%s.%N)
"$out/coverage_study" --cells "$CELLS" --replicates "$N" --replicates-exact "$NE" \
  --baseline-replicates "$NB" --interval-replicates "$NI" --bootstrap-resamples "$NBOOT" \
  --design-replicates "$ND" --designs "$DESIGNS" --design-intervals "$DI" \
  --rows "$ROWS" --jobs "$JOBS" --output "$out/coverage_fits.csv" 2> "$out/coverage_study.log"
wall=$(echo "$(date +%s.%N) - $start" | bc)
settings="$ROWS rows of the default design, Hertz pressure, truth f = 0.9, κ = 1.15, h = 0.08 \
(a, b, m, b̃, p0 of the Hertz law); default fit settings (global stage crs2 3000 evaluations, 4 \
starts) with one thread per fit, $JOBS fits in parallel on $(nproc) CPUs"
if [[ "$CELLS" = all ]]; then
  note="coverage_study at commit $commit; $settings; $N replicates per cell (exact model: $NE), \
baseline $NB; interval cells $NI replicates, bootstrap $NBOOT resamples; design cells $ND replicates, \
--intervals $DI."
elif [[ "$CELLS" = designs ]]; then
  note="Design cells: coverage_study --cells designs${DESIGNS:+ --designs $DESIGNS} at commit $commit; \
default fit settings (global stage crs2 3000 evaluations, 4 starts) with one thread per fit, $JOBS \
fits in parallel on $(nproc) CPUs; Hertz pressure, truth f = 0.9, κ = 1.15, h = 0.08 (a, b, m, b̃, \
p0 of the Hertz law); $ND replicates per cell, --intervals $DI."
else
  note="Interval cells: coverage_study --cells intervals at commit $commit; $settings; $NI \
replicates per cell, --intervals profile --bootstrap $NBOOT (wild bootstrap seed: the fit's \
seed, 1)."
fi
"$py" "$here/summarize.py" "$out/coverage_fits.csv" "$here" "$note" "$wall" "$out" "${merge[@]}"
echo "run.sh: wrote $here/results.md, results.csv, coverage.svg" >&2

[[ "${GLOBAL:-0}" = 1 ]] || exit 0

# B. The global stage, through the CLI: binary $FRICTIONID, else build/frictionid.
source "$here/../common.sh"
T="${T:-100}"          # random truths per model for the global-stage study
LAW=hertz
TRUTH_SEED=20261122
mkdir -p "$out/global"
cp "$bin" "$out/frictionid"   # a private copy: a rebuild of build/ cannot interfere
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"
export bin LAW ROWS

# One job: generate and fit noise-free data; every file of the job stays in its own directory.
job() {  # model id param_spec budget
  local model=$1 id=$2 param=$3 budget=$4
  local dir="$out/global/${model}_default_${budget}_$id"
  mkdir -p "$dir"
  "$bin" generate --model "$model" --pressure "$LAW" --param "$param" --rows 200 \
    --noise 0 --seed "$id" --output "$dir/data.csv" --truth "$dir/truth.json" > /dev/null 2>&1
  local rc=0 t0 t1
  t0=$(date +%s.%N)
  "$bin" fit "$dir/data.csv" --model "$model" --pressure "$LAW" --global-evaluations "$budget" \
    --report "$dir/report" > "$dir/fit.log" 2>&1 || rc=$?
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

tail -n +2 "$out/global/truths.csv" | while IFS=, read -r id f kappa h a b m; do
  for budget in 3000 500; do
    echo "seed $id f=$f,kappa=$kappa,h=$h,a=$a,b=$b,m=$m $budget"
    echo "exact $id f=$f,kappa=$kappa,h=$h $budget"
  done
done > "$out/global/jobs.txt"

echo "run.sh: $(wc -l < "$out/global/jobs.txt") generate+fit jobs on $JOBS cores ..." >&2
start=$(date +%s.%N)
xargs -P "$JOBS" -L 1 bash -c 'job "$@"' _ < "$out/global/jobs.txt"
wall=$(echo "$(date +%s.%N) - $start" | bc)

"$py" - "$out" "$here" "$binary_id" "$wall" "$T" "$JOBS" <<'PY'
import csv, json, math, os, statistics, sys
out, here, binary_id, wall, T, JOBS = sys.argv[1:7]
wall, T = float(wall), int(T)

def load(dir_):
    rc, secs = open(os.path.join(dir_, "status")).read().split()
    rep = os.path.join(dir_, "report", "report.json")
    return int(rc), float(secs), (json.load(open(rep)) if int(rc) == 0 and os.path.exists(rep) else None)

truths = {r["id"]: r for r in csv.DictReader(open(os.path.join(out, "global", "truths.csv")))}
gl = []
for model, names, budget in (("seed", ["f", "kappa", "h", "a", "b", "m"], 3000), ("seed", ["f", "kappa", "h", "a", "b", "m"], 500),
                             ("exact", ["f", "kappa", "h"], 3000), ("exact", ["f", "kappa", "h"], 500)):
    succ, worst_digits, secs, failed, misses = 0, [], [], 0, []
    for id_, tr in truths.items():
        rc, s, rep = load(os.path.join(out, "global", f"{model}_default_{budget}_{id_}"))
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
L = [f"{binary_id}; {JOBS} parallel jobs on {os.cpu_count()} CPUs; {wall:.0f} s wall.", "",
     f"**B. Global stage from the bounds box alone**: {T} random truths per model (f log-uniform "
     "0.2–2, κ log-uniform 0.3–3, h uniform ±0.5; seed also a uniform 0.3–3.5, b log-uniform 5–200, "
     "m log-uniform from the consistency bound to 100), noise-free data (200 rows), default `fit` "
     "settings (crs2, 3000 evaluations, 4 starts; and with 500 evaluations). Success: every "
     "parameter within 1e-6 relative.", "",
     "| model | global evaluations | successes | exit ≠ 0 | median digits of the worst parameter | fewest digits | median fit [s] | misses |",
     "|---|---:|---:|---:|---:|---:|---:|---|"]
for r in gl:
    L.append(f"| {r['model']} | {r['global_evaluations']} | {r['successes']}/{r['truths']} | {r['failed_exit']} | {r['median_min_digits']:.1f} | "
             f"{r['min_min_digits']:.1f} | {r['median_fit_s']:.2f} | {r['misses'] or '–'} |")
open(os.path.join(here, "results_global.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))
PY
echo "run.sh: wrote $here/results_global.md, results_global.csv" >&2
