#!/usr/bin/env bash
# A test campaign fitted four ways, side by side in one run (see README.md):
#   1. generates LOADS x PRESSURES x REPEATS runs of ROWS rows (seed model, Hertz pressure,
#      1 % noise): a friction f per load, kappa = 1.3 and h = 0.12 common to all runs, the
#      contact radius R set by the inflation pressure; a manifest lists them with load and
#      pressure as covariates;
#   2. `frictionid batch` of the manifest (per-run report.json);
#   3. the same with `--warm-start` (every run after the first starts from its fit), and with
#      `--shared kappa,h` (every run's own fit, then the joint fit);
#   4. a loop of single `frictionid fit` calls over the first SINGLE runs;
#   5. a loop of scipy least_squares (experiments/bench_fit_vs_scipy/fit_scipy.py, the same seed
#      model and whitening, local stage only, from the truth moved 10-20 %) over the same runs.
# Then summarize.py writes results.md (times, speed-ups, agreement) and results.svg.
#
#   experiments/batch/run.sh                      # 1000 runs (5 x 4 x 50) of 2000 rows
#   REPEATS=5 SINGLE=20 experiments/batch/run.sh  # a quick one: 100 runs
#
# Binary: $FRICTIONID, else build/frictionid. Scratch in out/ (git-ignored).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"

LOADS=(2000 3000 4000 5000 6000)
PRESSURES=(1.8 2.2 2.6 3.0)   # bar; R = 0.03 + 0.01 * (3.4 - p) / 0.4 m: softer tire, larger spot
REPEATS=${REPEATS:-50}
ROWS=${ROWS:-2000}
SINGLE=${SINGLE:-50}
cpus=$(nproc)   # before OMP_NUM_THREADS, which nproc obeys
JOBS=${JOBS:-$cpus}
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1

out="$here/out"
rm -rf "$out"
mkdir -p "$out/in" "$out/single" "$out/scipy"
cp "$bin" "$out/frictionid"   # a rebuild of build/ during the run cannot mix two versions
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"

# 1. The campaign.
echo "path,label,load,inflation_bar,f_true,R" > "$out/manifest.csv"
seed=1
for load in "${LOADS[@]}"; do
  f=$("$py" -c "print(round(1.0 - 0.05 * $load / 1000, 6))")   # friction falls with load
  for p in "${PRESSURES[@]}"; do
    R=$("$py" -c "print(round(0.03 + 0.01 * (3.4 - $p) / 0.4, 6))")
    for ((k = 1; k <= REPEATS; k++)); do
      label=$(printf "N%s_p%s_%03d" "$load" "$p" "$k")
      "$bin" generate --model seed --pressure hertz --rows "$ROWS" --noise 0.01 --seed $seed \
        --param "f=$f,kappa=1.3,h=0.12" --loads "$load" --R "$R" \
        --output "$out/in/$label.csv" > /dev/null 2>&1
      echo "in/$label.csv,$label,$load,$p,$f,$R" >> "$out/manifest.csv"
      seed=$((seed + 1))
    done
  done
done
runs=$((${#LOADS[@]} * ${#PRESSURES[@]} * REPEATS))
bytes=$(du -cb "$out"/in/*.csv | tail -n 1 | cut -f1)
echo "run.sh: $runs runs of $ROWS rows generated ($bytes bytes)" >&2

TIMEFORMAT="%3R %3U %3S"
timed() {  # timed NAME COMMAND...: wall, user and system seconds into out/NAME.time
  local name=$1
  shift
  { time "$@" > "$out/$name.log" 2>&1; } 2> "$out/$name.time"
}
load_before=$(cut -d" " -f1-3 /proc/loadavg)

# 2.-3. The batch, without and with the shared parameters.
timed batch "$bin" batch "$out/manifest.csv" --report "$out/batch" --jobs "$JOBS"
timed warm "$bin" batch "$out/manifest.csv" --report "$out/warm" --jobs "$JOBS" --warm-start
timed shared "$bin" batch "$out/manifest.csv" --report "$out/shared" --jobs "$JOBS" \
  --shared kappa,h
echo "run.sh: batch $(cat "$out/batch.time"), warm $(cat "$out/warm.time"), shared $(cat "$out/shared.time")" >&2

# 4. Single fits, one process per run, as a shell loop would do.
head -n $((SINGLE + 1)) "$out/manifest.csv" | tail -n +2 | cut -d, -f2 > "$out/single.txt"
single_loop() {
  while read -r label; do
    "$bin" fit "$out/in/$label.csv" --model seed --pressure hertz \
      --report "$out/single/$label" > /dev/null 2>&1
  done < "$out/single.txt"
}
timed single single_loop

# 5. scipy's least_squares on the same runs, from a start 10-20 % off the truth.
scipy_loop() {
  while read -r label; do
    f=$(grep ",$label," "$out/manifest.csv" | cut -d, -f5)
    "$py" "$here/../bench_fit_vs_scipy/fit_scipy.py" fit "$out/in/$label.csv" \
      --param "f=$("$py" -c "print($f * 1.1)"),kappa=1.1,h=0.1,a=0.75,b=24,m=8" \
      --aligned-only --json "$out/scipy/$label.json" > /dev/null
  done < "$out/single.txt"
}
timed scipy scipy_loop
load_after=$(cut -d" " -f1-3 /proc/loadavg)

"$py" "$here/summarize.py" --out "$out" --here "$here" --runs "$runs" --rows "$ROWS" \
  --single "$SINGLE" --jobs "$JOBS" --bytes "$bytes" --binary "$binary_id" \
  --load "$load_before -> $load_after" --cpus "$cpus"
echo "run.sh: wrote $here/results.md and results.svg" >&2
